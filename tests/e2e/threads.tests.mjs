// Browser tests of the page's WebAssembly threads: npm start's server (scripts/serve.mjs) sends
// COOP/COEP, so the page and its worker are cross-origin isolated and the worker runs the threaded
// module on every core; the same page without those headers runs the single-threaded module. Imported
// by browser.test.mjs, which owns the browser (useBrowser).

import assert from 'node:assert/strict';
import { describe } from 'node:test';
import { pageTest } from './support/fixtures.mjs';

/** What the page says about its threads, and what the browser says it has. */
function threadFacts(page) {
  return page.evaluate(() => ({
    isolated: globalThis.crossOriginIsolated === true,
    cores: navigator.hardwareConcurrency,
    threads: window.__straightest.threads,
    shown: document.getElementById('info-threads').textContent,
    paths: window.__straightest.paths?.count ?? 0,
  }));
}

/** Serves the page's HTML without the isolation headers (everything else as the server sends it). */
function withoutIsolation(context) {
  return context.route(
    (url) => url.pathname === '/web/index.html',
    async (route) => {
      const response = await route.fetch();
      const headers = { ...response.headers() };
      delete headers['cross-origin-opener-policy'];
      delete headers['cross-origin-embedder-policy'];
      await route.fulfill({ response, headers });
    },
  );
}

describe('threads', () => {
  pageTest(
    'served with COOP/COEP, the page is cross-origin isolated and its worker runs on every core',
    {},
    async ({ page }) => {
      const facts = await threadFacts(page);
      assert(facts.isolated, 'the page is not cross-origin isolated');
      assert(facts.cores >= 2, `headless Chromium reports ${facts.cores} core(s): nothing to test threads with`);
      assert(facts.threads === Math.min(facts.cores, 64), `${facts.threads} threads for ${facts.cores} cores`);
      assert(facts.shown.startsWith(`${facts.threads} `), `info panel: '${facts.shown}'`);
      assert(facts.paths > 0, 'no paths drawn by the threaded module');
    },
  );

  pageTest(
    'without COOP/COEP the page runs the single-threaded module',
    { setup: withoutIsolation },
    async ({ page }) => {
      const facts = await threadFacts(page);
      assert(!facts.isolated, 'the page is cross-origin isolated without COOP/COEP');
      assert(facts.threads === 1, `${facts.threads} threads`);
      assert(facts.shown.startsWith('1 '), `info panel: '${facts.shown}'`);
      assert(facts.paths > 0, 'no paths drawn by the single-threaded module');
    },
  );
});
