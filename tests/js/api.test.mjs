// The npm API as a user sees it: load, info, typed arrays, errors as Errors with messages, lifetime.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { createStraightest, StraightestError } from '../../wasm/index.js';

const st = await createStraightest();
const fixture = (name) => readFile(new URL(`../data/${name}`, import.meta.url));

test('loads an OBJ from bytes and reports its topology', async () => {
  const mesh = st.loadMesh(await fixture('good/quad_grid.obj'), 'obj');
  const info = mesh.info();
  assert.equal(info.vertices, 9);
  assert.equal(info.faces, 8);
  assert.deepEqual(info.boundaryLoops, [8]);
  assert.equal(info.eulerCharacteristic, 1);
  assert.deepEqual(info.bbox, { min: [0, 0, 0], max: [2, 2, 0] });
  mesh.delete();
});

test('loads an OFF with format auto-detection', async () => {
  const mesh = st.loadMesh(await fixture('good/tetrahedron.off'));
  assert.equal(mesh.info().eulerCharacteristic, 2);
  assert.deepEqual(mesh.info().boundaryLoops, []);
  mesh.delete();
});

test('positions and indices are typed-array copies in file order', () => {
  const mesh = st.meshFromArrays(
    new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0]),
    new Uint32Array([0, 1, 2, 1, 3, 2]),
  );
  const p = mesh.positions();
  const i = mesh.indices();
  assert.ok(p instanceof Float64Array);
  assert.ok(i instanceof Uint32Array);
  assert.deepEqual(Array.from(p), [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0]);
  assert.deepEqual(Array.from(i), [0, 1, 2, 1, 3, 2]);
  mesh.delete();
  assert.equal(p[3], 1, 'copies stay valid after delete');
});

test('reports reoriented faces', async () => {
  const mesh = st.loadMesh(await fixture('good/inconsistent.obj'), 'obj');
  assert.equal(mesh.info().reorientedFaces, 2);
  mesh.delete();
});

test('built-in samples come from the core', () => {
  assert.deepEqual(st.sampleNames(), ['mountain', 'cap', 'saddle', 'face', 'holes', 'sphere', 'torus']);
  const mesh = st.sample('mountain');
  assert.equal(mesh.info().vertices, 2500);
  mesh.delete();
  assert.throws(
    () => st.sample('teapot'),
    (e) => e instanceof Error && /unknown sample 'teapot'/.test(e.message),
  );
});

test('a malformed file throws an Error carrying the core message and category', async () => {
  const bytes = await fixture('bad/index_out_of_range.obj');
  assert.throws(
    () => st.loadMesh(bytes, 'obj'),
    (e) => {
      assert.ok(e instanceof Error);
      assert.ok(e instanceof StraightestError);
      assert.equal(e.category, 'index_out_of_range');
      assert.match(e.message, /line 4: face 0 refers to vertex 9/);
      return true;
    },
  );
});

test('every malformed category arrives as an Error, never a number', async () => {
  const cases = {
    'bad/moebius.obj': 'non_orientable',
    'bad/nonmanifold_edge.obj': 'non_manifold_edge',
    'bad/nonmanifold_vertex.obj': 'non_manifold_vertex',
    'bad/nan.obj': 'non_finite',
    'bad/garbage.bin': 'unsupported_format',
    'bad/empty.obj': 'empty',
    'bad/off_header_lies.off': 'too_large',
    'bad/duplicate_face.obj': 'duplicate_face',
  };
  for (const [file, category] of Object.entries(cases)) {
    const bytes = await fixture(file);
    assert.throws(
      () => st.loadMesh(bytes),
      (e) => e instanceof Error && e.category === category && e.message.length > 0,
      file,
    );
  }
});

