// The consumer tests' browser: Debian's Chromium driven by playwright-core. openApp loads a page and
// waits for the result the app leaves on window.__result, with the page's errors and warnings.
const TIMEOUT = 90_000; // liveness only: a loaded 2-core machine is slow, never wrong

export async function launchChromium() {
  const { chromium } = await import('playwright-core');
  return chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
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
