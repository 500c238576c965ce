// Straightest ÷ exact over every boundary target (issue 17): for the path source, the cutting-plane
// path length to each vertex of the longest boundary loop divided by its exact geodesic distance
// (both from the core, through the 'exactRatio' request), drawn as a plot against the target's place
// along the loop — with the minimum, median and maximum and the count of failed traces — and as a
// sortable table. Exact paths are the shortest, so every ratio is ≥ 1; on a plane every ratio is 1.
// What it has on display, as plain data, is status() (main.js puts it in the page's observable state
// as exactRatio, docs/PAGE.md).

import { latest } from './latest.js';
import { isCancelled } from './requests.js';
import { statusWords } from './data-export.js';
import { getIndexBase } from './panels.js';

const $ = (id) => document.getElementById(id);
const SVG = 'http://www.w3.org/2000/svg';
const format = (x, digits = 6) => (Number.isFinite(x) ? String(Number(x.toPrecision(digits))) : '–');

/** Minimum, median and maximum of the finite values (NaN each when there are none). */
export function summarize(values) {
  const finite = values.filter(Number.isFinite).sort((a, b) => a - b);
  const n = finite.length;
  if (n === 0) return { min: NaN, median: NaN, max: NaN };
  const median = n % 2 ? finite[(n - 1) / 2] : (finite[n / 2 - 1] + finite[n / 2]) / 2;
  return { min: finite[0], median, max: finite[n - 1] };
}

function svgElement(name, attributes) {
  const element = document.createElementNS(SVG, name);
  for (const [key, value] of Object.entries(attributes)) element.setAttribute(key, String(value));
  return element;
}

/** The plot: ratio (y) against the target's index along the loop (x); failed traces as marks on the axis. */
function drawPlot(svg, rows, { min, max }) {
  const width = 300;
  const height = 150;
  const pad = { left: 46, right: 8, top: 8, bottom: 22 };
  svg.setAttribute('viewBox', `0 0 ${width} ${height}`);
  svg.replaceChildren();
  // y from 1 (exact) to the largest ratio, with a little room; a flat plot still gets a range.
  const low = Math.min(1, Number.isFinite(min) ? min : 1);
  const high = Math.max(Number.isFinite(max) ? max : 1, low + 1e-3);
  const x = (i) => pad.left + (rows.length > 1 ? i / (rows.length - 1) : 0.5) * (width - pad.left - pad.right);
  const y = (r) => pad.top + (1 - (r - low) / (high - low)) * (height - pad.top - pad.bottom);
  const axis = svgElement('g', { class: 'axis' });
  axis.append(
    svgElement('line', { x1: pad.left, y1: y(low), x2: width - pad.right, y2: y(low) }),
    svgElement('line', { x1: pad.left, y1: pad.top, x2: pad.left, y2: y(low) }),
  );
  for (const [value, anchor] of [
    [low, 'low'],
    [high, 'high'],
  ]) {
    const label = svgElement('text', {
      x: pad.left - 4,
      y: y(value) + (anchor === 'low' ? 0 : 8),
      'text-anchor': 'end',
    });
    label.textContent = format(value, 5);
    axis.append(label);
  }
  const caption = svgElement('text', { x: (width + pad.left) / 2, y: height - 4, 'text-anchor': 'middle' });
  caption.textContent = 'boundary vertex, in loop order';
  axis.append(caption);
  svg.append(axis);
  if (low <= 1 && 1 <= high) {
    svg.append(svgElement('line', { class: 'unit', x1: pad.left, y1: y(1), x2: width - pad.right, y2: y(1) }));
  }
  const points = svgElement('g', { class: 'points' });
  rows.forEach((row, i) => {
    if (Number.isFinite(row.ratio)) {
      const dot = svgElement('circle', { cx: x(i), cy: y(row.ratio), r: 1.8 });
      dot.dataset.vertex = row.vertex;
      points.append(dot);
    } else {
      points.append(svgElement('line', { class: 'failed', x1: x(i), y1: y(low) - 5, x2: x(i), y2: y(low) }));
    }
  });
  svg.append(points);
}

const COLUMNS = [
  { key: 'index', label: '#', title: 'place along the boundary loop' },
  { key: 'vertex', label: 'Vertex' },
  { key: 'straightest', label: 'Straightest' },
  { key: 'exact', label: 'Exact' },
  { key: 'ratio', label: 'Ratio', title: 'straightest ÷ exact (≥ 1)' },
  { key: 'status', label: 'Status' },
];

