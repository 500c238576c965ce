// End-to-end tests of the web page in headless Debian Chromium (playwright-core, no bundled browser),
// on node:test with shared fixtures (support/fixtures.mjs): one server and one browser for the run,
// and a fresh browser context per test that opens /web/index.html and waits until it is ready.
//
//   node tests/e2e/browser.test.mjs       (TEST_FILTER=text runs only the tests whose name has it;
//                                          E2E_TIME_SCALE=k multiplies every timeout)
//
// Prints node:test's report and finally `N passed, M failed` (exit 1 on failure). Needs the WASM
// build (wasm/dist/) and `npm install` (three, playwright-core).

import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { describe } from 'node:test';
import {
  BIG_TEST_TIMEOUT_MS,
  BIG_WAIT_TIMEOUT_MS,
  counted,
  expectReady,
  pageTest,
  rawGet,
  settled,
  streamText,
  useBrowser,
} from './support/fixtures.mjs';
import { decodePng, fractionDiffering } from './support/images.mjs';
import {
  BIG_GRID_N,
  BIG_GRID_VERTICES,
  QUAD_GRID_OBJ,
  TETRAHEDRON_OFF,
  bigGridFile,
  removeBigGrid,
} from './support/meshes.mjs';

useBrowser({ onExit: removeBigGrid });
// After useBrowser: their tests use the shared browser.
await import('./camera.tests.mjs');
await import('./options.tests.mjs');
await import('./geoplot.tests.mjs');
await import('./keyboard.tests.mjs');
await import('./figure.tests.mjs');
await import('./formats.tests.mjs');
await import('./threads.tests.mjs');
await import('./layout.tests.mjs');
await import('./state.tests.mjs');
await import('./data.tests.mjs');
await import('./atlas.tests.mjs'); // after layout.tests.mjs, whose helpers it uses
await import('./plain-lines.tests.mjs');

/**
 * Starts a 50 ms setInterval on the page's main thread that records the longest gap between its
 * ticks (window.__ticker: { ticks, maxGap }); a main thread busy with long work would stretch it.
 */
async function startTicker(page) {
  await page.evaluate(() => {
    const ticker = { ticks: 0, maxGap: 0, last: performance.now() };
    ticker.timer = setInterval(() => {
      const now = performance.now();
      ticker.maxGap = Math.max(ticker.maxGap, now - ticker.last);
      ticker.last = now;
      ticker.ticks += 1;
    }, 50);
    window.__ticker = ticker;
  });
}

async function readTicker(page) {
  return page.evaluate(() => ({ ticks: window.__ticker.ticks, maxGap: window.__ticker.maxGap }));
}

/** The uv layout canvas's size and the share of its pixels that differ from its background colour. */
function uvLayoutCoverage(page) {
  return page.evaluate(() => {
    const canvas = document.getElementById('uv-canvas');
    const { data } = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
    const background = [
      data[4 * (canvas.width + 1)],
      data[4 * (canvas.width + 1) + 1],
      data[4 * (canvas.width + 1) + 2],
    ];
    let differing = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (background.some((c, k) => Math.abs(data[i + k] - c) > 12)) differing++;
    }
    return { width: canvas.width, height: canvas.height, fraction: differing / (data.length / 4) };
  });
}

describe('the static server', () => {
  counted('server redirects / to the page, serves WASM MIME types and refuses path traversal', {}, async ({ port }) => {
    const root = await rawGet(port, '/');
    assert(
      root.status === 302 && root.headers.location === '/web/index.html',
      `GET / gave ${root.status} -> ${root.headers.location}`,
    );
    const page = await rawGet(port, '/web/index.html');
    assert(
      page.status === 200 && page.headers['content-type'].startsWith('text/html'),
      `index.html: ${page.status} ${page.headers['content-type']}`,
    );
    const wasm = await rawGet(port, '/wasm/dist/straightest-core.wasm');
    assert(
      wasm.status === 200 && wasm.headers['content-type'] === 'application/wasm',
      `straightest-core.wasm: ${wasm.status} ${wasm.headers['content-type']}`,
    );
    const js = await rawGet(port, '/wasm/index.js');
    assert(
      js.status === 200 && js.headers['content-type'].startsWith('text/javascript'),
      `wasm/index.js: ${js.status} ${js.headers['content-type']}`,
    );
    for (const path of [
      '/../etc/passwd',
      '/web/../../etc/passwd',
      '/%2e%2e/etc/passwd',
      '/web/%2E%2E%2F..%2Fetc/passwd',
    ]) {
      const res = await rawGet(port, path);
      assert(res.status === 403 || res.status === 404, `${path} gave ${res.status}`);
    }
    const missing = await rawGet(port, '/web/no-such-file.js');
    assert(missing.status === 404, `missing file gave ${missing.status}`);
  });
});

