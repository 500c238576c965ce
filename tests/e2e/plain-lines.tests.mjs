// Browser test of the plain path lines (issue 31): with thousands of boundary paths (the 200k-vertex
// grid's 1788, drawn as 1-pixel translucent lines), the lines colour the surface alike on both sides
// of the source — they once showed on one half only, a line written into the depth buffer hiding the
// later ones at the same pixel. Seen from the top with no texture, the mean blueness (blue − red) of
// the view left and right of the source must agree. Imported by browser.test.mjs, which owns the
// browser (useBrowser).

import assert from 'node:assert/strict';
import { describe } from 'node:test';
import { BIG_TEST_TIMEOUT_MS, BIG_WAIT_TIMEOUT_MS, expectReady, pageTest } from './support/fixtures.mjs';
import { decodePng } from './support/images.mjs';
import { BIG_GRID_N, bigGridFile } from './support/meshes.mjs';

/** Mean (blue − red) / 255 over a box given as fractions of the image's width and height. */
function blueness({ width, height, channels, data }, [x0, x1], [y0, y1]) {
  let total = 0;
  let count = 0;
  for (let y = Math.floor(y0 * height); y < y1 * height; y++) {
    for (let x = Math.floor(x0 * width); x < x1 * width; x++) {
      const p = channels * (y * width + x);
      total += (data[p + 2] - data[p]) / 255;
      count += 1;
    }
  }
  return total / count;
}

describe('plain path lines', () => {
  pageTest(
    'thousands of plain path lines colour the surface on both sides of the source alike',
    { ready: 'window.__straightest.param && !window.__straightest.progress.busy', timeout: BIG_TEST_TIMEOUT_MS },
    async ({ page }) => {
      await page.setInputFiles('#file-input', bigGridFile());
      await page.waitForFunction(
        (count) => window.__straightest.paths?.count === count && !window.__straightest.progress.busy,
        4 * (BIG_GRID_N - 1),
        { timeout: BIG_WAIT_TIMEOUT_MS },
      );
      await expectReady(page, 'window.__straightest.param');
      const { paths } = await page.evaluate(() => window.__straightest);
      assert(paths.plain && paths.reached === paths.count, `paths: ${JSON.stringify(paths)}`);
      // The render count is read before the changes, so that a frame they cause cannot come before it.
      const renders = await page.evaluate(() => window.__straightest.renders);
      await page.selectOption('#texture-select', 'none');
      await page.click('#view-top-button', { force: true });
      await page.waitForFunction((n) => window.__straightest.renders > n, renders, { timeout: BIG_WAIT_TIMEOUT_MS });
      await page.waitForTimeout(500); // the frame reaches the screen
      const image = decodePng(await page.locator('#view-canvas').screenshot({ timeout: BIG_WAIT_TIMEOUT_MS }));
      // The source is the grid's centre, in the middle of the view; boxes above it, clear of the base
      // plane's disc, a tenth of the width to each side.
      const rows = [0.25, 0.42];
      const left = blueness(image, [0.34, 0.46], rows);
      const right = blueness(image, [0.54, 0.66], rows);
      assert(
        left > 0 && right > 0,
        `the lines do not tint the surface: blueness ${left.toFixed(3)} | ${right.toFixed(3)}`,
      );
      assert(
        Math.abs(left - right) < 0.25 * Math.max(left, right),
        `blueness left of the source ${left.toFixed(3)}, right ${right.toFixed(3)}`,
      );
    },
  );
});
