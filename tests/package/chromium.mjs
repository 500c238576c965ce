// The tests' browser: Debian's Chromium driven by playwright-core (CHROMIUM_PATH, which the browser
// tests of tests/e2e use too). openApp loads a page and waits for the result the app leaves on
// window.__result, with the page's errors and warnings.
import { existsSync } from 'node:fs';

const TIMEOUT = 90_000; // liveness only: a loaded 2-core machine is slow, never wrong

/**
 * The Chromium the tests drive: $CHROMIUM if set, else Debian's headless shell (chromium-headless-shell,
 * the old headless mode, which Playwright itself runs headless) where it is installed, else Debian's
 * Chromium. The shell runs the same Blink, V8 and SwiftShader without the browser's own windows: the
 * full browser starts a window with a WebUI renderer for its omnibox for every browser context,
 * which took about a third of the CPU of a page test.
 */
export const CHROMIUM_PATH =
  process.env.CHROMIUM ??
  ['/usr/bin/chromium-headless-shell', '/usr/bin/chromium'].find((path) => existsSync(path)) ??
  '/usr/bin/chromium';

export async function launchChromium() {
  const { chromium } = await import('playwright-core');
  return chromium.launch({
    executablePath: CHROMIUM_PATH,
    headless: true,
    args: ['--no-sandbox', '--disable-background-networking', '--disable-component-update', '--no-first-run'],
  });
}

/** Opens `url` in a new page: { result, errors, warnings } once window.__result is set. */
export async function openApp(browser, url) {
  const tab = await browser.newPage();
  const errors = [];
  const warnings = [];
  tab.on('pageerror', (e) => errors.push(String(e)));
  tab.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
    if (m.type() === 'warning') warnings.push(m.text());
  });
  try {
    await tab.goto(url);
    await tab
      .waitForFunction(() => globalThis.__result, null, { timeout: TIMEOUT })
      .catch((e) => {
        throw new Error(`${url}: no result (${e.message}); errors: ${errors.join('; ')}`);
      });
    return { result: await tab.evaluate(() => globalThis.__result), errors, warnings };
  } finally {
    await tab.close();
  }
}
