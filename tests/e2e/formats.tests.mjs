// Browser tests of the file formats the page reads through three's loaders (STL, PLY, glTF/GLB: welded
// into a mesh by meshFromBufferGeometry) and of the GLB export. The files are the unit cube of
// tests/data/good (8 vertices, 12 faces, closed) in each format; the GLB holds it as two meshes under
// nested transforms, so only merging them in world coordinates and welding gives the cube back.
// Imported by browser.test.mjs, which owns the browser (useBrowser).

import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { describe } from 'node:test';
import { expectReady, pageTest, settled } from './support/fixtures.mjs';

const good = new URL('../data/good/', import.meta.url);

async function loadCube(page, file, mimeType = 'application/octet-stream') {
  await page.setInputFiles('#file-input', { name: file, mimeType, buffer: await readFile(new URL(file, good)) });
  await expectReady(page, 'window.__straightest.lastInfo && window.__straightest.lastInfo.vertices !== 2500');
  return page.evaluate(() => window.__straightest.lastInfo);
}

function assertCube(info, file) {
  assert.equal(info.vertices, 8, `${file}: ${info.vertices} vertices after welding (the cube has 8)`);
  assert.equal(info.faces, 12, `${file}: ${info.faces} faces`);
  assert.equal(
    info.eulerCharacteristic,
    2,
    `${file}: Euler characteristic ${info.eulerCharacteristic} (closed, genus 0)`,
  );
  assert.equal(info.components, 1, `${file}: ${info.components} components`);
  assert.deepEqual(info.boundaryLoops, [], `${file}: boundary loops ${info.boundaryLoops}`);
}

describe('formats', () => {
  pageTest(
    'STL (binary and ASCII), PLY and a two-mesh GLB each load as the welded 8-vertex cube',
    {},
    async ({ page }) => {
      const accept = await page.getAttribute('#file-input', 'accept');
      for (const extension of ['.stl', '.ply', '.glb', '.gltf', '.obj', '.off'])
        assert(accept.split(',').includes(extension), `the file input does not accept ${extension}: ${accept}`);
      for (const file of ['cube_binary.stl', 'cube_ascii.stl', 'cube_binary_le.ply', 'cube_two_meshes.glb']) {
        assertCube(await loadCube(page, file), file);
        // The merged glTF meshes are said so in the status line.
        if (file.endsWith('.glb')) assert.match(await page.textContent('#status'), /2 glTF meshes merged/);
      }
    },
  );

  pageTest('an unreadable GLB and a PLY point cloud get readable errors', {}, async ({ page }) => {
    await page.setInputFiles('#file-input', {
      name: 'broken.glb',
      mimeType: 'model/gltf-binary',
      buffer: Buffer.from('glTF this is not a real binary glTF'),
    });
    let { state, lastError } = await settled(page, `document.body.dataset.state === 'error'`);
    assert.equal(state, 'error');
    assert.match(lastError.message, /broken\.glb/, `error: ${lastError.message}`);
    const cloud =
      'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n' +
      'end_header\n0 0 0\n1 0 0\n0 1 0\n';
    await page.setInputFiles('#file-input', { name: 'cloud.ply', mimeType: 'text/plain', buffer: Buffer.from(cloud) });
    ({ state, lastError } = await settled(page, `window.__straightest.lastError?.message.includes('cloud.ply')`));
    assert.equal(state, 'error');
    assert.match(lastError.message, /no faces/, `error: ${lastError.message}`);
  });

  pageTest(
    'the parameterized surface exports as a GLB with uv and an OBJ named by boundary and weights',
    {
      ready: 'window.__straightest.param',
    },
    async ({ page }) => {
      const { boundary, weights } = await page.evaluate(() => window.__straightest.param);
      const [obj] = await Promise.all([page.waitForEvent('download'), page.click('#export-obj-button')]);
      assert.equal(obj.suggestedFilename(), `mountain-${boundary}-${weights}.obj`);
      const [glb] = await Promise.all([page.waitForEvent('download'), page.click('#export-glb-button')]);
      assert.equal(glb.suggestedFilename(), `mountain-${boundary}-${weights}.glb`);
      const chunks = [];
      for await (const chunk of await glb.createReadStream()) chunks.push(chunk);
      const bytes = Buffer.concat(chunks);
      assert.equal(bytes.toString('latin1', 0, 4), 'glTF', 'not a binary glTF');
      const json = JSON.parse(bytes.toString('utf8', 20, 20 + bytes.readUInt32LE(12)));
      const attributes = json.meshes[0].primitives[0].attributes;
      assert('TEXCOORD_0' in attributes && 'POSITION' in attributes, `GLB attributes: ${Object.keys(attributes)}`);
      assert.equal(json.accessors[attributes.POSITION].count, 2500, 'the mountain has 2500 vertices (a disk: no seam)');
    },
  );
});
