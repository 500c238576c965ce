// The threaded WebAssembly module (Emscripten pthreads) through the npm API: which module
// createStraightest loads and how many threads it reports (st.threads), results bit-identical for any
// thread count and to the single-threaded module (the core's chunking does not depend on the count),
// and cancelling from a progress callback while other threads run chunks.
import assert from 'node:assert/strict';
import { availableParallelism } from 'node:os';
import { test } from 'node:test';
import { createStraightest, StraightestError } from '../../wasm/index.js';
import { createStraightest as createInline } from '../../wasm/inline.js';

/**
 * A height field over [-1, 1]² (n × n vertices, two triangles per cell) with a rectangular hole: two
 * boundary loops, and enough vertices for several chunks of every threaded loop.
 */
function heightField(n) {
  const positions = [];
  for (let j = 0; j < n; ++j) {
    for (let i = 0; i < n; ++i) {
      const x = -1 + (2 * i) / (n - 1);
      const y = -1 + (2 * j) / (n - 1);
      positions.push(x, y, 0.3 * Math.sin(2 * x) * Math.cos(3 * y) + 0.1 * x * y);
    }
  }
  const hole = (i, j) => i >= n / 2 && i < n / 2 + n / 8 && j >= n / 4 && j < n / 4 + n / 8;
  const indices = [];
  for (let j = 0; j + 1 < n; ++j) {
    for (let i = 0; i + 1 < n; ++i) {
      if (hole(i, j)) continue;
      const a = j * n + i;
      indices.push(a, a + 1, a + n + 1, a, a + n + 1, a + n);
    }
  }
  return { positions: new Float64Array(positions), indices: new Int32Array(indices) };
}

/** A typed array's bytes: equal bytes are equal bits (NaN payloads and -0 included). */
const bits = (array) => Buffer.from(array.buffer, array.byteOffset, array.byteLength);

function assertSameBits(actual, expected, what) {
  assert.equal(actual.length, expected.length, `${what}: length`);
  assert.ok(bits(actual).equals(bits(expected)), `${what}: not bit-identical`);
}

const FIELD = heightField(130); // 16 900 vertices: more than one chunk of the interior weights

function allBoundaryPaths(st) {
  const mesh = st.meshFromArrays(FIELD.positions, FIELD.indices);
  try {
    return mesh.straightestPaths({ targets: 'all-boundaries' });
  } finally {
    mesh.delete();
  }
}

function measuredMap(st) {
  const mesh = st.meshFromArrays(FIELD.positions, FIELD.indices);
  try {
    return mesh.parameterize({ boundary: 'measured' });
  } finally {
    mesh.delete();
  }
}

test('st.threads: every core by default in Node, the count asked for, 1 for the single-threaded module', async () => {
  assert.equal((await createStraightest()).threads, Math.min(availableParallelism(), 64));
  assert.equal((await createStraightest({ threads: 2 })).threads, 2);
  assert.equal((await createStraightest({ threads: 3 })).threads, 3, 'more threads than cores is allowed');
  assert.equal((await createStraightest({ threads: 1 })).threads, 1);
  // straightest/inline and explicit bytes load the single-threaded module.
  assert.equal((await createInline({ threads: 2 })).threads, 1);
  const inline = await createInline();
  assert.equal(inline.threads, 1);
  for (const threads of [-1, 1.5, '2']) {
    await assert.rejects(
      createStraightest({ threads }),
      (e) => e instanceof StraightestError && e.category === 'invalid_argument',
    );
  }
  // The count can be lowered and raised again, up to the count the module was loaded with.
  const st = await createStraightest({ threads: 2 });
  st.threads = 1;
  assert.equal(st.threads, 1);
  st.threads = 2;
  assert.equal(st.threads, 2);
  for (const count of [0, 3, 1.5]) {
    assert.throws(
      () => {
        st.threads = count;
      },
      (e) => e instanceof StraightestError && e.category === 'invalid_argument',
    );
  }
  assert.throws(
    () => {
      inline.threads = 2;
    },
    (e) => e.category === 'invalid_argument',
  );
});

test('all-boundary paths on a height field are bit-identical for 1, 2 and 3 threads and the single-threaded module', async () => {
  const single = allBoundaryPaths(await createStraightest({ threads: 1 }));
  assert.ok(single.lengths.length > 400, `${single.lengths.length} paths`);
  // Targets behind the hole are not reached by a cutting plane; the outer loop's are.
  assert.ok(single.reached > single.count / 2, `${single.reached} of ${single.count} reached`);
  const threaded = await createStraightest({ threads: 3 });
  for (const threads of [3, 2, 1]) {
    threaded.threads = threads;
    const paths = allBoundaryPaths(threaded);
    const what = `${threads} thread(s)`;
    assert.deepEqual(paths.statuses, single.statuses, `${what}: statuses`);
    assertSameBits(paths.lengths, single.lengths, `${what}: lengths`);
    assertSameBits(paths.points, single.points, `${what}: points`);
    assertSameBits(paths.offsets, single.offsets, `${what}: offsets`);
    assertSameBits(paths.directions, single.directions, `${what}: directions`);
    assert.deepEqual(paths.facesCrossed, single.facesCrossed, `${what}: faces crossed`);
  }
});

