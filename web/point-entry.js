// Typing surface points instead of clicking them: a source and destinations as vertex numbers, or as
// a face and barycentric coordinates ("face 12 0.2 0.3 0.5"). The parser is pure (checked against the
// mesh's vertex and face counts, every mistake named); the form applies what it reads as a click
// would: the source moves, the destinations are added.

// One entry: "face F b0 b1 b2" (or "f F (b0, b1, b2)"), or a vertex number.
const ENTRY = /^(?:f(?:ace)?\s*(\d+)\s*\(?\s*([^\s,()]+)[\s,]+([^\s,()]+)[\s,]+([^\s,()]+)\s*\)?|(\d+))/i;
const SEPARATOR = /^[\s,;]+/;

/**
 * The surface points in `text`, in order: { vertex } or { face, bary } (bary normalized to sum 1), in
 * the core's numbering. counts: { vertices, faces, base } of the mesh — base: the first number as the
 * file counts (1 for OBJ, 0 otherwise), what the user types. Throws an Error naming the first bad entry.
 */
export function parsePoints(text, { vertices, faces, base = 0 }) {
  const points = [];
  let rest = String(text).trim();
  while (rest.length) {
    const match = ENTRY.exec(rest);
    if (!match)
      throw new Error(`cannot read "${rest.split(/[,;]/)[0].trim()}": write a vertex number or "face F b0 b1 b2"`);
    const [whole, face, b0, b1, b2, vertex] = match;
    if (vertex !== undefined) {
      const v = Number(vertex);
      if (v < base || v >= vertices + base) {
        throw new Error(`vertex ${v} does not exist: the mesh has vertices ${base} to ${vertices - 1 + base}`);
      }
      points.push({ vertex: v - base });
    } else {
      const f = Number(face);
      if (f < base || f >= faces + base)
        throw new Error(`face ${f} does not exist: the mesh has faces ${base} to ${faces - 1 + base}`);
      const bary = [b0, b1, b2].map(Number);
      const total = bary[0] + bary[1] + bary[2];
      if (bary.some((b) => !Number.isFinite(b) || b < 0) || !(total > 0)) {
        throw new Error(`face ${f}: barycentric coordinates must be three numbers ≥ 0, not all 0`);
      }
      points.push({ face: f - base, bary: bary.map((b) => b / total) });
    }
    rest = rest.slice(whole.length);
    if (rest.length) {
      const separator = SEPARATOR.exec(rest);
      if (!separator) throw new Error(`after "${whole}": separate entries with commas or spaces`);
      rest = rest.slice(separator[0].length);
    }
  }
  return points;
}

/**
 * The form (#point-entry): counts() → { vertices, faces } of the mesh on display or null;
 * apply({ source (a point or null: unchanged), destinations (points to add) }); both fields may be
 * filled at once.
 */
export function createPointEntry({ counts, apply }) {
  const $ = (id) => document.getElementById(id);
  const error = $('point-entry-error');
  $('point-entry').addEventListener('submit', (event) => {
    event.preventDefault();
    const mesh = counts();
    if (!mesh) return;
    try {
      const [source, ...extra] = parsePoints($('source-entry').value, mesh);
      if (extra.length) throw new Error('the source is one point');
      const destinations = parsePoints($('targets-entry').value, mesh);
      error.hidden = true;
      error.textContent = '';
      $('targets-entry').value = ''; // added: typing them again would add them twice
      apply({ source: source ?? null, destinations });
    } catch (err) {
      error.textContent = err.message;
      error.hidden = false;
    }
  });
}
