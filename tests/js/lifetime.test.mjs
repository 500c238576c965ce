// The package's edges: how a mesh ends (delete, `using`'s Symbol.dispose, use after either), what an
// exception thrown by onProgress leaves behind, how a failed module load reads, and welding a
// non-indexed three.js geometry.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { PlaneGeometry } from 'three';
import { createStraightest, Mesh, Straightest, StraightestError } from '../../wasm/index.js';
import * as inline from '../../wasm/inline.js';
import * as single from '../../wasm/single.js';
import { meshFromBufferGeometry } from '../../wasm/three.js';

const st = await createStraightest();
const disposeKey = Symbol.dispose ?? Symbol.for('Symbol.dispose');

test('Symbol.dispose deletes a mesh, and any later use is a StraightestError', () => {
  const before = st.heapUsedBytes;
  const mesh = st.sample('cap');
  assert.ok(st.heapUsedBytes > before);
  mesh[disposeKey]();
  assert.equal(mesh.deleted, true);
  assert.equal(st.heapUsedBytes, before);
  for (const use of [() => mesh.info(), () => mesh.parameterize(), () => mesh.positions()]) {
    assert.throws(
      use,
      (e) => e instanceof StraightestError && e.category === 'invalid_argument' && /deleted/.test(e.message),
    );
  }
  mesh.delete(); // idempotent
});

test('Mesh and Straightest have no public constructor', () => {
  assert.throws(() => new Mesh(), TypeError);
  assert.throws(() => new Straightest(), TypeError);
});

test('an exception thrown by onProgress reaches the caller as is and leaks nothing in WASM memory', () => {
  const mesh = st.sample('cap');
  const calls = [
    (onProgress) => mesh.straightestPaths({ onProgress }),
    (onProgress) => mesh.parameterize({ onProgress }),
    (onProgress) => mesh.parameterize({ boundary: 'free', maxIterations: 2, onProgress }),
    (onProgress) => mesh.boundaryPolygons({ onProgress }),
    (onProgress) => mesh.compareParameterizations({ boundaries: ['circle'], weights: ['uniform'], onProgress }),
  ];
  const boom = new RangeError('from the progress callback');
  for (const call of calls) {
    const throwing = () => {
      throw boom;
    };
    // Warm-up, not measured: a call that completes starts the threaded module's pool (its threads
    // allocate their thread-local data once, when they first run, at a moment of their choosing), then
    // throwing calls let every one-time allocation happen before the count starts.
    call(() => true);
    for (let i = 0; i < 20; ++i)
      assert.throws(
        () => call(throwing),
        (e) => e === boom,
      );
    const before = st.heapUsedBytes;
    for (let i = 0; i < 50; ++i)
      assert.throws(
        () => call(throwing),
        (e) => e === boom,
      );
    assert.equal(
      st.heapUsedBytes,
      before,
      `${call}: WASM heap grew by ${st.heapUsedBytes - before} bytes over 50 calls`,
    );
  }
  // The mesh still works, and an onProgress that returns false still cancels.
  assert.equal(mesh.parameterize().bijective, true);
  assert.throws(
    () => mesh.parameterize({ onProgress: () => false }),
    (e) => e.category === 'cancelled',
  );
  mesh.delete();
});

test('a module that cannot be loaded is a StraightestError io naming the URL and what came back', async () => {
  const missing = new URL('./no-such-module.wasm', import.meta.url).href;
  await assert.rejects(
    createStraightest({ wasmUrl: missing }),
    (e) => e instanceof StraightestError && e.category === 'io' && e.message.includes(missing),
  );
  const html = new TextEncoder().encode('<!doctype html><title>index</title>');
  await assert.rejects(
    createStraightest({ wasmBinary: html }),
    (e) => e.category === 'io' && /3c 21 64 6f/.test(e.message) && /HTML page/.test(e.message),
  );
  const truncated = new Uint8Array([0x00, 0x61, 0x73, 0x6d, 1, 0, 0, 0, 9]);
  await assert.rejects(
    createStraightest({ wasmBinary: truncated }),
    (e) => e.category === 'io' && /wasmBinary/.test(e.message),
  );
});

test('in Node a file: URL is read from disk even where a window is defined (jsdom)', async () => {
  globalThis.window = globalThis;
  try {
    const url = new URL('../../wasm/dist/straightest-core.wasm', import.meta.url);
    const loaded = await createStraightest({ wasmUrl: url });
    assert.deepEqual(loaded.sampleNames(), st.sampleNames());
    const fromDefault = await createStraightest();
    assert.equal(fromDefault.sample('cap').info().faces, st.sample('cap').info().faces);
  } finally {
    delete globalThis.window;
  }
});

test('straightest/inline loads the embedded module with the same API', async () => {
  const embedded = await inline.createStraightest();
  assert.equal(inline.StraightestError, StraightestError);
  const mesh = embedded.sample('mountain');
  assert.equal(mesh.info().vertices, 2500);
  mesh.delete();
});

test('straightest/single loads the single-threaded module with the same API, and says so when threads are asked', async () => {
  const one = await single.createStraightest({ threads: 4 });
  assert.equal(single.StraightestError, StraightestError);
  assert.equal(one.threads, 1);
  assert.match(one.threadsUnavailable, /single-threaded module only/);
  const mesh = one.sample('mountain');
  assert.equal(mesh.info().vertices, 2500);
  assert.equal(mesh.parameterize().bijective, true);
  mesh.delete();
  assert.equal((await single.createStraightest({ threads: 1 })).threadsUnavailable, null);
});

test('a non-indexed geometry welds into one disk; unwelded, the topology error says why', () => {
  const soup = new PlaneGeometry(1, 1, 6, 6).toNonIndexed(); // 72 triangles sharing no vertex
  const apart = meshFromBufferGeometry(st, soup);
  assert.equal(apart.info().components, 72);
  assert.throws(
    () => apart.parameterize(),
    (e) => e.category === 'topology' && /weld: true/.test(e.message),
  );
  apart.delete();
  const welded = meshFromBufferGeometry(st, soup, { weld: true });
  const info = welded.info();
  assert.equal(info.vertices, 49);
  assert.equal(info.components, 1);
  assert.deepEqual(info.boundaryLoops, [24]);
  assert.equal(welded.parameterize().bijective, true);
  welded.delete();
  assert.throws(() => meshFromBufferGeometry(st, soup, { weld: -1 }), RangeError);
});
