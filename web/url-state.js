// The page's state in its URL (issue 31): the mesh (sample or file name), the path source and the
// added destinations, the parameterization's options, the view options, the mode (the tab over the
// view) and the Atlas mode's options, so a reload or a shared link shows the same thing. The encoding is pure (encodeState / decodeState, tested in Node); the
// page writes it with history.replaceState after each change (no history entry per click).
//
// A file cannot travel in a URL: the link keeps its name, the page asks for it again by that name,
// and the rest of the state is applied when a file of that name is opened.
//
// Surface points: 'v12' (vertex 12, as the core counts: from 0), 'f34_0.2_0.3_0.5' (face 34 and its
// barycentric coordinates); destinations joined by '-' (no coordinate is negative). Only the
// characters URLSearchParams leaves as they are.

// The view options and their controls: a checkbox (true/false) or a menu (its value); the default is
// what index.html has, and a value equal to it is left out of the URL.
export const OPTIONS = {
  boundary: { id: 'boundary-select' },
  weights: { id: 'weights-select', fallback: 'shape-preserving' },
  center: { id: 'param-source-toggle', check: false },
  targets: { id: 'boundary-toggle', check: true },
  up: { id: 'up-select', fallback: 'auto' },
  wire: { id: 'wireframe-toggle', check: false },
  flat: { id: 'flat-toggle', check: false },
  heat: { id: 'heat-toggle', check: false },
  base: { id: 'base-toggle', check: true },
  geo: { id: 'geodesic-toggle', check: true },
  clickadd: { id: 'pick-destination-toggle', check: false },
  texture: { id: 'texture-select', fallback: 'checker' },
  stretch: { id: 'stretch-toggle', check: false },
  paths: { id: 'paths-toggle', check: true },
  checker: { id: 'checker-cells', fallback: '16' },
  // The Atlas mode's options and view (atlas-mode.js); its fields are text the mode checks itself.
  atlasstretch: { id: 'atlas-max-stretch', fallback: '1.02' },
  atlasfill: { id: 'atlas-min-hull-fill', fallback: '0.75' },
  atlasres: { id: 'atlas-resolution', fallback: '1024' },
  atlaspad: { id: 'atlas-padding', fallback: '2' },
  atlasshow: { id: 'atlas-display', fallback: 'charts' },
  seams: { id: 'atlas-seams-toggle', check: true },
};

// The mode the page opens in (modes.js), left out of the URL.
export const DEFAULT_MODE = 'surface';

const round = (x) => String(Number(x.toFixed(6)));

/** 'v12' or 'f34_0.2_0.3_0.5' for a surface point ({ vertex } or { face, bary }). */
export function encodePoint(point) {
  if (typeof point?.vertex === 'number') return `v${point.vertex}`;
  if (typeof point?.face === 'number') return `f${point.face}_${point.bary.map(round).join('_')}`;
  throw new Error(`not a surface point: ${JSON.stringify(point)}`);
}

/** The surface point of encodePoint's text, or null if it is not one. */
export function decodePoint(text) {
  let match = /^v(\d+)$/.exec(text);
  if (match) return { vertex: Number(match[1]) };
  match = /^f(\d+)_([\d.e]+)_([\d.e]+)_([\d.e]+)$/.exec(text);
  if (!match) return null;
  const bary = match.slice(2).map(Number);
  const total = bary[0] + bary[1] + bary[2];
  if (bary.some((b) => !Number.isFinite(b) || b < 0) || !(total > 0)) return null;
  return { face: Number(match[1]), bary: bary.map((b) => b / total) };
}

/**
 * The query string of a state: { sample | file, mode (a modes.js id), source ('auto' or a point),
 * destinations (points), options: { name: value } (OPTIONS' names; booleans for checkboxes, strings for
 * menus and fields) }.
 */
export function encodeState({
  sample = null,
  file = null,
  mode = DEFAULT_MODE,
  source = 'auto',
  destinations = [],
  options = {},
}) {
  const params = new URLSearchParams();
  if (file) params.set('file', file);
  else if (sample) params.set('sample', sample);
  if (mode !== DEFAULT_MODE) params.set('mode', mode);
  if (source !== 'auto') params.set('source', encodePoint(source));
  if (destinations.length) params.set('dest', destinations.map(encodePoint).join('-'));
  for (const [name, value] of Object.entries(options)) {
    const option = OPTIONS[name];
    if (!option || value === undefined || value === null) continue;
    if ('check' in option) {
      if (value !== option.check) params.set(name, value ? '1' : '0');
    } else if (value !== option.fallback) {
      params.set(name, String(value));
    }
  }
  return params.toString();
}

/** The state in a query string (decodeState(encodeState(s)) gives s back; unknown or bad entries are dropped). */
export function decodeState(search) {
  const params = new URLSearchParams(search);
  const source = params.has('source') ? decodePoint(params.get('source')) : null;
  const destinations = (params.get('dest') ?? '').split('-').filter(Boolean).map(decodePoint).filter(Boolean);
  const options = {};
  for (const [name, option] of Object.entries(OPTIONS)) {
    if (!params.has(name)) continue;
    const value = params.get(name);
    options[name] = 'check' in option ? value === '1' : value;
  }
  return {
    sample: params.get('file') ? null : params.get('sample'),
    file: params.get('file'),
    mode: params.get('mode') || DEFAULT_MODE,
    source: source ?? 'auto',
    destinations,
    options,
  };
}

/** Whether every point lies on a mesh with these counts ({ vertices, faces }). */
export function pointsFit(points, { vertices, faces }) {
  return points.every((p) => (p.vertex !== undefined ? p.vertex < vertices : p.face < faces));
}
