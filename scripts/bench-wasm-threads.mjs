// The WebAssembly modules' threads under Node, through the npm API: all-boundary straightest paths and
// the measured-boundary parameterization of the n × n height field (bench_stages' heightfield:n, built
// here in JavaScript) with the single-threaded module, and with the threaded module at 1 and 2 threads
// and at 2 threads without the load's warm-up (st.warmUp = false). One process per variant (peak memory
// is per module); times are the median of REPEATS warm calls after one first call, which is reported too. Writes the table into docs/BENCHMARKS.md's section
// "## Threads in WebAssembly" (replacing it, or appending it when missing).
//
//   node scripts/bench-wasm-threads.mjs [SIDE=1000]      (REPEATS=3; NO_WRITE=1 only prints)
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { availableParallelism, cpus } from 'node:os';
import { fileURLToPath } from 'node:url';
import { mergeSections } from './doc-sections.mjs';

const repeats = Number(process.env.REPEATS ?? 3);

/** bench_stages' heightfield:n (samples.cpp makeHeightField: mountainHeight, alternating diagonals). */
function heightField(n) {
  const bump = (x, y, cx, cy, s, h) => h * Math.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2 * s * s));
  const positions = new Float64Array(3 * n * n);
  for (let j = 0, k = 0; j < n; ++j) {
    for (let i = 0; i < n; ++i, k += 3) {
      const x = -1 + (2 * i) / (n - 1);
      const y = -1 + (2 * j) / (n - 1);
      positions[k] = x;
      positions[k + 1] = y;
      positions[k + 2] =
        bump(x, y, 0.1, 0.05, 0.35, 0.8) + bump(x, y, -0.5, 0.45, 0.25, 0.45) + bump(x, y, 0.55, -0.5, 0.2, 0.35);
    }
  }
  const indices = new Int32Array(6 * (n - 1) * (n - 1));
  for (let j = 0, k = 0; j + 1 < n; ++j) {
    for (let i = 0; i + 1 < n; ++i, k += 6) {
      const a = j * n + i;
      const b = a + 1;
      const c = a + n;
      const d = c + 1;
      indices.set((i + j) % 2 === 1 ? [a, b, c, b, d, c] : [a, b, d, a, d, c], k);
    }
  }
  return { positions, indices };
}

function timed(call) {
  const start = performance.now();
  const value = call();
  return { ms: performance.now() - start, value };
}

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];

/** One variant, in this process: { first/median ms of traces and param, paths, bijective, memory }. */
async function measure(variant, side) {
  const { createStraightest } = await import('../wasm/index.js');
  const st = await createStraightest({ threads: variant === 'single' ? 1 : 2, warmUp: variant !== 'threaded-2-cold' });
  if (variant === 'threaded-1') st.threads = 1;
  const { positions, indices } = heightField(side);
  const load = timed(() => st.meshFromArrays(positions, indices));
  const mesh = load.value;
  const stage = (call) => {
    const first = timed(call);
    const warm = Array.from({ length: repeats }, () => timed(call).ms);
    return { first: first.ms, median: median(warm), value: first.value };
  };
  // The source found once: the calls time the base plane and the traces, not the default source's search.
  const source = { vertex: mesh.defaultSource() };
  const traces = stage(() => mesh.straightestPaths({ source, targets: 'all-boundaries', points: false }));
  const param = stage(() => mesh.parameterize({ boundary: 'measured' }));
  const result = {
    variant,
    threads: st.threads,
    warmUp: st.warmUp && st.threads > 1,
    loadMs: load.ms,
    vertices: positions.length / 3,
    paths: traces.value.count,
    reached: traces.value.reached,
    tracesFirst: traces.first,
    traces: traces.median,
    paramFirst: param.first,
    param: param.median,
    bijective: param.value.bijective,
    memoryMB: st.memoryBytes / 2 ** 20,
  };
  mesh.delete();
  return result;
}

if (process.argv[2] === '--variant') {
  process.stdout.write(`${JSON.stringify(await measure(process.argv[3], Number(process.argv[4])))}\n`);
} else {
  const side = Number(process.argv[2] ?? 1000);
  const self = fileURLToPath(import.meta.url);
  const rows = ['single', 'threaded-1', 'threaded-2', 'threaded-2-cold'].map((variant) => {
    const out = execFileSync(process.execPath, [self, '--variant', variant, String(side)], { encoding: 'utf8' });
    const row = JSON.parse(out.trim().split('\n').pop());
    process.stdout.write(`${variant}: traces ${row.traces.toFixed(0)} ms, param ${row.param.toFixed(0)} ms\n`);
    return row;
  });
  const f = (x) => (x >= 100 ? x.toFixed(0) : x.toFixed(1));
  const names = {
    single: 'single-threaded module',
    'threaded-1': 'threaded module, 1 thread',
    'threaded-2': 'threaded module, 2 threads',
    'threaded-2-cold': 'threaded module, 2 threads, `warmUp: false`',
  };
  const [single] = rows;
  const table = rows
    .map(
      (r) =>
        `| ${names[r.variant]} | ${r.threads} | ${r.warmUp ? 'yes' : 'no'} | ${f(r.loadMs)} | ${f(r.tracesFirst)} | ${f(r.traces)} | ` +
        `${(single.traces / r.traces).toFixed(2)} | ${f(r.paramFirst)} | ${f(r.param)} | ${(single.param / r.param).toFixed(2)} | ` +
        `${r.bijective} | ${f(r.memoryMB)} |`,
    )
    .join('\n');
  const section = `## Threads in WebAssembly

Generated by \`node scripts/bench-wasm-threads.mjs ${side}\` on ${new Date().toISOString().slice(0, 10)} (${availableParallelism()} × ${cpus()[0]?.model ?? 'CPU'}, Node ${process.version}),
through the npm API: heightfield:${side} (${rows[0].vertices} vertices), all-boundary straightest paths from the default source
found beforehand (${rows[0].paths} paths, points not copied out) and the measured-boundary parameterization (all its stages); "load" = \`meshFromArrays\`
(with the warm-up for the first call beside it where "warm-up" says yes: \`st.warmUp\`, the threaded module), "first" = the first call of its kind on the mesh (after the load and the source: the traces, then the parameterization), "warm" = median of the
${repeats} calls after it; speed-up = the single-threaded module's warm time ÷ this row's. One process per row; memory = the
module's WebAssembly memory at the end.

| module | st.threads | warm-up | load ms | traces first ms | traces warm ms | speed-up | param first ms | param warm ms | speed-up | bijective | memory MB |
|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---|---:|
${table}
`;
  process.stdout.write(`\n${section}`);
  const doc = fileURLToPath(new URL('../docs/BENCHMARKS.md', import.meta.url));
  if (!process.env.NO_WRITE && existsSync(doc)) {
    writeFileSync(doc, mergeSections(readFileSync(doc, 'utf8'), section));
    process.stdout.write('wrote docs/BENCHMARKS.md\n');
  }
}
