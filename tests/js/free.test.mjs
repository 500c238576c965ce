// The free boundary through the npm API: its fields, the start rule, its place in 'auto' and in the
// comparison, its options, errors and cancellation. These hold for any correct refinement.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createStraightest } from '../../wasm/index.js';

const st = await createStraightest();
const stages = ['cut', 'source', 'trace', 'boundary', 'weights', 'solve', 'refine', 'metrics', 'total'];

/** What every free result satisfies, whatever the refinement did. */
function checkFree(mesh, p, maxIterations) {
  assert.equal(p.boundary, 'free');
  assert.ok(p.init === 'measured' || p.init === 'circle', `init ${p.init}`);
  assert.ok(Number.isInteger(p.iterations) && p.iterations >= 0 && p.iterations <= maxIterations);
  assert.equal(typeof p.energyInitial, 'number');
  assert.equal(typeof p.energyFinal, 'number');
  assert.equal(typeof p.converged, 'boolean');
  assert.equal(typeof p.untangled, 'boolean');
  assert.equal(p.bijective, p.flipped === 0 && p.degenerate === 0 && p.overlaps === 0);
  assert.equal(Number.isFinite(p.stretch.l2), p.bijective, 'a finite stretch only for a bijective map');
  assert.equal(p.uv.length, 2 * mesh.info().vertices);
  assert.ok(p.uv.every((x) => x >= 0 && x <= 1));
  if (p.cut === 'disk') {
    assert.deepEqual(p.boundaryLoop, mesh.boundaryLoops()[0]);
    p.boundaryLoop.forEach((v, i) => {
      assert.equal(p.boundaryPolygon[2 * i], p.uv[2 * v]);
      assert.equal(p.boundaryPolygon[2 * i + 1], p.uv[2 * v + 1]);
    });
  } else {
    // Cut or filled: a seam vertex has a uv per side; the polygon's point is one of its corners' uv.
    const indices = mesh.indices();
    const corners = new Map();
    indices.forEach((v, c) => {
      if (!corners.has(v)) corners.set(v, []);
      corners.get(v).push(`${p.cornerUv[2 * c]},${p.cornerUv[2 * c + 1]}`);
    });
    p.boundaryLoop.forEach((v, i) => {
      assert.ok(corners.get(v).includes(`${p.boundaryPolygon[2 * i]},${p.boundaryPolygon[2 * i + 1]}`), `loop ${i}`);
    });
  }
  assert.equal(p.candidates.at(-1).boundary, 'free');
  assert.equal(p.candidates.at(-1).l2, p.stretch.l2);
  assert.equal(p.candidates.at(-1).overlaps, p.overlaps);
  assert.deepEqual(Object.keys(p.timings), stages);
}

test('free starts from the measured map when it is bijective, else from the circle, and says which', () => {
  for (const name of st.sampleNames()) {
    const mesh = st.sample(name);
    for (const weights of ['shape-preserving', 'cotan']) {
      const measured = mesh.parameterize({ weights });
      const p = mesh.parameterize({ boundary: 'free', weights, maxIterations: 10 });
      checkFree(mesh, p, 10);
      assert.equal(p.init, measured.bijective ? 'measured' : 'circle', `${name} ${weights}`);
      assert.equal(p.candidates[0].boundary, 'measured');
      if (p.init === 'measured') {
        assert.equal(p.candidates.length, 2, 'no circle solve when the measured map will do');
        assert.ok(!Number.isFinite(p.energyInitial) || p.energyFinal <= p.energyInitial, 'the energy never rises');
      }
    }
    mesh.delete();
  }
});

test('a fixed boundary has no refinement fields and spends nothing on refine', () => {
  const mesh = st.sample('cap');
  const p = mesh.parameterize({ boundary: 'square' });
  for (const field of ['init', 'iterations', 'energyInitial', 'energyFinal', 'converged', 'untangled'])
    assert.equal(p[field], null, field);
  assert.equal(p.overlaps, 0);
  assert.deepEqual(Object.keys(p.timings), stages);
  assert.equal(p.timings.refine, 0);
  mesh.delete();
});