describe('loading meshes', () => {
  pageTest('page loads the mountain sample without console errors', {}, async ({ page, loaded: { lastInfo } }) => {
    assert(lastInfo.vertices === 2500, `lastInfo.vertices is ${lastInfo.vertices}, expected 2500`);
    const vertices = await page.textContent('#info-vertices');
    assert(vertices.trim() === '2500', `info panel shows '${vertices}' vertices, expected 2500`);
    const selected = await page.inputValue('#sample-select');
    assert(selected === 'mountain', `sample select shows '${selected}'`);
    const options = await page.$$eval('#sample-select option', (els) => els.map((e) => e.value));
    for (const name of ['mountain', 'cap', 'saddle', 'face']) {
      assert(options.includes(name), `sample select lacks '${name}' (has ${options.join(', ')})`);
    }
    assert(await page.isHidden('#error-panel'), 'error panel is visible');
  });

  pageTest('mountain sample renders visible geometry on the canvas', {}, async ({ page }) => {
    await page.waitForFunction(() => window.__straightest.renders > 0);
    const background = await page.evaluate(() => window.__straightest.background);
    const image = decodePng(await page.locator('#view-canvas').screenshot());
    assert(image.width > 100 && image.height > 100, `canvas is only ${image.width}×${image.height}`);
    const fraction = fractionDiffering(image, background);
    assert(fraction > 0.05, `only ${(fraction * 100).toFixed(1)}% of pixels differ from the background (need > 5%)`);
  });

  pageTest('a malformed OBJ shows its error message in the error panel', {}, async ({ page }) => {
    await page.setInputFiles('#file-input', {
      name: 'bad.obj',
      mimeType: 'text/plain',
      buffer: Buffer.from('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n'),
    });
    const { state, lastError } = await settled(page, `document.body.dataset.state === 'error'`);
    assert(state === 'error', `page state is '${state}'`);
    assert(await page.isVisible('#error-panel'), 'error panel is not visible');
    const text = await page.textContent('#error-panel');
    assert(/out of range|\b9\b/.test(text), `error panel text does not mention vertex 9: '${text.trim()}'`);
    assert(lastError && lastError.message.length > 0, 'window.__straightest.lastError is empty');
  });

  pageTest('a valid quad-grid OBJ updates the info panel (9 vertices, 8 faces)', {}, async ({ page }) => {
    await page.setInputFiles('#file-input', {
      name: 'grid.obj',
      mimeType: 'text/plain',
      buffer: Buffer.from(QUAD_GRID_OBJ),
    });
    await expectReady(page, 'window.__straightest.lastInfo && window.__straightest.lastInfo.vertices !== 2500');
    const vertices = (await page.textContent('#info-vertices')).trim();
    const faces = (await page.textContent('#info-faces')).trim();
    assert(vertices === '9' && faces === '8', `info panel shows ${vertices} vertices, ${faces} faces`);
    const boundary = (await page.textContent('#info-boundary')).trim();
    assert(boundary.startsWith('1'), `a grid (disk) has one boundary loop, panel shows '${boundary}'`);
    const euler = (await page.textContent('#info-euler')).trim();
    assert(euler === '1', `a disk has Euler characteristic 1, panel shows '${euler}'`);
    assert(await page.isHidden('#error-panel'), 'error panel is visible');
  });

  pageTest(
    'dropping an OFF file onto the view loads it (closed tetrahedron: χ = 2, no boundary)',
    {},
    async ({ page }) => {
      const dataTransfer = await page.evaluateHandle((text) => {
        const transfer = new DataTransfer();
        transfer.items.add(new File([text], 'tetrahedron.off', { type: 'text/plain' }));
        return transfer;
      }, TETRAHEDRON_OFF);
      await page.dispatchEvent('#viewport', 'dragover', { dataTransfer });
      await page.dispatchEvent('#viewport', 'drop', { dataTransfer });
      const { lastInfo } = await expectReady(page, 'window.__straightest.lastInfo.vertices === 4');
      assert(lastInfo.faces === 4, `lastInfo.faces is ${lastInfo.faces}, expected 4`);
      const euler = (await page.textContent('#info-euler')).trim();
      const boundary = (await page.textContent('#info-boundary')).trim();
      assert(euler === '2', `a closed sphere-like mesh has χ = 2, panel shows '${euler}'`);
      assert(boundary.startsWith('0'), `a closed mesh has no boundary loop, panel shows '${boundary}'`);
      assert(await page.isHidden('#drop-overlay'), 'drop overlay still visible after the drop');
    },
  );
});

