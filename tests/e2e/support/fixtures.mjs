// The shared fixtures of the browser tests, on node:test: one static server and one headless
// Chromium for the whole run (useBrowser), and pageTest — a test that opens the page in a fresh
// browser context, waits until it is ready, runs its body and then checks that no console error,
// page error or failed request happened. Also the waits every test uses (settled, expectReady) and
// the `N passed, M failed` line that scripts/test.sh reads.
//
// Timeouts: E2E_TIME_SCALE (default 1) multiplies every one of them, for a machine under load.

import assert from 'node:assert/strict';
import http from 'node:http';
import { after, before, test } from 'node:test';
import { chromium } from 'playwright-core';
import { startServer } from '../../../scripts/serve.mjs';
import { CHROMIUM_PATH } from '../../package/chromium.mjs';

const CHROMIUM_ARGS = [
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
];
const TIME_SCALE = Number(process.env.E2E_TIME_SCALE) > 0 ? Number(process.env.E2E_TIME_SCALE) : 1;
export const WAIT_TIMEOUT_MS = 8_000 * TIME_SCALE; // any single wait in a page
export const BIG_WAIT_TIMEOUT_MS = 30_000 * TIME_SCALE; // waits for the work on the 200k-vertex mesh
export const TEST_TIMEOUT_MS = 20_000 * TIME_SCALE;
export const BIG_TEST_TIMEOUT_MS = 45_000 * TIME_SCALE; // tests on the 200k-vertex mesh
const RUN_TIMEOUT_MS = 600_000 * TIME_SCALE; // a guard against a hang, not a speed target: the whole run (~50 tests) takes ~5–6 min on 2 cores
const VIEWPORT = { width: 1000, height: 700 };

// The run: the server and the browser every test shares, and the tally of the tests' results.
const run = { server: null, browser: null, port: 0, baseUrl: '', passed: 0, failed: 0 };
const filter = process.env.TEST_FILTER ?? ''; // runs only the tests whose name has it

