// node scripts/bench-atlas.mjs — our texture atlas (`straightest atlas`) against xatlas (xatlasjs, WASM) on
// CGAL's sample meshes, closed and holed, every atlas measured by the same measureAtlas
// (core/atlas/include/straightest/atlas/atlas_quality.hpp): ours by the CLI itself, xatlas's by
// build/native/atlas_compare from the per-corner uv bench/atlas/xatlas-run.mjs writes. Then our atlas on
// meshes past xatlasjs's 65,535-vertex limit: armadillo subdivided 1:4 once and twice (bench/atlas/subdivide.mjs),
// man subdivided three times (~1.1M vertices, closed) and heightfield:1000 (1M, a disk).
//
// Prints the tables on stdout (progress on stderr), writes them as the section "Texture atlas vs xatlas" of
// docs/BENCHMARKS.md (WRITE_DOCS=0: not) and every run as a JSON line to build/bench/atlas/runs.jsonl;
// `--report` only rebuilds the tables and the section from that file. Seconds are each tool's whole process (start-up, loading and writing
// included), from outside: min / median over REPEATS runs for ours, one run for xatlas (1–300 s each).
// Each process runs alone (xatlas in Node on one thread; ours natively with --threads 1 and --threads 2).
//
// Environment:
//   REPEATS=3                 runs per (mesh, padding, threads) of ours
//   MESHES="elephant ..."     CGAL sample meshes (data/meshes/NAME.off of libcgal-demo's data archive)
//   PADDINGS="0 2"            ours at each padding (2 is its default, 0 is xatlas's)
//   XATLAS_PADDINGS="0"       xatlas at each padding (its default is 0; add 2 for like against like)
//   XATLAS=1                  0: skip xatlas (then the table has our rows only)
//   BIG=1                     0: skip the large meshes
//   BIG_REPEATS=1             runs per thread count on the large meshes
//   WASM=1                    0: skip the WebAssembly column (see runOursWasm)
//   WRITE_DOCS=1              0: print only
// Takes ~20–25 minutes on 2 loaded cores, most of it xatlas on bunny00 and refined_elephant and the
// subdivision of the large meshes (cached in build/data/atlas).
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync, appendFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { mergeSections } from './doc-sections.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const env = process.env;
const repeats = Number(env.REPEATS ?? 3);
const bigRepeats = Number(env.BIG_REPEATS ?? 1);
const meshNames = (
  env.MESHES ??
  'eight elephant elephant-with-holes cow triceratops dino bull lion-head camel ' +
    'ChineseDragon-10kv mannequin-devil man diplodocus armadillo bunny00 refined_elephant'
)
  .split(/\s+/)
  .filter(Boolean);
const paddings = (env.PADDINGS ?? '0 2').split(/\s+/).filter(Boolean).map(Number);
const xatlasPaddings = (env.XATLAS_PADDINGS ?? '0').split(/\s+/).filter(Boolean).map(Number);
const cli = join(root, 'build/native/straightest');
const compare = join(root, 'build/native/atlas_compare');
const archive = '/usr/share/doc/libcgal-dev/data.tar.gz';
const dataDir = join(root, 'build/data');
const bigDir = join(dataDir, 'atlas');
const outDir = join(root, 'build/bench/atlas');
const runsFile = join(outDir, 'runs.jsonl');
const log = (line) => process.stderr.write(`bench-atlas: ${line}\n`);

// ---------------------------------------------------------------- setup: packages, build, meshes
function setup() {
  execFileSync('bash', [join(root, 'scripts/setup.sh'), 'libcgal-demo'], { stdio: ['ignore', 2, 2] });
  execFileSync('cmake', ['--preset', 'native'], { cwd: root, stdio: ['ignore', 'ignore', 2] });
  execFileSync('cmake', ['--build', '--preset', 'native', '--target', 'straightest', 'atlas_compare'], {
    cwd: root,
    stdio: ['ignore', 'ignore', 2],
  });
  mkdirSync(bigDir, { recursive: true });
  mkdirSync(outDir, { recursive: true });
  writeFileSync(runsFile, '');
}