describe('straightest paths', () => {
  pageTest(
    'mountain shows straightest paths from the default source to its 196 boundary vertices',
    {
      ready: 'window.__straightest.paths',
    },
    async ({ page }) => {
      const paths = await page.evaluate(() => window.__straightest.paths);
      assert(paths.count === 196, `window.__straightest.paths.count is ${paths.count}, expected 196`);
      assert(
        typeof paths.source?.vertex === 'number',
        `default source is ${JSON.stringify(paths.source)}, expected a vertex`,
      );
      assert(paths.traceMs >= 0, `traceMs is ${paths.traceMs}`);
      const shown = (await page.textContent('#stats-paths')).trim();
      assert(shown === '196', `stats panel shows '${shown}' paths, expected 196`);
      const reachedText = (await page.textContent('#stats-reached')).trim();
      const reached = Number(/^\d+/.exec(reachedText)?.[0]);
      assert(
        reached === paths.reached && reached > 0 && reached <= 196,
        `stats panel shows '${reachedText}' reached (hook says ${paths.reached})`,
      );
      assert(
        (await page.textContent('#stats-source')).includes(`vertex ${paths.source.vertex}`),
        'stats panel does not name the default source',
      );
      // The paths are drawn: some pixels have the (blue) path colour, which the mesh never has.
      await page.waitForFunction(() => window.__straightest.renders > 0);
      const image = decodePng(await page.locator('#view-canvas').screenshot());
      let blue = 0;
      for (let i = 0; i < image.width * image.height; i++) {
        const [r, g, b] = image.data.subarray(i * image.channels, i * image.channels + 3);
        if (b > r + 60 && b > g + 20) blue++;
      }
      const fraction = blue / (image.width * image.height);
      assert(fraction > 0.005, `only ${(fraction * 100).toFixed(2)}% of the pixels show the path colour`);
    },
  );

  // The worker is idle before the click: the progress panel over the view would take a click made
  // while the automatic parameterization still runs.
  pageTest(
    'clicking the mesh moves the source to a face point and retraces; Reset goes back',
    {
      ready: 'window.__straightest.param && !window.__straightest.progress.busy',
    },
    async ({ page }) => {
      const before = await page.evaluate(() => ({ ...window.__straightest }));
      const statsBefore = await page.textContent('#stats-panel');
      const box = await page.locator('#view-canvas').boundingBox();
      await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
      await expectReady(page, `window.__straightest.traces > ${before.traces}`);
      const after = await page.evaluate(() => ({ ...window.__straightest }));
      const { source } = after.paths;
      assert(
        typeof source?.face === 'number' && source.bary?.length === 3,
        `source after the click is ${JSON.stringify(source)}, expected {face, bary}`,
      );
      const sum = source.bary.reduce((a, b) => a + b, 0);
      assert(
        Math.abs(sum - 1) < 1e-6 && source.bary.every((b) => b >= 0),
        `bad barycentric coordinates ${source.bary}`,
      );
      assert(JSON.stringify(source) !== JSON.stringify(before.paths.source), 'the source did not move');
      assert(after.paths.count === 196, `${after.paths.count} paths after the click, expected 196`);
      const statsAfter = await page.textContent('#stats-panel');
      assert(statsAfter !== statsBefore, 'the stats panel did not change');
      assert(
        (await page.textContent('#stats-source')).includes(`face ${source.face}`),
        'stats panel does not show the new source',
      );
      assert((await page.textContent('#stats-traces')).trim() === String(after.traces), 'trace count not updated');

      await page.click('#reset-button');
      await expectReady(page, `window.__straightest.traces > ${after.traces}`);
      const reset = await page.evaluate(() => window.__straightest.paths.source);
      assert(
        JSON.stringify(reset) === JSON.stringify(before.paths.source),
        `Reset gave source ${JSON.stringify(reset)}, expected ${JSON.stringify(before.paths.source)}`,
      );
    },
  );

  // The worker is idle before the click: the progress panel over the view would take a click made
  // while the automatic parameterization still runs.
  pageTest(
    'shift+click adds a destination; hovering a path shows its length, status and faces crossed',
    {
      ready: 'window.__straightest.param && !window.__straightest.progress.busy',
    },
    async ({ page }) => {
      const traces = await page.evaluate(() => window.__straightest.traces);
      const box = await page.locator('#view-canvas').boundingBox();
      await page.keyboard.down('Shift');
      await page.mouse.click(box.x + box.width * 0.55, box.y + box.height * 0.6);
      await page.keyboard.up('Shift');
      await expectReady(page, `window.__straightest.traces > ${traces}`);
      const paths = await page.evaluate(() => window.__straightest.paths);
      assert(paths.count === 197, `${paths.count} paths after shift+click, expected 196 + 1`);
      assert(typeof paths.source?.vertex === 'number', 'shift+click moved the source');
      const targets = (await page.textContent('#stats-targets')).trim();
      assert(/196 boundary \+ 1 added/.test(targets), `destinations shown as '${targets}'`);
      assert(await page.isEnabled('#clear-targets-button'), 'the clear button stays disabled');

      // The paths cover the mountain densely: one of a few spots on it lies on a path.
      let tip = '';
      for (const [fx, fy] of [
        [0.5, 0.75],
        [0.4, 0.7],
        [0.6, 0.8],
        [0.45, 0.65],
        [0.55, 0.85],
        [0.35, 0.6],
      ]) {
        await page.mouse.move(box.x + box.width * fx, box.y + box.height * fy);
        tip = await page
          .waitForFunction(
            () => {
              const el = document.getElementById('path-tooltip');
              return el.hidden ? '' : el.textContent;
            },
            null,
            { timeout: 600 },
          )
          .then((h) => h.jsonValue())
          .catch(() => '');
        if (tip) break;
      }
      assert(
        /Path \d+ of 197/.test(tip) &&
          /length [\d.]+/.test(tip) &&
          /\d+ faces crossed/.test(tip) &&
          /reached|hit_boundary|other_component|loop|step_limit|no_exit|degenerate_plane/.test(tip),
        `hover tooltip: '${tip}'`,
      );
    },
  );

  pageTest(
    'shift+click compares the cutting-plane path, the shot geodesic and the exact shortest path',
    {
      ready: 'window.__straightest.param && !window.__straightest.progress.busy',
    },
    async ({ page }) => {
      const box = await page.locator('#view-canvas').boundingBox();
      await page.keyboard.down('Shift');
      await page.mouse.click(box.x + box.width * 0.55, box.y + box.height * 0.6);
      await page.keyboard.up('Shift');
      await expectReady(page, 'window.__straightest.geodesics');
      const g = await page.evaluate(() => window.__straightest.geodesics);
      assert(Number.isInteger(g.target), `destination vertex ${g.target}`);
      for (const key of ['planeLength', 'shotLength', 'exactLength']) {
        assert(Number.isFinite(g[key]) && g[key] > 0, `${key} = ${g[key]}`);
      }
      assert(g.planeStatus === 'reached', `the cutting plane's path: ${g.planeStatus}`);
      // The exact distance is the shortest: no path on the surface is shorter.
      assert(g.exactLength <= g.planeLength + 1e-9, `exact ${g.exactLength} > cutting plane ${g.planeLength}`);
      assert(Number.isFinite(g.missDistance) && g.missDistance >= 0, `miss distance ${g.missDistance}`);
      assert(g.drawn.plane && g.drawn.shot && g.drawn.exact, `drawn: ${JSON.stringify(g.drawn)}`);
      assert(await page.isVisible('#geodesic-compare'), 'the comparison table is hidden');
      for (const id of ['#geo-plane-length', '#geo-shot-length', '#geo-exact-length']) {
        const text = (await page.textContent(id)).trim();
        assert(/^[\d.]+(e[-+]?\d+)?$/.test(text), `${id} shows '${text}'`);
      }
      assert(/misses by/.test(await page.textContent('#geo-shot-note')), 'no miss distance shown');

      // The toggle hides the comparison.
      await page.uncheck('#geodesic-toggle');
      await page.waitForFunction(() => window.__straightest.geodesics === null);
      assert(!(await page.isVisible('#geodesic-compare')), 'the comparison stays after the toggle is off');
    },
  );

  pageTest(
    'a closed mesh shows its info and a note instead of paths',
    {
      ready: 'window.__straightest.paths',
    },
    async ({ page }) => {
      await page.setInputFiles('#file-input', {
        name: 'tetrahedron.off',
        mimeType: 'text/plain',
        buffer: Buffer.from(TETRAHEDRON_OFF),
      });
      await expectReady(page, 'window.__straightest.lastInfo.vertices === 4 && window.__straightest.paths.count === 0');
      assert((await page.textContent('#stats-paths')).trim() === '0', 'stats panel does not show 0 paths');
      assert(await page.isVisible('#stats-note'), 'no note for the closed mesh');
      assert(/closed/i.test(await page.textContent('#stats-note')), 'the note does not say the mesh is closed');
    },
  );

  pageTest(
    'on a closed sphere shift+click and a click give a path and the other way round, both lengths shown',
    {
      ready: 'window.__straightest.paths',
    },
    async ({ page }) => {
      const icosphere = await readFile(new URL('../data/good/icosphere.obj', import.meta.url));
      await page.setInputFiles('#file-input', { name: 'icosphere.obj', mimeType: 'text/plain', buffer: icosphere });
      await expectReady(
        page,
        'window.__straightest.lastInfo.vertices === 42 && window.__straightest.paths.count === 0 ' +
          '&& !window.__straightest.progress.busy',
      );
      assert(
        /closed surface: no boundary.*shift\+click.*to add a destination; a plain click moves the source/i.test(
          await page.textContent('#stats-note'),
        ),
        `the note does not ask for a destination: '${await page.textContent('#stats-note')}'`,
      );
      assert(await page.isHidden('#error-panel'), 'a closed mesh shows an error for paths');
      const box = await page.locator('#view-canvas').boundingBox();
      // As the panel says on every mesh: shift+click adds the destination (from the default source), a
      // click moves the source.
      for (const [fx, fy, shift] of [
        [0.5, 0.5, true],
        [0.56, 0.42, false],
      ]) {
        const traces = await page.evaluate(() => window.__straightest.traces);
        if (shift) await page.keyboard.down('Shift');
        await page.mouse.click(box.x + box.width * fx, box.y + box.height * fy);
        if (shift) await page.keyboard.up('Shift');
        await expectReady(page, `window.__straightest.traces > ${traces} && !window.__straightest.progress.busy`);
      }
      const paths = await page.evaluate(() => window.__straightest.paths);
      assert(
        paths.count === 1 && typeof paths.source?.face === 'number',
        `paths after two clicks: ${JSON.stringify(paths)}`,
      );
      const [arc] = paths.arcs;
      assert(arc.status === 'reached', `the path is ${arc.status}`);
      assert(paths.otherArcs === 1, `${paths.otherArcs} other arcs drawn, expected 1`);
      assert(arc.length > 0 && arc.length <= arc.other, `shorter ${arc.length}, other ${arc.other}`);
      assert(arc.length + arc.other < 2 * Math.PI, 'both arcs make up a section inscribed in the unit sphere');
      const note = await page.textContent('#stats-note');
      const shown = /Path 1: ([\d.]*\d) (forward|backward), the other way round ([\d.]*\d)/.exec(note);
      assert(shown, `the panel does not show both lengths and the direction: '${note}'`);
      assert(
        Math.abs(Number(shown[1]) - arc.length) < 0.01 * arc.length &&
          Math.abs(Number(shown[3]) - arc.other) < 0.01 * arc.other,
        `the panel shows ${shown[1]} and ${shown[3]}, the paths are ${arc.length} and ${arc.other}`,
      );
      assert(shown[2] === (arc.backward ? 'backward' : 'forward'), `direction shown ${shown[2]}`);
    },
  );
});

