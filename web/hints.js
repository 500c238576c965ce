// When a result is poor, what to try next: the one rule the page's panels ask (a pure function of the
// numbers the core returned, testable in Node) and the small helper that writes its answer into a
// panel's hint element. Two signs of a poor measured boundary (issue 16): straightest paths from the
// centre that do not reach the boundary (the section through the source closes or leaves through
// another loop first, so the core falls back to edge-graph distances), and a measured boundary whose
// L2 stretch is worse than the plain circle's.

// The measured map is called worse than the circle only when its L2 exceeds the circle's by more than
// this fraction: on near-developable meshes the two agree to a few digits, and which one wins there
// says nothing about the centre.
export const L2_MARGIN = 0.01;

/**
 * The hint for a result, or null when nothing looks poor.
 *   failedTraces, traces: how many of the straightest paths to the boundary failed, of how many
 *     (omit or traces 0 when unknown);
 *   measuredL2, circleL2: the L2 stretch of the measured and circle maps with the same weights
 *     (either missing: not compared);
 *   boundary: the boundary on display ('measured', 'circle', 'square', 'free', or undefined for the
 *     paths panel); freeAvailable: whether the free boundary can be chosen.
 * Returns { reasons: string[], advice: string[], text } (text: the reasons, then the advice).
 */
export function poorResultHint({
  failedTraces = 0,
  traces = 0,
  measuredL2 = NaN,
  circleL2 = NaN,
  boundary = undefined,
  freeAvailable = false,
} = {}) {
  const reasons = [];
  if (traces > 0 && failedTraces > 0) {
    reasons.push(`${failedTraces} of ${traces} straightest paths from the centre do not reach the boundary.`);
  }
  const worseThanCircle =
    Number.isFinite(measuredL2) && Number.isFinite(circleL2) && measuredL2 > circleL2 * (1 + L2_MARGIN);
  if (worseThanCircle) {
    reasons.push(
      `The measured boundary stretches more than the circle (L2 ${measuredL2.toPrecision(4)} > ` +
        `${circleL2.toPrecision(4)}).`,
    );
  }
  if (reasons.length === 0) return null;
  const advice = [
    'Move the centre: click a point nearer the middle of the surface' +
      (boundary === undefined ? '' : ' and tick "Center at the path source"') +
      '.',
  ];
  if (boundary !== 'auto') advice.push('Use the auto boundary: it keeps the map of least stretch.');
  if (freeAvailable && boundary !== 'free')
    advice.push('Use the free boundary: it refines the map with the boundary free to move.');
  return { reasons, advice, text: [...reasons, ...advice].join(' ') };
}

/** Shows `hint` (poorResultHint's answer) in `element`, or hides the element when there is none. */
export function renderHint(element, hint) {
  element.hidden = !hint;
  element.textContent = hint ? hint.text : '';
}

/**
 * The hint for a parameterization (mesh.parameterize()'s reply, as the page requested it: `requested`
 * is the Boundary menu's choice, 'auto' included; boundaryKinds: the core's boundary names). Failed
 * traces are the measured boundary's fallbacks of its boundaryLoop's traces; the circle's L2 is known
 * when 'auto' compared the candidates.
 */
export function parameterizationHint(reply, requested, boundaryKinds) {
  const traced = reply.boundary === 'measured' || reply.init === 'measured' || requested === 'auto';
  const l2 = (boundary) => reply.candidates?.find((c) => c.boundary === boundary)?.l2 ?? NaN;
  return poorResultHint({
    failedTraces: traced ? reply.fallbacks : 0,
    traces: traced ? (reply.boundaryLoop?.length ?? 0) : 0,
    measuredL2: l2('measured'),
    circleL2: l2('circle'),
    boundary: requested,
    freeAvailable: boundaryKinds.includes('free') && reply.boundary !== 'free', // auto may have chosen it
  });
}

/**
 * The hint for a comparison (compareParameterizations' rows): the measured and circle rows with
 * `weights` (those on display, or the default) — no trace counts in its rows, only their L2.
 */
export function comparisonHint(rows, weights = 'shape-preserving') {
  const l2 = (boundary) => rows.find((r) => r.boundary === boundary && r.weights === weights && !r.error)?.l2 ?? NaN;
  return poorResultHint({
    measuredL2: l2('measured'),
    circleL2: l2('circle'),
    boundary: 'compare',
    freeAvailable: rows.some((r) => r.boundary === 'free' && !r.error),
  });
}