function withTimeout(promise, ms, what) {
  let timer;
  const timeout = new Promise((_, reject) => {
    timer = setTimeout(() => reject(new Error(`${what} timed out after ${ms} ms`)), ms);
  });
  return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

function printTally() {
  console.log(`${run.passed} passed, ${run.failed} failed`);
}

async function shutDown() {
  await withTimeout(run.browser?.close() ?? Promise.resolve(), 3000, 'browser close').catch(() => {});
  run.browser = null;
  if (run.server) {
    run.server.closeAllConnections();
    await new Promise((resolve) => run.server.close(resolve));
    run.server = null;
  }
}

/**
 * Starts the server and the browser before the first test and stops them after the last, then
 * prints the tally; onExit() runs last (e.g. removing temporary files). A run that exceeds
 * RUN_TIMEOUT_MS counts one more failure and exits.
 */
export function useBrowser({ onExit = () => {} } = {}) {
  const watchdog = setTimeout(async () => {
    console.log(`not ok - whole run: exceeded ${RUN_TIMEOUT_MS} ms`);
    run.failed += 1;
    printTally();
    run.server?.closeAllConnections();
    onExit();
    await withTimeout(run.browser?.close() ?? Promise.resolve(), 3000, 'browser close').catch(() => {});
    process.exit(1);
  }, RUN_TIMEOUT_MS);
  watchdog.unref();

  before(async () => {
    try {
      run.server = await startServer({ port: 0 });
      run.port = run.server.address().port;
      run.baseUrl = `http://127.0.0.1:${run.port}`;
      run.browser = await chromium.launch({
        executablePath: CHROMIUM_PATH,
        headless: true,
        args: CHROMIUM_ARGS,
        timeout: 20_000,
      });
    } catch (err) {
      run.failed += 1;
      console.log(`not ok - setup: ${String(err.message).split('\n')[0]}`);
      throw err;
    }
  });

  after(async () => {
    await shutDown();
    clearTimeout(watchdog);
    onExit();
    printTally();
  });
}

/** A test counted in the tally; fn({ port, baseUrl }) fails it by throwing or taking longer than timeout. */
export function counted(name, { timeout = TEST_TIMEOUT_MS } = {}, fn) {
  const skip = !name.includes(filter) && 'TEST_FILTER';
  // node:test's own timeout is only a backstop: the tally needs the race below to settle.
  test(name, { skip, timeout: timeout + 5_000 }, async () => {
    if (!run.browser) throw new Error('the browser did not start');
    try {
      await withTimeout(fn({ port: run.port, baseUrl: run.baseUrl }), timeout, 'test');
      run.passed += 1;
    } catch (err) {
      run.failed += 1;
      throw err;
    }
  });
}

/**
 * Opens the page (with `query`, e.g. '?sample=cap', as a link would) in a fresh context and records
 * console errors and uncaught page errors. setup(context), if given, runs before the page loads (e.g.
 * to route requests).
 */
async function openPage(setup = null, query = '', open = true) {
  const context = await run.browser.newContext({ viewport: VIEWPORT });
  await setup?.(context);
  const page = await context.newPage();
  page.setDefaultTimeout(WAIT_TIMEOUT_MS);
  const problems = [];
  page.on('console', (msg) => {
    if (msg.type() === 'error') problems.push(`console error: ${msg.text()}`);
  });
  page.on('pageerror', (err) => problems.push(`page error: ${err.message}`));
  page.on('requestfailed', (req) => problems.push(`request failed: ${req.url()} (${req.failure()?.errorText})`));
  const url = `${run.baseUrl}/web/index.html${query}`;
  if (open) await page.goto(url);
  return { page, context, problems, url };
}

/**
 * A test of the page: opens it (setup(context) first, if given; at `query`, if given, so a test of a
 * link opens the link instead of the default page and then the link), waits until it is ready with
 * the `ready` predicate true (page JavaScript over window.__straightest), runs fn({ page, loaded, url })
 * — loaded: what settled() returned, url: the page's — and then expects no console error, page error
 * or failed request. With `open: false` the page is left blank (loaded null) for fn to open at `url`
 * itself, e.g. to watch it load.
 */
export function pageTest(
  name,
  { query = '', ready = 'true', setup = null, open = true, timeout = TEST_TIMEOUT_MS } = {},
  fn,
) {
  counted(name, { timeout }, async () => {
    const { page, context, problems, url } = await openPage(setup, query, open);
    try {
      const loaded = open ? await expectReady(page, ready) : null;
      await fn({ page, loaded, url });
      expectNoProblems(problems);
    } finally {
      await context.close();
    }
  });
}

/**
 * For a bench script (not a test): the static server and a Chromium launched as the tests launch it.
 * Resolves with { browser, pageUrl, close }; close() stops both.
 */
export async function startBenchBrowser() {
  const server = await startServer({ port: 0 });
  const browser = await chromium.launch({ executablePath: CHROMIUM_PATH, headless: true, args: CHROMIUM_ARGS });
  return {
    browser,
    pageUrl: `http://127.0.0.1:${server.address().port}/web/index.html`,
    async close() {
      await browser.close();
      server.closeAllConnections();
      server.close();
    },
  };
}

/** Waits (up to `timeout` ms) until the page is ready, no work is under way and `predicate` holds. */
export function whenIdle(page, predicate, timeout = 600_000) {
  return page.waitForFunction(
    `document.body.dataset.state === 'ready' && !window.__straightest.progress.busy && (${predicate})`,
    null,
    { timeout, polling: 100 },
  );
}

/** Waits until the page has finished loading something and returns its state and hooks. */
export async function settled(page, predicate = 'true') {
  try {
    await page.waitForFunction(`document.body.dataset.state !== 'loading' && window.__straightest && (${predicate})`);
  } catch (err) {
    const state = await page.evaluate(() => document.body.dataset.state).catch(() => 'unknown');
    const status = await page.textContent('#status', { timeout: 1000 }).catch(() => '');
    throw new Error(`page stayed in state '${state}' (status: ${status.trim()}): ${err.message.split('\n')[0]}`, {
      cause: err,
    });
  }
  return page.evaluate(() => ({
    state: document.body.dataset.state,
    lastInfo: window.__straightest.lastInfo,
    lastError: window.__straightest.lastError,
  }));
}

export async function expectReady(page, predicate) {
  const result = await settled(page, predicate);
  assert(
    result.state === 'ready',
    `page state is '${result.state}'${result.lastError ? `: ${result.lastError.message}` : ''}`,
  );
  return result;
}

function expectNoProblems(problems) {
  assert(problems.length === 0, problems.join('; '));
}

/** Raw GET on the test server without URL normalisation (so `..` reaches the server as sent). */
export function rawGet(port, path) {
  return new Promise((resolve, reject) => {
    const req = http.get({ host: '127.0.0.1', port, path, timeout: 5000 }, (res) => {
      res.resume();
      res.on('end', () => resolve({ status: res.statusCode, headers: res.headers }));
    });
    req.on('timeout', () => req.destroy(new Error(`GET ${path} timed out`)));
    req.on('error', reject);
  });
}

/** Reads a download's stream into a string. */
export async function streamText(stream, encoding = 'utf8') {
  const chunks = [];
  for await (const chunk of stream) chunks.push(chunk);
  return Buffer.concat(chunks).toString(encoding);
}
