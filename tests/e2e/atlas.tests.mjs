// Browser tests of the Atlas mode (issue 29, item 5): on a closed sample the metrics the page shows are
// the npm package's own for the same mesh and options (computed here in Node); the packed layout has one
// colour per chart; the OBJ, GLB, PNG and SVG downloads carry the atlas; Cancel leaves a usable page; bad
// options get a readable error; every number fits the window at a laptop's and a phone's size.
// Imported by browser.test.mjs, which owns the browser (useBrowser). ATLAS_SCREENSHOTS=dir saves the
// mode at both sizes there.

import assert from 'node:assert/strict';
import { mkdir } from 'node:fs/promises';
import { after, before, describe } from 'node:test';
import { createStraightest } from '../../wasm/index.js';
import { formatCount, formatMetric, formatPercent } from '../../web/param-format.js';
import {
  BIG_TEST_TIMEOUT_MS,
  BIG_WAIT_TIMEOUT_MS,
  WAIT_TIMEOUT_MS,
  expectReady,
  pageTest,
} from './support/fixtures.mjs';
import { decodePng } from './support/images.mjs';
import { SIZES, misplacedBoxes } from './layout.tests.mjs';

const SAMPLE = 'torus'; // closed, genus 1: the atlas must cut it into disks
const OPTIONS = { maxStretch: 1.02, minHullFill: 0.75, resolution: 1024, padding: 2 }; // the page's defaults
const STATS = '#atlas-stats dt, #atlas-stats dd, #results-summary .summary-item, #results-summary dd';

/** Opens the sample and the Atlas tab; resolves with the atlas's hook once it is shown. */
async function openAtlas(page, sample = SAMPLE) {
  await page.selectOption('#sample-select', sample);
  await expectReady(page, `window.__straightest.lastInfo && document.body.dataset.mesh === '${sample}'`);
  await page.click('#mode-tab-atlas');
  await page.waitForFunction(() => window.__straightest.atlas && !window.__straightest.progress.busy, null, {
    timeout: BIG_WAIT_TIMEOUT_MS,
  });
  return page.evaluate(() => window.__straightest.atlas);
}

async function downloaded(page, button) {
  const [file] = await Promise.all([page.waitForEvent('download'), page.click(button)]);
  const chunks = [];
  for await (const chunk of await file.createReadStream()) chunks.push(chunk);
  return { name: file.suggestedFilename(), bytes: Buffer.concat(chunks) };
}

const text = (page, id) => page.textContent(`#${id}`).then((t) => t.trim());