test('bad arguments are Errors with messages', () => {
  assert.throws(() => st.loadMesh('v 0 0 0', 'gltf'), /unknown mesh format 'gltf'/);
  assert.throws(() => st.loadMesh('v 0 0 0', 'stl'), /binary STL needs at least 84 bytes/);
  assert.throws(() => st.loadMesh(42), TypeError);
  assert.throws(() => st.meshFromArrays([0, 0, 0, 1, 0], [0, 1, 2]), /not a multiple of 3/);
  for (const notArrays of [
    [null, [0, 1, 2]],
    [[0, 0, 0], undefined],
    ['0 0 0', [0]],
    [3, [0]],
  ])
    assert.throws(() => st.meshFromArrays(...notArrays), TypeError);
  // Elements that are no numbers fail in JavaScript, before the module: nothing is left allocated in it.
  const heapBefore = st.heapUsedBytes;
  const triangle = [0, 0, 0, 1, 0, 0, 0, 1, 0];
  const throwing = new Proxy([0, 1, 2], {
    get: (t, key) => {
      if (key === '1') throw new RangeError('no element');
      return t[key];
    },
  });
  assert.throws(() => st.meshFromArrays(triangle, new BigInt64Array(3)), TypeError);
  assert.throws(() => st.meshFromArrays(triangle, [0n, 1n, 2n]), TypeError);
  assert.throws(() => st.meshFromArrays([Symbol('x'), 0, 0], [0, 1, 2]), TypeError);
  assert.throws(() => st.meshFromArrays(triangle, throwing), /no element/);
  assert.equal(st.heapUsedBytes, heapBefore);
  const fromTyped = st.meshFromArrays(new Float32Array(triangle), new Uint32Array([0, 1, 2]));
  assert.equal(fromTyped.info().faces, 1);
  fromTyped.delete();
  assert.throws(() => st.meshFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 1.5]), /not a vertex index/);
  assert.throws(
    () => st.meshFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2], { maxVertices: 2 }),
    (e) => e.category === 'too_large',
  );
});

test('a misspelt or unknown option is refused, not ignored for the default', async () => {
  const invalid = (e) => e instanceof StraightestError && e.category === 'invalid_argument';
  const mesh = st.sample('cap');
  try {
    assert.throws(
      () => mesh.parameterize({ boundry: 'free' }),
      (e) => invalid(e) && /unknown option 'boundry'/.test(e.message),
    );
    assert.throws(
      () => mesh.parameterize('free'),
      (e) => invalid(e) && /object of options/.test(e.message),
    );
    assert.throws(() => mesh.parameterize(null), invalid);
    assert.throws(() => mesh.straightestPaths({ target: 'boundary' }), invalid);
    assert.throws(() => mesh.exactShortestPaths([0]), invalid);
    assert.throws(() => mesh.shootGeodesic({ angle: 0, lenght: 1 }), invalid);
    assert.throws(() => mesh.boundaryPolygons({ boundary: 'free' }), invalid);
    assert.throws(() => mesh.compareParameterizations({ boundary: 'circle' }), invalid);
    // Known names, undefined values included, are taken as before.
    assert.equal(mesh.parameterize({ boundary: 'circle', maxIterations: undefined }).boundary, 'circle');
  } finally {
    mesh.delete();
  }
  const triangle = 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n';
  assert.throws(() => st.loadMesh(triangle, 'off', { maxVerts: 1 }), invalid);
  for (const cap of [-1, 0, 1.5, NaN, '3'])
    assert.throws(
      () => st.loadMesh(triangle, 'off', { maxVertices: cap }),
      (e) => invalid(e) && /maxVertices must be a positive integer/.test(e.message),
    );
  assert.throws(() => st.meshFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2], { maxFaces: -2 }), invalid);
  await assert.rejects(createStraightest({ thread: 1 }), invalid);
});

test('use after delete throws an Error; delete is idempotent', () => {
  const mesh = st.sample('cap');
  mesh.delete();
  assert.equal(mesh.deleted, true);
  assert.doesNotThrow(() => mesh.delete());
  assert.throws(() => mesh.info(), /has been deleted/);
  assert.throws(() => mesh.positions(), /has been deleted/);
});

test('10,000 meshes created and deleted leave the WASM heap at its baseline', () => {
  const text = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n';
  for (let i = 0; i < 100; ++i) st.loadMesh(text).delete(); // warm up allocator free lists
  const baseline = st.heapUsedBytes;
  const reserved = st.memoryBytes;
  for (let i = 0; i < 10000; ++i) {
    const mesh = i % 2 ? st.loadMesh(text) : st.meshFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2]);
    mesh.info();
    mesh.positions();
    mesh.delete();
  }
  // Failed loads must not leak either.
  for (let i = 0; i < 1000; ++i) assert.throws(() => st.loadMesh('v 0 0 0\nf 1 2 3\n'));
  assert.equal(st.heapUsedBytes, baseline, 'bytes still allocated after deleting every mesh');
  assert.equal(st.memoryBytes, reserved, 'WASM memory grew while meshes were deleted');
});
