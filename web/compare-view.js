// The "Compare" panel: every boundary kind with every weights in the worker (with their progress),
// as a table grouped by boundary with the best row marked and the row on display outlined; clicking
// a row shows that combination. Free rows also say where their refinement started and its iterations.
// Its rows and hint on display are getters (param-view.js's status() reports them).

import { latest } from './latest.js';
import { BOUNDARY_COLORS } from './colormap.js';
import { isCancelled } from './requests.js';
import { comparisonHint, renderHint } from './hints.js';
import { WEIGHT_LABELS, formatMetric, formatMs } from './param-format.js';

const $ = (id) => document.getElementById(id);

// The weights column's words, short enough for the side panel (each cell's title has the full name).
const SHORT_WEIGHTS = {
  'shape-preserving': 'shape-pres.',
  'mean-value': 'mean val.',
  cotan: 'cotan',
  uniform: 'uniform',
};

/**
 * session: session.js; source(): the source option of the runs; current(): the parameterization on
 * display ({ boundary, weights } or null); onChoose(boundary, weights): a row was clicked;
 * onSettled(): a run ended (the buttons may change).
 */
export function createCompareView({ session, source, current, onChoose, onSettled }) {
  const runs = latest();
  let comparing = false; // a compare request is in flight
  let shownRows = null; // the rows of the table on display
  let hintText = null; // the hint under the table, as text

  async function run() {
    const request = runs.begin(session.meshes);
    const progress = $('compare-progress');
    const status = $('compare-status');
    progress.value = 0;
    progress.hidden = false;
    status.textContent = 'starting…';
    $('compare-button').disabled = true;
    comparing = true;
    try {
      const reply = await session.request('compare', { source: source() }, ({ done, total }) => {
        if (request.stale() || done === undefined) return;
        progress.max = total;
        progress.value = done;
        status.textContent = `${done} / ${total}`;
      });
      if (request.stale()) return;
      shownRows = reply.rows;
      showTable(reply.rows, reply.rows[reply.best] ?? null);
      showHint(comparisonHint(reply.rows, current()?.weights));
      const total = reply.rows.reduce((sum, row) => sum + row.timeMs, 0);
      status.textContent = `${reply.rows.length} runs in ${formatMs(total)}`;
    } catch (err) {
      if (request.stale() || isCancelled(err)) return;
      status.textContent = `failed: ${err.message}`;
    } finally {
      if (!request.stale()) {
        comparing = false;
        progress.hidden = true;
        onSettled();
      }
    }
  }

  function showTable(rows, best) {
    const table = $('compare-table');
    const body = table.tBodies[0];
    body.replaceChildren();
    for (const boundary of session.boundaryKinds) {
      // A header row per boundary, then its rows, one per weights.
      const header = body.insertRow();
      header.className = 'group';
      const th = document.createElement('th');
      th.scope = 'rowgroup';
      th.colSpan = 6;
      th.innerHTML = '<span class="dot"></span>';
      th.firstChild.style.background = BOUNDARY_COLORS[boundary];
      th.append(`${boundary} boundary`);
      header.append(th);
      for (const row of rows.filter((r) => r.boundary === boundary)) {
        const tr = body.insertRow();
        tr.dataset.boundary = row.boundary;
        tr.dataset.weights = row.weights;
        tr.title = row.error ?? `Show ${row.boundary} / ${WEIGHT_LABELS[row.weights]}`;
        if (!row.error) tr.tabIndex = 0; // Enter or Space shows it, as a click does
        // Short enough for the side panel's width: the cell's title says it in full.
        const start = row.init === 'measured' ? 'meas.' : row.init;
        const refine = row.init ? `${start} ${row.iterations}${row.converged ? '' : '+'}` : '–';
        const cells = row.error
          ? [SHORT_WEIGHTS[row.weights], 'failed', '', '', '', formatMs(row.timeMs, '')]
          : [
              SHORT_WEIGHTS[row.weights],
              formatMetric(row.l2),
              formatMetric(row.linf),
              `${row.flipped + row.degenerate}/${row.overlaps}`,
              refine,
              formatMs(row.timeMs, ''),
            ];
        for (const text of cells) tr.insertCell().textContent = text;
        tr.cells[0].title = WEIGHT_LABELS[row.weights];
        if (!row.error) {
          tr.cells[3].title =
            `${row.flipped} flipped, ${row.degenerate} degenerate faces; ${row.overlaps} pairs of ` +
            'boundary edges crossing';
        }
        if (best && row.boundary === best.boundary && row.weights === best.weights) tr.classList.add('best');
        if (row.error) tr.classList.add('failed');
        if (!row.error && row.flipped + row.degenerate + row.overlaps > 0) tr.cells[3].classList.add('bad');
        if (row.init) {
          tr.cells[4].title =
            `refined from the ${row.init} map in ${row.iterations} iterations` +
            (row.converged ? '' : ' (stopped by the iteration cap or the time budget)');
        }
      }
    }
    table.hidden = false;
    $('compare-legend').hidden = false;
    $('compare-data').hidden = false;
    markCurrent();
  }

  /** Outlines the table row of the parameterization on display. */
  function markCurrent() {
    const shown = current();
    for (const tr of $('compare-table').tBodies[0].rows) {
      if (!tr.dataset.boundary) continue;
      tr.classList.toggle(
        'current',
        !!shown && tr.dataset.boundary === shown.boundary && tr.dataset.weights === shown.weights,
      );
    }
  }

  /** The poor-result hint under the table (hints.js decides), or none. */
  function showHint(hint) {
    renderHint($('compare-hint'), hint);
    hintText = hint?.text ?? null;
  }

  $('compare-button').addEventListener('click', () => run());
  function choose(event) {
    const tr = event.target.closest('tr');
    if (!tr?.dataset.boundary || tr.classList.contains('failed')) return;
    onChoose(tr.dataset.boundary, tr.dataset.weights);
  }
  $('compare-table').tBodies[0].addEventListener('click', choose);
  $('compare-table').tBodies[0].addEventListener('keydown', (event) => {
    if (event.key !== 'Enter' && event.key !== ' ') return;
    event.preventDefault(); // Space would scroll
    choose(event);
  });

  return {
    markCurrent,
    /** The rows of the table on display, or null. */
    get rows() {
      return shownRows;
    },
    /** The poor-result hint under the table, as text, or null. */
    get hint() {
      return hintText;
    },

    /** No table (a new mesh). */
    clear() {
      runs.supersede();
      comparing = false;
      shownRows = null;
      $('compare-table').tBodies[0].replaceChildren();
      $('compare-table').hidden = true;
      $('compare-legend').hidden = true;
      $('compare-data').hidden = true;
      $('compare-progress').hidden = true;
      $('compare-status').textContent = '';
      showHint(null);
    },

    /** Cancel stopped the worker: the runs in flight will not come. */
    cancelled() {
      runs.supersede();
      if (!comparing) return;
      comparing = false;
      $('compare-progress').hidden = true;
      $('compare-status').textContent = 'cancelled';
    },
  };
}
