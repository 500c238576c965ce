// Browser tests of straightest ÷ exact over every boundary target (issue 17) and of the poor-result
// hint (issue 16). Imported by browser.test.mjs, which owns the browser (useBrowser).

import assert from 'node:assert/strict';
import { describe } from 'node:test';
import { expectReady, pageTest } from './support/fixtures.mjs';

const hooks = (page) => page.evaluate(() => window.__straightest);

/** OBJ text of a flat n × n grid over [-1, 1]² in the plane z = 0, split along alternating diagonals. */
function flatGridObj(n = 11) {
  const lines = ['# flat grid'];
  for (let j = 0; j < n; j += 1) {
    for (let i = 0; i < n; i += 1) lines.push(`v ${(2 * i) / (n - 1) - 1} ${(2 * j) / (n - 1) - 1} 0`);
  }
  for (let j = 0; j + 1 < n; j += 1) {
    for (let i = 0; i + 1 < n; i += 1) {
      const a = j * n + i + 1;
      if ((i + j) % 2) lines.push(`f ${a} ${a + 1} ${a + n + 1}`, `f ${a} ${a + n + 1} ${a + n}`);
      else lines.push(`f ${a} ${a + 1} ${a + n}`, `f ${a + 1} ${a + n + 1} ${a + n}`);
    }
  }
  return `${lines.join('\n')}\n`;
}

/** Clicks "Straightest ÷ exact" and returns hooks.exactRatio once the plot is on display. */
async function ratioPlot(page) {
  await page.click('#exact-ratio-button');
  await page.waitForFunction(() => window.__straightest.exactRatio !== null);
  return (await hooks(page)).exactRatio;
}

describe('straightest ÷ exact, and the poor-result hint', () => {
  // One page for both (every page load counts against the run's time): the mountain, a plane, holes.
  pageTest(
    'ratios ≥ 1 on the mountain, some above, exactly 1 on a plane; a hint only where traces fail',
    {
      ready: 'window.__straightest.param && !window.__straightest.progress.busy',
    },
    async ({ page }) => {
      const opened = await hooks(page);
      assert.equal(opened.pathsHint, null, `a hint on the default sample: ${opened.pathsHint}`);
      assert.equal(opened.paramHint, null, `a hint on the default sample: ${opened.paramHint}`);
      assert((await page.isHidden('#paths-hint')) && (await page.isHidden('#param-hint')));

      let plot = await ratioPlot(page);
      assert.equal(plot.count, opened.paths.count, 'one ratio per boundary vertex');
      assert.equal(plot.failed, 0, 'every trace on the mountain reaches the boundary');
      // Exact paths are the shortest: no straightest path is shorter.
      for (const r of plot.ratios) assert(r >= 1 - 1e-9, `a ratio of ${r} < 1: the exact distance is not the least`);
      assert(plot.max > 1 + 1e-4, `the mountain bends paths, yet the largest ratio is ${plot.max}`);
      assert(plot.min <= plot.median && plot.median <= plot.max);
      assert.equal(await page.locator('#exact-ratio-plot circle').count(), plot.count, 'one dot per ratio');
      assert.equal(await page.locator('#exact-ratio-table tbody tr').count(), plot.count, 'one row per target');
      assert.match(await page.textContent('#exact-ratio-summary'), /196 boundary targets .* 0 failed traces/);

      // Sorting by ratio, twice: descending, the largest first.
      await page.click('#exact-ratio-table th[data-key="ratio"]');
      await page.click('#exact-ratio-table th[data-key="ratio"]');
      const first = Number(await page.textContent('#exact-ratio-table tbody tr:first-child td:nth-child(5)'));
      assert(
        Math.abs(first - plot.max) < 1e-6 * plot.max,
        `the first row after sorting shows ${first}, the max is ${plot.max}`,
      );

      await page.setInputFiles('#file-input', {
        name: 'flat.obj',
        mimeType: 'text/plain',
        buffer: Buffer.from(flatGridObj()),
      });
      await expectReady(page, 'window.__straightest.lastInfo?.vertices === 121');
      assert.equal((await hooks(page)).exactRatio, null, 'the plot of the previous mesh is gone');
      assert(await page.isHidden('#exact-ratio'));
      plot = await ratioPlot(page);
      assert.equal(plot.count, 40, 'the grid has 40 boundary vertices');
      for (const r of plot.ratios) assert(Math.abs(r - 1) < 1e-9, `on a plane every ratio is 1, got ${r}`);

      // The holes sample: paths from the centre to the outer loop run into the inner loops.
      await page.selectOption('#sample-select', 'holes');
      await expectReady(
        page,
        'window.__straightest.lastInfo?.boundaryLoops?.length === 4 && window.__straightest.pathsHint !== null',
      );
      const now = await hooks(page);
      const failed = now.paths.count - now.paths.reached;
      assert(failed > 0, 'no trace failed on the holes sample');
      assert(now.pathsHint.startsWith(`${failed} of ${now.paths.count} `), now.pathsHint);
      assert(await page.isVisible('#paths-hint'));
      assert.match(await page.textContent('#paths-hint'), /Move the centre/);
    },
  );
});
