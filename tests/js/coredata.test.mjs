// The data the page reads from the core instead of computing it: name lists, the format of a file
// name, boundary loops, vertex normals, boundary polygons without a solve, the in-plane directions of
// the cutting planes, 'boundary' targets, distances by method and the comparison table.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { createStraightest } from '../../wasm/index.js';
import { toBufferGeometry } from '../../wasm/three.js';

const st = await createStraightest();
const quadGrid = await readFile(new URL('../data/good/quad_grid.obj', import.meta.url));

test('name lists come from the core', () => {
  assert.deepEqual(st.traceStatuses, [
    'reached',
    'hit_boundary',
    'other_component',
    'loop',
    'step_limit',
    'no_exit',
    'degenerate_plane',
  ]);
  assert.deepEqual(st.boundaryKinds, ['measured', 'circle', 'square', 'free']);
  assert.deepEqual(st.polygonBoundaryKinds, ['measured', 'circle', 'square']);
  assert.deepEqual(st.boundaryChoices, [...st.boundaryKinds, 'auto']);
  assert.deepEqual(st.weightKinds, ['shape-preserving', 'mean-value', 'cotan', 'uniform']);
  assert.deepEqual(st.solvers, ['multigrid', 'lu', 'bicgstab']);
  assert.deepEqual(st.distanceMethods, ['heat', 'dijkstra', 'exact']);
  assert.deepEqual(st.meshFormats, ['obj', 'off', 'ply', 'stl', 'auto']);
  assert.ok(st.errorCategories.includes('invalid_argument') && st.errorCategories.includes('internal'));
  // Every listed name is accepted where it is used.
  const mesh = st.sample('face');
  for (const boundary of st.boundaryChoices)
    assert.equal(typeof mesh.parameterize({ boundary, weights: 'uniform' }).stretch.l2, 'number');
  mesh.delete();
});

test('formatFromFileName reads the extension in any case', () => {
  assert.equal(st.formatFromFileName('bunny.OBJ'), 'obj');
  assert.equal(st.formatFromFileName('dir/lion.off'), 'off');
  assert.equal(st.formatFromFileName('mesh.stl'), 'stl');
  assert.equal(st.formatFromFileName('scan.PLY'), 'ply');
  assert.equal(st.formatFromFileName('scene.glb'), 'auto');
  assert.equal(st.formatFromFileName('noextension'), 'auto');
});

test('boundaryLoops are the loops in order, longest first', () => {
  const mesh = st.loadMesh(quadGrid, 'obj');
  const loops = mesh.boundaryLoops();
  assert.equal(loops.length, 1);
  assert.ok(loops[0] instanceof Int32Array);
  assert.deepEqual(
    Array.from(loops[0]).sort((a, b) => a - b),
    [0, 1, 2, 3, 5, 6, 7, 8],
  ); // all but the center
  assert.deepEqual(mesh.info().boundaryLoops, [8]);
  // Consecutive loop vertices are joined by a boundary edge: one grid step apart.
  const p = mesh.positions();
  for (let i = 0; i < 8; ++i) {
    const a = loops[0][i];
    const b = loops[0][(i + 1) % 8];
    assert.equal(Math.hypot(p[3 * a] - p[3 * b], p[3 * a + 1] - p[3 * b + 1]), 1);
  }
  mesh.delete();
  const sphere = st.meshFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]);
  assert.deepEqual(sphere.boundaryLoops(), []);
  sphere.delete();
});

test('vertexNormals are area-weighted unit normals', () => {
  const flat = st.loadMesh(quadGrid, 'obj');
  const n = flat.vertexNormals();
  assert.ok(n instanceof Float32Array);
  assert.equal(n.length, 27);
  for (let v = 0; v < 9; ++v) assert.deepEqual(Array.from(n.subarray(3 * v, 3 * v + 3)).map(Math.abs), [0, 0, 1]);
  flat.delete();
  const cap = st.sample('cap');
  const normals = cap.vertexNormals();
  const base = cap.basePlane(cap.defaultSource());
  const v = cap.defaultSource();
  const nv = Array.from(normals.subarray(3 * v, 3 * v + 3));
  assert.ok(Math.abs(Math.hypot(...nv) - 1) < 1e-6);
  assert.ok(
    nv[0] * base.normal[0] + nv[1] * base.normal[1] + nv[2] * base.normal[2] > 0.99,
    'at the pole the normal is the axis',
  );
  assert.deepEqual(toBufferGeometry(cap).getAttribute('normal').array, normals, "three.js gets the core's normals");
  cap.delete();
});

test("boundaryPolygons are parameterize's polygons in its frame, without a solve", () => {
  for (const name of st.sampleNames()) {
    const mesh = st.sample(name);
    const polygons = mesh.boundaryPolygons();
    assert.deepEqual(
      polygons.map((p) => p.boundary),
      st.polygonBoundaryKinds,
    );
    for (const entry of polygons) {
      assert.equal(entry.error, null, `${name} ${entry.boundary}: ${entry.error}`);
      const p = mesh.parameterize({ boundary: entry.boundary });
      assert.deepEqual(entry.loop, p.boundaryLoop);
      assert.deepEqual(entry.polygon, p.boundaryPolygon, `${name} ${entry.boundary}`);
    }
    mesh.delete();
  }
  const cap = st.sample('cap');
  const onBoundary = cap.boundaryLoops()[0][0];
  const [measured, circle] = cap.boundaryPolygons({ source: onBoundary, kinds: ['measured', 'circle'] });
  assert.equal(measured.polygon, null);
  assert.equal(measured.category, 'invalid_argument');
  assert.match(measured.error, /on the boundary/);
  assert.ok(circle.polygon instanceof Float32Array);
  assert.throws(() => cap.boundaryPolygons({ kinds: ['ellipse'] }), /unknown boundary 'ellipse'/);
  assert.throws(
    () => cap.boundaryPolygons({ kinds: ['circle', 'free'] }),
    (e) => e.category === 'invalid_argument' && /free boundary has no polygon/.test(e.message),
  );
  assert.throws(
    () => cap.boundaryPolygons({ onProgress: () => false }),
    (e) => e.category === 'cancelled',
  );
  cap.delete();
});