/** A CGAL sample mesh, extracted from libcgal-demo's archive as scripts/patches.sh does. */
function cgalMesh(name) {
  const file = join(dataDir, 'data/meshes', `${name}.off`);
  if (!existsSync(file)) execFileSync('tar', ['xzf', archive, '-C', dataDir, `data/meshes/${name}.off`]);
  return file;
}

/** NAME subdivided 1:4 LEVELS times (cached). */
function subdivided(name, levels) {
  const file = join(bigDir, `${name}-x${4 ** levels}.off`);
  if (!existsSync(file)) {
    execFileSync(process.execPath, [join(root, 'bench/atlas/subdivide.mjs'), cgalMesh(name), file, String(levels)], {
      stdio: ['ignore', 2, 2],
    });
  }
  return file;
}

// ---------------------------------------------------------------- runs
/** Runs a command as one process and times it from outside (wall clock around spawn → exit). */
/** A mesh's name: its file name without the .off. */
const meshName = (mesh) => mesh.replace(/^.*\//, '').replace(/\.off$/, '');

function timed(cmd, args) {
  const start = process.hrtime.bigint();
  const r = spawnSync(cmd, args, { encoding: 'utf8', maxBuffer: 1 << 28 });
  const seconds = Number(process.hrtime.bigint() - start) / 1e9;
  return { seconds, status: r.status, stdout: r.stdout, stderr: r.stderr };
}

function record(row) {
  appendFileSync(runsFile, `${JSON.stringify({ ...row, load: loadavg()[0] })}\n`);
  return row;
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.floor((s.length - 1) / 2)];
};

/** Ours, native: REPEATS whole-process runs per thread count; the quality of the first (the runs agree). */
function runOurs(mesh, padding, n, threadCounts = [1, 2]) {
  const row = { tool: 'ours', mesh, padding, seconds: {} };
  for (const threads of threadCounts) {
    const times = [];
    for (let k = 0; k < n; ++k) {
      const r = timed(cli, [
        'atlas',
        mesh,
        '--padding',
        String(padding),
        '--threads',
        String(threads),
        '--json-errors',
      ]);
      const out = JSON.parse(r.stdout.trim().split('\n').pop());
      if (out.error) return record({ ...row, error: out.error });
      if (!row.result) row.result = out;
      else if (out.charts !== row.result.charts || out.stretch.l2 !== row.result.stretch.l2)
        row.nondeterministic = true;
      times.push(r.seconds);
      record({ tool: 'ours', mesh, padding, threads, seconds: r.seconds, timings_ms: out.timings_ms });
    }
    row.seconds[`t${threads}`] = { min: Math.min(...times), median: median(times), runs: times.length };
  }
  log(
    `ours ${mesh} padding ${padding}: ${row.result.charts} charts, L2 ${row.result.stretch.l2.toFixed(4)}, ` +
      Object.entries(row.seconds)
        .map(([t, s]) => `${t} ${s.median.toFixed(2)} s`)
        .join(', '),
  );
  return record(row);
}

/**
 * Ours through the npm module on one thread (WebAssembly in Node, like xatlasjs), REPEATS whole-process
 * runs, each recorded with the atlas call's own seconds (the process's first call, as xatlas's is); null
 * (the table says n/a) when the module is not built (npm run build:wasm).
 */
