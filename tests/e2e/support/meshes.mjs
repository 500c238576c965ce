// The meshes the browser tests load: small OBJ/OFF texts and the large height-field grid of the
// responsiveness tests (written once to a temporary file).

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

// A 3×3 vertex grid (z = 0) with 4 quads: the OBJ loader triangulates them into 8 faces.
export const QUAD_GRID_OBJ = [
  '# 3x3 quad grid',
  'v 0 0 0',
  'v 1 0 0',
  'v 2 0 0',
  'v 0 1 0',
  'v 1 1 0.2',
  'v 2 1 0',
  'v 0 2 0',
  'v 1 2 0',
  'v 2 2 0',
  'f 1 2 5 4',
  'f 2 3 6 5',
  'f 4 5 8 7',
  'f 5 6 9 8',
  '',
].join('\n');

// A consistently oriented tetrahedron: closed, genus 0.
export const TETRAHEDRON_OFF = 'OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n';

/** OBJ text of an n × n height-field grid over [0,1]² (two triangles per cell): a disk. */
export function heightFieldObj(n) {
  const lines = [`# ${n}x${n} height field`];
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const [x, y] = [i / (n - 1), j / (n - 1)];
      lines.push(`v ${x.toFixed(6)} ${y.toFixed(6)} ${(0.15 * Math.sin(3 * x) * Math.cos(2 * y)).toFixed(6)}`);
    }
  }
  for (let j = 0; j + 1 < n; j++) {
    for (let i = 0; i + 1 < n; i++) {
      const a = j * n + i + 1; // OBJ indices start at 1
      lines.push(`f ${a} ${a + 1} ${a + n + 1}`, `f ${a} ${a + n + 1} ${a + n}`);
    }
  }
  return `${lines.join('\n')}\n`;
}

// The large mesh of the responsiveness tests: 448 × 448 = 200,704 vertices, 399,618 faces, and
// 4 × 447 = 1788 boundary vertices (~14 MB). Written once to a temporary file: Playwright hands a
// file path to the input directly, while a buffer would be decoded on the page's main thread.
export const BIG_GRID_N = 448;
export const BIG_GRID_VERTICES = BIG_GRID_N * BIG_GRID_N;
let bigGridDir = null;
export function bigGridFile() {
  if (!bigGridDir) {
    bigGridDir = fs.mkdtempSync(path.join(os.tmpdir(), 'straightest-e2e-'));
    fs.writeFileSync(path.join(bigGridDir, 'grid-200k.obj'), heightFieldObj(BIG_GRID_N));
  }
  return path.join(bigGridDir, 'grid-200k.obj');
}
export function removeBigGrid() {
  if (bigGridDir) fs.rmSync(bigGridDir, { recursive: true, force: true });
  bigGridDir = null;
}