/** session: session.js; source(): the path source ('auto' or a surface point). */
export function createExactRatio({ session, source }) {
  const runs = latest();
  let rows = [];
  let sort = { key: 'index', descending: false };
  let shownSource = null; // JSON of the resolved source the plot belongs to
  let plotted = null; // the plot on display, for status(); null while a run is in flight

  function showTable() {
    const table = $('exact-ratio-table');
    const head = table.tHead.rows[0];
    head.replaceChildren(
      ...COLUMNS.map(({ key, label, title }) => {
        const th = document.createElement('th');
        th.scope = 'col';
        th.tabIndex = 0;
        th.dataset.key = key;
        th.textContent = label + (sort.key === key ? (sort.descending ? ' ▾' : ' ▴') : '');
        th.setAttribute('aria-sort', sort.key === key ? (sort.descending ? 'descending' : 'ascending') : 'none');
        if (title) th.title = title;
        return th;
      }),
    );
    const order = (value) => (typeof value === 'number' && !Number.isFinite(value) ? Infinity : value);
    const sorted = [...rows].sort((a, b) => {
      const [p, q] = [order(a[sort.key]), order(b[sort.key])];
      const c = typeof p === 'string' ? p.localeCompare(q) : p - q;
      return (sort.descending ? -c : c) || a.index - b.index;
    });
    table.tBodies[0].replaceChildren(
      ...sorted.map((row) => {
        const tr = document.createElement('tr');
        if (row.status !== 'reached') tr.className = 'failed';
        for (const text of [
          row.index + 1,
          row.vertex + getIndexBase(),
          format(row.straightest),
          format(row.exact),
          format(row.ratio, 7),
          statusWords(row.status),
        ]) {
          tr.insertCell().textContent = String(text);
        }
        tr.cells[5].title = row.status; // the core's code
        return tr;
      }),
    );
  }

  function sortBy(key) {
    sort = { key, descending: sort.key === key ? !sort.descending : false };
    showTable();
  }
  $('exact-ratio-table').tHead.addEventListener('click', (event) => {
    const key = event.target.closest('th')?.dataset.key;
    if (key) sortBy(key);
  });
  $('exact-ratio-table').tHead.addEventListener('keydown', (event) => {
    const key = event.target.closest('th')?.dataset.key;
    if (key && (event.key === 'Enter' || event.key === ' ')) {
      event.preventDefault();
      sortBy(key);
    }
  });

  function clear() {
    runs.supersede();
    rows = [];
    shownSource = null;
    $('exact-ratio').hidden = true;
    plotted = null;
  }

  async function run() {
    const request = runs.begin(session.meshes);
    $('exact-ratio').hidden = false;
    $('exact-ratio-summary').textContent = 'Computing exact distances and straightest paths…';
    plotted = null;
    try {
      const reply = await session.request('exactRatio', { source: source() });
      if (request.stale()) return;
      rows = Array.from(reply.targets, (vertex, index) => ({
        index,
        vertex,
        straightest: reply.lengths[index],
        exact: reply.distances[index],
        ratio: reply.ratios[index],
        status: reply.statuses[index],
      }));
      const stats = summarize(Array.from(reply.ratios));
      const failed = rows.filter((row) => row.status !== 'reached').length;
      shownSource = JSON.stringify(reply.source);
      $('exact-ratio-summary').textContent =
        `${rows.length} boundary targets · ratio min ${format(stats.min, 7)}, ` +
        `median ${format(stats.median, 7)}, max ${format(stats.max, 7)} · ${failed} failed trace${failed === 1 ? '' : 's'}`;
      drawPlot($('exact-ratio-plot'), rows, stats);
      showTable();
      plotted = {
        count: rows.length,
        failed,
        ...stats,
        ratios: Array.from(reply.ratios),
        statuses: [...reply.statuses],
        source: reply.source,
      };
    } catch (err) {
      if (request.stale() || isCancelled(err)) {
        if (!request.stale()) $('exact-ratio-summary').textContent = 'cancelled';
        return;
      }
      $('exact-ratio-summary').textContent = `Could not compare with the exact distances: ${err.message}`;
    }
  }

  $('exact-ratio-button').addEventListener('click', () => run());
  $('exact-ratio-close').addEventListener('click', () => clear());

  return {
    clear,
    /** The table's rows on display ({ index, vertex, straightest, exact, ratio, status }), or null. */
    get rows() {
      return rows.length ? rows : null;
    },
    /**
     * The plot on display: { count, failed, min, median, max, ratios (NaN where the trace failed),
     * statuses, source }, or null.
     */
    status: () => plotted,
    /** The paths were traced from `resolved`: a plot of another source is out of date. */
    sourceChanged(resolved) {
      if (shownSource !== null && shownSource !== JSON.stringify(resolved)) clear();
    },
    /** Cancel stopped the worker: the run in flight will not come. */
    cancelled() {
      if (!$('exact-ratio').hidden && !plotted) {
        runs.supersede();
        $('exact-ratio-summary').textContent = 'cancelled';
      }
    },
  };
}
