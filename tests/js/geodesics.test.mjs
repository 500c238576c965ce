// Geodesics shot from a direction (the initial value problem) and exact shortest paths through the npm
// API: the geometric facts of the core survive the bindings, bad aims are clear errors, long work cancels.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createStraightest } from '../../wasm/index.js';

const st = await createStraightest();

/** An n × n grid of squares on [0, 1]² at z = 0, diagonals alternating so that the triangles are not all alike. */
function flatGrid(n) {
  const positions = [];
  const indices = [];
  for (let j = 0; j <= n; ++j) for (let i = 0; i <= n; ++i) positions.push(i / n, j / n, 0);
  const at = (i, j) => j * (n + 1) + i;
  for (let j = 0; j < n; ++j) {
    for (let i = 0; i < n; ++i) {
      const [a, b, c, d] = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
      if ((i + j) % 2) indices.push(a, b, c, a, c, d);
      else indices.push(a, b, d, b, c, d);
    }
  }
  return st.meshFromArrays(positions, indices);
}

const center = 5 * 11 + 5; // the middle vertex of flatGrid(10): (0.5, 0.5, 0)

/** Distance from point p to the line through a along the unit vector u. */
function distanceToLine(p, a, u) {
  const d = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
  const along = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
  return Math.hypot(d[0] - along * u[0], d[1] - along * u[1], d[2] - along * u[2]);
}

function polylineLength(points, from, to) {
  let length = 0;
  for (let k = from + 1; k < to; ++k)
    length += Math.hypot(
      points[3 * k] - points[3 * k - 3],
      points[3 * k + 1] - points[3 * k - 2],
      points[3 * k + 2] - points[3 * k - 1],
    );
  return length;
}

test('on a plane a shot geodesic is a straight segment of the length asked for', () => {
  const mesh = flatGrid(10);
  for (const angle of [0, 0.3, 1, Math.PI / 4, 2.5, -2]) {
    const shot = mesh.shootGeodesic({ source: center, angle, length: 0.4 });
    assert.equal(shot.status, 'reached_length');
    assert.deepEqual(shot.source, { vertex: center });
    assert.deepEqual(shot.sourcePosition, [0.5, 0.5, 0]);
    assert.ok(Math.abs(shot.length - 0.4) < 1e-12, `angle ${angle}: length ${shot.length}`);
    assert.equal(shot.requestedLength, 0.4);
    assert.ok(Math.abs(Math.abs(shot.normal[2]) - 1) < 1e-12, 'the tangent plane is the plane itself');
    assert.ok(Math.abs(shot.direction[2]) < 1e-12);
    const points = shot.points;
    assert.ok(points instanceof Float64Array);
    assert.equal(points.length % 3, 0);
    assert.ok(points.length >= 6 && shot.facesCrossed >= 1);
    for (let k = 0; k < points.length / 3; ++k)
      assert.ok(
        distanceToLine(points.subarray(3 * k, 3 * k + 3), shot.sourcePosition, shot.direction) < 1e-12,
        `point ${k} is off the line`,
      );
    assert.ok(Math.abs(polylineLength(points, 0, points.length / 3) - 0.4) < 1e-12);
    for (let c = 0; c < 3; ++c) {
      assert.ok(Math.abs(shot.endPosition[c] - (shot.sourcePosition[c] + 0.4 * shot.direction[c])) < 1e-12);
      assert.equal(points[points.length - 3 + c], shot.endPosition[c]);
    }
    // The opposite angle leaves the opposite way.
    const back = mesh.shootGeodesic({ source: center, angle: angle + Math.PI, length: 0.4, points: false });
    const dot = back.direction[0] * shot.direction[0] + back.direction[1] * shot.direction[1];
    assert.ok(Math.abs(dot + 1) < 1e-12, `angle ${angle}: opposite directions dot to ${dot}`);
    assert.equal(back.points.length, 0, 'points: false');
  }
  mesh.delete();
});

