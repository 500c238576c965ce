// Meshes that are not disks through the npm API: holes filled, closed surfaces cut along a seam; the
// map per face corner, the seam, the OBJ export that splits it and the three.js geometry split along it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createStraightest } from '../../wasm/index.js';
import { toSeamSplitGeometry } from '../../wasm/three.js';

const st = await createStraightest();

/** Corner c's uv as a key (exact Float32 values). */
const cornerKey = (p, c) => `${p.cornerUv[2 * c]},${p.cornerUv[2 * c + 1]}`;

test('a sphere and a torus are cut along a seam: corners agree with uv off the seam and split across it', () => {
  for (const [name, cut, genus] of [
    ['sphere', 'path', 0],
    ['torus', 'cut-graph', 1],
  ]) {
    const mesh = st.sample(name);
    const { vertices, faces } = mesh.info();
    const p = mesh.parameterize({ boundary: 'circle', weights: 'mean-value' });
    assert.equal(p.cut, cut, name);
    assert.equal(p.genus, genus, name);
    assert.equal(p.bijective, true, name);
    assert.ok(Number.isFinite(p.stretch.l2), name);
    assert.ok(p.cornerUv instanceof Float32Array && p.cornerUv.length === 6 * faces, name);
    assert.ok(p.seam instanceof Int32Array && p.seam.length === 2 * p.seamEdges && p.seamEdges > 0, name);
    assert.ok(p.seamLength > 0, name);
    assert.deepEqual(p.filledLoops, []);
    assert.equal(p.uv.length, 2 * vertices);
    assert.ok(p.timings.cut > 0, 'the cut is timed');
    const seamVertices = new Set(p.seam);
    const indices = mesh.indices();
    indices.forEach((v, c) => {
      if (seamVertices.has(v)) return;
      assert.equal(p.cornerUv[2 * c], p.uv[2 * v]);
      assert.equal(p.cornerUv[2 * c + 1], p.uv[2 * v + 1]);
    });
    // A seam vertex inside the seam (two seam edges or more) has several corner uv: the surface is split
    // there (a seam's loose end, where a path seam stops, has one).
    const seamDegree = new Map();
    for (const v of p.seam) seamDegree.set(v, (seamDegree.get(v) ?? 0) + 1);
    const keys = new Map();
    indices.forEach((v, c) => {
      if (!seamVertices.has(v)) return;
      if (!keys.has(v)) keys.set(v, new Set());
      keys.get(v).add(cornerKey(p, c));
    });
    let inner = 0;
    for (const [v, set] of keys) {
      if (seamDegree.get(v) < 2) continue;
      inner += 1;
      assert.ok(set.size >= 2, `${name}: seam vertex ${v} is not split`);
    }
    assert.ok(inner > 0, name);
    mesh.delete();
  }
});

test('holes are filled virtually: no seam, one virtual vertex per hole, none of them in the output', () => {
  const mesh = st.sample('holes');
  for (const boundary of ['measured', 'circle', 'free']) {
    const p = mesh.parameterize({ boundary, maxIterations: 30 });
    assert.equal(p.cut, 'fill');
    assert.equal(p.filledLoops.length, 3);
    assert.equal(p.virtualVertices, 3);
    assert.equal(p.seam.length, 0);
    assert.equal(p.bijective, true, boundary);
    assert.equal(p.uv.length, 2 * mesh.info().vertices, 'uv for the real vertices only');
    mesh.indices().forEach((v, c) => assert.equal(p.cornerUv[2 * c], p.uv[2 * v]));
  }
  const { rows } = mesh.compareParameterizations({ boundaries: ['circle', 'free'], weights: ['uniform'] });
  for (const row of rows) assert.equal(row.error, null, `${row.boundary}: ${row.error}`);
  mesh.delete();
});

test('toOBJ with cornerUv writes a vt per distinct uv: the seam splits, and the mesh reads back', () => {
  const mesh = st.sample('torus');
  const p = mesh.parameterize({ boundary: 'circle' });
  const text = mesh.toOBJ(p.cornerUv);
  const vt = text.split('\n').filter((line) => line.startsWith('vt '));
  const distinct = new Set(Array.from({ length: p.cornerUv.length / 2 }, (_, c) => cornerKey(p, c)));
  assert.ok(vt.length > mesh.info().vertices, 'more vt than vertices');
  assert.ok(vt.length >= distinct.size && vt.length <= p.cornerUv.length / 2, 'one vt per distinct uv');
  assert.match(text, /\nf \d+\/\d+ \d+\/\d+ \d+\/\d+\n/);
  const again = st.loadMesh(text, 'obj');
  assert.equal(again.info().faces, mesh.info().faces);
  again.delete();
  assert.throws(() => mesh.toOBJ(new Float32Array(5)), /2 per face corner/);
  // A vertex's vt is always written: it must be a number (a corner's NaN only drops its vt).
  const perVertex = new Float64Array(2 * mesh.info().vertices).fill(0.5);
  perVertex[7] = NaN;
  assert.throws(
    () => mesh.toOBJ(perVertex),
    (e) => e.category === 'non_finite' && /uv\[7\]/.test(e.message),
  );
  mesh.delete();
});

test('toSeamSplitGeometry gives each side of the seam its own vertices and the corners their uv', () => {
  const torus = st.sample('torus');
  const p = torus.parameterize({ boundary: 'circle' });
  const geometry = toSeamSplitGeometry(torus, p);
  const uv = geometry.getAttribute('uv');
  const position = geometry.getAttribute('position');
  const index = geometry.getIndex().array;
  const positions = torus.positions();
  const indices = torus.indices();
  assert.ok(position.count > torus.info().vertices, 'seam vertices are duplicated');
  assert.equal(index.length, indices.length);
  index.forEach((g, c) => {
    assert.equal(uv.getX(g), p.cornerUv[2 * c]);
    assert.equal(uv.getY(g), p.cornerUv[2 * c + 1]);
    assert.equal(geometry.userData.vertexOrigin[g], indices[c]);
    assert.equal(position.getX(g), Math.fround(positions[3 * indices[c]]));
  });
  torus.delete();
  const disk = st.sample('cap');
  const q = disk.parameterize({ boundary: 'circle' });
  assert.equal(
    toSeamSplitGeometry(disk, q).getAttribute('position').count,
    disk.info().vertices,
    'a disk is not split',
  );
  assert.throws(() => toSeamSplitGeometry(disk, { cornerUv: new Float32Array(3) }), RangeError);
  disk.delete();
});

test('cutting is the first stage reported, and cancelling there is an error that leaves the mesh usable', () => {
  const mesh = st.sample('sphere');
  const stages = [];
  mesh.parameterize({
    boundary: 'circle',
    onProgress: (stage) => {
      stages.push(stage);
      return true;
    },
  });
  assert.equal(stages[0], 'cut');
  assert.throws(
    () => mesh.parameterize({ onProgress: (stage) => stage !== 'cut' }),
    (e) => e.category === 'cancelled',
  );
  assert.equal(mesh.parameterize({ boundary: 'square' }).bijective, true);
  mesh.delete();
});
