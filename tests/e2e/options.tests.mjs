// Browser tests of the parameterization following its options: changing Boundary, Weights or "Center at
// the path source" runs it again without the Parameterize button. Imported by browser.test.mjs, which
// owns the browser (useBrowser).

import assert from 'node:assert/strict';
import { describe } from 'node:test';
import { pageTest } from './support/fixtures.mjs';

const hooks = (page) => page.evaluate(() => window.__straightest);

/** Waits until the parameterization on display has `field` === `value`; returns the hooks then. */
async function shownWith(page, field, value) {
  await page.waitForFunction(([f, v]) => window.__straightest.param?.[f] === v, [field, value]);
  return hooks(page);
}

describe('parameterization options', () => {
  pageTest(
    'changing Boundary, Weights or the centre re-runs the parameterization without the button',
    {
      ready: 'window.__straightest.param && !window.__straightest.progress.busy',
    },
    async ({ page }) => {
      const first = await hooks(page);
      assert(first.param.boundary === 'measured', `the page opened with the ${first.param.boundary} boundary`);

      await page.selectOption('#boundary-select', 'circle');
      let now = await shownWith(page, 'boundary', 'circle');
      assert(now.parameterizations > first.parameterizations, 'no new parameterization was shown');
      assert(
        (await page.textContent('#param-method')).includes('circle boundary'),
        'the method line does not say circle',
      );

      // Several quick changes: what ends up on display is what the menus say, and stays so.
      await page.selectOption('#boundary-select', 'square');
      await page.selectOption('#weights-select', 'uniform');
      await page.selectOption('#boundary-select', 'measured');
      await page.waitForFunction(() => {
        const { param, progress } = window.__straightest;
        return param?.boundary === 'measured' && param.weights === 'uniform' && !progress.busy;
      });
      await page.waitForTimeout(600); // longer than the re-run delay: no older run shows up after it
      now = await hooks(page);
      assert(
        now.param.boundary === 'measured' && now.param.weights === 'uniform',
        `shown ${now.param.boundary}/${now.param.weights}, the menus say measured/uniform`,
      );

      // The centre toggle runs it again too (centred at the path source: here still the default one).
      const before = now.parameterizations;
      const l2Before = now.param.l2;
      await page.check('#param-source-toggle');
      await page.waitForFunction((n) => window.__straightest.parameterizations > n, before);
      now = await hooks(page);
      assert(
        now.param.boundary === 'measured' && now.param.weights === 'uniform',
        `after the toggle: ${JSON.stringify(now.param)}`,
      );
      assert(Number.isFinite(now.param.l2) && Number.isFinite(l2Before), 'no stretch shown');
    },
  );
});