test('a 3D direction is projected onto the tangent plane, and a long shot stops at the boundary', () => {
  const mesh = flatGrid(10);
  const shot = mesh.shootGeodesic({ source: { face: 7, bary: [0.2, 0.3, 0.5] }, direction: [1, 2, 5], length: 10 });
  const unit = [1 / Math.sqrt(5), 2 / Math.sqrt(5), 0];
  for (let c = 0; c < 3; ++c) assert.ok(Math.abs(shot.direction[c] - unit[c]) < 1e-12);
  assert.equal(shot.status, 'hit_boundary');
  assert.ok(shot.length < 10 && shot.length > 0);
  // Leaving at slope 2 it meets the top edge y = 1, having walked the straight line there.
  assert.ok(Math.abs(shot.endPosition[1] - 1) < 1e-12, `ends at y = ${shot.endPosition[1]}`);
  const walked = Math.hypot(shot.endPosition[0] - shot.sourcePosition[0], shot.endPosition[1] - shot.sourcePosition[1]);
  assert.ok(Math.abs(walked - shot.length) < 1e-12);
  assert.equal(shot.target, null);
  assert.equal(shot.missDistance, null);
  assert.equal(shot.straightestDistance, null);
  mesh.delete();
});

test('on a plane exact distances are Euclidean and exact shortest paths are straight', () => {
  const mesh = flatGrid(10);
  const r = mesh.exactShortestPaths({ source: center }); // targets default: the boundary loop
  const loop = mesh.boundaryLoops()[0];
  assert.deepEqual(Array.from(r.targets), Array.from(loop));
  assert.equal(r.method, 'exact');
  assert.equal(r.count, loop.length);
  assert.equal(r.offsets.length, r.count + 1);
  assert.equal(r.points.length, 3 * r.offsets[r.count]);
  assert.ok(r.exact.windows > 0);
  const positions = mesh.positions();
  const all = mesh.geodesicDistances(center, 'exact');
  for (let i = 0; i < r.count; ++i) {
    const v = r.targets[i];
    const euclid = Math.hypot(positions[3 * v] - 0.5, positions[3 * v + 1] - 0.5);
    assert.ok(Math.abs(r.distances[i] - euclid) < 1e-12, `target ${v}: ${r.distances[i]} vs ${euclid}`);
    assert.equal(r.distances[i], all[v]);
    const [from, to] = [r.offsets[i], r.offsets[i + 1]];
    assert.ok(to - from >= 2);
    const u = [(positions[3 * v] - 0.5) / euclid, (positions[3 * v + 1] - 0.5) / euclid, 0];
    for (let k = from; k < to; ++k)
      assert.ok(distanceToLine(r.points.subarray(3 * k, 3 * k + 3), [0.5, 0.5, 0], u) < 1e-6);
    for (let c = 0; c < 3; ++c)
      assert.ok(Math.abs(r.points[3 * (to - 1) + c] - positions[3 * v + c]) < 1e-6, 'ends at its target');
    assert.ok(Math.abs(polylineLength(r.points, from, to) - euclid) < 1e-5);
  }
  mesh.delete();
});

