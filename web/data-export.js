// The page's results as data (issue 31): CSV and JSON of the straightest ÷ exact table, the Compare
// table, the paths (polylines, lengths, statuses) and the distances, and the words the page uses for
// the core's status codes. The tables are built by pure functions (tested in Node); numbers are
// written in full (JavaScript's shortest round-trip form), never as the panels round them.
//
// Vertex and face numbers are written as the file counts them: from 1 for an OBJ file (its `f`
// lines do), from 0 otherwise (OFF, PLY, the samples) — `indexBase`.

/** The core's status codes (paths and shots) in words; the code itself goes in a tooltip or a column. */
export const STATUS_WORDS = {
  reached: 'reached',
  reached_length: 'walked its whole length',
  hit_boundary: 'stopped at a boundary',
  other_component: 'destination on another loop of the section',
  loop: 'closed on itself',
  step_limit: 'too many steps',
  no_exit: 'no way out of a face',
  degenerate_plane: 'no cutting plane (degenerate)',
};

export function statusWords(code) {
  return STATUS_WORDS[code] ?? String(code);
}

/** 1 for a file whose format numbers vertices from 1 (OBJ), else 0. label: the file or sample name. */
export function indexBaseOf(label, isFile) {
  return isFile && /\.obj$/i.test(label ?? '') ? 1 : 0;
}

function csvCell(value) {
  if (value === null || value === undefined) return '';
  if (typeof value === 'number')
    return Number.isFinite(value) ? String(value) : Number.isNaN(value) ? 'NaN' : String(value);
  const text = String(value);
  return /[",\n\r]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}

/** CSV text (RFC 4180, \n line ends) of a table: { columns: [name], rows: [[value]] }. */
export function toCsv({ columns, rows }) {
  return [columns, ...rows].map((row) => row.map(csvCell).join(',')).join('\n') + '\n';
}

/** A surface point as the file counts it: 'v12' or 'f34 (0.2 0.3 0.5)'. */
function pointText(point, base) {
  if (typeof point?.vertex === 'number') return `v${point.vertex + base}`;
  if (typeof point?.face === 'number') return `f${point.face + base} (${point.bary.join(' ')})`;
  if (typeof point?.halfedge === 'number') return `h${point.halfedge} t=${point.t}`;
  return '';
}

/**
 * The paths of a 'paths' reply as a long table: one row per polyline point (a path with no points
 * gets one row without coordinates), with its target, status and length.
 */
export function pathsTable(reply, base = 0) {
  const columns = ['path', 'target', 'status', 'status_code', 'length', 'faces_crossed', 'point', 'x', 'y', 'z'];
  const rows = [];
  for (let i = 0; i < reply.count; i++) {
    const head = [
      i + 1,
      pointText(reply.targets[i], base),
      statusWords(reply.statuses[i]),
      reply.statuses[i],
      reply.lengths[i],
      reply.facesCrossed[i],
    ];
    const [from, to] = [reply.offsets[i] ?? 0, reply.offsets[i + 1] ?? 0];
    if (to <= from) rows.push([...head, '', '', '', '']);
    for (let k = from; k < to; k++) {
      rows.push([...head, k - from, reply.points[3 * k], reply.points[3 * k + 1], reply.points[3 * k + 2]]);
    }
  }
  return { columns, rows };
}

/** The paths as JSON-ready data: the source, and per path its target, status, length and polyline. */
export function pathsJson(reply, base = 0) {
  return {
    indexBase: base,
    source: pointText(reply.source, base),
    paths: Array.from({ length: reply.count }, (_, i) => {
      const [from, to] = [reply.offsets[i] ?? 0, reply.offsets[i + 1] ?? 0];
      return {
        path: i + 1,
        target: pointText(reply.targets[i], base),
        status: statusWords(reply.statuses[i]),
        statusCode: reply.statuses[i],
        length: reply.lengths[i],
        facesCrossed: reply.facesCrossed[i],
        points: Array.from({ length: to - from }, (__, k) =>
          Array.from(reply.points.subarray(3 * (from + k), 3 * (from + k) + 3)),
        ),
      };
    }),
  };
}

/** Per-vertex distances (a 'distances' reply's Float32Array, or any array) as a table. */
export function distancesTable(distances, base = 0) {
  return { columns: ['vertex', 'distance'], rows: Array.from(distances, (d, v) => [v + base, d]) };
}

/** The Compare rows (compareParameterizations') as a table. */
export function compareTable(rows) {
  const columns = [
    'boundary',
    'weights',
    'l2',
    'linf',
    'flipped',
    'degenerate',
    'overlaps',
    'bijective',
    'refined_from',
    'iterations',
    'converged',
    'time_ms',
    'error',
  ];
  return {
    columns,
    rows: rows.map((r) => [
      r.boundary,
      r.weights,
      r.l2,
      r.linf,
      r.flipped,
      r.degenerate,
      r.overlaps,
      r.error ? '' : r.flipped + r.degenerate + r.overlaps === 0,
      r.init ?? '',
      r.iterations ?? '',
      r.converged ?? '',
      r.timeMs,
      r.error ?? '',
    ]),
  };
}

/** The straightest ÷ exact rows ({ index, vertex, straightest, exact, ratio, status }) as a table. */
export function exactRatioTable(rows, base = 0) {
  return {
    columns: ['index', 'vertex', 'straightest', 'exact', 'ratio', 'status', 'status_code'],
    rows: rows.map((r) => [
      r.index + 1,
      r.vertex + base,
      r.straightest,
      r.exact,
      r.ratio,
      statusWords(r.status),
      r.status,
    ]),
  };
}

/** JSON text of a table ({ columns, rows }) as an array of objects (NaN and ∞ as null, as JSON has them). */
export function tableJson(table, extra = {}) {
  const records = table.rows.map((row) => Object.fromEntries(table.columns.map((c, k) => [c, row[k]])));
  return JSON.stringify({ ...extra, rows: records }, null, 1);
}
