// The colour scales the page maps data through, each defined once: the heat distance (3D view and
// its legend), the per-face stretch (3D heat map, UV layout and both legends) and the colours of
// the boundary kinds (layout polygons, legend and comparison table).

import { Color, SRGBColorSpace } from 'three';

// ------------------------------------------------------------------ heat distance

// A sequential colormap (light → dark) with darker bands every 1/HEAT_BANDS of the range, so the
// level sets of the distance show; the paths (blue) stay readable on top.
const HEAT_STOPS_HEX = [0xfff1c7, 0xf6c37a, 0xe98b57, 0xc9574f, 0x8f3558, 0x4f2456];
const HEAT_STOPS = HEAT_STOPS_HEX.map((c) => new Color(c));
const HEAT_BANDS = 12;
const UNREACHABLE_COLOR = new Color(0x555a63);

/** The heat colour of t ∈ [0, 1] (in three.js' linear working space), written into `target`. */
function heatColor(t, target) {
  const x = Math.min(Math.max(t, 0), 1) * (HEAT_STOPS.length - 1);
  const k = Math.min(Math.floor(x), HEAT_STOPS.length - 2);
  target.lerpColors(HEAT_STOPS[k], HEAT_STOPS[k + 1], x - k);
  const band = (t * HEAT_BANDS) % 1;
  if (band < 0.12) target.multiplyScalar(0.82); // a thin darker stripe at each band start
  return target;
}

/** Vertex colours (linear RGB, 3 floats per vertex) of distances scaled by `max`; grey if unreachable. */
export function heatColors(distances, max) {
  const colors = new Float32Array(3 * distances.length);
  const color = new Color();
  distances.forEach((d, v) => {
    (Number.isFinite(d) ? heatColor(max > 0 ? d / max : 0, color) : UNREACHABLE_COLOR).toArray(colors, 3 * v);
  });
  return colors;
}

/** A CSS linear-gradient of the heat scale (its legend). */
export function heatGradient() {
  return `linear-gradient(to right, ${HEAT_STOPS_HEX.map((c) => `#${c.toString(16).padStart(6, '0')}`).join(', ')})`;
}

// ------------------------------------------------------------------ stretch

// Per-face L2 stretch, 1 (an isometry: good) … ≥ 2 (bad): green → yellow → red (ColorBrewer RdYlGn,
// reversed); flipped or degenerate faces (infinite stretch) are magenta.
const STRETCH_STOPS = [
  [26, 152, 80],
  [145, 207, 96],
  [254, 224, 139],
  [252, 141, 89],
  [215, 48, 39],
];
export const STRETCH_INFINITE = [255, 0, 255];
export const STRETCH_MIN = 1;
export const STRETCH_MAX = 2;
const STRETCH_STEPS = 256; // table entries over [STRETCH_MIN, STRETCH_MAX]; one more for ∞

/** The stretch colour as [r, g, b] in 0…255 (sRGB). */
export function stretchRgb(stretch) {
  if (!Number.isFinite(stretch)) return STRETCH_INFINITE;
  const t = Math.min(Math.max((stretch - STRETCH_MIN) / (STRETCH_MAX - STRETCH_MIN), 0), 1);
  const x = t * (STRETCH_STOPS.length - 1);
  const k = Math.min(Math.floor(x), STRETCH_STOPS.length - 2);
  const f = x - k;
  return STRETCH_STOPS[k].map((c, i) => Math.round(c + f * (STRETCH_STOPS[k + 1][i] - c)));
}

/** The entry of `stretch` in stretchTable(): 0…255 over [STRETCH_MIN, STRETCH_MAX], 256 for ∞. */
export function stretchIndex(stretch) {
  if (!Number.isFinite(stretch)) return STRETCH_STEPS;
  const t = Math.min(Math.max(stretch - STRETCH_MIN, 0) / (STRETCH_MAX - STRETCH_MIN), 1);
  return Math.round((STRETCH_STEPS - 1) * t);
}

const stretchTables = new Map(); // 'srgb' | 'linear' -> Uint8Array
/**
 * stretchRgb at STRETCH_STEPS steps of [STRETCH_MIN, STRETCH_MAX], then the infinite colour: 3 bytes
 * each, indexed by stretchIndex(). space 'srgb' for canvases, 'linear' for three.js vertex colours.
 */
export function stretchTable(space = 'srgb') {
  let table = stretchTables.get(space);
  if (table) return table;
  table = new Uint8Array(3 * (STRETCH_STEPS + 1));
  const color = new Color();
  for (let i = 0; i <= STRETCH_STEPS; i++) {
    const rgb =
      i < STRETCH_STEPS
        ? stretchRgb(STRETCH_MIN + (i / (STRETCH_STEPS - 1)) * (STRETCH_MAX - STRETCH_MIN))
        : STRETCH_INFINITE;
    if (space === 'linear') {
      color.setRGB(rgb[0] / 255, rgb[1] / 255, rgb[2] / 255, SRGBColorSpace); // to the linear working space
      table.set(
        [color.r, color.g, color.b].map((c) => Math.round(255 * c)),
        3 * i,
      );
    } else {
      table.set(rgb, 3 * i);
    }
  }
  stretchTables.set(space, table);
  return table;
}

/** A CSS linear-gradient of the stretch scale (legends). */
export function stretchGradient() {
  const stops = STRETCH_STOPS.map((c, i) => `rgb(${c.join(',')}) ${(100 * i) / (STRETCH_STOPS.length - 1)}%`);
  return `linear-gradient(to right, ${stops.join(', ')})`;
}

// ------------------------------------------------------------------ boundary kinds

/** Colours of the boundary polygons in the layout (and its legend and the comparison table). */
export const BOUNDARY_COLORS = {
  measured: '#f0b429', // the paper's boundary: the accent gold
  circle: '#4ea8ff',
  square: '#5fd08a',
  free: '#e07be0', // the refined boundary: not convex, drawn from the loop's uv
};