function runOursWasm(mesh, padding) {
  if (env.WASM === '0') return null;
  const script = `
    import { readFileSync } from 'node:fs';
    const { createStraightest } = await import(${JSON.stringify(join(root, 'wasm/index.js'))});
    const st = await createStraightest({ threads: 1 });
    const mesh = st.loadMesh(readFileSync(${JSON.stringify(mesh)}));
    if (typeof mesh.atlas !== 'function') process.exit(3);
    const started = performance.now();
    const result = mesh.atlas({ padding: ${padding} });
    const call = (performance.now() - started) / 1000;
    process.stdout.write(JSON.stringify({ charts: result.charts, l2: result.stretch?.l2, call }) + '\\n');`;
  const runs = [];
  for (let k = 0; k < repeats; ++k) {
    const r = timed(process.execPath, ['--no-experimental-fetch', '--input-type=module', '-e', script]);
    if (r.status !== 0) return null;
    const { call } = JSON.parse(r.stdout.trim().split('\n').pop());
    runs.push(record({ tool: 'ours-wasm', mesh, padding, seconds: r.seconds, call }));
  }
  return wasmSeconds(runs);
}

/** The whole process's seconds and the call's over some runs of ours in WebAssembly (min, median). */
function wasmSeconds(runs) {
  if (runs.length === 0) return null;
  const times = runs.map((r) => r.seconds);
  const calls = runs.map((r) => r.call).filter((c) => typeof c === 'number');
  const call = calls.length ? { min: Math.min(...calls), median: median(calls), runs: calls.length } : null;
  return { min: Math.min(...times), median: median(times), runs: times.length, call };
}

/** xatlas (xatlasjs 0.2.0, WASM in Node, one thread): one whole-process run, measured by atlas_compare. */
function runXatlas(mesh, padding) {
  const json = join(outDir, `xatlas-${meshName(mesh)}-p${padding}.json`);
  const r = timed(process.execPath, [
    join(root, 'bench/atlas/xatlas-run.mjs'),
    mesh,
    json,
    '--padding',
    String(padding),
  ]);
  const c = spawnSync(compare, [json, '--mesh', mesh, '--padding', String(padding)], {
    encoding: 'utf8',
    maxBuffer: 1 << 26,
  });
  const result = JSON.parse(c.stdout.trim().split('\n').pop());
  const call = existsSync(json) ? JSON.parse(readFileSync(json, 'utf8')).seconds : undefined;
  const row = {
    tool: 'xatlas',
    mesh,
    padding,
    seconds: { t1: { min: r.seconds, median: r.seconds, runs: 1 } },
    call: typeof call === 'number' ? { min: call, median: call, runs: 1 } : null,
    result,
  };
  if (result.error) row.error = result.error;
  log(
    `xatlas ${mesh} padding ${padding}: ${row.error ?? `${result.charts} charts, L2 ${result.l2}`}, ${r.seconds.toFixed(1)} s`,
  );
  return record(row);
}

// ---------------------------------------------------------------- table
/** The fields of one row, from the CLI's JSON (ours) or atlas_compare's (xatlas): the same measureAtlas. */
function fields(row) {
  const q = row.result;
  if (row.tool === 'ours') {
    return {
      vertices: null,
      charts: q.charts,
      nonDisk: q.non_disk_charts,
      l2: q.stretch.l2,
      linf: q.stretch.linf,
      utilization: q.utilization,
      flipped: q.flipped,
      degenerate: q.degenerate,
      mirrored: q.mirrored,
      overlaps: q.overlaps,
      gap: q.min_gap_texels,
      size: `${q.width}×${q.height}`,
    };
  }
  return {
    vertices: q.vertices,
    charts: q.charts,
    nonDisk: q.non_disk_charts,
    l2: q.l2,
    linf: q.linf,
    utilization: q.utilization,
    flipped: q.flipped,
    degenerate: q.degenerate,
    mirrored: q.mirrored_charts,
    overlaps: q.overlaps,
    gap: q.min_gap_texels,
    size: `${q.width}×${q.height}`,
  };
}

const num = (x, d) => (typeof x === 'number' && Number.isFinite(x) ? x.toFixed(d) : String(x));
const secs = (s) => (s ? `${num(s.min, s.min < 10 ? 2 : 1)} / ${num(s.median, s.median < 10 ? 2 : 1)}` : '—');

