// Browser tests of the page's layout (issue 31): every number stays inside its panel and the window
// at a laptop's and a phone's size, whatever the boundary (the free one's refinement line used to
// push the values out of the sidebar); the results bar repeats them over the view; phones get touch
// targets of at least 32 px; the loading indicator covers the view from the first frame. Imported by
// browser.test.mjs, which owns the browser (useBrowser).

import assert from 'node:assert/strict';
import { describe } from 'node:test';
import { BIG_TEST_TIMEOUT_MS, pageTest } from './support/fixtures.mjs';

export const SIZES = [
  { width: 1280, height: 800 },
  { width: 1920, height: 1080 },
  { width: 390, height: 844 },
];

/**
 * The boxes of the elements matching `selector` that do not lie inside their container (the closest
 * `.panel`, or the results bar) and the window's width, or that overflow their own box — as text.
 */
export function misplacedBoxes(page, selector) {
  return page.evaluate((sel) => {
    const bad = [];
    for (const element of document.querySelectorAll(sel)) {
      const box = element.getBoundingClientRect();
      if (box.width === 0 && box.height === 0) continue; // not displayed
      const container = element.closest('.panel, #mode-bar');
      const outer = container.getBoundingClientRect();
      const name = `${element.id || element.tagName.toLowerCase()} '${element.textContent.trim().slice(0, 40)}'`;
      const eps = 0.5;
      if (
        box.left < outer.left - eps ||
        box.right > outer.right + eps ||
        box.top < outer.top - eps ||
        box.bottom > outer.bottom + eps
      ) {
        bad.push(
          `${name} [${box.left.toFixed(0)}, ${box.right.toFixed(0)}] outside ${container.id} [${outer.left.toFixed(0)}, ${outer.right.toFixed(0)}]`,
        );
      }
      if (box.left < -eps || box.right > window.innerWidth + eps) bad.push(`${name} beyond the window's width`);
      if (element.scrollWidth > element.clientWidth + 1 && getComputedStyle(element).textOverflow !== 'ellipsis') {
        bad.push(`${name} overflows its box (${element.scrollWidth} > ${element.clientWidth})`);
      }
    }
    return bad;
  }, selector);
}

// The values of the parameterization panel, the paths panel and the results bar.
const STATS =
  '#param-stats dt, #param-stats dd, #param-method, #stats-panel dl dd, #stats-panel dl dt, ' +
  '#results-summary .summary-item, #results-summary dd';

describe('layout', () => {
  for (const size of SIZES) {
    pageTest(
      `at ${size.width}×${size.height} every stat lies inside its panel and the window, for every boundary and in Compare`,
      {
        ready: 'window.__straightest.param && !window.__straightest.progress.busy',
        timeout: BIG_TEST_TIMEOUT_MS,
      },
      async ({ page }) => {
        await page.setViewportSize(size);
        const kinds = await page.$$eval('#boundary-select option', (options) => options.map((o) => o.value));
        assert(kinds.includes('free') && kinds.includes('auto'), `boundary menu: ${kinds}`);
        for (const kind of kinds) {
          const shown = await page.evaluate(() => window.__straightest.parameterizations);
          await page.selectOption('#boundary-select', kind);
          await page.waitForFunction(
            (n) => window.__straightest.parameterizations > n && !window.__straightest.progress.busy,
            shown,
            { timeout: 20_000 },
          );
          const bad = await misplacedBoxes(page, STATS);
          assert.deepEqual(bad, [], `${kind} boundary at ${size.width}×${size.height}`);
          const summary = await page.textContent('#summary-l2');
          const l2 = await page.textContent('#param-l2');
          assert(summary.trim() === l2.trim() && /^\d/.test(l2.trim()), `results bar L2 '${summary}', panel '${l2}'`);
        }
        // The results bar is in the window (at its top), whatever the sidebar shows.
        const bar = await page.locator('#results-summary').boundingBox();
        assert(
          bar.y >= 0 && bar.y + bar.height <= size.height && bar.x >= 0 && bar.x + bar.width <= size.width,
          `results bar at ${JSON.stringify(bar)}`,
        );

        await page.click('#compare-button');
        await page.waitForFunction(() => window.__straightest.compare, null, { timeout: 30_000 });
        const table = await page.$eval('#compare-table', (t) => ({ scroll: t.scrollWidth, client: t.clientWidth }));
        assert(table.scroll <= table.client + 1, `the Compare table is cut: ${table.scroll} px in ${table.client}`);
        const cells = await misplacedBoxes(page, '#compare-table th, #compare-table td');
        assert.deepEqual(cells, [], `Compare at ${size.width}×${size.height}`);
      },
    );
  }

  pageTest('on a phone every control is a touch target of at least 32 px', {}, async ({ page }) => {
    await page.setViewportSize({ width: 390, height: 844 });
    const small = await page.evaluate(() => {
      const bad = [];
      for (const element of document.querySelectorAll(
        '#side-panel button, #side-panel select, #side-panel input, #mode-bar button',
      )) {
        const target = element.type === 'checkbox' ? element.closest('label') : element;
        const box = target.getBoundingClientRect();
        if (box.width === 0) continue; // hidden
        if (box.height < 32 - 0.5) bad.push(`${element.id || element.type} ${box.height.toFixed(0)} px high`);
      }
      return bad;
    });
    assert.deepEqual(small, [], 'touch targets under 32 px');
    // The view comes first, with the results bar over it.
    const view = await page.locator('#view-canvas').boundingBox();
    assert(view.y < 200 && view.height > 250, `the view at ${JSON.stringify(view)}`);
  });

  pageTest(
    'a loading indicator covers the view until the mesh is drawn; panels collapse',
    {
      setup: (context) =>
        context.route('**/wasm/worker-entry.js', async (route) => {
          await new Promise((resolve) => {
            setTimeout(resolve, 1500);
          }); // a slow network: the module comes late
          await route.continue();
        }),
      open: false, // opened below, to look for the indicator from the start
    },
    async ({ page, url }) => {
      await page.goto(url, { waitUntil: 'commit' });
      await page.waitForSelector('#view-loading', { state: 'visible', timeout: 2000 });
      const box = await page.locator('#view-loading').boundingBox();
      const view = await page.locator('#viewport').boundingBox();
      assert(
        Math.abs(box.width - view.width) < 2 && Math.abs(box.height - view.height) < 2,
        'the indicator does not cover the view',
      );
      await page.waitForFunction(() => document.body.dataset.state === 'ready', null, { timeout: 30_000 });
      assert(await page.isHidden('#view-loading'), 'the indicator stays once the mesh is drawn');

      await page.click('#info-panel .panel-toggle');
      assert(await page.isHidden('#info-vertices'), 'the info panel did not collapse');
      assert((await page.getAttribute('#info-panel .panel-toggle', 'aria-expanded')) === 'false', 'aria-expanded');
      await page.click('#info-panel .panel-toggle');
      assert(await page.isVisible('#info-vertices'), 'the info panel did not open again');
    },
  );
});