describe('atlas mode', () => {
  let st = null;
  let reference = null; // the npm API's atlas of the sample, in Node
  before(async () => {
    st = await createStraightest({ threads: 1 });
    const mesh = st.sample(SAMPLE);
    reference = { ...mesh.atlas(OPTIONS), faces: mesh.info().faces };
    mesh.delete();
  });
  after(() => {
    st = null;
  });

  pageTest(
    'Atlas mode shows the npm API’s metrics and one layout colour per chart',
    {
      timeout: BIG_TEST_TIMEOUT_MS,
    },
    async ({ page }) => {
      const atlas = await openAtlas(page);
      assert.deepEqual(atlas.options, OPTIONS, 'the page’s default options');
      assert(reference.charts > 1, `the torus gives ${reference.charts} charts`);
      for (const key of [
        'charts',
        'utilization',
        'width',
        'height',
        'texelsPerUnit',
        'seamEdges',
        'seamLength',
        'flipped',
        'mirrored',
        'overlaps',
        'minGapTexels',
        'paddingViolations',
      ]) {
        assert.equal(atlas[key], reference[key], `${key}: page ${atlas[key]}, npm ${reference[key]}`);
      }
      assert.equal(atlas.l2, reference.stretch.l2);
      assert.equal(atlas.linf, reference.stretch.linf);
      // The panel writes them as the page writes every number.
      assert.equal(await text(page, 'atlas-charts'), formatCount(reference.charts));
      assert.equal(await text(page, 'atlas-l2'), formatMetric(reference.stretch.l2));
      assert.equal(await text(page, 'atlas-linf'), formatMetric(reference.stretch.linf));
      assert.equal(await text(page, 'atlas-utilization'), formatPercent(reference.utilization));
      assert.equal(await text(page, 'atlas-flipped'), String(reference.flipped));
      assert.equal(await text(page, 'atlas-mirrored'), String(reference.mirrored));
      assert.equal(await text(page, 'atlas-overlaps'), String(reference.overlaps));
      assert.equal(await text(page, 'atlas-gap'), formatMetric(reference.minGapTexels));
      assert.equal(
        await text(page, 'atlas-seam'),
        `${formatCount(reference.seamEdges)} · ${formatMetric(reference.seamLength)}`,
      );
      assert.match(await text(page, 'atlas-time'), /^[\d.< ]+ \/ [\d.< ]+ \/ [\d.< ]+ \/ [\d.,< ]+ ms$/);
      assert.equal(await text(page, 'summary-atlas-charts'), formatCount(reference.charts), 'the results bar');
      assert.equal(await text(page, 'summary-atlas-l2'), formatMetric(reference.stretch.l2), 'the results bar');
      assert(await page.isHidden('#summary-l2'), 'the parameterization’s L2 stays in the bar in Atlas mode');
      const stages = await page.evaluate(() => window.__straightest.progress.stages);
      for (const stage of ['segment', 'flatten', 'pack', 'measure'])
        assert.equal(stages[`atlas:${stage}`], 1, `stage ${stage}`);

      // The layout beside the view: every chart's colour is in the canvas, and no two charts share one.
      assert.equal(new Set(atlas.colors).size, reference.charts, 'two charts share a colour');
      assert(await page.isVisible('#atlas-canvas'), 'the layout is not shown beside the view');
      const present = await page.evaluate((colors) => {
        const canvas = document.getElementById('atlas-canvas');
        const { data } = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
        const seen = new Set();
        for (let i = 0; i < data.length; i += 4) seen.add(`rgb(${data[i]},${data[i + 1]},${data[i + 2]})`);
        return colors.filter((c) => seen.has(c)).length;
      }, atlas.colors);
      assert.equal(present, reference.charts, `${present} of ${reference.charts} chart colours in the layout canvas`);

      // The 3D view draws the atlas (the surface mode's objects are on another layer).
      const view = decodePng(await page.locator('#view-canvas').screenshot());
      assert(view.width > 100, 'no 3D view');
      await page.click('#mode-tab-surface');
      assert(await page.isHidden('#mode-side'), 'the layout stays beside the view in the surface mode');
      assert(await page.isVisible('#summary-l2'), 'the surface mode’s results bar');
    },
  );

  pageTest(
    'Atlas mode downloads OBJ (vt, f v/vt), GLB (TEXCOORD_0), layout PNG and SVG (a path per chart)',
    {
      timeout: BIG_TEST_TIMEOUT_MS,
    },
    async ({ page }) => {
      const atlas = await openAtlas(page);
      const obj = await downloaded(page, '#atlas-obj-button');
      assert.equal(obj.name, `${SAMPLE}-atlas.obj`);
      const lines = obj.bytes.toString('utf8').split('\n');
      const vt = lines.filter((l) => l.startsWith('vt ')).map((l) => l.split(/\s+/).slice(1).map(Number));
      const faces = lines.filter((l) => l.startsWith('f '));
      assert(
        vt.length > 0 && vt.every(([u, v]) => u >= 0 && u <= 1 && v >= 0 && v <= 1),
        `${vt.length} vt lines in [0,1]²`,
      );
      assert.equal(faces.length, reference.faces);
      assert(
        faces.every((l) => /^f( \d+\/\d+){3}$/.test(l)),
        `a face line without v/vt: ${faces.find((l) => !/^f( \d+\/\d+){3}$/.test(l))}`,
      );

      const glb = await downloaded(page, '#atlas-glb-button');
      assert.equal(glb.name, `${SAMPLE}-atlas.glb`);
      assert.equal(glb.bytes.toString('latin1', 0, 4), 'glTF', 'not a binary glTF');
      const json = JSON.parse(glb.bytes.toString('utf8', 20, 20 + glb.bytes.readUInt32LE(12)));
      const { attributes, indices } = json.meshes[0].primitives[0];
      assert('TEXCOORD_0' in attributes && 'POSITION' in attributes, `GLB attributes: ${Object.keys(attributes)}`);
      const uv = json.accessors[attributes.TEXCOORD_0];
      assert(uv.min.every((x) => x >= 0) && uv.max.every((x) => x <= 1), `GLB uv range ${uv.min} – ${uv.max}`);
      assert.equal(json.accessors[indices].count, 3 * reference.faces, 'the GLB’s triangles');
      assert(
        uv.count > json.accessors[attributes.POSITION].count - 1 && uv.count >= reference.seamEdges,
        'the GLB is not split along the seams',
      );

      const png = await downloaded(page, '#atlas-png-button');
      assert.equal(png.name, `${SAMPLE}-atlas-layout.png`);
      const image = decodePng(png.bytes);
      assert.equal(image.width, atlas.width);
      assert.equal(image.height, atlas.height);

      const svg = await downloaded(page, '#atlas-svg-button');
      assert.equal(svg.name, `${SAMPLE}-atlas-layout.svg`);
      const source = svg.bytes.toString('utf8');
      assert.match(source, new RegExp(`viewBox="0 0 ${atlas.width} ${atlas.height}"`));
      const paths = [...source.matchAll(/<path data-chart="(\d+)" fill="([^"]+)" d="([^"]*)"/g)];
      assert.equal(paths.length, reference.charts, 'one path per chart');
      assert.equal(new Set(paths.map((p) => p[2])).size, reference.charts, 'one colour per chart');
      assert(
        paths.every((p) => p[3].length > 0),
        'an empty chart path',
      );
      await page.waitForFunction(
        (said) => document.getElementById('atlas-export-status').textContent === said,
        `Saved ${SAMPLE}-atlas-layout.svg.`,
      );
    },
  );

  pageTest(
    'Atlas mode: Cancel returns to a usable page; bad options get a readable error',
    {
      timeout: BIG_TEST_TIMEOUT_MS,
    },
    async ({ page }) => {
      await openAtlas(page);
      const before = await page.evaluate(() => ({
        atlases: window.__straightest.atlases,
        cancels: window.__straightest.cancels,
      }));
      // Cancel as the request leaves: the worker is stopped mid-atlas whatever its speed.
      await page.selectOption('#atlas-resolution', '2048');
      await page.waitForFunction(() => window.__straightest.progress.busy, null, { timeout: WAIT_TIMEOUT_MS });
      await page.evaluate(() => document.getElementById('cancel-button').click());
      await page.waitForFunction(
        (n) => window.__straightest.cancels > n && document.body.dataset.state === 'ready',
        before.cancels,
        { timeout: BIG_WAIT_TIMEOUT_MS },
      );
      const note = await text(page, 'atlas-message');
      const cancelledOrDone =
        /cancelled/i.test(note) || (await page.evaluate(() => window.__straightest.atlases)) > before.atlases;
      assert(cancelledOrDone, `after Cancel the panel says '${note}'`);
      // Still usable: the atlas is made again in the restarted worker.
      await page.click('#atlas-button');
      await page.waitForFunction(
        (n) => window.__straightest.atlases > n && !window.__straightest.progress.busy,
        before.atlases,
        { timeout: BIG_WAIT_TIMEOUT_MS },
      );
      assert.equal(await page.evaluate(() => window.__straightest.atlas.width), 2048);

      await page.fill('#atlas-max-stretch', '0.5');
      await page.dispatchEvent('#atlas-max-stretch', 'change');
      await page.waitForFunction(() => window.__straightest.atlasError, null, { timeout: WAIT_TIMEOUT_MS });
      assert.match(await text(page, 'atlas-message'), /Max stretch must be above 1/);
      assert.equal(await page.getAttribute('#atlas-max-stretch', 'aria-invalid'), 'true');
      await page.fill('#atlas-max-stretch', '1.05');
      await page.fill('#atlas-min-hull-fill', '1.5');
      await page.click('#atlas-button');
      assert.match(await text(page, 'atlas-message'), /Min hull fill must be from 0 to 1/);
      assert.equal(await page.getAttribute('#atlas-min-hull-fill', 'aria-invalid'), 'true');
      await page.fill('#atlas-min-hull-fill', '0.75');
      await page.fill('#atlas-padding', '2.5');
      await page.click('#atlas-button');
      assert.match(await text(page, 'atlas-message'), /Padding must be a whole number/);
    },
  );

  for (const size of SIZES) {
    pageTest(
      `Atlas mode at ${size.width}×${size.height}: every stat lies inside its panel and the window`,
      {
        timeout: BIG_TEST_TIMEOUT_MS,
      },
      async ({ page }) => {
        await page.setViewportSize(size);
        await openAtlas(page);
        await page.waitForTimeout(100); // a resize observer's redraw
        assert.deepEqual(await misplacedBoxes(page, STATS), [], `at ${size.width}×${size.height}`);
        // Each value can be scrolled into the window and is then wholly in it.
        for (const id of await page.$$eval('#atlas-stats dd', (dds) => dds.map((dd) => dd.id))) {
          await page.locator(`#${id}`).scrollIntoViewIfNeeded();
          const box = await page.locator(`#${id}`).boundingBox();
          assert(
            box && box.y >= 0 && box.y + box.height <= size.height && box.x >= 0 && box.x + box.width <= size.width,
            `#${id} at ${JSON.stringify(box)}`,
          );
        }
        const layout = await page.locator('#atlas-canvas').boundingBox();
        assert(
          layout.width > 150 && layout.x >= 0 && layout.x + layout.width <= size.width + 0.5,
          `the layout canvas at ${JSON.stringify(layout)}`,
        );
        if (size.width < 720) {
          const small = await page.$$eval(
            '#atlas-panel button, #atlas-panel select, #atlas-panel input:not([type="checkbox"])',
            (elements) => elements.filter((e) => e.getBoundingClientRect().height < 31.5).map((e) => e.id),
          );
          assert.deepEqual(small, [], 'touch targets under 32 px in the Atlas panel');
        }
        if (process.env.ATLAS_SCREENSHOTS) {
          const dir = process.env.ATLAS_SCREENSHOTS;
          await mkdir(dir, { recursive: true });
          await page.evaluate(() => window.scrollTo(0, 0));
          await page.screenshot({ path: `${dir}/atlas-${size.width}x${size.height}.png` });
          await page.selectOption('#atlas-display', 'checker');
          await page.waitForTimeout(300);
          await page.screenshot({ path: `${dir}/atlas-checker-${size.width}x${size.height}.png` });
        }
      },
    );
  }
});