test('on the mountain: Euclidean ≤ exact ≤ straightest (reached) and exact ≤ Dijkstra, each polyline as long as its distance', () => {
  const mesh = st.sample('mountain');
  const straightest = mesh.straightestPaths({ points: false });
  const exact = mesh.exactShortestPaths();
  const dijkstra = mesh.geodesicDistances('auto', 'dijkstra');
  assert.deepEqual(exact.source, straightest.source);
  const s = straightest.source.vertex;
  const positions = mesh.positions();
  let strictlyShorter = 0;
  for (let i = 0; i < exact.count; ++i) {
    const v = exact.targets[i];
    assert.equal(straightest.targets[i].vertex, v);
    const d = exact.distances[i];
    const euclid = Math.hypot(
      positions[3 * v] - positions[3 * s],
      positions[3 * v + 1] - positions[3 * s + 1],
      positions[3 * v + 2] - positions[3 * s + 2],
    );
    assert.ok(euclid <= d + 1e-12, `target ${v}: Euclidean ${euclid} > exact ${d}`);
    assert.ok(d <= dijkstra[v] + 1e-12, `target ${v}: exact ${d} > Dijkstra ${dijkstra[v]}`);
    if (straightest.statuses[i] === 'reached') {
      assert.ok(
        d <= straightest.lengths[i] * (1 + 1e-12),
        `target ${v}: exact ${d} > straightest ${straightest.lengths[i]}`,
      );
      if (d < straightest.lengths[i] * (1 - 1e-6)) ++strictlyShorter;
    }
    const traced = polylineLength(exact.points, exact.offsets[i], exact.offsets[i + 1]);
    assert.ok(Math.abs(traced - d) < 1e-5 * d, `target ${v}: polyline ${traced} vs ${d}`);
  }
  assert.ok(strictlyShorter > 0, 'on a curved surface some plane sections are longer than the shortest paths');
  const table = mesh.exactShortestPaths({ targets: [exact.targets[3], { vertex: exact.targets[7] }], points: false });
  assert.deepEqual(Array.from(table.distances), [exact.distances[3], exact.distances[7]]);
  assert.equal(table.points.length, 0);
  assert.equal(table.offsets.length, 0);
  mesh.delete();
});

test("shot toward a boundary vertex, a geodesic reports its miss distance and the cutting plane's length", () => {
  const mesh = st.sample('mountain');
  const paths = mesh.straightestPaths({ points: false });
  const positions = mesh.positions();
  let missed = 0;
  for (const i of [0, 13, 29, 41, 57]) {
    const v = paths.targets[i].vertex;
    const shot = mesh.shootGeodesic({ toward: v });
    assert.deepEqual(shot.source, paths.source);
    assert.deepEqual(shot.target, Array.from(positions.subarray(3 * v, 3 * v + 3)));
    assert.ok(shot.missDistance >= 0 && Number.isFinite(shot.missDistance));
    if (paths.statuses[i] === 'reached') {
      assert.ok(Math.abs(shot.straightestDistance - paths.lengths[i]) < 1e-12);
      assert.equal(shot.requestedLength, shot.straightestDistance);
    }
    assert.ok(shot.length <= shot.requestedLength + 1e-12);
    // It starts along the cutting plane's direction.
    const dir = paths.directions.subarray(3 * i, 3 * i + 3);
    assert.ok(shot.direction[0] * dir[0] + shot.direction[1] * dir[1] + shot.direction[2] * dir[2] > 0.5);
    // The closest approach is no farther than the end of the path.
    const endGap = Math.hypot(
      shot.endPosition[0] - shot.target[0],
      shot.endPosition[1] - shot.target[1],
      shot.endPosition[2] - shot.target[2],
    );
    assert.ok(shot.missDistance <= endGap + 1e-12);
    if (shot.missDistance > 1e-6) ++missed;
    const given = mesh.shootGeodesic({ toward: v, length: 0.25 });
    assert.equal(given.requestedLength, 0.25);
  }
  assert.ok(missed > 0, 'on a curved surface a geodesic shot from a direction misses some destinations');
  mesh.delete();
});

