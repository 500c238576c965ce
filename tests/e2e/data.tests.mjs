// Browser tests of the data downloads (issue 31): the paths, the straightest ÷ exact table and the
// Compare table as CSV and JSON carry the core's numbers in full — checked against the npm package's
// own results for the same mesh, computed here in Node — with readable statuses beside the codes.
// Imported by browser.test.mjs, which owns the browser (useBrowser).

import assert from 'node:assert/strict';
import { after, before, describe } from 'node:test';
import { createStraightest } from '../../wasm/index.js';
import { BIG_TEST_TIMEOUT_MS, expectReady, pageTest, streamText } from './support/fixtures.mjs';
import { QUAD_GRID_OBJ } from './support/meshes.mjs';

/** Rows of a CSV without quoted commas (ours: numbers and plain words), as objects by the header. */
function parseCsv(text) {
  const [header, ...lines] = text.trim().split('\n');
  const columns = header.split(',');
  return lines.map((line) => Object.fromEntries(line.split(',').map((cell, k) => [columns[k], cell])));
}

async function downloaded(page, button) {
  const [file] = await Promise.all([page.waitForEvent('download'), page.click(button)]);
  return { name: file.suggestedFilename(), text: await streamText(await file.createReadStream()) };
}

const close = (a, b) => Math.abs(a - b) <= 1e-9 * Math.max(1, Math.abs(b));

describe('data downloads', () => {
  let st = null;
  let mesh = null;
  before(async () => {
    st = await createStraightest({ threads: 1 });
    mesh = st.sample('mountain');
  });
  after(() => mesh?.delete());

  pageTest(
    'paths, straightest ÷ exact and Compare download as CSV and JSON with the core’s numbers',
    {
      ready: 'window.__straightest.param && !window.__straightest.progress.busy',
      timeout: BIG_TEST_TIMEOUT_MS,
    },
    async ({ page }) => {
      const reference = mesh.straightestPaths({ source: 'auto', targets: 'boundary' });
      const csv = await downloaded(page, '#paths-csv-button');
      assert(csv.name === 'mountain-paths.csv', csv.name);
      const rows = parseCsv(csv.text);
      assert(
        rows.length === reference.offsets[reference.count],
        `${rows.length} rows, ${reference.offsets[reference.count]} points`,
      );
      for (let i = 0; i < reference.count; i++) {
        const row = rows[reference.offsets[i]];
        assert(Number(row.path) === i + 1 && row.point === '0', `path ${i + 1}'s first row: ${JSON.stringify(row)}`);
        assert(
          close(Number(row.length), reference.lengths[i]),
          `path ${i + 1}: ${row.length} against ${reference.lengths[i]}`,
        );
        assert(row.status_code === reference.statuses[i], `path ${i + 1}: ${row.status_code}`);
        assert(close(Number(row.x), reference.points[3 * reference.offsets[i]]), `path ${i + 1}'s first x`);
      }
      const json = JSON.parse((await downloaded(page, '#paths-json-button')).text);
      assert(
        json.paths.length === reference.count &&
          json.paths[5].points.length === reference.offsets[6] - reference.offsets[5],
        'the JSON polylines',
      );
      assert(
        json.paths.every((p, i) => p.length === reference.lengths[i]),
        'the JSON lengths are not the core’s',
      );

      // Straightest ÷ exact.
      await page.click('#exact-ratio-button');
      await page.waitForFunction(() => window.__straightest.exactRatio, null, { timeout: 30_000 });
      const exact = mesh.exactShortestPaths({ source: 'auto', targets: 'boundary', points: false });
      const ratios = parseCsv((await downloaded(page, '#exact-ratio-csv-button')).text);
      assert(ratios.length === exact.count, `${ratios.length} ratio rows`);
      ratios.forEach((row, i) => {
        assert(
          Number(row.vertex) === Number(exact.targets[i].vertex ?? exact.targets[i]),
          `row ${i}: vertex ${row.vertex}`,
        );
        assert(
          close(Number(row.exact), exact.distances[i]),
          `row ${i}: exact ${row.exact} against ${exact.distances[i]}`,
        );
        assert(
          row.status_code === 'reached' ? row.status === 'reached' : row.status !== row.status_code,
          'a raw status',
        );
      });

      // Compare.
      await page.click('#compare-button');
      await page.waitForFunction(() => window.__straightest.compare, null, { timeout: 60_000 });
      const compared = mesh.compareParameterizations({});
      const table = parseCsv((await downloaded(page, '#compare-csv-button')).text);
      assert(table.length === compared.rows.length, `${table.length} Compare rows`);
      for (const row of table) {
        const ref = compared.rows.find((r) => r.boundary === row.boundary && r.weights === row.weights);
        assert(
          ref && close(Number(row.l2), ref.l2) && close(Number(row.linf), ref.linf),
          `${row.boundary}/${row.weights}: L2 ${row.l2} against ${ref?.l2}`,
        );
      }
      const compareJson = JSON.parse((await downloaded(page, '#compare-json-button')).text);
      assert(compareJson.rows.length === compared.rows.length && compareJson.mesh === 'mountain', 'the Compare JSON');

      const distances = parseCsv((await downloaded(page, '#distances-csv-button')).text);
      assert(
        distances.length === 2500 &&
          Number(distances[0].vertex) === 0 &&
          Number.isFinite(Number(distances[0].distance)),
        'the distances CSV',
      );
    },
  );

  pageTest(
    'an OBJ file’s vertices are numbered from 1 in the panels, the typed points and the data',
    {
      ready: 'window.__straightest.param && !window.__straightest.progress.busy',
    },
    async ({ page }) => {
      await page.setInputFiles('#file-input', {
        name: 'grid.obj',
        mimeType: 'text/plain',
        buffer: Buffer.from(QUAD_GRID_OBJ),
      });
      await expectReady(page, 'window.__straightest.lastInfo.vertices === 9 && window.__straightest.paths?.count > 0');
      const { source } = await page.evaluate(() => window.__straightest.paths);
      assert(
        (await page.textContent('#stats-source')).includes(`vertex ${source.vertex + 1}`),
        'the source is not numbered from 1',
      );
      const csv = parseCsv((await downloaded(page, '#distances-csv-button')).text);
      assert(csv.length === 9 && csv[0].vertex === '1', `the distances CSV starts at vertex ${csv[0].vertex}`);
      // Typed: vertex 1 is the file's first (the core's 0).
      const traces = await page.evaluate(() => window.__straightest.traces);
      await page.fill('#source-entry', '1');
      await page.click('#point-entry-button');
      await expectReady(page, `window.__straightest.traces > ${traces}`);
      assert(
        (await page.evaluate(() => window.__straightest.paths.source.vertex)) === 0,
        'typed vertex 1 is not the first',
      );
      await page.fill('#source-entry', '0');
      await page.click('#point-entry-button');
      assert(
        /vertices 1 to 9/.test(await page.textContent('#point-entry-error')),
        'vertex 0 of an OBJ file is accepted',
      );
    },
  );
});
