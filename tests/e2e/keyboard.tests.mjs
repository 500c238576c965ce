// Browser tests of the page without a mouse (issue 16): the focused 3D view's keys, typing the source
// and destinations, the "Clicks add destinations" toggle for touch screens, and the comparison table
// from the keyboard. Imported by browser.test.mjs, which owns the browser (useBrowser).

import assert from 'node:assert/strict';
import { describe } from 'node:test';
import { pageTest } from './support/fixtures.mjs';

const hooks = (page) => page.evaluate(() => window.__straightest);
const sub = (a, b) => a.map((v, i) => v - b[i]);
const norm = (a) => Math.hypot(...a);

/** The camera after the next frame that differs from `before` (hooks.camera). */
async function cameraAfter(page, before) {
  const handle = await page.waitForFunction((old) => {
    const cam = window.__straightest.camera;
    return cam && JSON.stringify(cam.position) !== JSON.stringify(old.position) ? cam : null;
  }, before);
  return handle.jsonValue();
}

describe('keyboard and touch', () => {
  pageTest(
    'the focused view: arrows orbit, + and − zoom, 0 goes back; a typed source vertex moves the source',
    {},
    async ({ page }) => {
      await page.waitForFunction(() => window.__straightest.camera);
      const start = (await hooks(page)).camera;
      const distance = (cam) => norm(sub(cam.position, cam.target));
      await page.focus('#view-canvas');
      assert(await page.evaluate(() => document.activeElement?.id === 'view-canvas'), 'the canvas takes no focus');

      await page.keyboard.press('ArrowLeft');
      const turned = await cameraAfter(page, start);
      assert.deepEqual(turned.target, start.target, 'orbiting moved the centre');
      assert(Math.abs(distance(turned) - distance(start)) < 1e-9 * distance(start), 'orbiting changed the distance');
      await page.keyboard.press('ArrowUp');
      const raised = await cameraAfter(page, turned);
      assert(Math.abs(distance(raised) - distance(start)) < 1e-9 * distance(start));

      await page.keyboard.press('+');
      const closer = await cameraAfter(page, raised);
      assert(distance(closer) < distance(raised) * 0.95, '+ did not zoom in');
      await page.keyboard.press('-');
      await page.keyboard.press('-');
      const farther = await page.waitForFunction((d) => {
        const cam = window.__straightest.camera;
        return Math.hypot(...cam.position.map((v, i) => v - cam.target[i])) > d * 1.05 ? cam : null;
      }, distance(raised));
      assert(farther, '− did not zoom out');

      await page.keyboard.press('0');
      const home = await page.waitForFunction((old) => {
        const cam = window.__straightest.camera;
        return Math.hypot(...cam.position.map((v, i) => v - old.position[i])) < 1e-9 ? cam : null;
      }, start);
      assert(home, '0 did not bring back the opening view');

      // Typing instead of clicking.
      const before = await hooks(page);
      await page.fill('#source-entry', '1275');
      await page.click('#point-entry-button');
      await page.waitForFunction(() => window.__straightest.paths?.source?.vertex === 1275);
      await page.fill('#targets-entry', '3, face 100 0.2 0.3 0.5');
      await page.press('#targets-entry', 'Enter');
      await page.waitForFunction((n) => window.__straightest.paths?.count === n + 2, before.paths.count);
      const now = await hooks(page);
      assert.equal(now.paths.source.vertex, 1275, 'adding destinations moved the source');
      assert.equal(await page.inputValue('#targets-entry'), '', 'the added destinations stay in the field');

      await page.fill('#source-entry', '2500');
      await page.click('#point-entry-button');
      await page.waitForSelector('#point-entry-error:not([hidden])');
      assert.match(
        await page.textContent('#point-entry-error'),
        /vertex 2500 does not exist: the mesh has vertices 0 to 2499/,
      );
      assert.equal((await hooks(page)).traces, now.traces, 'a mistake traced anyway');
    },
  );

  pageTest(
    '"Clicks add destinations": a click adds one instead of moving the source; compare rows answer Enter',
    {
      ready: 'window.__straightest.param && !window.__straightest.progress.busy',
    },
    async ({ page }) => {
      const before = await hooks(page);
      await page.check('#pick-destination-toggle');
      await page.click('#view-canvas'); // the middle of the view: the mountain
      await page.waitForFunction((n) => window.__straightest.paths?.count === n + 1, before.paths.count);
      const now = await hooks(page);
      assert.deepEqual(now.paths.source, before.paths.source, 'the click moved the source');

      await page.click('#compare-button');
      await page.waitForFunction(() => window.__straightest.compare !== null);
      assert.equal((await hooks(page)).compareHint, null, "the mountain's measured map stretches less than the circle");
      assert(await page.isHidden('#compare-hint'));
      const row = page.locator('#compare-table tr[data-boundary="circle"][data-weights="uniform"]');
      assert.equal(await row.getAttribute('tabindex'), '0', 'the row is not focusable');
      await row.focus();
      await page.keyboard.press('Enter');
      await page.waitForFunction(() => {
        const { param } = window.__straightest;
        return param?.boundary === 'circle' && param.weights === 'uniform';
      });
    },
  );
});