describe('parameterization', () => {
  pageTest(
    'mountain is parameterized after loading: stats, UV layout and a checkerboard on the mesh',
    {
      ready: 'window.__straightest.param', // the automatic parameterization runs once the paths are drawn
    },
    async ({ page }) => {
      const param = await page.evaluate(() => window.__straightest.param);
      assert(
        param.boundary === 'measured' && param.weights === 'shape-preserving',
        `default parameterization is ${param.boundary} / ${param.weights}`,
      );
      assert(Number.isFinite(param.l2) && param.l2 >= 1, `L2 stretch is ${param.l2}, expected finite and ≥ 1`);
      assert(Number.isFinite(param.linf) && param.linf >= param.l2, `L∞ stretch is ${param.linf} (L2 ${param.l2})`);
      assert(param.bijective === true && param.flipped === 0, `bijective ${param.bijective}, ${param.flipped} flipped`);
      const shownL2 = (await page.textContent('#param-l2')).trim();
      assert(Math.abs(Number(shownL2) - param.l2) < 1e-3, `the panel shows L2 '${shownL2}', the hook ${param.l2}`);
      const panel = await page.textContent('#param-panel');
      assert(panel.includes(shownL2) && /bijective\s*yes/i.test(panel), `param panel: '${panel.replace(/\s+/g, ' ')}'`);
      assert(await page.isHidden('#error-panel'), 'error panel is visible');

      // The layout is drawn: a good share of the uv canvas differs from its background.
      const layout = await uvLayoutCoverage(page);
      assert(layout.width > 100 && layout.height > 100, `uv canvas is ${layout.width}×${layout.height}`);
      assert(layout.fraction > 0.1, `only ${(layout.fraction * 100).toFixed(1)}% of the uv canvas is drawn on`);

      // The checkerboard: many sharp dark↔light steps along the rows of the 3D view, far more than
      // the same view without the texture has (shading and the paths make some too).
      const steps = async () => {
        await page.waitForFunction(() => window.__straightest.renders > 0);
        const image = decodePng(await page.locator('#view-canvas').screenshot());
        const luma = (i) => 0.299 * image.data[i] + 0.587 * image.data[i + 1] + 0.114 * image.data[i + 2];
        let count = 0;
        for (let y = 0; y < image.height; y++) {
          for (let x = 0; x + 3 < image.width; x++) {
            const [a, b] = [
              luma((y * image.width + x) * image.channels),
              luma((y * image.width + x + 3) * image.channels),
            ];
            if ((a < 90 && b > 170) || (a > 170 && b < 90)) count++;
          }
        }
        return count;
      };
      const checker = await steps();
      const renders = await page.evaluate(() => window.__straightest.renders);
      await page.selectOption('#texture-select', 'none');
      await page.waitForFunction((n) => window.__straightest.renders > n, renders);
      const plain = await steps();
      assert(
        checker > 1500 && checker > 2 * plain,
        `${checker} dark/light steps with the checkerboard, ${plain} without: no checkerboard on the mesh`,
      );
    },
  );

  pageTest(
    'comparison table, stretch heat map and the OBJ/PNG downloads',
    {
      ready: 'window.__straightest.param',
    },
    async ({ page }) => {
      await page.click('#compare-button');
      await page.waitForFunction(() => window.__straightest.compare);
      const rows = await page.evaluate(() => window.__straightest.compare);
      assert(rows.length === 16, `${rows.length} comparison rows, expected 4 × 4`);
      const combos = new Set(rows.map((r) => `${r.boundary}/${r.weights}`));
      assert(combos.size === 16, `the rows repeat combinations: ${[...combos].join(', ')}`);
      const freeRows = rows.filter((r) => r.boundary === 'free');
      assert(
        freeRows.length === 4 &&
          freeRows.every(
            (r) =>
              ['measured', 'circle'].includes(r.init) && Number.isInteger(r.iterations) && Number.isInteger(r.overlaps),
          ),
        `free rows: ${JSON.stringify(freeRows)}`,
      );
      assert(
        rows.every((r) => (r.boundary === 'free') === (r.init !== null)),
        'only free rows have a start',
      );
      assert(
        rows.every((r) => !r.error && Number.isFinite(r.l2) && r.timeMs >= 0),
        'a comparison cell failed',
      );
      const tableRows = await page.$$eval('#compare-table tbody tr[data-boundary]', (trs) => trs.length);
      assert(tableRows === 16, `the table shows ${tableRows} rows`);
      const best = rows.reduce((a, b) => (b.l2 < a.l2 ? b : a));
      const bestRow = await page.$eval('#compare-table tr.best', (tr) => [tr.dataset.boundary, tr.dataset.weights]);
      assert(
        bestRow[0] === best.boundary && bestRow[1] === best.weights,
        `highlighted ${bestRow.join('/')}, least L2 is ${best.boundary}/${best.weights}`,
      );

      // The heat map replaces the surface: greens (stretch near 1) fill the view.
      const renders = await page.evaluate(() => window.__straightest.renders);
      await page.check('#stretch-toggle');
      await page.waitForFunction((n) => window.__straightest.renders > n, renders);
      assert(await page.isVisible('#stretch-legend'), 'no stretch legend');
      const image = decodePng(await page.locator('#view-canvas').screenshot());
      let green = 0;
      for (let i = 0; i < image.width * image.height; i++) {
        const [r, g, b] = image.data.subarray(i * image.channels, i * image.channels + 3);
        if (g > r + 30 && g > b + 30) green++;
      }
      assert(green / (image.width * image.height) > 0.05, `only ${green} green pixels with the stretch heat map`);

      const [obj] = await Promise.all([page.waitForEvent('download'), page.click('#export-obj-button')]);
      const text = await streamText(await obj.createReadStream());
      const vt = text.split('\n').filter((line) => line.startsWith('vt ')).length;
      assert(vt === 2500 && /^f \d+\/\d+ /m.test(text), `the OBJ has ${vt} vt lines (expected 2500) or no v/vt faces`);
      const [png] = await Promise.all([page.waitForEvent('download'), page.click('#export-png-button')]);
      const layout = decodePng(Buffer.from(await streamText(await png.createReadStream(), 'latin1'), 'latin1'));
      assert(layout.width > 100 && png.suggestedFilename().endsWith('.png'), `layout PNG ${png.suggestedFilename()}`);
    },
  );

  pageTest(
    'the free boundary from the menu: its layout, stats, stage and exports',
    {
      ready: 'window.__straightest.param',
    },
    async ({ page }) => {
      const menu = await page.$$eval('#boundary-select option', (options) => options.map((o) => o.value));
      assert(menu.join() === 'measured,circle,square,free,auto', `boundary menu: ${menu.join()}`);
      const before = await page.evaluate(() => window.__straightest.parameterizations);
      await page.selectOption('#boundary-select', 'free'); // the menu alone runs it (no button)
      await page.waitForFunction(
        (n) =>
          window.__straightest.parameterizations > n &&
          window.__straightest.param?.boundary === 'free' &&
          !window.__straightest.progress.busy,
        before,
      );
      const { param, progress } = await page.evaluate(() => window.__straightest);
      assert(
        param.boundary === 'free' && ['measured', 'circle'].includes(param.init) && Number.isInteger(param.iterations),
        `free parameterization: ${JSON.stringify(param)}`,
      );
      assert(
        !param.bijective || (param.flipped === 0 && param.overlaps === 0),
        `bijective with folds: ${JSON.stringify(param)}`,
      );
      assert(progress.stages['parameterize:refine'] === 1, `refine stage: ${JSON.stringify(progress.stages)}`);
      const refine = (await page.textContent('#param-refine')).trim();
      assert(
        refine.startsWith(`from ${param.init}`) && refine.includes(`${param.iterations} it.`),
        `refine stat: '${refine}'`,
      );
      assert((await page.textContent('#param-method')).includes('free boundary'), 'the method line does not say free');

      // The layout shows the free map: a good share of the canvas is drawn on.
      const drawn = (await uvLayoutCoverage(page)).fraction;
      assert(drawn > 0.1, `only ${(drawn * 100).toFixed(1)}% of the uv canvas is drawn on`);

      const [obj] = await Promise.all([page.waitForEvent('download'), page.click('#export-obj-button')]);
      const text = await streamText(await obj.createReadStream());
      const vt = text.split('\n').filter((line) => line.startsWith('vt ')).length;
      assert(
        vt === 2500 && obj.suggestedFilename().includes('free'),
        `free OBJ ${obj.suggestedFilename()}: ${vt} vt lines`,
      );
      const [png] = await Promise.all([page.waitForEvent('download'), page.click('#export-png-button')]);
      assert(
        png.suggestedFilename().includes('free') && png.suggestedFilename().endsWith('.png'),
        `layout PNG ${png.suggestedFilename()}`,
      );
    },
  );

  pageTest(
    'closed meshes are cut to a disk: the sphere and torus samples show a layout and report their seam',
    {
      ready: 'window.__straightest.param',
    },
    async ({ page }) => {
      for (const [name, cut] of [
        ['sphere', 'path'],
        ['torus', 'cut-graph'],
      ]) {
        await page.selectOption('#sample-select', name);
        await page.waitForFunction(
          (c) => window.__straightest.param?.cut === c && !window.__straightest.progress.busy,
          cut,
        );
        const { param, paramError } = await page.evaluate(() => window.__straightest);
        assert(paramError === null, `${name}: ${JSON.stringify(paramError)}`);
        assert(
          param.seamEdges > 0 && param.bijective && Number.isFinite(param.l2),
          `${name}: ${JSON.stringify(param)}`,
        );
        const message = await page.textContent('#param-message');
        assert(message.includes(`seam of ${param.seamEdges} edges`), `${name}: the panel says '${message}'`);
        const layout = await uvLayoutCoverage(page);
        assert(
          layout.fraction > 0.1,
          `${name}: only ${(layout.fraction * 100).toFixed(1)}% of the uv canvas is drawn on`,
        );
        assert(await page.isHidden('#error-panel'), `${name}: the error panel is visible`);
      }
      // A closed file too (it was refused before): no error, a cut.
      await page.setInputFiles('#file-input', {
        name: 'tetrahedron.off',
        mimeType: 'text/plain',
        buffer: Buffer.from(TETRAHEDRON_OFF),
      });
      await expectReady(page, 'window.__straightest.lastInfo.vertices === 4 && window.__straightest.param');
      const { param } = await page.evaluate(() => window.__straightest);
      assert(param.cut === 'path', `tetrahedron: ${JSON.stringify(param)}`);
      assert(!(await page.isDisabled('#compare-button')), 'compare stays disabled on a cut mesh');
    },
  );

  pageTest('holes are filled virtually, with a note', { ready: 'window.__straightest.param' }, async ({ page }) => {
    await page.selectOption('#sample-select', 'holes');
    await page.waitForFunction(() => window.__straightest.param?.cut === 'fill' && !window.__straightest.progress.busy);
    const { param } = await page.evaluate(() => window.__straightest);
    assert(param.filledLoops.length === 3 && param.bijective, `holes: ${JSON.stringify(param)}`);
    const message = await page.textContent('#param-message');
    assert(/3 holes filled virtually; outer boundary = loop \d/.test(message), `the panel says '${message}'`);
  });
});

