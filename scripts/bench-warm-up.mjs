// The load's warm-up (st.warmUp) against none, through the npm API under Node with the threaded module
// on 2 threads, on n × n height fields given as an OBJ file's text (loadMesh) and as arrays
// (meshFromArrays):
//   first  — a fresh process's load and its first measured-boundary parameterize (where the warm-up is
//            meant to pay): the least of REPEATS processes, each measurement in a process of its own;
//   cycles — CYCLES loads + parameterize + delete in one process after as many unmeasured ones (what an
//            app that loads many small meshes sees): the median cycle.
// It shows where the warm-up pays, which sets the size below which loads do without it
// (wasm/straightest.js, WARM_UP_MIN_VERTICES and WARM_UP_MIN_BYTES; docs/BENCHMARKS.md).
//
//   node scripts/bench-warm-up.mjs [SIDES=31,71,100,141,224,316]      (REPEATS=5, CYCLES=100)
import { execFileSync } from 'node:child_process';

/** An n × n height field's OBJ text and arrays (vertices on [-1, 1]², two triangles per cell). */
function heightField(n) {
  const positions = new Float64Array(3 * n * n);
  const lines = [];
  for (let j = 0, k = 0; j < n; ++j) {
    for (let i = 0; i < n; ++i, k += 3) {
      const x = -1 + (2 * i) / (n - 1);
      const y = -1 + (2 * j) / (n - 1);
      const z = 0.3 * Math.sin(2 * x) * Math.cos(3 * y);
      positions.set([x, y, z], k);
      lines.push(`v ${x.toFixed(6)} ${y.toFixed(6)} ${z.toFixed(6)}`);
    }
  }
  const indices = new Int32Array(6 * (n - 1) * (n - 1));
  for (let j = 0, k = 0; j + 1 < n; ++j) {
    for (let i = 0; i + 1 < n; ++i, k += 6) {
      const a = j * n + i;
      indices.set([a, a + 1, a + n + 1, a, a + n + 1, a + n], k);
      lines.push(`f ${a + 1} ${a + 2} ${a + n + 2}`, `f ${a + 1} ${a + n + 2} ${a + n + 1}`);
    }
  }
  return { obj: lines.join('\n') + '\n', positions, indices };
}

function timed(call) {
  const start = performance.now();
  const value = call();
  return { ms: performance.now() - start, value };
}

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];

/** One measurement in this process: { loadMs, paramMs, bytes } (first), or the median cycle's (cycles). */
async function measureHere(mode, side, warmUp, source) {
  const { createStraightest } = await import('../wasm/index.js');
  const st = await createStraightest({ threads: 2, warmUp });
  const { obj, positions, indices } = heightField(side);
  const cycle = () => {
    const load = timed(() => (source === 'obj' ? st.loadMesh(obj, 'obj') : st.meshFromArrays(positions, indices)));
    const param = timed(() => load.value.parameterize({ boundary: 'measured' }));
    load.value.delete();
    return { loadMs: load.ms, paramMs: param.ms, bytes: obj.length };
  };
  if (mode === 'first') return cycle();
  const cycles = Number(process.env.CYCLES ?? 100);
  for (let i = 0; i < cycles; ++i) cycle();
  const runs = Array.from({ length: cycles }, cycle);
  return { loadMs: median(runs.map((r) => r.loadMs)), paramMs: median(runs.map((r) => r.paramMs)), bytes: obj.length };
}

/** { load, param, total, bytes } in ms: the least of REPEATS fresh processes (first) or one process (cycles). */
function measure(mode, side, warmUp, source) {
  const repeats = mode === 'first' ? Number(process.env.REPEATS ?? 5) : 1;
  const runs = [];
  for (let r = 0; r < repeats; ++r) {
    const args = [process.argv[1], '--one', mode, String(side), String(warmUp), source];
    runs.push(JSON.parse(execFileSync(process.execPath, args, { encoding: 'utf8' })));
  }
  const least = (key) => Math.min(...runs.map(key));
  return {
    load: least((r) => r.loadMs),
    param: least((r) => r.paramMs),
    total: least((r) => r.loadMs + r.paramMs),
    bytes: runs[0].bytes,
  };
}

if (process.argv[2] === '--one') {
  const [mode, side, warmUp, source] = process.argv.slice(3);
  console.log(JSON.stringify(await measureHere(mode, Number(side), warmUp === 'true', source)));
} else {
  const sides = (process.argv[2] ?? '31,71,100,141,224,316').split(',').map(Number);
  const ms = (v) => v.toFixed(2).padStart(9);
  console.log('threaded module on 2 threads, ms; first: least of REPEATS fresh processes; cycles: median cycle');
  console.log(
    'mode    source  vertices     bytes | warm-up: load     param     total | none: load     param     total',
  );
  for (const mode of ['first', 'cycles']) {
    for (const source of ['obj', 'arrays']) {
      for (const side of sides) {
        if (mode === 'cycles' && side * side > 20000) continue; // many loads of large meshes: not the case in question
        const on = measure(mode, side, true, source);
        const off = measure(mode, side, false, source);
        const bytes = source === 'obj' ? String(on.bytes) : '-';
        console.log(
          `${mode.padEnd(7)} ${source.padEnd(7)} ${String(side * side).padStart(8)} ${bytes.padStart(9)} |` +
            `         ${ms(on.load)} ${ms(on.param)} ${ms(on.total)} |      ${ms(off.load)} ${ms(off.param)} ${ms(off.total)}`,
        );
      }
    }
  }
}
