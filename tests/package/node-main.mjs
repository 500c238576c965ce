// Run by tests/js/consumer.test.mjs inside a fresh project where the packed package is installed:
// Node ESM through the package's own exports, the inline variant, the three.js helpers and the .wasm's
// export. Prints one JSON line of facts for the test to check.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { createStraightest, StraightestError } from 'straightest';
import * as inline from 'straightest/inline';
import { meshFromBufferGeometry } from 'straightest/three';
import { PlaneGeometry } from 'three';

const st = await createStraightest();
const mesh = st.sample('cap');
const param = mesh.parameterize();
const embedded = await inline.createStraightest();
const welded = meshFromBufferGeometry(embedded, new PlaneGeometry(1, 1, 4, 4).toNonIndexed(), { weld: true });
const wasmPath = fileURLToPath(import.meta.resolve('straightest/straightest-core.wasm'));
let missing;
try {
  await createStraightest({ wasmUrl: 'http://127.0.0.1:9/straightest-core.wasm' });
} catch (e) {
  missing = { isStraightestError: e instanceof StraightestError, category: e.category, message: e.message };
}
console.log(
  JSON.stringify({
    vertices: mesh.info().vertices,
    bijective: param.bijective,
    inlineVertices: embedded.sample('cap').info().vertices,
    sameErrorClass: inline.StraightestError === StraightestError,
    weldedVertices: welded.info().vertices,
    weldedComponents: welded.info().components,
    wasmMagic: readFileSync(wasmPath).subarray(0, 4).toString('hex'),
    missing,
  }),
);
mesh.delete();
welded.delete();