describe('a 200k-vertex mesh in the worker', () => {
  pageTest(
    'a 200k-vertex OBJ loads, traces and parameterizes in the worker while the page keeps ticking',
    {
      ready: 'window.__straightest.param && !window.__straightest.progress.busy',
      timeout: BIG_TEST_TIMEOUT_MS,
    },
    async ({ page }) => {
      await startTicker(page);
      const started = Date.now();
      await page.setInputFiles('#file-input', bigGridFile());
      // While the worker loads, traces and parameterizes, the main thread keeps ticking: sample the
      // ticker every 250 ms until the work is done (each sample also needs the main thread).
      await page.waitForSelector('#progress-panel', { state: 'visible', timeout: BIG_WAIT_TIMEOUT_MS });
      const samples = [];
      for (;;) {
        const { ticks, maxGap } = await readTicker(page);
        const { busy, done } = await page.evaluate(
          (n) => ({
            busy: window.__straightest.progress.busy,
            done: window.__straightest.lastInfo?.vertices === n && !!window.__straightest.param,
          }),
          BIG_GRID_VERTICES,
        );
        samples.push({ ticks, maxGap, busy });
        if (done && !busy) break;
        assert(
          Date.now() - started < BIG_WAIT_TIMEOUT_MS,
          `the work did not finish in ${BIG_WAIT_TIMEOUT_MS} ms (state ${await page.evaluate(() => document.body.dataset.state)})`,
        );
        await page.waitForTimeout(250);
      }
      const busySamples = samples.filter((sample) => sample.busy);
      assert(busySamples.length >= 4, `only ${busySamples.length} samples while the worker was busy`);
      for (let i = 1; i < samples.length; i++) {
        assert(
          samples[i].ticks > samples[i - 1].ticks,
          `the main-thread timer stopped between samples ${i - 1} and ${i}`,
        );
      }
      const { maxGap, ticks } = await readTicker(page);
      assert(maxGap < 500, `the main thread was blocked for ${maxGap.toFixed(0)} ms (${ticks} ticks)`);

      // Every stage of the three requests reported 100%.
      const { progress, lastInfo, paths, param } = await page.evaluate(() => window.__straightest);
      const expected = [
        'file:load',
        'file:upload',
        'paths:trace',
        'paths:upload',
        'parameterize:source',
        'parameterize:trace',
        'parameterize:weights',
        'parameterize:solve',
        'parameterize:metrics',
        'parameterize:overlays',
        'parameterize:upload',
      ];
      for (const key of expected) {
        assert(
          progress.stages[key] === 1,
          `stage ${key} reached ${progress.stages[key]}, expected 1 ` + `(stages: ${JSON.stringify(progress.stages)})`,
        );
      }
      assert(progress.messages >= expected.length, `${progress.messages} progress messages`);
      assert(lastInfo.vertices === BIG_GRID_VERTICES, `lastInfo.vertices is ${lastInfo.vertices}`);
      const vertices = (await page.textContent('#info-vertices')).trim();
      assert(
        vertices === BIG_GRID_VERTICES.toLocaleString('en-US'), // thousands separators from five digits on
        `info panel shows '${vertices}' vertices, expected ${BIG_GRID_VERTICES}`,
      );
      assert(paths.count === 4 * (BIG_GRID_N - 1) && paths.plain, `paths: ${JSON.stringify(paths)}`);
      assert(param.bijective && Number.isFinite(param.l2), `parameterization: ${JSON.stringify(param)}`);
      assert(await page.isHidden('#progress-panel'), 'the progress panel stays visible when idle');
      assert(await page.isHidden('#error-panel'), 'error panel is visible');
      // Its layout, filled in slices (too many faces to stroke), is drawn once they are all in.
      await page.waitForFunction(() => !window.__straightest.layoutFilling, null, { timeout: BIG_WAIT_TIMEOUT_MS });
      const layout = await uvLayoutCoverage(page);
      assert(layout.fraction > 0.1, `only ${(layout.fraction * 100).toFixed(1)}% of the uv canvas is drawn on`);
    },
  );

  pageTest(
    'Cancel stops the parameterization of the 200k-vertex mesh; the mesh stays and the worker works again',
    {
      ready: 'window.__straightest.param && !window.__straightest.progress.busy',
      timeout: BIG_TEST_TIMEOUT_MS,
    },
    async ({ page }) => {
      // Once the paths are drawn the page parameterizes the mesh: with the 'auto' boundary (a solve
      // for each of the three) that is seconds of work. Cancel it midway.
      // Choosing 'auto' re-runs the parameterization of the sample on display: let that finish first,
      // so the stages waited for below are the big mesh's.
      const before = await page.evaluate(() => window.__straightest.parameterizations);
      await page.selectOption('#boundary-select', 'auto');
      await page.waitForFunction(
        (n) => window.__straightest.parameterizations > n && !window.__straightest.progress.busy,
        before,
        { timeout: BIG_WAIT_TIMEOUT_MS, polling: 100 },
      );
      await page.setInputFiles('#file-input', bigGridFile());
      await page.waitForFunction(
        (n) => {
          const { lastInfo, progress } = window.__straightest;
          return (
            lastInfo?.vertices === n &&
            document.body.dataset.state === 'ready' &&
            progress.stages['parameterize:source'] !== undefined &&
            !(progress.stages['parameterize:upload'] >= 1)
          );
        },
        BIG_GRID_VERTICES,
        { timeout: BIG_WAIT_TIMEOUT_MS, polling: 100 },
      );
      const { traces, parameterizations } = await page.evaluate(() => window.__straightest);
      // force: no waiting for the view to be stable (software-rendered frames of this mesh are slow).
      await page.click('#cancel-button', { force: true });
      const stages = await page.evaluate(() => window.__straightest.progress.stages);
      assert(
        !(stages['parameterize:upload'] >= 1),
        `the parameterization finished before Cancel: ${JSON.stringify(stages)}`,
      );
      await expectReady(page, 'window.__straightest.cancels === 1');
      const status = await page.textContent('#status');
      assert(
        /cancelled/i.test(status) && status.includes('200704 vertices'),
        `status after Cancel: '${status.trim()}'`,
      );
      await page.waitForSelector('#progress-panel', { state: 'hidden' }); // it lingers a moment at 100%
      assert(
        /cancelled/i.test(await page.textContent('#param-message')),
        'the parameterization panel does not say cancelled',
      );
      const after = await page.evaluate(() => window.__straightest);
      assert(
        after.param === null && after.parameterizations === parameterizations,
        `a cancelled parameterization was shown: ${JSON.stringify(after.param)}`,
      );
      assert(after.lastInfo.vertices === BIG_GRID_VERTICES, `lastInfo.vertices is ${after.lastInfo.vertices}`);
      assert(
        (await page.textContent('#info-vertices')).trim() === BIG_GRID_VERTICES.toLocaleString('en-US'),
        'info panel changed',
      );
      assert(await page.isHidden('#error-panel'), 'error panel is visible');
      // The mesh is still drawn.
      await page.waitForFunction(() => window.__straightest.renders > 0);
      const background = await page.evaluate(() => window.__straightest.background);
      const fraction = fractionDiffering(decodePng(await page.locator('#view-canvas').screenshot()), background);
      assert(fraction > 0.05, `only ${(fraction * 100).toFixed(1)}% of the view differs from the background`);
      // The new worker has the mesh: Reset traces its paths again.
      await page.click('#reset-button');
      await expectReady(page, `window.__straightest.traces > ${traces}`);
      const paths = await page.evaluate(() => window.__straightest.paths);
      assert(paths.count === 4 * (BIG_GRID_N - 1), `${paths.count} paths after the restart`);
      const late = await page.evaluate(() => window.__straightest);
      assert(
        late.param === null && late.parameterizations === parameterizations,
        'a reply of the terminated worker reached the page',
      );
    },
  );
});

