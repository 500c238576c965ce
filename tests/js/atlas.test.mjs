// Texture atlases through the npm API (mesh.atlas, st.atlas), the worker API and straightest/three's
// unwrap / packAtlas. Every uv property is recomputed here from cornerUv, not read from the result.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { Worker as NodeWorker } from 'node:worker_threads';
import { BufferAttribute, BufferGeometry } from 'three';
import { createStraightest } from '../../wasm/index.js';
import { createStraightestWorker } from '../../wasm/worker.js';
import { meshFromBufferGeometry, packAtlas, toBufferGeometry, unwrap } from '../../wasm/three.js';

const st = await createStraightest();
const fixture = (name) => readFileSync(new URL(`../data/${name}`, import.meta.url), 'utf8');

/** Twice the signed area of uv triangle f (counter-clockwise: positive). */
function signedArea(uv, f) {
  const [ax, ay, bx, by, cx, cy] = uv.subarray(6 * f, 6 * f + 6);
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/**
 * The largest gap between the two uv triangles' projections on any of their edge normals (separating axis):
 * > 0 means they are disjoint, with at least that distance between them.
 */
function separation(uvA, a, uvB, b) {
  const points = (uv, f) => [0, 1, 2].map((k) => [uv[6 * f + 2 * k], uv[6 * f + 2 * k + 1]]);
  const p = points(uvA, a),
    q = points(uvB, b);
  let best = -Infinity;
  for (const tri of [p, q]) {
    for (let k = 0; k < 3; ++k) {
      const [x0, y0] = tri[k],
        [x1, y1] = tri[(k + 1) % 3];
      const length = Math.hypot(x1 - x0, y1 - y0);
      const n = [(y1 - y0) / length, (x0 - x1) / length];
      const project = (pts) => pts.map(([x, y]) => x * n[0] + y * n[1]);
      const [pp, qq] = [project(p), project(q)];
      best = Math.max(best, Math.min(...qq) - Math.max(...pp), Math.min(...pp) - Math.max(...qq));
    }
  }
  return best;
}

/** What every atlas promises, checked on its own uv. */
function assertAtlas(mesh, a, { maxL2 = 1.05 } = {}) {
  const faces = mesh.info().faces;
  assert.ok(a.cornerUv instanceof Float32Array);
  assert.equal(a.cornerUv.length, 6 * faces);
  assert.equal(a.chartOfFace.length, faces);
  assert.ok(
    a.cornerUv.every((x) => x >= 0 && x <= 1),
    'every corner uv in [0, 1]',
  );
  for (let f = 0; f < faces; ++f)
    assert.ok(signedArea(a.cornerUv, f) > 0, `uv triangle ${f} counter-clockwise like its face`);
  assert.ok(a.chartOfFace.every((c) => c >= 0 && c < a.charts));
  assert.equal(new Set(a.chartOfFace).size, a.charts);
  assert.equal(a.chartStretch.length, a.charts);
  for (const name of ['flipped', 'mirrored', 'overlaps', 'paddingViolations', 'nonDiskCharts', 'degenerate']) {
    assert.equal(a[name], 0, name);
  }
  assert.ok(a.stretch.l2 >= 1 - 1e-9 && a.stretch.l2 <= maxL2, `L2 ${a.stretch.l2}`);
  assert.ok(a.stretch.linf >= a.stretch.l2 - 1e-9);
  assert.ok(a.utilization > 0 && a.utilization <= 1);
  assert.equal(a.seam.length, 2 * a.seamEdges);
  assert.ok(a.texelsPerUnit > 0);
  assert.ok(a.timings.total >= 0);
}

/** Every pair of faces in different charts is disjoint in uv (a small mesh: all pairs). */
function assertChartsDisjoint(a) {
  const faces = a.chartOfFace.length;
  for (let f = 0; f < faces; ++f) {
    for (let g = f + 1; g < faces; ++g) {
      if (a.chartOfFace[f] !== a.chartOfFace[g])
        assert.ok(separation(a.cornerUv, f, a.cornerUv, g) > 0, `faces ${f}, ${g}`);
    }
  }
}

test('atlases of closed, holed and disk samples keep every promise', () => {
  for (const name of ['sphere', 'torus', 'holes', 'cap']) {
    const mesh = st.sample(name);
    const a = mesh.atlas();
    assertAtlas(mesh, a);
    assert.equal(a.width, 1024);
    assert.equal(a.height, 1024);
    assert.ok(a.minGapTexels >= 2 || a.charts === 1, `${name}: gap ${a.minGapTexels}`);
    mesh.delete();
  }
});

test('a cube flattens isometrically, its charts disjoint', () => {
  const mesh = st.loadMesh(fixture('good/cube.obj'), 'obj');
  const a = mesh.atlas();
  assertAtlas(mesh, a);
  assert.ok(Math.abs(a.stretch.l2 - 1) < 1e-6, `L2 ${a.stretch.l2}`);
  assert.ok(a.chartStretch.every((s) => Math.abs(s - 1) < 1e-6));
  assertChartsDisjoint(a);
  mesh.delete();
});

test('options reach the core: a rectangle, a padding, no rotation', () => {
  const mesh = st.sample('torus');
  const a = mesh.atlas({ width: 512, height: 256, padding: 4, rotate: false, maxStretch: 1.05, maxCharts: 0 });
  assert.equal(a.width, 512);
  assert.equal(a.height, 256);
  // The core measures stretch on the [0, 1]² uv, which a non-square atlas scales unevenly: not checked here.
  assertAtlas(mesh, a, { maxL2: Infinity });
  assert.ok(a.minGapTexels >= 4);
  const small = mesh.atlas({ resolution: 256 });
  assert.equal(small.width, 256);
  mesh.delete();
});

test('toOBJ writes the atlas cornerUv as vt per corner', () => {
  const mesh = st.loadMesh(fixture('good/cube.obj'), 'obj');
  const a = mesh.atlas();
  const lines = mesh.toOBJ(a.cornerUv).split('\n');
  const vt = lines.filter((l) => l.startsWith('vt ')).map((l) => l.split(' ').slice(1).map(Number));
  const corners = lines
    .filter((l) => l.startsWith('f '))
    .flatMap((l) =>
      l
        .split(' ')
        .slice(1)
        .map((c) => c.split('/').map(Number)),
    );
  const indices = mesh.indices();
  assert.equal(corners.length, indices.length);
  corners.forEach(([v, t], c) => {
    assert.equal(v - 1, indices[c]);
    assert.ok(
      Math.abs(vt[t - 1][0] - a.cornerUv[2 * c]) < 1e-6 && Math.abs(vt[t - 1][1] - a.cornerUv[2 * c + 1]) < 1e-6,
    );
  });
  assert.equal(new Set(corners.map(([, t]) => t)).size, vt.length);
  mesh.delete();
});

test('several meshes share one atlas, split per mesh, their charts disjoint', () => {
  const cube = st.loadMesh(fixture('good/cube.obj'), 'obj');
  const ball = st.loadMesh(fixture('good/icosphere.obj'), 'obj');
  const shared = st.atlas([cube, ball]);
  const [fa, fb] = [cube.info().faces, ball.info().faces];
  assert.equal(shared.meshes.length, 2);
  assert.equal(shared.meshes[0].cornerUv.length, 6 * fa);
  assert.equal(shared.meshes[1].cornerUv.length, 6 * fb);
  assert.equal(shared.meshes[0].chartOfFace.length, fa);
  assert.equal(shared.meshes[1].chartOfFace.length, fb);
  assert.deepEqual(shared.cornerUv, Float32Array.of(...shared.meshes[0].cornerUv, ...shared.meshes[1].cornerUv));
  assert.deepEqual(shared.chartOfFace, Int32Array.of(...shared.meshes[0].chartOfFace, ...shared.meshes[1].chartOfFace));
  const chartsOf = (m) => new Set(m.chartOfFace);
  const [ca, cb] = [chartsOf(shared.meshes[0]), chartsOf(shared.meshes[1])];
  assert.ok(
    [...ca].every((c) => !cb.has(c)),
    'no chart spans two meshes',
  );
  assert.equal(ca.size + cb.size, shared.charts);
  for (let f = 0; f < fa; ++f) {
    for (let g = 0; g < fb; ++g) assert.ok(separation(shared.meshes[0].cornerUv, f, shared.meshes[1].cornerUv, g) > 0);
  }
  // The same as one mesh made of both arrays.
  const positions = Float64Array.of(...cube.positions(), ...ball.positions());
  const offset = cube.info().vertices;
  const both = st.meshFromArrays(
    positions,
    Uint32Array.of(...cube.indices(), ...ball.indices().map((i) => i + offset)),
  );
  const single = both.atlas();
  assertAtlas(both, shared);
  assert.deepEqual(single.cornerUv, shared.cornerUv);
  assert.equal(single.charts, shared.charts);
  for (const m of [cube, ball, both]) m.delete();
});

test('bad options and bad meshes throw with a category', () => {
  const mesh = st.sample('cap');
  const category =
    (c, pattern = /./) =>
    (e) =>
      e.category === c && pattern.test(e.message);
  assert.throws(() => mesh.atlas({ resolutoin: 512 }), category('invalid_argument', /unknown option 'resolutoin'/));
  assert.throws(() => mesh.atlas({ maxStretch: 0.5 }), category('invalid_argument', /maxStretch/));
  assert.throws(() => mesh.atlas({ maxStretch: NaN }), category('invalid_argument', /maxStretch/));
  assert.throws(() => mesh.atlas({ maxCharts: -1 }), category('invalid_argument', /maxCharts/));
  assert.throws(() => mesh.atlas({ resolution: -4 }), category('invalid_argument', /resolution/));
  assert.throws(() => mesh.atlas({ resolution: 100000 }), category('invalid_argument', /resolution/));
  assert.throws(() => mesh.atlas({ resolution: 512.5 }), category('invalid_argument', /resolution must be an integer/));
  assert.throws(() => mesh.atlas({ width: 512 }), category('invalid_argument', /width and height/));
  assert.throws(() => mesh.atlas({ padding: -1 }), category('invalid_argument', /padding/));
  assert.throws(() => mesh.atlas({ padding: '2' }), category('invalid_argument', /padding must be a number/));
  assert.throws(() => mesh.atlas({ rotate: 1 }), category('invalid_argument', /rotate/));
  assert.throws(() => mesh.atlas({ texelsPerUnit: 1e9 }), category('too_large'));
  assert.throws(() => mesh.atlas([]), category('invalid_argument'));
  assert.throws(() => st.atlas([]), category('empty'));
  assert.throws(() => st.atlas([mesh], { padding: -1 }), category('invalid_argument', /padding/));
  assert.throws(() => st.atlas(mesh), TypeError);
  assert.throws(() => st.atlas([mesh, {}]), TypeError);
  const gone = st.sample('cap');
  gone.delete();
  assert.throws(() => st.atlas([mesh, gone]), category('invalid_argument', /deleted/));
  assert.throws(() => gone.atlas(), category('invalid_argument', /deleted/));
  mesh.delete();
});

test('progress reports the four stages; cancelling in each leaves the mesh usable', () => {
  const mesh = st.sample('torus');
  const seen = [];
  const first = mesh.atlas({
    onProgress: (stage, fraction) => {
      seen.push([stage, fraction]);
    },
  });
  assert.deepEqual([...new Set(seen.map(([s]) => s))], ['segment', 'flatten', 'pack', 'measure']);
  assert.ok(seen.every(([, f]) => f >= 0 && f <= 1));
  assert.deepEqual(seen.at(-1), ['measure', 1]);
  st.atlas([mesh]);
  const heap = st.heapUsedBytes;
  for (const stop of ['segment', 'flatten', 'pack', 'measure']) {
    assert.throws(
      () => mesh.atlas({ onProgress: (stage) => stage !== stop }),
      (e) => e.category === 'cancelled',
      stop,
    );
    assert.throws(
      () => st.atlas([mesh], { onProgress: (stage) => stage !== stop }),
      (e) => e.category === 'cancelled',
    );
  }
  assert.equal(st.heapUsedBytes, heap, 'a cancelled atlas frees what it allocated');
  const again = mesh.atlas();
  assert.deepEqual(again.cornerUv, first.cornerUv);
  assert.equal(mesh.info().faces, first.chartOfFace.length);
  assert.throws(() => mesh.atlas({ onProgress: 'no' }), TypeError);
  mesh.delete();
});

/** A Web-Worker-like wrapper of a Node worker thread running wasm/worker-entry.js (Node has no module Web Worker). */
function nodeWorker() {
  const entry = new URL('../../wasm/worker-entry.js', import.meta.url).href;
  const worker = new NodeWorker(
    `
    const { parentPort } = require('node:worker_threads');
    globalThis.postMessage = (message, transfer) => parentPort.postMessage(message, transfer);
    globalThis.addEventListener = (type, listener) => parentPort.on(type, (data) => listener({ data }));
    import(${JSON.stringify(entry)});`,
    { eval: true },
  );
  return {
    postMessage: (message, transfer) => worker.postMessage(message, transfer),
    addEventListener(type, listener) {
      if (type === 'message') worker.on('message', (data) => listener({ data }));
      else worker.on('error', (error) => listener({ message: error.message }));
    },
    terminate: () => worker.terminate(),
  };
}

test("the worker API gives the direct API's atlas, with progress and cancel", async () => {
  const remote = await createStraightestWorker({ createWorker: nodeWorker });
  try {
    const [local, cube] = [st.sample('torus'), st.loadMesh(fixture('good/cube.obj'), 'obj')];
    const [far, farCube] = [await remote.sample('torus'), await remote.loadMesh(fixture('good/cube.obj'), 'obj')];
    const stages = new Set();
    const a = await far.atlas({ padding: 3, onProgress: (stage) => stages.add(stage) });
    const b = local.atlas({ padding: 3 });
    const { timings: ta, ...fieldsA } = a;
    const { timings: tb, ...fieldsB } = b;
    assert.deepEqual(Object.keys(ta), Object.keys(tb));
    assert.deepEqual(fieldsA, fieldsB);
    assert.deepEqual([...stages], ['segment', 'flatten', 'pack', 'measure']);
    const shared = await remote.atlas([farCube, far]);
    const direct = st.atlas([cube, local]);
    assert.deepEqual(shared.meshes, direct.meshes);
    assert.equal(shared.stretch.l2, direct.stretch.l2);
    const controller = new AbortController();
    const cancelled = far.atlas({ signal: controller.signal, onProgress: () => controller.abort() });
    await assert.rejects(cancelled, (e) => e.category === 'cancelled');
    assert.deepEqual((await far.atlas({ padding: 3 })).cornerUv, b.cornerUv);
    assert.throws(() => remote.atlas([local]), TypeError);
    local.delete();
    cube.delete();
  } finally {
    remote.terminate();
  }
});

/** A BufferGeometry of a mesh with a 'color' attribute (one value per vertex) to follow through the split. */
function coloredGeometry(mesh) {
  const geometry = toBufferGeometry(mesh);
  const count = geometry.getAttribute('position').count;
  geometry.setAttribute(
    'color',
    new BufferAttribute(
      Float32Array.from({ length: 3 * count }, (_, i) => i),
      3,
    ),
  );
  return geometry;
}

/** unwrap's promises: uv per vertex = cornerUv at its corners, positions and attributes per corner kept. */
function assertSplit(source, split, cornerUv, meshIndices, channel = 'uv') {
  const index = split.getIndex().array;
  const sourceIndex = source.getIndex().array;
  assert.equal(index.length, sourceIndex.length);
  const uv = split.getAttribute(channel);
  const [position, color] = [split.getAttribute('position'), split.getAttribute('color')];
  const [p0, c0] = [source.getAttribute('position'), source.getAttribute('color')];
  for (let c = 0; c < index.length; ++c) {
    const v = index[c],
      w = sourceIndex[c];
    // toBufferGeometry's index is the mesh's, so the geometry's corner is the mesh's corner.
    assert.equal(meshIndices[c], w);
    assert.equal(uv.getX(v), cornerUv[2 * c]);
    assert.equal(uv.getY(v), cornerUv[2 * c + 1]);
    for (const [a, b] of [
      [position, p0],
      [color, c0],
    ]) {
      assert.deepEqual([a.getX(v), a.getY(v), a.getZ(v)], [b.getX(w), b.getY(w), b.getZ(w)]);
    }
  }
  // One vertex per distinct (vertex, uv): no two new vertices of one origin share a uv.
  const keys = new Set();
  split.userData.vertexOrigin.forEach((o, v) => keys.add(`${o} ${uv.getX(v)} ${uv.getY(v)}`));
  assert.equal(keys.size, position.count);
}

test('straightest/three unwrap splits the geometry along the seams with the atlas uv', () => {
  const mesh = st.sample('torus');
  const geometry = coloredGeometry(mesh);
  geometry.addGroup(0, 300, 1);
  const { geometry: split, atlas } = unwrap(st, geometry, { channel: 'uv1', padding: 3 });
  assertAtlas(mesh, atlas);
  assertSplit(geometry, split, atlas.cornerUv, mesh.indices(), 'uv1');
  assert.equal(split.getIndex().count, 3 * mesh.info().faces);
  assert.equal(split.getAttribute('uv'), undefined);
  assert.ok(split.getAttribute('position').count > mesh.info().vertices, 'seam vertices are split');
  assert.deepEqual(split.groups, geometry.groups);
  // The geometry's positions are float32: the atlas is that of the mesh made from it.
  const fromGeometry = meshFromBufferGeometry(st, geometry);
  assert.deepEqual(atlas.cornerUv, fromGeometry.atlas({ padding: 3 }).cornerUv);
  fromGeometry.delete();
  assert.throws(() => unwrap(st, geometry, { channel: 'uv2' }), TypeError);
  assert.throws(
    () => unwrap(st, geometry, { padding: -1 }),
    (e) => e.category === 'invalid_argument',
  );
  mesh.delete();
});

test('straightest/three unwrap welds a non-indexed geometry; packAtlas shares one atlas', () => {
  const cube = st.loadMesh(fixture('good/cube.obj'), 'obj');
  const soup = toBufferGeometry(cube).toNonIndexed();
  const { geometry, atlas } = unwrap(st, soup);
  assert.equal(atlas.charts < 12, true, 'welded: the cube is not a triangle soup');
  assert.ok(Math.abs(atlas.stretch.l2 - 1) < 1e-6);
  assert.equal(geometry.getIndex().count, 36);
  const positions = soup.getAttribute('position');
  const index = geometry.getIndex().array;
  for (let c = 0; c < 36; ++c) assert.equal(geometry.getAttribute('position').getX(index[c]), positions.getX(c));

  const ball = st.loadMesh(fixture('good/icosphere.obj'), 'obj');
  const sources = [coloredGeometry(cube), coloredGeometry(ball)];
  const packed = packAtlas(st, sources, { resolution: 512 });
  const fromGeometries = sources.map((g) => meshFromBufferGeometry(st, g));
  const direct = st.atlas(fromGeometries, { resolution: 512 });
  assert.equal(packed.geometries.length, 2);
  assert.equal(packed.atlas.width, 512);
  assert.deepEqual(packed.atlas.meshes, direct.meshes);
  packed.geometries.forEach((g, i) =>
    assertSplit(sources[i], g, direct.meshes[i].cornerUv, fromGeometries[i].indices()),
  );
  assert.throws(() => packAtlas(st, sources[0]), TypeError);
  for (const m of [cube, ball, ...fromGeometries]) m.delete();
});

test('straightest/three unwrap finds each corner by its vertex where the core reoriented a face', () => {
  // A 2 × 1 grid whose second and fourth triangles are wound the other way (tests/data/good/inconsistent.obj).
  const indices = [0, 1, 4, 0, 3, 4, 1, 2, 5, 1, 4, 5];
  const geometry = new BufferGeometry();
  geometry.setAttribute(
    'position',
    new BufferAttribute(Float32Array.of(0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0), 3),
  );
  geometry.setIndex(indices);
  const { geometry: split, atlas } = unwrap(st, geometry);
  const mesh = meshFromBufferGeometry(st, geometry);
  assert.equal(mesh.info().reorientedFaces, 2);
  const [meshIndices, index, uv] = [mesh.indices(), split.getIndex().array, split.getAttribute('uv')];
  for (let c = 0; c < indices.length; ++c) {
    assert.equal(split.userData.vertexOrigin[index[c]], indices[c]);
    const face = c - (c % 3);
    const k = [face, face + 1, face + 2].find((m) => meshIndices[m] === indices[c]);
    assert.deepEqual([uv.getX(index[c]), uv.getY(index[c])], [atlas.cornerUv[2 * k], atlas.cornerUv[2 * k + 1]]);
  }
  mesh.delete();
});

test('createStraightestWorker without Web Workers (Node) says what to use instead', async () => {
  assert.equal(typeof globalThis.Worker, 'undefined', 'this test runs where Worker is missing');
  await assert.rejects(
    createStraightestWorker(),
    (e) => e instanceof TypeError && /createStraightest\b/.test(e.message),
  );
});

test('straightest/three unwrap takes three’s own primitives as they come (their seams and caps welded)', async () => {
  const { BoxGeometry, ConeGeometry, CylinderGeometry, SphereGeometry } = await import('three');
  for (const geometry of [
    new CylinderGeometry(1, 1, 2, 24, 1),
    new ConeGeometry(1, 2, 16),
    new BoxGeometry(1, 2, 3),
    new SphereGeometry(1, 16, 12),
  ]) {
    const { geometry: split, atlas } = unwrap(st, geometry);
    assert.equal(atlas.flipped + atlas.mirrored + atlas.overlaps, 0, geometry.type);
    assert.equal(split.getIndex().count, geometry.getIndex().count, geometry.type);
    // Welded, each is one closed surface (its uv and normal seams joined), which the atlas cuts itself.
    const welded = meshFromBufferGeometry(st, geometry, { weld: true });
    assert.equal(welded.info().boundaryLoops.length, 0, `${geometry.type} welded is closed`);
    welded.delete();
    if (geometry.type === 'BoxGeometry')
      assert.ok(Math.abs(atlas.stretch.l2 - 1) < 1e-6, 'a box flattens isometrically');
  }
  // Kept apart, a cylinder's cap triangles only touch at its centre: the error says how to weld.
  assert.throws(
    () => unwrap(st, new CylinderGeometry(1, 1, 2, 24, 1), { weld: false }),
    (e) => e.category === 'non_manifold_vertex' && /weld: true/.test(e.message),
  );
  assert.throws(
    () => meshFromBufferGeometry(st, new ConeGeometry(1, 2, 16)),
    (e) => e.category === 'non_manifold_vertex' && /weld: true/.test(e.message),
  );
});
