// The parameterization panel's words: its stats (method, stretch, bijectivity, flips, distortion,
// refinement, times, with their tooltips) and the note on what the core did to make the mesh a disk.
// Pure DOM writing from a parameterize reply; param-view.js decides when.

import { WEIGHT_LABELS, formatMetric, formatMs } from './param-format.js';

const $ = (id) => document.getElementById(id);

const STATS_FIELDS = ['l2', 'linf', 'bijective', 'flips', 'fallbacks', 'angle', 'area', 'refine', 'time'];

/** Empties the stats (a new mesh, a failure). */
export function clearStats() {
  for (const field of STATS_FIELDS) {
    const dd = $(`param-${field}`);
    dd.textContent = '–';
    dd.className = '';
    dd.removeAttribute('title');
  }
  $('param-method').textContent = '–';
  $('param-method').removeAttribute('title');
  $('param-method').hidden = false;
  $('param-stats').hidden = false;
}

/** The stats of a reply; requested: the boundary asked for ('auto' shows what it chose). */
export function showStats(reply, requested) {
  const set = (field, text, className = '', title = '') => {
    const dd = $(`param-${field}`);
    dd.textContent = text;
    dd.className = className;
    if (title) dd.title = title;
    else dd.removeAttribute('title');
  };
  const method = $('param-method');
  const weights = document.createElement('span'); // breaks before, never inside 'shape-preserving weights'
  weights.className = 'nowrap';
  weights.textContent = `${WEIGHT_LABELS[reply.weights]} weights`;
  method.replaceChildren(
    `${requested === 'auto' ? 'auto → ' : ''}${reply.boundary} boundary` +
      `${reply.init ? ` (from ${reply.init})` : ''} · `,
    weights,
  );
  method.title =
    reply.candidates.length > 1
      ? `least L2 stretch of ${reply.candidates.map((c) => `${c.boundary} ${formatMetric(c.l2)}`).join(', ')}`
      : '';
  set('l2', formatMetric(reply.stretch.l2), 'strong');
  set('linf', formatMetric(reply.stretch.linf));
  set('bijective', reply.bijective ? 'yes' : 'no', reply.bijective ? 'good' : 'bad');
  set(
    'flips',
    `${reply.flipped} / ${reply.degenerate} / ${reply.overlaps}`,
    reply.flipped + reply.degenerate + reply.overlaps ? 'bad' : '',
    'flipped triangles / degenerate triangles / pairs of boundary edges crossing in the plane',
  );
  set(
    'fallbacks',
    `${reply.fallbacks} / ${reply.weightFallbacks}`,
    '',
    'traces of the measured boundary that used the edge-graph distance / faces whose weights fell back',
  );
  set('angle', `${formatMetric(reply.angleDistortion.mean)} / ${formatMetric(reply.angleDistortion.max)}`);
  set('area', `${formatMetric(reply.areaDistortion.mean)} / ${formatMetric(reply.areaDistortion.max)}`);
  if (reply.init) {
    set(
      'refine',
      `from ${reply.init} · ${reply.iterations} it. · ${formatMetric(reply.energyInitial)} → ` +
        `${formatMetric(reply.energyFinal)}${reply.untangled ? ' · untangled' : ''}`,
      reply.converged ? '' : 'warn',
      'the start of the refinement, its iterations and its symmetric Dirichlet energy per unit area (4 for an ' +
        `isometry); ${reply.converged ? 'converged' : 'stopped by the iteration cap or the time budget'}` +
        (reply.untangled ? '; the start had folded triangles and was untangled first' : ''),
    );
  } else {
    set('refine', '–', '', 'only the free boundary is refined');
  }
  const t = reply.timings;
  set(
    'time',
    `${formatMs(t.solve, '')}${t.refine > 0 ? ` + ${formatMs(t.refine, '')}` : ''} / ${formatMs(t.total)}`,
    '',
    `source ${formatMs(t.source)}, trace ${formatMs(t.trace)}, boundary ${formatMs(t.boundary)}, ` +
      `weights ${formatMs(t.weights)}, solve ${formatMs(t.solve)}, refine ${formatMs(t.refine)}, ` +
      `metrics ${formatMs(t.metrics)}; ` +
      `relative residual ${reply.residual.toExponential(1)}; ${formatMs(reply.timeMs)} in the worker ` +
      "(plus the other boundaries' polygons)",
  );
}

/** What the core did to make the mesh a disk, in words (empty for a disk). */
export function cutNote(reply, loops = []) {
  const parts = [];
  if (reply.components > 1) {
    parts.push(
      `Component ${reply.component} of ${reply.components} (the largest) is parameterized; ` + 'the others have no uv.',
    );
  }
  if (reply.cut === 'fill' || reply.filledLoops.length > 0) {
    const outer = loops.findIndex((_, i) => !reply.filledLoops.includes(i));
    const n = reply.filledLoops.length;
    parts.push(
      `${n} hole${n === 1 ? '' : 's'} filled virtually` +
        `${reply.cut === 'fill' ? `; outer boundary = loop ${outer}` : ''}.`,
    );
  }
  if (reply.cut === 'path' || reply.cut === 'cut-graph') {
    parts.push(
      `${reply.cut === 'path' ? 'Closed surface' : `Genus ${reply.genus}`}: cut to a disk along a seam ` +
        `of ${reply.seamEdges} edges (length ${formatMetric(reply.seamLength)}), drawn in magenta.`,
    );
  }
  return parts.join(' ');
}
