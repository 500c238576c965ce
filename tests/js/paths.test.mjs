// Straightest paths through the npm API: geometric facts survive the bindings.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { createStraightest } from '../../wasm/index.js';

const st = await createStraightest();
const quadGrid = await readFile(new URL('../data/good/quad_grid.obj', import.meta.url));
const icosphere = await readFile(new URL('../data/good/icosphere.obj', import.meta.url));
const annulus = await readFile(new URL('../data/good/annulus.off', import.meta.url));

test('on a flat grid every boundary path is reached at its Euclidean length', () => {
  const mesh = st.loadMesh(quadGrid, 'obj');
  const r = mesh.straightestPaths(); // defaults: source 'auto' (the center, vertex 4), targets 'boundary'
  assert.deepEqual(r.source, { vertex: 4 });
  assert.deepEqual(r.sourcePosition, [1, 1, 0]);
  assert.equal(r.count, 8);
  assert.equal(r.reached, 8);
  const positions = mesh.positions();
  for (let i = 0; i < r.count; ++i) {
    const v = r.targets[i].vertex;
    const euclid = Math.hypot(positions[3 * v] - 1, positions[3 * v + 1] - 1);
    assert.ok(Math.abs(r.lengths[i] - euclid) < 1e-12, `path ${i}: ${r.lengths[i]} vs ${euclid}`);
    assert.deepEqual(
      Array.from(r.targetPositions.subarray(3 * i, 3 * i + 3)),
      Array.from(positions.subarray(3 * v, 3 * v + 3)),
    );
    const last = 3 * (r.offsets[i + 1] - 1);
    assert.ok(Math.abs(r.points[last] - positions[3 * v]) < 1e-6, 'the path ends at its target');
  }
  assert.equal(r.offsets.length, r.count + 1);
  assert.equal(r.points.length, 3 * r.offsets[r.count]);
  mesh.delete();
});

test('face and edge points are valid sources and targets, and the targets come back as given', () => {
  const mesh = st.sample('cap');
  const targets = [{ face: 100, bary: [1 / 3, 1 / 3, 1 / 3] }, 50, { halfedge: 30, t: 0.25 }];
  const r = mesh.straightestPaths({ source: { face: 0, bary: [0.2, 0.3, 0.5] }, targets });
  assert.equal(r.count, 3);
  assert.deepEqual(r.statuses, ['reached', 'reached', 'reached']);
  assert.deepEqual(r.targets, [targets[0], { vertex: 50 }, targets[2]]);
  assert.ok(r.lengths[0] > 0 && r.lengths[1] > 0 && r.lengths[2] > 0);
  mesh.delete();
});

test('the base plane of a spherical cap at its pole is the axis', () => {
  const mesh = st.sample('cap');
  const b = mesh.basePlane(0);
  assert.ok(Math.abs(b.normal[2] - 1) < 1e-9);
  assert.equal(b.fallback, false);
  mesh.delete();
});

test('heat and Dijkstra distances are Float64Arrays with 0 at the source', () => {
  const mesh = st.sample('mountain');
  const source = mesh.defaultSource();
  const heat = mesh.geodesicDistances(source, 'heat');
  const graph = mesh.geodesicDistances(source, 'dijkstra');
  assert.ok(heat instanceof Float64Array && graph instanceof Float64Array);
  assert.equal(heat.length, 2500);
  assert.ok(Math.abs(heat[source]) < 1e-9);
  assert.equal(graph[source], 0);
  const paths = mesh.straightestPaths({ points: false });
  for (let i = 0; i < paths.count; ++i) {
    if (paths.statuses[i] !== 'reached') continue;
    assert.ok(
      heat[paths.targets[i].vertex] <= paths.lengths[i] * 1.05,
      'heat distance never exceeds straightest (+5%)',
    );
  }
  assert.equal(paths.points.length, 0);
  mesh.delete();
});

