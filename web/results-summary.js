// The results bar over the view (index.html #results-summary): the numbers a user came for — the
// parameterization's L2 and L∞ stretch, whether it is bijective, its boundary, the paths that reached
// their destination and the times — always in sight, whatever panel the sidebar is scrolled to. The
// panels keep the details; this only repeats their key values, short, with the full text as a title.

import { formatCount, formatMetric, formatMs, formatPercent } from './param-format.js';

const $ = (id) => document.getElementById(id);

let pathsTime = ''; // the parts of the Time item: the last trace's and the last parameterization's
let paramTime = '';

function set(id, text, title = '', className = '') {
  const dd = $(id);
  dd.textContent = text;
  dd.className = className;
  if (title) dd.title = title;
  else dd.removeAttribute('title');
}

function showTime() {
  const parts = [pathsTime, paramTime].filter(Boolean);
  set('summary-time', parts.join(' · ') || '–');
}

/** The parameterization on display (its reply; requested: the Boundary menu's choice), or null for none. */
export function summarizeParameterization(reply, requested = '') {
  if (!reply) {
    for (const id of ['summary-l2', 'summary-linf', 'summary-bijective', 'summary-boundary']) set(id, '–');
    paramTime = '';
    showTime();
    return;
  }
  set('summary-l2', formatMetric(reply.stretch.l2), `L2 stretch ${reply.stretch.l2}`);
  set('summary-linf', formatMetric(reply.stretch.linf), `L∞ stretch ${reply.stretch.linf}`);
  set('summary-bijective', reply.bijective ? 'yes' : 'no', '', reply.bijective ? 'good' : 'bad');
  const boundary = `${requested === 'auto' ? 'auto → ' : ''}${reply.boundary}${reply.init ? ` (from ${reply.init})` : ''}`;
  set('summary-boundary', boundary, `${boundary} boundary, ${reply.weights} weights`);
  paramTime = `param ${formatMs(reply.timeMs)}`;
  showTime();
}

/** The paths on display ('paths' reply), or null for none. */
export function summarizePaths(reply) {
  if (!reply) {
    set('summary-paths', '–');
    pathsTime = '';
    showTime();
    return;
  }
  const { count, reached } = reply;
  set(
    'summary-paths',
    count ? `${formatCount(reached)} / ${formatCount(count)} reached` : 'none',
    count ? `${count - reached} failed` : 'no destinations',
  );
  pathsTime = count ? `trace ${formatMs(reply.timings.trace)}` : '';
  showTime();
}

/** The status line, repeated in the bar (truncated; its title has it whole) and over the empty view. */
export function summarizeStatus(text) {
  set('summary-status', text, text);
  $('view-loading-text').textContent = text;
}

/** The atlas on display (an 'atlas' reply), or null: the Atlas mode's items of the bar. */
export function summarizeAtlas(reply) {
  const ids = [
    'summary-atlas-charts',
    'summary-atlas-l2',
    'summary-atlas-linf',
    'summary-atlas-utilization',
    'summary-atlas-time',
  ];
  if (!reply) {
    for (const id of ids) set(id, '–');
    return;
  }
  set('summary-atlas-charts', formatCount(reply.charts), `${reply.charts} charts`);
  set('summary-atlas-l2', formatMetric(reply.stretch.l2), `L2 stretch ${reply.stretch.l2}`);
  set('summary-atlas-linf', formatMetric(reply.stretch.linf), `L∞ stretch ${reply.stretch.linf}`);
  set('summary-atlas-utilization', formatPercent(reply.utilization), `utilization ${reply.utilization}`);
  set('summary-atlas-time', formatMs(reply.timeMs), 'in the worker');
}
