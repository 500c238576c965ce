// The malformed-input corpus through the npm API: each file throws an Error with the expected
// category and a message (never a number, never a crash of the module).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { createStraightest } from '../../wasm/index.js';

const st = await createStraightest();
const dir = new URL('../data/bad/', import.meta.url);
const expected = JSON.parse(await readFile(new URL('expected.json', dir), 'utf8'));

test(`the malformed corpus (${Object.keys(expected).length} files) is rejected with its categories`, async () => {
  for (const [name, category] of Object.entries(expected)) {
    const bytes = await readFile(new URL(name, dir));
    const format = /\.(obj|off|ply|stl)$/.exec(name)?.[1] ?? 'auto';
    assert.throws(
      () => st.loadMesh(bytes, format),
      (e) => {
        assert.ok(e instanceof Error, `${name}: not an Error`);
        assert.equal(e.category, category, `${name}: ${e.message}`);
        assert.ok(e.message.length > 10, `${name}: message too short`);
        return true;
      },
      name,
    );
  }
  // The module is still healthy afterwards.
  const mesh = st.sample('cap');
  assert.equal(mesh.info().components, 1);
  mesh.delete();
});
