// The side panels' text: the mesh info, the path statistics, the error panel and the status line,
// the page's state, and how the page writes numbers and surface points. Only DOM: it shows what it is
// handed (and remembers the last error shown: shownError()).

import { formatCount, formatMs } from './param-format.js';
import { summarizeStatus } from './results-summary.js';
import { statusWords } from './data-export.js';

const $ = (id) => document.getElementById(id);

// What to do about an error, per category, below the core's own message.
const ERROR_HINTS = {
  too_large:
    'The browser could not give this mesh enough memory: WebAssembly memory is limited to ' +
    '4 GB, and a mesh takes about 1.3 GB per million vertices once parameterized. Try a smaller or ' +
    'decimated mesh.',
  worker: 'Reload the page to start a new geometry worker.',
};

export function formatNumber(x) {
  if (!Number.isFinite(x)) return String(x);
  return Number.isInteger(x) ? formatCount(x) : String(Number(x.toPrecision(3)));
}

// Vertex and face numbers as the file on display counts them: from 1 for an OBJ file, else from 0
// (the core's). setIndexBase is called with each new mesh.
let indexBase = 0;
export function setIndexBase(base) {
  indexBase = base;
}
export function getIndexBase() {
  return indexBase;
}

/**
 * 'vertex 12', 'face 34, barycentric (0.20, 0.30, 0.50)' (or just 'face 34' without the coordinates), …
 * numbered as the file counts (setIndexBase).
 */
export function describePoint(point, withCoordinates = true) {
  if (typeof point === 'number') return `vertex ${point + indexBase}`;
  if (typeof point?.vertex === 'number') return `vertex ${point.vertex + indexBase}`;
  if (typeof point?.face === 'number') {
    const bary = point.bary.map((b) => b.toFixed(2)).join(', ');
    const face = point.face + indexBase;
    return withCoordinates ? `face ${face}, barycentric (${bary})` : `face ${face}`;
  }
  if (typeof point?.halfedge === 'number') {
    return withCoordinates ? `halfedge ${point.halfedge}, t = ${point.t.toFixed(2)}` : `halfedge ${point.halfedge}`;
  }
  return String(point);
}

export function setStatus(text) {
  $('status').textContent = text;
  summarizeStatus(text);
}

/**
 * The page's state: 'loading' | 'ready' ('ready' once the mesh and its paths are drawn) | 'error', as
 * document.body.dataset.state (the view's busy cursor; the browser tests wait on it).
 */
export function setState(state) {
  document.body.dataset.state = state;
}

/** The threads the worker's WebAssembly module runs on, in the info panel. */
export function showThreads(threads) {
  $('info-threads').textContent = threads > 1 ? `${threads} (WebAssembly threads)` : '1 (single-threaded WebAssembly)';
}

/** Fills the info panel from mesh.info(); label: the sample or file name. */
export function showInfo(info, label) {
  $('info-source').textContent = label ? `— ${label}` : '';
  $('info-vertices').textContent = formatNumber(info.vertices);
  $('info-faces').textContent = formatNumber(info.faces);
  $('info-edges').textContent = formatNumber(info.edges);
  const loops = info.boundaryLoops ?? [];
  $('info-boundary').textContent = loops.length === 0 ? '0 (closed)' : `${loops.length} (${loops.join(', ')} edges)`;
  $('info-euler').textContent = formatNumber(info.eulerCharacteristic);
  $('info-components').textContent = formatNumber(info.components);
  $('info-degenerate').textContent = formatNumber(info.degenerateFaces);
  $('info-reoriented').textContent = formatNumber(info.reorientedFaces);
  $('info-unreferenced').textContent = formatNumber(info.unreferencedVertices);
  const { min, max } = info.bbox;
  $('info-bbox').textContent = min.map((m, i) => formatNumber(max[i] - m)).join(' × ');

  const list = $('info-problems');
  list.replaceChildren();
  const problems = info.problems ?? [];
  for (const text of problems.length ? problems : ['none']) {
    const item = document.createElement('li');
    item.textContent = text;
    if (!problems.length) item.className = 'muted';
    list.append(item);
  }
}

/**
 * Fills the stats panel from a 'paths' reply. request: { isDefault (the source is the default one),
 * boundary (the boundary destinations are in), added (the number of added destinations), closed
 * (the mesh has no boundary) }; drawn: { plain, stride } of the path view; traces: the traces
 * completed so far.
 */
