// xatlas-run.mjs — runs xatlas (xatlasjs, WASM) with its default options on one mesh and writes its atlas as
// per-corner uv aligned with the input's faces, for bench/atlas_compare.cpp to measure.
//
//   node bench/atlas/xatlas-run.mjs MESH.off|obj OUT.json [--padding TEXELS]
//
// --padding sets xatlas's PackOptions.padding (its default, 0, otherwise); every other option is xatlas's default.
// Installs xatlasjs into bench/atlas/node_modules on first use (bench-only: the straightest package never
// lists it). OUT.json: { mesh, vertices, indices, cornerUv, width, height, charts, seconds } with cornerUv
// 3 per input face in [0,1]² (xatlasjs's binding already divides xatlas's texel uv by width and height) and
// charts null (the binding does not report xatlas's chart count: measureAtlas counts the charts from the
// uv), or { mesh, error }.
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import process from 'node:process';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));

/** Installs bench/atlas's own dependencies when they are missing, then loads xatlasjs's Node build. */
async function loadXatlasApi() {
  const dist = join(here, 'node_modules', 'xatlasjs', 'dist', 'node');
  if (!existsSync(join(dist, 'api.mjs'))) {
    execFileSync('npm', ['install', '--prefix', here, '--no-audit', '--no-fund'], { stdio: 'inherit' });
  }
  const { Api } = await import(join(dist, 'api.mjs'));
  const { default: createXAtlasModule } = await import(join(dist, 'xatlas.js'));
  const XatlasApi = Api(createXAtlasModule);
  return new Promise((resolve) => {
    const api = new XatlasApi(
      () => resolve(api),
      (path, dir) => (path === 'xatlas.wasm' ? join(dist, path) : dir + path),
    );
  });
}

/** The non-comment tokens of a text file's lines ('#' starts a comment in both OFF and OBJ). */
function lines(text) {
  return text
    .split(/\r?\n/)
    .map((line) => line.replace(/#.*/, '').trim())
    .filter((line) => line.length > 0);
}

/** Fan-triangulates one polygon (as core's readers do for convex polygons: CGAL's samples are triangles). */
function pushPolygon(indices, corners) {
  for (let k = 1; k + 1 < corners.length; ++k) indices.push(corners[0], corners[k], corners[k + 1]);
}

/** OFF, COFF, NOFF…: a vertex line's first three numbers are its position (colours and normals follow). */
function readOff(text) {
  const rows = lines(text).map((line) => line.split(/\s+/));
  if (/^[A-Z]*OFF$/.test(rows[0][0])) rows[0].shift();
  if (rows[0].length === 0) rows.shift();
  const [nv, nf] = rows[0].map(Number);
  const vertices = rows.slice(1, 1 + nv).flatMap((row) => row.slice(0, 3).map(Number));
  const indices = [];
  for (const row of rows.slice(1 + nv, 1 + nv + nf)) pushPolygon(indices, row.slice(1, 1 + Number(row[0])).map(Number));
  return { vertices, indices };
}

function readObj(text) {
  const vertices = [],
    indices = [];
  for (const line of lines(text)) {
    const [tag, ...rest] = line.split(/\s+/);
    if (tag === 'v') vertices.push(...rest.slice(0, 3).map(Number));
    if (tag === 'f') {
      const nv = vertices.length / 3;
      pushPolygon(
        indices,
        rest.map((c) => {
          const i = parseInt(c, 10);
          return i < 0 ? nv + i : i - 1;
        }),
      );
    }
  }
  return { vertices, indices };
}

function readMesh(path) {
  const text = readFileSync(path, 'utf8');
  return /\.off$/i.test(path) ? readOff(text) : readObj(text);
}

/**
 * Reads xatlas's output for mesh 0 straight from the module's heap: xatlasjs's getAtlas copies the 32-bit
 * output indices into a Uint16Array, which wraps once seams split the mesh past 65,535 vertices.
 */
function readAtlasOutput(module) {
  const data = module.getMeshData(0);
  const u32 = (offset, count) => Uint32Array.from(module.HEAPU32.subarray(offset / 4, offset / 4 + count));
  const index = u32(data.indexOffset, data.newIndexCount);
  const xref = u32(data.originalIndexOffset, data.newVertexCount);
  const uv = Float32Array.from(module.HEAPF32.subarray(data.uvOffset / 4, data.uvOffset / 4 + 2 * data.newVertexCount));
  module.destroyMeshData(data);
  data.subMeshes.delete();
  return { index, xref, uv };
}

/**
 * Per-corner uv in the input's face and corner order: output face f is input face f (xatlas keeps the face
 * order), and each output corner is matched to the input corner whose vertex its xref names.
 */
function cornerUvOfInput(indices, out) {
  if (out.index.length !== indices.length)
    throw new Error(`xatlas returned ${out.index.length / 3} faces for ${indices.length / 3}`);
  const cornerUv = new Array(2 * indices.length);
  for (let c = 0; c < indices.length; c += 3) {
    for (let k = 0; k < 3; ++k) {
      const j = [0, 1, 2].find((m) => out.xref[out.index[c + m]] === indices[c + k]);
      if (j === undefined) throw new Error(`xatlas output face ${c / 3} does not hold input vertex ${indices[c + k]}`);
      const v = out.index[c + j];
      cornerUv[2 * (c + k)] = out.uv[2 * v];
      cornerUv[2 * (c + k) + 1] = out.uv[2 * v + 1];
    }
  }
  return cornerUv;
}

async function run(meshPath, padding) {
  const { vertices, indices } = readMesh(meshPath);
  if (vertices.length / 3 > 65535) {
    return { error: `xatlasjs takes 16-bit indices: ${vertices.length / 3} vertices > 65535` };
  }
  const api = await loadXatlasApi();
  const start = process.hrtime.bigint();
  api.createAtlas();
  if (!api.addMesh(new Uint16Array(indices), new Float32Array(vertices))) return { error: 'Error adding mesh' };
  api.generateAtlas({}, padding === undefined ? {} : { padding }, false);
  const atlas = api.xatlas.getAtlas();
  const out = readAtlasOutput(api.xatlas);
  const seconds = Number(process.hrtime.bigint() - start) / 1e9;
  const { width, height } = atlas;
  return { vertices, indices, cornerUv: cornerUvOfInput(indices, out), width, height, charts: null, seconds };
}

const [meshPath, outPath, ...flags] = process.argv.slice(2);
const padding = flags[0] === '--padding' ? Number(flags[1]) : undefined;
if (!meshPath || !outPath || (flags.length > 0 && !(padding >= 0))) {
  process.stderr.write('usage: node bench/atlas/xatlas-run.mjs MESH.off|obj OUT.json [--padding TEXELS]\n');
  process.exit(2);
}
let result;
try {
  result = await run(meshPath, padding);
} catch (error) {
  result = { error: String(error?.message ?? error) };
}
writeFileSync(outPath, JSON.stringify({ mesh: meshPath, padding: padding ?? 0, ...result }));
process.stdout.write(
  result.error
    ? `${meshPath}: ${result.error}\n`
    : `${meshPath}: ${result.width}x${result.height}, ${result.seconds.toFixed(2)} s\n`,
);
process.exit(result.error ? 1 : 0);