test('straightestPaths: directions span each cutting plane with the normal; boundary entries expand', () => {
  const mesh = st.sample('saddle');
  const loop = mesh.boundaryLoops()[0];
  const source = mesh.defaultSource();
  const r = mesh.straightestPaths({ source, targets: [7, 'boundary', source], points: false });
  assert.equal(r.count, loop.length + 2);
  assert.deepEqual(
    r.targets.slice(1, -1).map((t) => t.vertex),
    Array.from(loop),
  );
  assert.equal(r.reached, r.statuses.filter((s) => s === 'reached').length);
  assert.equal(r.summary.paths, r.count);
  assert.equal(r.summary.reached, r.reached);
  assert.equal(r.summary.maxFacesCrossed, Math.max(...r.facesCrossed));
  assert.ok(r.directions instanceof Float64Array && r.directions.length === 3 * r.count);
  const [sx, sy, sz] = r.sourcePosition;
  const n = r.normal;
  for (let i = 0; i < r.count - 1; ++i) {
    const t = r.directions.subarray(3 * i, 3 * i + 3);
    const d = [r.targetPositions[3 * i] - sx, r.targetPositions[3 * i + 1] - sy, r.targetPositions[3 * i + 2] - sz];
    assert.ok(Math.abs(Math.hypot(...t) - 1) < 1e-12);
    assert.ok(Math.abs(t[0] * n[0] + t[1] * n[1] + t[2] * n[2]) < 1e-12, 'in the base plane');
    assert.ok(t[0] * d[0] + t[1] * d[1] + t[2] * d[2] > 0, 'toward the target');
    const m = [t[1] * n[2] - t[2] * n[1], t[2] * n[0] - t[0] * n[2], t[0] * n[1] - t[1] * n[0]];
    assert.ok(
      Math.abs(m[0] * d[0] + m[1] * d[1] + m[2] * d[2]) < 1e-9 * Math.hypot(...d),
      'the target lies in the plane',
    );
  }
  assert.ok(Array.from(r.directions.subarray(-3)).every(Number.isNaN), 'no plane toward the source itself');
  mesh.delete();
  const closed = st.meshFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]);
  assert.throws(
    () => closed.straightestPaths({ source: 0, targets: [1, 'boundary'] }),
    (e) => e.category === 'topology' && /closed/.test(e.message),
  );
  closed.delete();
});

test('geodesicDistances dispatches by method in the core', () => {
  const mesh = st.sample('mountain');
  const heat = mesh.geodesicDistances('auto', 'heat');
  const again = mesh.geodesicDistances('auto', 'heat');
  assert.deepEqual(again, heat);
  const dijkstra = mesh.geodesicDistances('auto', 'dijkstra');
  for (let v = 0; v < heat.length; v += 97)
    assert.ok(heat[v] <= dijkstra[v] * 1.05 + 1e-9, 'edge paths are never much shorter');
  const exact = mesh.geodesicDistances('auto', 'exact');
  for (let v = 0; v < exact.length; v++)
    assert.ok(exact[v] <= dijkstra[v] * (1 + 1e-12), 'the exact distance is the shortest');
  assert.throws(
    () => mesh.geodesicDistances('auto', 'magic'),
    (e) => e.category === 'invalid_argument' && /heat, dijkstra or exact/.test(e.message),
  );
  mesh.delete();
});

test('compareParameterizations: every boundary × weights, best by the rule of boundary auto', () => {
  const mesh = st.sample('face');
  const stages = new Set();
  const c = mesh.compareParameterizations({
    onProgress: (stage) => {
      stages.add(stage);
    },
  });
  assert.deepEqual([...stages], ['compare']);
  assert.equal(c.rows.length, 16);
  assert.deepEqual(
    c.rows.slice(0, 4).map((r) => r.weights),
    st.weightKinds,
  );
  assert.deepEqual([...new Set(c.rows.map((r) => r.boundary))], st.boundaryKinds);
  for (const row of c.rows) {
    assert.equal(row.error, null);
    const p = mesh.parameterize({ boundary: row.boundary, weights: row.weights });
    assert.equal(row.l2, p.stretch.l2);
    assert.equal(row.bijective, p.bijective);
    assert.equal(row.overlaps, p.overlaps);
    assert.equal(row.init, p.init, 'free rows start where boundary free starts; fixed rows have none');
    assert.equal(row.iterations, p.iterations);
    assert.ok(row.timeMs >= 0);
  }
  assert.ok(c.best >= 0);
  const best = c.rows[c.best];
  const auto = mesh.parameterize({ boundary: 'auto', weights: best.weights });
  assert.equal(auto.boundary, best.boundary, 'the best row is the boundary auto keeps');
  assert.throws(
    () => mesh.compareParameterizations({ onProgress: () => false }),
    (e) => e.category === 'cancelled',
  );
  assert.throws(() => mesh.compareParameterizations({ weights: ['magic'] }), /unknown weights 'magic'/);
  mesh.delete();
});
