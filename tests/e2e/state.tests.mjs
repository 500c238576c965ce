// Browser tests of what a mesh opens with and of the page's state in its URL (issue 31): a mesh that
// is not a disk opens with the auto boundary and says why, and clicks on it do what the panel says;
// a link restores the sample, the source, the destinations, the boundary, the weights, the view
// options, the mode and the Atlas mode's options, and a link to a file asks for the file by name. Imported by browser.test.mjs, which owns
// the browser (useBrowser).

import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { describe } from 'node:test';
import { BIG_TEST_TIMEOUT_MS, BIG_WAIT_TIMEOUT_MS, expectReady, pageTest } from './support/fixtures.mjs';

const ICOSPHERE = new URL('../data/good/icosphere.obj', import.meta.url);
const hooks = (page) => page.evaluate(() => window.__straightest);
const idle = 'window.__straightest.param && !window.__straightest.progress.busy';

describe('default per mesh and state in the URL', () => {
  pageTest(
    'a closed mesh opens with the auto boundary and says why; a click moves its source',
    { ready: idle },
    async ({ page }) => {
      assert((await page.inputValue('#boundary-select')) === 'measured', 'the mountain (a disk) opens measured');
      assert(await page.isHidden('#param-why'), 'a disk gets a note about its boundary');
      await page.setInputFiles('#file-input', {
        name: 'icosphere.obj',
        mimeType: 'text/plain',
        buffer: await readFile(ICOSPHERE),
      });
      await expectReady(page, `window.__straightest.lastInfo.vertices === 42 && ${idle}`);
      const { param, defaultBoundary } = await hooks(page);
      assert(defaultBoundary.boundary === 'auto' && defaultBoundary.applied, JSON.stringify(defaultBoundary));
      assert((await page.inputValue('#boundary-select')) === 'auto', 'the menu does not say auto');
      assert(param.bijective && param.cut === 'path', `the closed mesh's map: ${JSON.stringify(param)}`);
      const why = await page.textContent('#param-why');
      assert((await page.isVisible('#param-why')) && /auto/i.test(why) && /closed/.test(why), `the note says '${why}'`);
      assert((await page.textContent('#param-method')).startsWith('auto →'), 'the method line does not say auto');
      assert((await page.textContent('#summary-boundary')).startsWith('auto →'), 'the results bar does not say auto');

      // A plain click moves the source (no destination yet: nothing traced), as the panel says.
      const box = await page.locator('#view-canvas').boundingBox();
      const traces = (await hooks(page)).traces;
      await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
      await expectReady(page, `window.__straightest.traces > ${traces}`);
      const { paths } = await hooks(page);
      assert(paths.count === 0 && typeof paths.source?.face === 'number', `after a click: ${JSON.stringify(paths)}`);
    },
  );

  const viewQuery = '?sample=cap&source=v40&dest=v300-f20_0.2_0.3_0.5&boundary=circle&weights=uniform&targets=0&wire=1';
  pageTest(
    'a link restores the sample, source, destinations, boundary, weights and view options; changes go back into the URL',
    {
      query: viewQuery,
      ready: `(${idle}) && window.__straightest.param.boundary === 'circle'`,
    },
    async ({ page }) => {
      const { paths, param, lastInfo } = await hooks(page);
      assert((await page.inputValue('#sample-select')) === 'cap', 'not the cap sample');
      assert(lastInfo.vertices > 0 && paths.source?.vertex === 40, `source ${JSON.stringify(paths.source)}`);
      assert(paths.count === 2, `${paths.count} paths (targets off: the two added destinations)`);
      assert(param.boundary === 'circle' && param.weights === 'uniform', `${param.boundary} / ${param.weights}`);
      assert(
        (await page.isChecked('#wireframe-toggle')) && !(await page.isChecked('#boundary-toggle')),
        'view options',
      );
      assert(new URL(page.url()).search === viewQuery, `the URL became ${new URL(page.url()).search}`);

      // A click moves the source: the URL follows, and a reload shows the same.
      const box = await page.locator('#view-canvas').boundingBox();
      const traces = (await hooks(page)).traces;
      await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
      await expectReady(page, `window.__straightest.traces > ${traces}`);
      const moved = (await hooks(page)).paths.source;
      assert(typeof moved.face === 'number', `clicked source ${JSON.stringify(moved)}`);
      const saved = new URL(page.url()).searchParams;
      assert(saved.get('source').startsWith(`f${moved.face}_`) && saved.get('boundary') === 'circle', `URL ${saved}`);
      await page.reload();
      await expectReady(page, `${idle} && window.__straightest.paths?.source?.face === ${moved.face}`);
      const again = await hooks(page);
      assert(
        again.paths.source.bary.every((b, k) => Math.abs(b - moved.bary[k]) < 1e-5),
        'the barycentric coordinates changed',
      );
      assert(again.paths.count === 2 && again.param.boundary === 'circle', JSON.stringify(again.paths));
    },
  );

  const fileQuery = '?file=icosphere.obj&source=v3&dest=v20&flat=1';
  pageTest(
    'a link to a file asks for it by name and restores its points once it is opened',
    { query: fileQuery, ready: idle },
    async ({ page }) => {
      const wanted = await page.textContent('#file-wanted');
      assert((await page.isVisible('#file-wanted')) && wanted.includes('icosphere.obj'), `asks '${wanted}'`);
      assert(new URL(page.url()).search === fileQuery, 'the link was overwritten before its file came');
      assert(await page.isChecked('#flat-toggle'), 'the view option was not applied');
      await page.setInputFiles('#file-input', {
        name: 'icosphere.obj',
        mimeType: 'text/plain',
        buffer: await readFile(ICOSPHERE),
      });
      await expectReady(
        page,
        `window.__straightest.lastInfo.vertices === 42 && window.__straightest.paths?.count === 1`,
      );
      const { paths } = await hooks(page);
      assert(paths.source?.vertex === 3, `source ${JSON.stringify(paths.source)}`);
      assert(await page.isHidden('#file-wanted'), 'still asking for the file');
      await page.waitForFunction(() => new URL(location.href).searchParams.get('file') === 'icosphere.obj');
    },
  );

  const atlasQuery =
    '?sample=torus&mode=atlas&atlasstretch=1.1&atlasfill=0.5&atlasres=512&atlaspad=4&atlasshow=checker&seams=0';
  pageTest(
    'a link restores the Atlas mode and its options; changing them and the mode goes back into the URL',
    { query: atlasQuery, timeout: BIG_TEST_TIMEOUT_MS },
    async ({ page }) => {
      const atlasShown = (more) =>
        page.waitForFunction(`window.__straightest.atlas && !window.__straightest.progress.busy && ${more}`, null, {
          timeout: BIG_WAIT_TIMEOUT_MS,
        });
      await atlasShown('true');
      const { atlas } = await hooks(page);
      assert.deepEqual(
        atlas.options,
        { maxStretch: 1.1, minHullFill: 0.5, resolution: 512, padding: 4 },
        'the atlas made',
      );
      assert((await page.getAttribute('#mode-tab-atlas', 'aria-selected')) === 'true', 'the Atlas tab is not selected');
      assert((await page.evaluate(() => document.body.dataset.mode)) === 'atlas', 'the page is not in the Atlas mode');
      assert((await page.inputValue('#atlas-max-stretch')) === '1.1', 'max stretch field');
      assert((await page.inputValue('#atlas-min-hull-fill')) === '0.5', 'min hull fill field');
      assert((await page.inputValue('#atlas-resolution')) === '512', 'resolution menu');
      assert((await page.inputValue('#atlas-padding')) === '4', 'padding field');
      assert((await page.inputValue('#atlas-display')) === 'checker', 'show menu');
      assert(!(await page.isChecked('#atlas-seams-toggle')), 'seams toggle');
      assert(new URL(page.url()).search === atlasQuery, `the URL became ${new URL(page.url()).search}`);

      // A changed option makes the atlas again and goes into the URL; a reload keeps it.
      const atlases = (await hooks(page)).atlases;
      await page.fill('#atlas-padding', '3');
      await page.dispatchEvent('#atlas-padding', 'change');
      await atlasShown(`window.__straightest.atlases > ${atlases} && window.__straightest.atlas.options.padding === 3`);
      assert(new URL(page.url()).searchParams.get('atlaspad') === '3', `URL ${new URL(page.url()).search}`);
      await page.reload();
      await atlasShown('window.__straightest.atlas.options.padding === 3');
      assert.deepEqual((await hooks(page)).atlas.options, {
        maxStretch: 1.1,
        minHullFill: 0.5,
        resolution: 512,
        padding: 3,
      });

      // Back to the 3D surface: the mode leaves the URL, the atlas options stay.
      await page.click('#mode-tab-surface');
      await page.waitForFunction(() => !new URL(location.href).searchParams.has('mode'));
      const saved = new URL(page.url()).searchParams;
      assert(saved.get('atlasstretch') === '1.1' && saved.get('atlasres') === '512', `URL ${saved}`);
    },
  );
});
