// The page's first atlas (issue 29): opens the page, leaves it idle for IDLE_MS (the worker's warm-up runs
// then: web/requests.js), loads each mesh file through the file input and opens the Atlas tab, and prints
// the wall time until the atlas is shown and the page's own timings (charts / pack / measure / total ms).
// Each mesh in a fresh page, so each atlas is that page's first. A bench, not a test: it prints numbers
// and never fails on them.
//
//   node tests/e2e/first-atlas.bench.mjs MESH...      (IDLE_MS=5000)

import { existsSync } from 'node:fs';
import { startBenchBrowser, whenIdle } from './support/fixtures.mjs';

const files = process.argv.slice(2);
const missing = files.filter((file) => !existsSync(file));
if (files.length === 0 || missing.length > 0) {
  console.error('usage: node tests/e2e/first-atlas.bench.mjs MESH_FILE...');
  if (missing.length > 0) console.error(`no such file: ${missing.join(', ')}`);
  process.exit(2);
}
const idleMs = Number(process.env.IDLE_MS ?? 5000);
const { browser, pageUrl, close } = await startBenchBrowser();
try {
  for (const file of files) {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await page.goto(pageUrl);
    const idle = (predicate) => whenIdle(page, predicate, 300_000);
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
  await close();
}