test('bad aims and lengths are clear invalid_argument errors', () => {
  const mesh = flatGrid(10);
  const corner = 0; // (0, 0, 0)
  const bad = [
    [{ source: center, direction: [0, 0, 0], length: 1 }, /zero length/],
    [{ source: center, direction: [NaN, 1, 0], length: 1 }, /not finite/],
    [{ source: center, direction: [0, 0, 1], length: 1 }, /normal/],
    [{ source: center, direction: [1, 0], length: 1 }, /\[x, y, z\]/],
    [{ source: center, angle: NaN, length: 1 }, /angle/],
    [{ source: center, angle: 'north', length: 1 }, /angle must be a number/],
    [{ source: center, angle: 0, length: 0 }, /length/],
    [{ source: center, angle: 0, length: -1 }, /length/],
    [{ source: center, angle: 0, length: Infinity }, /length/],
    [{ source: center, angle: 0 }, /needs a length/],
    [{ source: center, angle: 0, direction: [1, 0, 0], length: 1 }, /exactly one/],
    [{ source: center, length: 1 }, /exactly one/],
    [{ source: center, toward: center }, /destination is the source/],
    [{ source: center, toward: 'auto' }, /toward must be/],
    [{ source: center, toward: 5000 }, /destination/],
    [{ source: center, toward: 0, length: -2 }, /length/],
    [{ source: corner, direction: [-1, -1, 0], length: 1 }, /off the surface/],
  ];
  for (const [options, message] of bad) {
    assert.throws(
      () => mesh.shootGeodesic(options),
      (e) => e.category === 'invalid_argument' && message.test(e.message),
      JSON.stringify(options),
    );
  }
  // Inward from the same corner is fine.
  assert.equal(mesh.shootGeodesic({ source: corner, direction: [1, 1, 0], length: 0.5 }).status, 'reached_length');
  assert.throws(
    () => mesh.exactShortestPaths({ source: center, targets: [{ face: 0, bary: [0.2, 0.3, 0.5] }] }),
    (e) => e.category === 'invalid_argument' && /vertices/.test(e.message),
  );
  assert.throws(
    () => mesh.exactShortestPaths({ source: center, targets: [5000] }),
    (e) => e.category === 'index_out_of_range' || e.category === 'invalid_argument',
  );
  mesh.delete();
  assert.throws(
    () => mesh.shootGeodesic({ angle: 0, length: 1 }),
    (e) => e.category === 'invalid_argument' && /deleted/.test(e.message),
  );
  assert.throws(
    () => mesh.exactShortestPaths(),
    (e) => e.category === 'invalid_argument' && /deleted/.test(e.message),
  );
});

test('long work reports its stage and cancels, leaving the mesh usable', () => {
  const sphere = st.sample('sphere');
  // Around the sphere many times: more steps than the walk reports progress after.
  const stages = new Set();
  assert.throws(
    () =>
      sphere.shootGeodesic({
        source: 0,
        angle: 0.3,
        length: 3000,
        points: false,
        onProgress: (stage) => {
          stages.add(stage);
          return false;
        },
      }),
    (e) => e.category === 'cancelled',
  );
  assert.deepEqual([...stages], ['shoot']);
  assert.equal(sphere.shootGeodesic({ source: 0, angle: 0.3, length: 1 }).status, 'reached_length');
  stages.clear();
  assert.throws(
    () =>
      sphere.exactShortestPaths({
        source: 0,
        targets: [100],
        onProgress: (stage) => {
          stages.add(stage);
          return false;
        },
      }),
    (e) => e.category === 'cancelled',
  );
  assert.deepEqual([...stages], ['distances']);
  const fractions = [];
  const r = sphere.exactShortestPaths({
    source: 0,
    targets: [100, 200],
    onProgress: (stage, fraction) => {
      fractions.push(fraction);
    },
  });
  assert.equal(r.count, 2);
  assert.ok(fractions.length > 0 && fractions.every((f, k) => f >= 0 && f <= 1 && (k === 0 || f >= fractions[k - 1])));
  // A shot on a closed surface never meets a boundary.
  assert.ok(st.shootStatuses.includes(sphere.shootGeodesic({ source: 0, angle: 1, length: 20, points: false }).status));
  assert.equal(sphere.shootGeodesic({ source: 0, angle: 1, length: 20, points: false }).status, 'reached_length');
  sphere.delete();
});

test('the name lists include the shot statuses and the exact method', () => {
  assert.deepEqual(st.shootStatuses, ['reached_length', 'hit_boundary', 'step_limit', 'no_exit']);
  assert.ok(st.distanceMethods.includes('exact'));
});
