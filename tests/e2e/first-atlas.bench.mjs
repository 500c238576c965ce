// The page's first atlas (issue 29): opens the page, leaves it idle for IDLE_MS (the worker's warm-up runs
// then: web/requests.js), loads each mesh file through the file input and opens the Atlas tab, and prints
// the wall time until the atlas is shown and the page's own timings (charts / pack / measure / total ms).
// Each mesh in a fresh page, so each atlas is that page's first. A bench, not a test: it prints numbers
// and never fails on them.
//
//   node tests/e2e/first-atlas.bench.mjs MESH...      (IDLE_MS=5000)

import { chromium } from 'playwright-core';
import { startServer } from '../../scripts/serve.mjs';

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: node tests/e2e/first-atlas.bench.mjs MESH...');
  process.exit(2);
}
const idleMs = Number(process.env.IDLE_MS ?? 5000);
const server = await startServer({ port: 0 });
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
try {
  for (const file of files) {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await page.goto(`http://127.0.0.1:${server.address().port}/web/index.html`);
    const idle = (predicate) =>
      page.waitForFunction(
        `document.body.dataset.state === 'ready' && !window.__straightest.progress.busy && (${predicate})`,
        null,
        { timeout: 300_000, polling: 100 },
      );
    await idle('window.__straightest.param');
    await page.waitForTimeout(idleMs);
    await page.setInputFiles('#file-input', file);
    await idle(`window.__straightest.lastInfo && document.body.dataset.mesh !== 'mountain'`);
    const started = Date.now();
    await page.click('#mode-tab-atlas');
    await idle('window.__straightest.atlas');
    const wall = Date.now() - started;
    const panel = (await page.textContent('#atlas-time')).trim();
    console.log(`${file.replace(/.*\//, '')}: first atlas shown after ${wall} ms; the page's timings ${panel}`);
    await page.close();
  }
} finally {
  await browser.close();
  server.close();
}