function table(rows, vertexCounts) {
  const lines = [
    '| mesh | vertices | tool, padding | charts | L2 | L∞ | utilization | flipped | degenerate | mirrored charts | overlaps | non-disk charts | min gap (texels) | size | s, 1 thread (min / median) | s, 2 threads | s, WASM 1 thread | s, WASM call |',
    '|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|',
  ];
  for (const row of rows) {
    const name = meshName(row.mesh);
    const label = `${row.tool === 'ours' ? 'ours (native)' : 'xatlas (WASM)'}, ${row.padding}`;
    if (row.error) {
      lines.push(
        `| ${name} | ${vertexCounts[row.mesh] ?? ''} | ${label} | ${String(row.error).replace(/\|/g, '\\|')} ||||||||||||||`,
      );
      continue;
    }
    const f = fields(row);
    const wasm = row.tool === 'xatlas' ? secs(row.seconds.t1) : row.wasm ? secs(row.wasm) : 'n/a';
    const call = row.tool === 'xatlas' ? secs(row.call) : row.wasm ? secs(row.wasm.call) : 'n/a';
    lines.push(
      `| ${name} | ${vertexCounts[row.mesh] ?? ''} | ${label} | ${f.charts} | ${num(f.l2, 4)} | ${num(f.linf, 2)} | ` +
        `${num(f.utilization, 3)} | ${f.flipped} | ${f.degenerate} | ${f.mirrored}${f.charts ? ` (${Math.round((100 * f.mirrored) / f.charts)} %)` : ''} | ` +
        `${f.overlaps} | ${f.nonDisk} | ${num(f.gap, 2)} | ${f.size} | ` +
        `${row.tool === 'ours' ? secs(row.seconds.t1) : '—'} | ${row.tool === 'ours' ? secs(row.seconds.t2) : '—'} | ${wasm} | ${call} |` +
        (row.nondeterministic ? ' ⚠ runs differ' : ''),
    );
  }
  return lines.join('\n');
}

