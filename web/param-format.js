// How the page writes numbers: counts, weights, metrics and times (the panels, the comparison table,
// the layout captions and the figure all use these, so one number reads the same everywhere).

export const WEIGHT_LABELS = {
  'shape-preserving': 'shape-preserving',
  'mean-value': 'mean value',
  cotan: 'cotan',
  uniform: 'uniform',
};

/**
 * A count: thousands separators (1,790,100) from five digits on; four digits stay as they are
 * (2500), so a count never changes its width by one separator only.
 */
export function formatCount(n) {
  if (!Number.isFinite(n)) return String(n);
  return Math.abs(n) >= 10_000 ? n.toLocaleString('en-US', { maximumFractionDigits: 0 }) : String(Math.round(n));
}

/** Metrics close to 1 differ in the third decimal: four significant digits; ∞ for Infinity. */
export function formatMetric(x) {
  if (x === Infinity) return '∞';
  if (!Number.isFinite(x)) return String(x);
  if (Math.abs(x) >= 1000) return formatCount(x);
  return x.toPrecision(4);
}

/** A duration: whole milliseconds from 100 on, one decimal below, "< 0.1" for what would round to 0.0. */
export function formatMs(ms, unit = ' ms') {
  if (!Number.isFinite(ms)) return `–${unit}`;
  if (ms === 0) return `0${unit}`;
  if (ms < 0.05) return `< 0.1${unit}`;
  return (ms >= 100 ? formatCount(ms) : ms.toFixed(1)) + unit;
}

/** A fraction as a percentage with one decimal (0.7312 → "73.1 %"). */
export function formatPercent(x) {
  return Number.isFinite(x) ? `${(100 * x).toFixed(1)} %` : String(x);
}
