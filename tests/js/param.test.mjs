// Parameterization through the npm API, and the three.js helper.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { BufferGeometry, PlaneGeometry } from 'three';
import { createStraightest } from '../../wasm/index.js';
import { applyUV, meshFromBufferGeometry, toBufferGeometry } from '../../wasm/three.js';

const st = await createStraightest();

test('parameterize returns uv in [0, 1]², per-face stretch and finite metrics for a sample', () => {
  const mesh = st.sample('mountain');
  const p = mesh.parameterize();
  assert.equal(p.boundary, 'measured');
  assert.equal(p.weights, 'shape-preserving');
  assert.ok(p.uv instanceof Float32Array);
  assert.equal(p.uv.length, 2 * 2500);
  assert.ok(p.uv.every((x) => x >= -1e-6 && x <= 1 + 1e-6));
  assert.equal(p.faceStretch.length, mesh.info().faces);
  assert.equal(p.bijective, true);
  assert.equal(p.flipped, 0);
  assert.ok(p.stretch.l2 >= 1 && Number.isFinite(p.stretch.l2));
  assert.ok(p.stretch.linf >= p.stretch.l2);
  assert.equal(p.boundaryPolygon.length, 2 * p.boundaryLoop.length);
  assert.ok(p.residual < 1e-9);
  assert.ok(p.timings.total > 0);
  mesh.delete();
});

test('auto reports every candidate and keeps the least stretched', () => {
  const mesh = st.sample('face');
  const p = mesh.parameterize({ boundary: 'auto', weights: 'mean-value' });
  assert.deepEqual(
    p.candidates.map((c) => c.boundary),
    ['measured', 'circle', 'square', 'free'],
  );
  for (const c of p.candidates) assert.ok(p.stretch.l2 <= c.l2);
  mesh.delete();
});

test('refusals are Errors with messages', () => {
  // A closed mesh is not refused: it is cut along a seam (cut.test.mjs), and a source on the seam is.
  const closed = st.loadMesh('OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n');
  const cut = closed.parameterize({ boundary: 'circle' });
  assert.equal(cut.cut, 'path');
  assert.throws(
    () => closed.parameterize({ source: cut.seam[0] }),
    (e) => e instanceof Error && e.category === 'invalid_argument' && /seam/.test(e.message),
  );
  closed.delete();
  const mesh = st.sample('cap');
  assert.throws(() => mesh.parameterize({ boundary: 'ellipse' }), /unknown boundary 'ellipse'/);
  assert.throws(() => mesh.parameterize({ weights: 'magic' }), /unknown weights/);
  const boundaryVertex = mesh.straightestPaths({ points: false }).targets[0].vertex;
  assert.throws(() => mesh.parameterize({ source: boundaryVertex }), /on the boundary/);
  mesh.delete();
});

test('toOBJ writes vt lines that round-trip through loadMesh', () => {
  const mesh = st.sample('saddle');
  const p = mesh.parameterize({ boundary: 'circle' });
  const text = mesh.toOBJ(p.uv);
  assert.match(text, /\nvt /);
  const again = st.loadMesh(text, 'obj');
  assert.equal(again.info().vertices, mesh.info().vertices);
  assert.throws(() => mesh.toOBJ(new Float32Array(3)), /expected 2 per vertex/);
  again.delete();
  mesh.delete();
});

test('straightest/three applyUV sets the uv attribute of a geometry', () => {
  const mesh = st.sample('cap');
  const geometry = toBufferGeometry(mesh);
  assert.ok(geometry instanceof BufferGeometry);
  const p = mesh.parameterize();
  applyUV(geometry, p.uv);
  assert.equal(geometry.getAttribute('uv').count, mesh.info().vertices);
  assert.throws(() => applyUV(geometry, new Float32Array(4)), RangeError);
  mesh.delete();
});

test('applyUV after a weld says to texture toBufferGeometry(mesh) instead of the original geometry', () => {
  const original = new PlaneGeometry(1, 1, 4, 4).toNonIndexed(); // every triangle its own 3 vertices
  const welded = meshFromBufferGeometry(st, original, { weld: true });
  const { uv } = welded.parameterize();
  assert.throws(
    () => applyUV(original, uv),
    (e) => e instanceof RangeError && /fewer vertices than the geometry \(made with weld\?\)/.test(e.message),
  );
  assert.equal(applyUV(toBufferGeometry(welded), uv).getAttribute('uv').count, welded.info().vertices);
  welded.delete();
});

test('progress callbacks report the stages and can cancel', () => {
  const mesh = st.sample('mountain');
  const seen = [];
  mesh.parameterize({
    onProgress: (stage, fraction) => {
      seen.push([stage, fraction]);
    },
  });
  const stages = [...new Set(seen.map(([s]) => s))];
  assert.deepEqual(
    stages.filter((s) => s !== 'solve'),
    ['source', 'trace', 'weights', 'metrics'],
  );
  assert.ok(seen.every(([, f]) => f >= 0 && f <= 1));
  assert.deepEqual(seen.at(-1), ['metrics', 1]);
  assert.throws(
    () => mesh.parameterize({ onProgress: (stage) => stage !== 'weights' }),
    (e) => e.category === 'cancelled',
  );
  // Stop at the second call: with threads the caller may see only the start and the end of the traces (the
  // workers can run every chunk meanwhile), so a later call is not guaranteed to come.
  let calls = 0;
  assert.throws(
    () => mesh.straightestPaths({ onProgress: () => ++calls < 2 }),
    (e) => e.category === 'cancelled',
  );
  const traced = [];
  mesh.straightestPaths({ points: false, onProgress: (s, f) => traced.push(f) });
  assert.equal(traced.at(-1), 1);
  assert.throws(() => mesh.parameterize({ onProgress: 42 }), TypeError);
  mesh.delete();
});
