// Real WebAssembly allocation failure (its own file, so its own process: the module's memory stays at
// its 4 GB maximum afterwards). Meshes of 1.44 M vertices are kept alive until the memory is full; the
// failing call must be a StraightestError 'too_large', and the module must keep working after the
// meshes are deleted. Takes ~15-20 s.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createStraightest, StraightestError } from '../../wasm/index.js';

const st = await createStraightest();

test('filling the 4 GB WebAssembly memory gives a too_large Error, and the module still works', () => {
  const n = 1200;
  const positions = new Float64Array(3 * n * n);
  const indices = new Uint32Array(6 * (n - 1) * (n - 1));
  for (let j = 0; j < n; ++j)
    for (let i = 0; i < n; ++i) positions.set([i, j, Math.sin(i * 0.01) * Math.cos(j * 0.01)], 3 * (j * n + i));
  let k = 0;
  for (let j = 0; j + 1 < n; ++j)
    for (let i = 0; i + 1 < n; ++i) {
      const a = j * n + i;
      indices.set([a, a + 1, a + n + 1, a, a + n + 1, a + n], k);
      k += 6;
    }
  const kept = [];
  let failure;
  try {
    for (let r = 0; r < 64 && !failure; ++r)
      kept.push(st.meshFromArrays(positions, indices, { maxVertices: 1e8, maxFaces: 1e8 }));
  } catch (e) {
    failure = e;
  }
  const count = kept.length;
  for (const m of kept) m.delete();
  assert.ok(failure, `${count} meshes of ${n * n} vertices fit: memory never ran out`);
  assert.ok(failure instanceof StraightestError, `not a StraightestError: ${failure}`);
  assert.ok(failure instanceof Error);
  assert.equal(failure.category, 'too_large');
  assert.match(failure.message, /too large for the available memory/);
  assert.ok(count >= 4, `failed after only ${count} meshes`);
  // The module is intact: a new mesh loads and parameterizes.
  const mesh = st.sample('mountain');
  assert.equal(mesh.info().vertices, 2500);
  assert.equal(mesh.parameterize().bijective, true);
  mesh.delete();
});
