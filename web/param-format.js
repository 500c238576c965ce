// How the parameterization panels (param-view.js, compare-view.js) write weights, metrics and times.

export const WEIGHT_LABELS = {
  'shape-preserving': 'shape-preserving',
  'mean-value': 'mean value',
  cotan: 'cotan',
  uniform: 'uniform',
};

/** Metrics close to 1 differ in the third decimal: four significant digits; ∞ for Infinity. */
export function formatMetric(x) {
  if (x === Infinity) return '∞';
  if (!Number.isFinite(x)) return String(x);
  if (Math.abs(x) >= 1000) return x.toFixed(0);
  return x.toPrecision(4);
}

export function formatMs(ms, unit = ' ms') {
  return (ms >= 100 ? ms.toFixed(0) : ms.toFixed(1)) + unit;
}