export function showPathStats(reply, request, drawn, traces) {
  const { summary } = reply; // the core's
  const { paths: count, reached } = summary;
  const source = $('stats-source');
  source.textContent = describePoint(reply.source, false) + (request.isDefault ? ' (default)' : '');
  source.title = describePoint(reply.source);
  const parts = [];
  if (request.boundary && !request.closed) parts.push(`${count - request.added} boundary`);
  if (request.added) parts.push(`${request.added} added`);
  $('stats-targets').textContent = parts.join(' + ') || 'none';
  $('stats-paths').textContent = formatCount(count);
  $('stats-reached').textContent = count ? `${formatCount(reached)} (${((100 * reached) / count).toFixed(0)}%)` : '0';
  $('stats-failed').textContent = formatCount(count - reached);

  const list = $('stats-failures');
  const failures = Object.entries(summary.failures);
  list.replaceChildren(
    ...failures.map(([status, n]) => {
      const item = document.createElement('li');
      item.innerHTML = `<code></code> <span></span>`;
      item.firstChild.textContent = statusWords(status);
      item.firstChild.title = status; // the core's code
      item.lastChild.textContent = formatCount(n);
      return item;
    }),
  );
  list.hidden = failures.length === 0;

  $('stats-length').textContent = reached
    ? `${formatNumber(summary.meanLength)} / ${formatNumber(summary.maxLength)}`
    : '–';
  $('stats-faces').textContent = count
    ? `${formatCount(summary.facesCrossed)} / ${formatCount(summary.maxFacesCrossed)}`
    : '–';
  const { timings } = reply;
  const time = $('stats-time');
  time.textContent = formatMs(timings.trace);
  time.title =
    `tracing ${formatMs(timings.trace)}, setup ${formatMs(timings.prepare)} ` +
    `(${formatMs(reply.timeMs)} in the worker in all)`;
  $('stats-traces').textContent = formatCount(traces);

  const notes = [];
  if (request.closed && count === 0) {
    notes.push(
      'Closed surface: no boundary to trace to. Shift+click (or tick “Clicks add destinations” ' +
        'and click) to add a destination; a plain click moves the source.',
    );
  } else if (request.closed) {
    // Each section through the source is a closed curve: the shorter arc is the path, the other dimmed.
    notes.push(
      'Closed surface: each path is the shorter way round its section through the source; ' +
        'the other way is dimmed. Click to move the source, shift+click to add destinations.',
    );
    for (let i = 0; i < Math.min(count, 3); i++) {
      const other = reply.otherArcLengths[i];
      notes.push(
        reply.statuses[i] !== 'reached'
          ? `Path ${i + 1}: ${statusWords(reply.statuses[i])} (${reply.statuses[i]}).`
          : `Path ${i + 1}: ${formatNumber(reply.lengths[i])} ${reply.backward[i] ? 'backward' : 'forward'}` +
              (Number.isFinite(other) ? `, the other way round ${formatNumber(other)}.` : '.'),
      );
    }
  } else if (count === 0) {
    notes.push('No destinations: tick “Boundary destinations” or shift+click the mesh to add some.');
  }
  if (reply.baseNote) notes.push(`Base plane: ${reply.baseNote}.`);
  if (drawn?.plain) {
    const every = drawn.stride > 1 ? ` through 1 point in ${drawn.stride}` : '';
    notes.push(
      `${formatCount(reply.points.length / 3)} path points: drawn as thin plain ` +
        `lines${every} (failed ones solid red), and hovering a path is off.`,
    );
  }
  $('stats-note').textContent = notes.join(' ');
  $('stats-note').hidden = notes.length === 0;
  $('clear-targets-button').disabled = request.added === 0;
}

let lastError = null; // { message, category } of the last error shown (shownError())

/** Shows an error (message and category from the core) in the error panel; the page state is 'error'. */
export function showError(err, title) {
  lastError = { message: err.message, category: err.category ?? 'error' };
  $('error-title').textContent = title;
  $('error-message').textContent = err.message;
  $('error-category').textContent = err.category ?? 'error';
  const hint = ERROR_HINTS[err.category] ?? '';
  $('error-hint').textContent = hint;
  $('error-hint').hidden = !hint;
  $('error-panel').hidden = false;
  setStatus(`Error — ${title}`);
  setState('error');
}

/** Hides the error panel; forget: shownError() is null again (a mesh loaded). */
export function clearError({ forget = false } = {}) {
  $('error-panel').hidden = true;
  if (forget) lastError = null;
}

/** { message, category } of the last error shown in the error panel, or null (none since a mesh loaded). */
export function shownError() {
  return lastError;
}