// The package's worker (straightest/worker) answers every loadMesh as the npm package does when WASM
// memory runs out: a listener registered before worker-entry.js's own (imported first) replies and
// stops the event.
const TOO_LARGE_MESSAGE = 'the mesh is too large for the available memory (WebAssembly allocation failed)';
function routeWorkerToTooLarge(context) {
  const prelude = `self.addEventListener('message', (event) => {
    if (event.data?.type !== 'create' || event.data.method !== 'loadMesh') return;
    event.stopImmediatePropagation();
    self.postMessage({ id: event.data.id, type: 'error', category: 'too_large', message: ${JSON.stringify(TOO_LARGE_MESSAGE)} });
  });`;
  return context.route(
    (url) => url.pathname === '/wasm/worker-entry.js' && url.search === '',
    (route) =>
      route.fulfill({
        contentType: 'text/javascript',
        // As the server's own responses: a worker script without COEP does not load in an isolated page.
        headers: { 'Cross-Origin-Embedder-Policy': 'require-corp' },
        body: `import ${JSON.stringify(`data:text/javascript,${encodeURIComponent(prelude)}`)};\nimport './worker-entry.js?real';\n`,
      }),
  );
}

describe('errors', () => {
  pageTest(
    'a too_large error (WebAssembly allocation failed) shows a readable message',
    {
      setup: routeWorkerToTooLarge,
    },
    async ({ page }) => {
      await page.setInputFiles('#file-input', {
        name: 'huge.obj',
        mimeType: 'text/plain',
        buffer: Buffer.from(QUAD_GRID_OBJ),
      });
      const { state, lastError } = await settled(page, `document.body.dataset.state === 'error'`);
      assert(
        state === 'error' && lastError?.category === 'too_large',
        `state '${state}', error ${JSON.stringify(lastError)}`,
      );
      assert(await page.isVisible('#error-panel'), 'error panel is not visible');
      const title = (await page.textContent('#error-title')).trim();
      assert(title.includes('huge.obj'), `error title '${title}'`);
      assert((await page.textContent('#error-message')).includes(TOO_LARGE_MESSAGE), 'the core message is not shown');
      assert((await page.textContent('#error-category')).trim() === 'too_large', 'category not shown');
      const hint = await page.textContent('#error-hint');
      assert((await page.isVisible('#error-hint')) && /memory/i.test(hint) && /smaller/i.test(hint), `hint: '${hint}'`);
      // The mesh on display stays.
      assert((await page.textContent('#info-vertices')).trim() === '2500', 'the mountain is no longer listed');
    },
  );
});