test('bad sources and targets are Errors with messages', () => {
  const mesh = st.sample('mountain');
  assert.throws(() => mesh.straightestPaths({ source: 99999 }), /out of range/);
  assert.throws(() => mesh.straightestPaths({ source: { face: 0, bary: [1, 1, 1] } }), /sum to 1/);
  assert.throws(() => mesh.straightestPaths({ targets: 'everything' }), /targets must be/);
  assert.throws(() => mesh.straightestPaths({ targets: [{ nope: 1 }] }), /targets\[0\] must be/);
  assert.throws(() => mesh.geodesicDistances(0, 'magic'), /unknown distance method/);
  mesh.delete();
  const closed = st.loadMesh('OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n');
  assert.throws(
    () => closed.straightestPaths(),
    (e) => e.category === 'topology' && /closed/.test(e.message),
  );
  assert.throws(() => closed.straightestPaths({ targets: 'all-boundaries' }), /name the targets/);
  closed.delete();
});

test('on a closed sphere both arcs come back: the shorter as the path, the other with its length and points', () => {
  const mesh = st.loadMesh(icosphere, 'obj'); // unit icosphere, 42 vertices; vertex 3 is antipodal to 0
  const r = mesh.straightestPaths({ source: 0, targets: [30, 41, 9, 3] });
  assert.equal(r.baseFallback, true);
  assert.match(r.baseNote, /area-weighted normal/);
  assert.ok(r.backward instanceof Uint8Array && r.otherArcLengths instanceof Float64Array);
  assert.ok(r.otherPoints instanceof Float32Array && r.otherOffsets instanceof Uint32Array);
  assert.equal(r.otherOffsets.length, r.count + 1);
  assert.equal(r.otherPoints.length, 3 * r.otherOffsets[r.count]);
  for (let i = 0; i < 3; ++i) {
    assert.equal(r.statuses[i], 'reached');
    // The section through S is a plane's, inscribed in the unit sphere: both arcs make up less than 2π.
    assert.ok(r.lengths[i] <= r.otherArcLengths[i], `path ${i}: ${r.lengths[i]} vs ${r.otherArcLengths[i]}`);
    assert.ok(r.lengths[i] + r.otherArcLengths[i] < 2 * Math.PI);
    assert.ok(r.lengths[i] + r.otherArcLengths[i] > 0.9 * 2 * Math.PI);
    assert.equal(r.backward[i], 0); // on a sphere the shorter arc leaves toward the target
    let polyline = 0;
    for (let k = r.otherOffsets[i] + 1; k < r.otherOffsets[i + 1]; ++k)
      polyline += Math.hypot(...[0, 1, 2].map((c) => r.otherPoints[3 * k + c] - r.otherPoints[3 * (k - 1) + c]));
    assert.ok(Math.abs(polyline - r.otherArcLengths[i]) < 1e-5, 'the other points trace the other arc');
  }
  assert.equal(r.statuses[3], 'degenerate_plane');
  assert.ok(Number.isNaN(r.otherArcLengths[3]));
  assert.equal(r.otherOffsets[4], r.otherOffsets[3]);
  assert.equal(r.summary.otherArcs, 3);
  assert.ok(st.traceStatuses.includes('other_component'));
  mesh.delete();
});

test("'all-boundaries' targets every loop's vertices, longest first; a disk has no other arcs", () => {
  const mesh = st.loadMesh(annulus, 'off');
  const loops = mesh.boundaryLoops();
  assert.equal(loops.length, 2);
  const r = mesh.straightestPaths({ source: 0, targets: 'all-boundaries' });
  assert.deepEqual(
    r.targets.map((t) => t.vertex),
    [...loops[0], ...loops[1]],
  );
  assert.ok(r.otherArcLengths.every(Number.isNaN));
  assert.equal(r.otherPoints.length, 0);
  assert.equal(r.summary.otherArcs, 0);
  mesh.delete();
});
