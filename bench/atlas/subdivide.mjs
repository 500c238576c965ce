// subdivide.mjs — midpoint 1:4 subdivision of a triangle mesh in OFF, for the atlas benchmark's large meshes
// (xatlasjs takes at most 65,535 vertices; the targets are on 416k and 1M vertices).
//
//   node bench/atlas/subdivide.mjs IN.off OUT.off [LEVELS]
//
// Each level splits every triangle into four at its edge midpoints (one new vertex per edge, shared by the
// edge's two faces), so the surface, its genus and its boundary are unchanged and a closed mesh of V vertices
// gets about 4V. The geometry stays the input's (no smoothing): the charts a mesh needs do not change, only
// the number of triangles in them. Polygons are fan-triangulated first; colours and normals are dropped.
import { readFileSync, writeFileSync } from 'node:fs';
import process from 'node:process';

function readOff(path) {
  const rows = readFileSync(path, 'utf8')
    .split(/\r?\n/)
    .map((l) => l.replace(/#.*/, '').trim())
    .filter((l) => l.length > 0)
    .map((l) => l.split(/\s+/));
  if (/^[A-Z]*OFF$/.test(rows[0][0])) rows[0].shift();
  if (rows[0].length === 0) rows.shift();
  const [nv, nf] = rows[0].map(Number);
  const positions = new Float64Array(3 * nv);
  for (let v = 0; v < nv; ++v) for (let k = 0; k < 3; ++k) positions[3 * v + k] = Number(rows[1 + v][k]);
  const triangles = [];
  for (const row of rows.slice(1 + nv, 1 + nv + nf)) {
    const corners = row.slice(1, 1 + Number(row[0])).map(Number);
    for (let k = 1; k + 1 < corners.length; ++k) triangles.push(corners[0], corners[k], corners[k + 1]);
  }
  return { positions, triangles: Uint32Array.from(triangles) };
}

function subdivideOnce({ positions, triangles }) {
  const nv = positions.length / 3;
  const midpoint = new Map(); // edge key (smaller * nv + larger) → new vertex
  const added = [];
  const mid = (a, b) => {
    const key = Math.min(a, b) * nv + Math.max(a, b);
    let m = midpoint.get(key);
    if (m === undefined) {
      m = nv + added.length / 3;
      midpoint.set(key, m);
      for (let k = 0; k < 3; ++k) added.push((positions[3 * a + k] + positions[3 * b + k]) / 2);
    }
    return m;
  };
  const out = new Uint32Array(4 * triangles.length);
  for (let t = 0; t < triangles.length; t += 3) {
    const [a, b, c] = [triangles[t], triangles[t + 1], triangles[t + 2]];
    const [ab, bc, ca] = [mid(a, b), mid(b, c), mid(c, a)];
    out.set([a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca], 4 * t);
  }
  const grown = new Float64Array(positions.length + added.length);
  grown.set(positions);
  grown.set(added, positions.length);
  return { positions: grown, triangles: out };
}

function writeOff(path, { positions, triangles }) {
  const parts = [`OFF\n${positions.length / 3} ${triangles.length / 3} 0\n`];
  const g = (x) => String(Number(x.toPrecision(9)));
  let chunk = [];
  const flush = () => {
    parts.push(chunk.join(''));
    chunk = [];
  };
  for (let v = 0; v < positions.length; v += 3) {
    chunk.push(`${g(positions[v])} ${g(positions[v + 1])} ${g(positions[v + 2])}\n`);
    if (chunk.length === 65536) flush();
  }
  for (let t = 0; t < triangles.length; t += 3) {
    chunk.push(`3 ${triangles[t]} ${triangles[t + 1]} ${triangles[t + 2]}\n`);
    if (chunk.length === 65536) flush();
  }
  flush();
  writeFileSync(path, parts.join(''));
}

const [input, output, levelsArg] = process.argv.slice(2);
if (!input || !output) {
  process.stderr.write('usage: node bench/atlas/subdivide.mjs IN.off OUT.off [LEVELS]\n');
  process.exit(2);
}
let mesh = readOff(input);
for (let level = 0; level < Number(levelsArg ?? 1); ++level) mesh = subdivideOnce(mesh);
writeOff(output, mesh);
process.stdout.write(`${output}: ${mesh.positions.length / 3} vertices, ${mesh.triangles.length / 3} faces\n`);