test('the measured parameterization of a height field is bit-identical for 1 and 2 threads', async () => {
  const single = measuredMap(await createStraightest({ threads: 1 }));
  assert.equal(single.bijective, true);
  const threaded = await createStraightest({ threads: 2 });
  for (const threads of [2, 1]) {
    threaded.threads = threads;
    const map = measuredMap(threaded);
    assertSameBits(map.uv, single.uv, `${threads} thread(s): uv`);
    assertSameBits(map.cornerUv, single.cornerUv, `${threads} thread(s): cornerUv`);
    assertSameBits(map.faceStretch, single.faceStretch, `${threads} thread(s): faceStretch`);
    assert.deepEqual(map.stretch, single.stretch);
    assert.equal(map.bijective, true);
  }
});

test('the threaded module cancels from a progress callback, reports monotone progress, and works on afterwards', async () => {
  const st = await createStraightest({ threads: 2 });
  assert.equal(st.threads, 2);
  const mesh = st.meshFromArrays(FIELD.positions, FIELD.indices);
  try {
    // Paths: cancel at the first report of the trace stage.
    let traceReports = 0;
    assert.throws(
      () =>
        mesh.straightestPaths({
          targets: 'all-boundaries',
          onProgress: (stage) => {
            if (stage === 'trace') traceReports += 1;
            return stage !== 'trace';
          },
        }),
      (e) => e instanceof StraightestError && e.category === 'cancelled',
    );
    assert.equal(traceReports, 1, 'no report after the cancelling one');
    // Parameterization: cancel half way through; an exception thrown by the callback comes back as is.
    assert.throws(
      () => mesh.parameterize({ onProgress: (stage, fraction) => fraction < 0.5 }),
      (e) => e instanceof StraightestError && e.category === 'cancelled',
    );
    const thrown = new Error('stop here');
    assert.throws(
      () =>
        mesh.parameterize({
          onProgress: () => {
            throw thrown;
          },
        }),
      (e) => e === thrown,
    );
    // The same mesh, uncancelled: progress never goes back within a stage, and the results are whole.
    const last = new Map();
    const paths = mesh.straightestPaths({
      targets: 'all-boundaries',
      onProgress: (stage, fraction) => {
        assert.ok(fraction >= (last.get(stage) ?? 0), `${stage}: ${fraction} after ${last.get(stage)}`);
        last.set(stage, fraction);
      },
    });
    assert.equal(last.get('trace'), 1);
    assert.equal(paths.lengths.length, paths.statuses.length);
    assert.equal(mesh.parameterize().bijective, true);
  } finally {
    mesh.delete();
  }
});

test('loads warm up for the first call on a spare thread without changing a result or keeping memory', async () => {
  assert.equal((await createStraightest({ threads: 1 })).warmUp, true); // the default (a no-op on one thread)
  const cold = await createStraightest({ threads: 2, warmUp: false });
  assert.equal(cold.warmUp, false);
  assert.throws(() => {
    cold.warmUp = 'yes';
  }, TypeError);
  await assert.rejects(createStraightest({ threads: 2, warmUp: 1 }), TypeError); // before any worker starts
  const reference = measuredMap(cold);
  const st = await createStraightest({ threads: 2 });
  assert.equal(st.warmUp, true);
  // An OFF file of 70 000 vertices: the heap the warm-up touches (~17 MB) is above its 16 MB floor.
  const n = 265;
  const lines = [`OFF\n${n * n} ${2 * (n - 1) * (n - 1)} 0`];
  for (let j = 0; j < n; ++j)
    for (let i = 0; i < n; ++i)
      lines.push(`${i / (n - 1)} ${j / (n - 1)} ${0.2 * Math.sin(i / 20) * Math.cos(j / 30)}`);
  for (let j = 0; j + 1 < n; ++j) {
    for (let i = 0; i + 1 < n; ++i) {
      const a = j * n + i;
      lines.push(`3 ${a} ${a + 1} ${a + n + 1}`, `3 ${a} ${a + n + 1} ${a + n}`);
    }
  }
  const off = `${lines.join('\n')}\n`;
  // A warmed-up load of the map above (the first call also starts the pool's worker and its stack).
  assertSameBits(measuredMap(st).uv, reference.uv, 'uv after a warmed-up load');
  const heapBefore = st.heapUsedBytes;
  const maps = [true, false].map((warmUp) => {
    st.warmUp = warmUp;
    const mesh = st.loadMesh(off, 'off');
    try {
      assert.equal(mesh.info().vertices, n * n);
      return mesh.parameterize({ boundary: 'measured' });
    } finally {
      mesh.delete();
    }
  });
  assert.equal(maps[0].bijective, true);
  assertSameBits(maps[0].uv, maps[1].uv, 'uv with and without the warm-up');
  // Everything the warm-ups took was given back (the module keeps its grown memory, not allocations).
  assert.equal(st.heapUsedBytes, heapBefore);
});
