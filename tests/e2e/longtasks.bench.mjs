// The page's main thread on a big mesh (issue 31, item 3): loads an n × n height field OBJ (default
// 1000: 1M vertices) through the file input, traces its boundary paths, parameterizes it (the button:
// large meshes are not parameterized unasked) and prints every long task (> 50 ms, the browser's own
// `longtask` entries) of each phase: count, longest, total and the five longest. A bench, not a test:
// it prints numbers and never fails on them (headless Chromium renders in software here, so frame
// times are no guide to a real GPU's).
//
//   node tests/e2e/longtasks.bench.mjs [n=1000]

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { startBenchBrowser, whenIdle } from './support/fixtures.mjs';
import { heightFieldObj } from './support/meshes.mjs';

const n = Number(process.argv[2] ?? 1000);
const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'straightest-longtasks-'));
const file = path.join(dir, `heightfield-${n}.obj`);
fs.writeFileSync(file, heightFieldObj(n));

const { browser, pageUrl, close } = await startBenchBrowser();
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  // Every long task from the first script on, with its start (ms since navigation) and duration.
  await page.addInitScript(() => {
    window.__longTasks = [];
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries())
        window.__longTasks.push({ start: entry.startTime, duration: entry.duration });
    }).observe({ type: 'longtask', buffered: true });
  });
  await page.goto(pageUrl);
  const idle = (predicate) => whenIdle(page, predicate);
  // Until the page has drawn no frame and had no long task for `ms`: what a phase leaves behind (the
  // uploads, the first frames; the opening sample's textured frame, which compiles a shader and
  // uploads the checkerboard, can come after its parameterization is shown) is counted in that phase,
  // not the next. Gives up quietly after a while (a page that keeps drawing).
  const settle = (ms = 1500) =>
    page
      .waitForFunction(
        (quietMs) => {
          const now = performance.now();
          const renders = window.__straightest.renders;
          if (window.__settle?.renders !== renders) window.__settle = { renders, since: now };
          const last = window.__longTasks.at(-1);
          return now - Math.max(window.__settle.since, last ? last.start + last.duration : 0) > quietMs;
        },
        ms,
        { polling: 100, timeout: 30_000 },
      )
      .catch(() => {});
  await idle('window.__straightest.param');
  const phases = [];
  const phase = async (name, run) => {
    const from = await page.evaluate(() => performance.now());
    const started = Date.now();
    await run();
    await settle();
    const tasks = await page.evaluate((t) => window.__longTasks.filter((e) => e.start >= t), from);
    phases.push({ name, seconds: (Date.now() - started) / 1000, tasks });
  };
  await phase('open the page (mountain)', async () => {});
  phases[0].tasks = await page.evaluate(() => window.__longTasks.slice()); // since navigation
  await phase(`load ${n}×${n} OBJ + trace ${4 * (n - 1)} boundary paths`, async () => {
    await page.setInputFiles('#file-input', file);
    await idle(`window.__straightest.lastInfo?.vertices === ${n * n} && window.__straightest.paths`);
  });
  await phase('parameterize (measured)', async () => {
    const before = await page.evaluate(() => window.__straightest.parameterizations);
    await page.click('#param-button');
    // (and its layout drawn: a dense one is filled in slices after the parameterization is shown)
    await idle(`window.__straightest.parameterizations > ${before} && !window.__straightest.layoutFilling`);
  });
  for (const { name, seconds, tasks } of phases) {
    const durations = tasks.map((t) => t.duration).sort((a, b) => b - a);
    const total = durations.reduce((a, b) => a + b, 0);
    console.log(
      `${name}: ${seconds.toFixed(1)} s; ${durations.length} long tasks, longest ${(durations[0] ?? 0).toFixed(0)} ms, ` +
        `total ${total.toFixed(0)} ms; longest five: ${
          durations
            .slice(0, 5)
            .map((d) => d.toFixed(0))
            .join(', ') || '–'
        } ms`,
    );
  }
} finally {
  await close();
  fs.rmSync(dir, { recursive: true, force: true });
}
