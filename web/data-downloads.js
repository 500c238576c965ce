// The data buttons (issue 31): CSV and JSON downloads of the paths on display, the distances from
// their source, the Compare table and the straightest ÷ exact table (data-export.js builds them).
// The compare and ratio buttons show with their tables; the paths' say so when there are none.

import {
  compareTable,
  distancesTable,
  exactRatioTable,
  indexBaseOf,
  pathsJson,
  pathsTable,
  tableJson,
  toCsv,
} from './data-export.js';
import { download } from './image-export.js';
import { isCancelled } from './requests.js';

const $ = (id) => document.getElementById(id);

/**
 * session: session.js; paths(): the 'paths' reply on display or null; source(): the path source;
 * compareRows(): the Compare rows on display or null; exactRows(): the straightest ÷ exact rows or null.
 */
export function createDataDownloads({ session, paths, source, compareRows, exactRows }) {
  const base = () => indexBaseOf(session.label, !!session.origin?.file);
  const name = (what, ext) =>
    `${(session.label || 'mesh').replace(/\.[^.]+$/, '').replace(/[^\w.-]+/g, '_')}-${what}.${ext}`;

  function save(text, what, ext) {
    download(new Blob([text], { type: ext === 'csv' ? 'text/csv' : 'application/json' }), name(what, ext));
  }

  const tables = {
    paths: {
      csv: () => toCsv(pathsTable(paths(), base())),
      json: () => JSON.stringify(pathsJson(paths(), base()), null, 1),
      ready: () => !!paths()?.count,
    },
    compare: {
      csv: () => toCsv(compareTable(compareRows())),
      json: () => tableJson(compareTable(compareRows()), { mesh: session.label }),
      ready: () => !!compareRows()?.length,
    },
    'exact-ratio': {
      csv: () => toCsv(exactRatioTable(exactRows(), base())),
      json: () => tableJson(exactRatioTable(exactRows(), base()), { mesh: session.label, indexBase: base() }),
      ready: () => !!exactRows()?.length,
    },
  };

  for (const [what, table] of Object.entries(tables)) {
    for (const ext of ['csv', 'json']) {
      $(`${what}-${ext}-button`).addEventListener('click', () => {
        $('data-status').textContent = '';
        if (table.ready()) save(table[ext](), what, ext);
        else $('data-status').textContent = `No ${what.replace('-', ' ')} data on display yet.`;
      });
    }
  }

  // The distances are asked for when wanted (the heat method from the path source).
  async function saveDistances(ext) {
    try {
      const reply = await session.request('distances', { source: source() });
      const table = distancesTable(reply.distances, base());
      save(
        ext === 'csv' ? toCsv(table) : tableJson(table, { mesh: session.label, method: 'heat', indexBase: base() }),
        'distances',
        ext,
      );
    } catch (err) {
      if (!isCancelled(err)) $('data-status').textContent = `Could not compute the distances: ${err.message}`;
    }
  }
  $('distances-csv-button').addEventListener('click', () => saveDistances('csv'));
  $('distances-json-button').addEventListener('click', () => saveDistances('json'));
}