test('auto adds the free candidate, refined from the map it already solved', () => {
  const mesh = st.sample('mountain');
  const auto = mesh.parameterize({ boundary: 'auto', maxIterations: 10 });
  assert.deepEqual(
    auto.candidates.map((c) => c.boundary),
    st.boundaryKinds,
  );
  const free = mesh.parameterize({ boundary: 'free', maxIterations: 10 });
  assert.equal(auto.candidates[3].l2, free.stretch.l2);
  assert.equal(auto.init !== null, auto.boundary === 'free');
  mesh.delete();
});

test('the comparison has a free row per weights, with its start and iterations', () => {
  const mesh = st.sample('face');
  const weights = ['mean-value', 'uniform'];
  const c = mesh.compareParameterizations({ boundaries: ['circle', 'free'], weights, maxIterations: 8 });
  assert.deepEqual(
    c.rows.map((r) => r.boundary),
    ['circle', 'circle', 'free', 'free'],
  );
  for (const row of c.rows.slice(2)) {
    assert.equal(row.error, null);
    const p = mesh.parameterize({ boundary: 'free', weights: row.weights, maxIterations: 8 });
    assert.equal(row.init, p.init);
    assert.equal(row.iterations, p.iterations);
    assert.equal(row.l2, p.stretch.l2);
    assert.equal(row.overlaps, p.overlaps);
    assert.equal(row.converged, p.converged);
  }
  for (const row of c.rows.slice(0, 2)) assert.equal(row.init, null);
  mesh.delete();
});

test('cancelling during refine throws cancelled and the mesh and module stay usable', () => {
  const mesh = st.sample('mountain');
  const before = st.heapUsedBytes;
  let seen = false;
  assert.throws(
    () =>
      mesh.parameterize({
        boundary: 'free',
        onProgress: (stage) => {
          seen ||= stage === 'refine';
          return stage !== 'refine';
        },
      }),
    (e) => e.category === 'cancelled',
  );
  assert.ok(seen, 'the refine stage was reported');
  assert.throws(
    () => mesh.parameterize({ boundary: 'auto', onProgress: (stage) => stage !== 'refine' }),
    (e) => e.category === 'cancelled',
  );
  assert.throws(
    () => mesh.compareParameterizations({ boundaries: ['free'], onProgress: () => false }),
    (e) => e.category === 'cancelled',
  );
  assert.ok(st.heapUsedBytes <= before + 1024, 'a cancelled refinement leaves nothing allocated');
  const p = mesh.parameterize({ boundary: 'free', maxIterations: 5 });
  checkFree(mesh, p, 5);
  const other = st.sample('cap');
  assert.equal(other.parameterize({ boundary: 'free', maxIterations: 5 }).boundary, 'free');
  other.delete();
  mesh.delete();
});

test('the refinement options are checked; a boundary source is refused as for measured; a non-disk is cut', () => {
  const mesh = st.sample('cap');
  for (const maxIterations of [0, -3, 1.5, 'ten', Infinity])
    assert.throws(
      () => mesh.parameterize({ boundary: 'free', maxIterations }),
      (e) => e.category === 'invalid_argument' && /maxIterations/.test(e.message),
    );
  for (const timeBudgetMs of [0, -1, NaN, 'soon'])
    assert.throws(
      () => mesh.parameterize({ boundary: 'free', timeBudgetMs }),
      (e) => e.category === 'invalid_argument' && /timeBudgetMs/.test(e.message),
    );
  assert.throws(
    () => mesh.compareParameterizations({ maxIterations: 0 }),
    (e) => e.category === 'invalid_argument',
  );
  const onBoundary = mesh.boundaryLoops()[0][0];
  const measuredError = (() => {
    try {
      mesh.parameterize({ source: onBoundary });
    } catch (e) {
      return e.message;
    }
  })();
  assert.throws(
    () => mesh.parameterize({ boundary: 'free', source: onBoundary }),
    (e) => e.category === 'invalid_argument' && e.message === measuredError,
  );
  mesh.delete();
  const closed = st.meshFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]);
  const cut = closed.parameterize({ boundary: 'free', maxIterations: 10 });
  checkFree(closed, cut, 10);
  assert.equal(cut.cut, 'path');
  closed.delete();
});

test('a free map exports as OBJ texture coordinates', () => {
  const mesh = st.sample('saddle');
  const p = mesh.parameterize({ boundary: 'free', maxIterations: 5 });
  const text = mesh.toOBJ(p.uv);
  assert.equal(text.split('\nvt ').length - 1, mesh.info().vertices);
  mesh.delete();
});