/** A mesh's vertex count from its OFF header (or N² for heightfield:N). */
function vertexCount(mesh) {
  const hf = /^heightfield:(\d+)$/.exec(mesh);
  if (hf) return Number(hf[1]) ** 2;
  const head = readFileSync(mesh, 'utf8')
    .slice(0, 4096)
    .split('\n')
    .map((l) => l.replace(/#.*/, '').trim())
    .filter(Boolean);
  const tokens = head.join(' ').split(/\s+/);
  return Number(/^[A-Z]*OFF$/.test(tokens[0]) ? tokens[1] : tokens[0]);
}

// ---------------------------------------------------------------- report
const isBig = (mesh) => mesh.startsWith('heightfield:') || mesh.startsWith(bigDir);
const targets = [
  { mesh: 'armadillo-x16', what: 'closed 416k-vertex mesh: L2 ≤ 1.05 in < 60 s native', l2: 1.05, seconds: 60 },
  { mesh: 'man-x64', what: '1M-vertex mesh (closed): < 120 s native', seconds: 120 },
  { mesh: 'heightfield:1000', what: '1M-vertex mesh (a disk): < 120 s native', seconds: 120 },
];

/** The issue's targets against the large meshes' rows: met or missed, with the numbers. */
function targetLines(rows) {
  return targets
    .map((t) => {
      const row = rows.find((r) => r.tool === 'ours' && meshName(r.mesh) === t.mesh);
      if (!row) return `- ${t.what}: not run`;
      if (row.error) return `- ${t.what}: **miss** (${row.error})`;
      const fastest = Math.min(...Object.values(row.seconds).map((s) => s.median));
      const l2 = row.result.stretch.l2;
      const met = fastest < t.seconds && (t.l2 === undefined || l2 <= t.l2);
      return (
        `- ${t.what}: ${met ? 'met' : '**miss**'} — L2 ${l2.toFixed(4)}, ` +
        `${Object.entries(row.seconds)
          .map(([k, s]) => `${s.median.toFixed(1)} s on ${k.slice(1)} thread${k === 't1' ? '' : 's'}`)
          .join(', ')}`
      );
    })
    .join('\n');
}

/**
 * The issue's targets over the set of meshes xatlas also runs on: ours at the default padding (2) against
 * xatlas at its default (0) — L2 no higher, utilization ≥ 0.70, and WebAssembly at least 10× faster.
 */
function setTargetLines(rows) {
  const pairs = [];
  for (const ours of rows.filter((r) => r.tool === 'ours' && r.padding === 2 && r.result)) {
    const xatlas = rows.find((r) => r.tool === 'xatlas' && r.mesh === ours.mesh && !r.error);
    if (xatlas) pairs.push({ name: meshName(ours.mesh), ours, xatlas });
  }
  if (pairs.length === 0) return '- not run';
  // (atlas_compare writes an infinite L2 — degenerate faces — as text)
  const theirL2 = (row) => (typeof fields(row).l2 === 'number' ? fields(row).l2 : Infinity);
  const l2Miss = pairs.filter((p) => !(p.ours.result.stretch.l2 <= theirL2(p.xatlas)));
  const util = pairs.map((p) => p.ours.result.utilization);
  const utilMiss = pairs.filter((p) => p.ours.result.utilization < 0.7);
  const timed = pairs.filter((p) => p.ours.wasm);
  const ratios = timed.map((p) => ({ name: p.name, ratio: p.xatlas.seconds.t1.min / p.ours.wasm.min }));
  const slower = ratios.filter((r) => r.ratio < 1);
  const tenfold = ratios.filter((r) => r.ratio >= 10);
  const callRatios = timed
    .filter((p) => p.ours.wasm.call && p.xatlas.call)
    .map((p) => ({ name: p.name, ratio: p.xatlas.call.min / p.ours.wasm.call.min }));
  const names = (list) => list.map((p) => p.name).join(', ');
  const lines = [
    `- L2 ≤ xatlas's on every mesh: ${l2Miss.length ? `**miss** on ${names(l2Miss)}` : 'met'} (${pairs.length} meshes)`,
    `- utilization ≥ 0.70 at padding 2 on every mesh: ${utilMiss.length ? '**miss**' : 'met'} — ` +
      `${pairs.length - utilMiss.length} of ${pairs.length} (${Math.min(...util).toFixed(3)}–${Math.max(...util).toFixed(3)})`,
  ];
  if (ratios.length) {
    const range = ratios.map((r) => r.ratio);
    lines.push(
      `- ≥ 10× faster than xatlasjs, WebAssembly against WebAssembly: ${tenfold.length === ratios.length ? 'met' : '**miss**'} — ` +
        `${tenfold.length} of ${ratios.length} meshes; xatlas's seconds over ours ${Math.min(...range).toFixed(2)}–` +
        `${Math.max(...range).toFixed(1)}×` +
        (slower.length ? `; ours slower on ${names(slower)}` : ''),
    );
  }
  if (callRatios.length) {
    const range = callRatios.map((r) => r.ratio);
    const callSlower = callRatios.filter((r) => r.ratio < 1);
    lines.push(
      `- the same, the atlas call alone (each process's first, after the module's start and the mesh's load): ` +
        `${callRatios.filter((r) => r.ratio >= 10).length} of ${callRatios.length} meshes at ≥ 10×; xatlas's seconds over ` +
        `ours ${Math.min(...range).toFixed(2)}–${Math.max(...range).toFixed(1)}×` +
        (callSlower.length ? `; ours slower on ${names(callSlower)}` : ''),
    );
  }
  return lines.join('\n');
}

/** Our rows that break the atlas's promises (no overlap, every chart a disk, no fold, no mirror, padding kept). */
function oursMisses(rows) {
  const misses = [];
  for (const r of rows.filter((x) => x.tool === 'ours' && x.result)) {
    const q = r.result;
    const what = [
      ['overlaps', q.overlaps],
      ['non-disk charts', q.non_disk_charts],
      ['flipped', q.flipped],
      ['mirrored charts', q.mirrored],
      ['padding violations', q.padding_violations],
    ]
      .filter(([, n]) => n > 0)
      .map(([k, n]) => `${n} ${k}`);
    if (what.length)
      misses.push(
        `- ${meshName(r.mesh)}, padding ${r.padding}: ${what.join(', ')} (min gap ${q.min_gap_texels.toFixed(2)} texels)`,
      );
  }
  return misses.length ? misses.join('\n') : '- none';
}

function report(rows, machine) {
  const vertexCounts = {};
  for (const row of rows)
    vertexCounts[row.mesh] =
      row.result?.vertices ??
      (existsSync(row.mesh) || row.mesh.startsWith('heightfield:') ? vertexCount(row.mesh) : '');
  const small = rows.filter((r) => !isBig(r.mesh));
  const big = rows.filter((r) => isBig(r.mesh));
  const section = `## Texture atlas vs xatlas (scripts/bench-atlas.mjs)

\`node scripts/bench-atlas.mjs\` at commit ${machine.commit ?? '?'} on ${machine.date} (${machine.cpus} × ${machine.model}, shared with other jobs: 1-minute load average ${machine.load} during the runs),
Node ${machine.node}. Ours: \`straightest atlas MESH --padding P --threads T\` (native CLI), ${machine.repeats} runs per
padding and thread count (min / median); xatlas: xatlasjs 0.2.0 (xatlas compiled to WebAssembly, one thread in Node) with
its default options and the padding given, one run (bench/atlas/xatlas-run.mjs). Seconds are each tool's whole process
(start-up, loading the mesh and writing the result included). Every quality column is measureAtlas's
(core/atlas/include/straightest/atlas/atlas_quality.hpp): the CLI's own fields for ours, build/native/atlas_compare on
xatlas's per-corner uv for xatlas, so charts are counted from the uv alone (a cluster of degenerate faces is a chart).
The last two columns are WebAssembly against WebAssembly: ours through the npm module in Node on one thread
(\`createStraightest({ threads: 1 })\`, \`st.loadMesh(bytes)\`, \`mesh.atlas({ padding })\`), a whole process like xatlas's,
${machine.repeats} runs (min / median); then the atlas call alone in that process (its first, so in part before V8's
optimizing tier: the module's start and the mesh's load left out) and xatlas's (its own timer around its calls,
bench/atlas/xatlas-run.mjs). Degenerate faces are faces xatlas leaves unmapped (all corners
at one uv point): they make its L2/L∞ infinite and its min gap 0.

${table(small, vertexCounts)}

### Meshes over xatlasjs's 65,535 vertices

armadillo-xK and man-xK are CGAL's armadillo and man subdivided 1:4 at edge midpoints (bench/atlas/subdivide.mjs; the
surface is unchanged, closed), heightfield:1000 is the CLI's 1M-vertex disk. xatlasjs refuses them (its addMesh copies
the indices to 16 bits). Ours at padding 2, ${machine.bigRepeats} run(s) per thread count; 1-minute load average
${machine.loadBig} during these runs.

${table(big, vertexCounts)}

The issue's targets:

${setTargetLines(small)}
${targetLines(big)}

Our atlases that break its promises (overlap, non-disk chart, fold, mirror or padding violation, as measureAtlas finds them):

${oursMisses(rows)}
`;
  process.stdout.write(`${section}\n`);
  if (env.WRITE_DOCS !== '0') {
    const file = join(root, 'docs/BENCHMARKS.md');
    writeFileSync(
      file,
      mergeSections(readFileSync(file, 'utf8'), section, (a, b) => a.split(' (')[0] === b.split(' (')[0]),
    );
    log('wrote its section of docs/BENCHMARKS.md');
  }
}

// ---------------------------------------------------------------- main
const loadText = () =>
  loadavg()
    .map((x) => x.toFixed(1))
    .join(' ');
function repeatsOf(runs) {
  const counts = new Map();
  for (const r of runs)
    counts.set(`${r.mesh}|${r.padding}|${r.threads}`, (counts.get(`${r.mesh}|${r.padding}|${r.threads}`) ?? 0) + 1);
  return Math.max(0, ...counts.values());
}

/** The machine's state from the runs themselves: the range of the load average each run saw. */
function machineOf(lines) {
  const loadRange = (ls) => {
    const xs = ls.filter((l) => typeof l.load === 'number').map((l) => l.load);
    return xs.length ? `${Math.min(...xs).toFixed(1)}–${Math.max(...xs).toFixed(1)}` : 'n/a';
  };
  const single = lines.filter((l) => l.tool === 'ours' && typeof l.threads === 'number');
  return {
    date: new Date().toISOString().slice(0, 10),
    cpus: cpus().length,
    model: cpus()[0]?.model ?? 'CPU',
    node: process.version,
    load: loadRange(lines.filter((l) => l.mesh && !isBig(l.mesh))),
    loadBig: loadRange(lines.filter((l) => l.mesh && isBig(l.mesh))),
    repeats: repeatsOf(single.filter((l) => !isBig(l.mesh))),
    bigRepeats: repeatsOf(single.filter((l) => isBig(l.mesh))),
  };
}
if (process.argv.includes('--report')) {
  // Only the tables and the docs section, from the last run's build/bench/atlas/runs.jsonl.
  const lines = readFileSync(runsFile, 'utf8')
    .split('\n')
    .filter(Boolean)
    .map((l) => JSON.parse(l));
  const rows = lines.filter((l) => (l.tool === 'ours' || l.tool === 'xatlas') && typeof l.seconds === 'object');
  for (const row of rows.filter((r) => r.tool === 'ours')) {
    const runs = lines.filter((l) => l.tool === 'ours-wasm' && l.mesh === row.mesh && l.padding === row.padding);
    row.wasm = wasmSeconds(runs);
  }
  report(rows, { ...machineOf(lines), ...lines.find((l) => l.tool === 'machine') });
  process.exit(0);
}
setup();
record({
  tool: 'machine',
  commit: execFileSync('git', ['rev-parse', '--short', 'HEAD'], { cwd: root, encoding: 'utf8' }).trim(),
});
log(`${cpus().length} × ${cpus()[0]?.model ?? 'CPU'}, load average ${loadText()}`);
const rows = [];
for (const name of meshNames) {
  const mesh = cgalMesh(name);
  for (const padding of paddings) {
    const row = runOurs(mesh, padding, repeats);
    row.wasm = runOursWasm(mesh, padding);
    rows.push(row);
  }
  if (env.XATLAS !== '0') for (const padding of xatlasPaddings) rows.push(runXatlas(mesh, padding));
}
if (env.BIG !== '0') {
  for (const mesh of [
    subdivided('armadillo', 1),
    subdivided('armadillo', 2),
    subdivided('man', 3),
    'heightfield:1000',
  ]) {
    rows.push(runOurs(mesh, 2, bigRepeats));
    if (env.XATLAS !== '0' && !mesh.startsWith('heightfield:')) rows.push(runXatlas(mesh, 0));
  }
}
const all = readFileSync(runsFile, 'utf8')
  .split('\n')
  .filter(Boolean)
  .map((l) => JSON.parse(l));
report(rows, { ...machineOf(all), ...all.find((l) => l.tool === 'machine') });
log(`runs in ${runsFile}`);
