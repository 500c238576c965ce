// The geometry of the plain path lines, path-view.js's fallback for many paths: 1-pixel LineSegments
// over every k-th point of each path. It is built in slices (slices.js): a large mesh's thousands of
// boundary paths hold millions of points, and walking them takes longer than a task on the page's
// main thread should.

import * as THREE from 'three';
import { inSlices } from './slices.js';

// Plain lines draw at most about this many points: every k-th point of each path (and its last).
// Beyond that the points are closer than a pixel, and uploading and drawing them would only cost
// time (a 1M-vertex mesh's boundary paths have ~5M points).
const PLAIN_LINE_POINTS = 250_000;
const PATHS_PER_CHUNK = 16; // paths walked between two looks at the slice's time

/**
 * start[i]: the first kept point of path i, keeping every `stride`-th point and the last; a path of
 * n ≥ 2 points keeps ⌈(n−1)/stride⌉ + 1, and start[count] is how many are kept in all.
 */
function keptStarts(offsets, count, stride) {
  const start = new Uint32Array(count + 1);
  for (let i = 0; i < count; i++) {
    const n = offsets[i + 1] - offsets[i];
    start[i + 1] = start[i] + (n < 2 ? n : Math.ceil((n - 1) / stride) + 1);
  }
  return start;
}

/** Copies the kept points of paths [from, to) into `kept` and grows `box` around them. */
function copyKept({ points, offsets }, start, stride, kept, box, from, to) {
  const copy = (j, k) => {
    kept[3 * k] = points[3 * j];
    kept[3 * k + 1] = points[3 * j + 1];
    kept[3 * k + 2] = points[3 * j + 2];
  };
  for (let i = from; i < to; i++) {
    const first = offsets[i];
    const end = offsets[i + 1];
    let k = start[i];
    for (let j = first; j < end; j += stride) copy(j, k++);
    if (k < start[i + 1]) copy(end - 1, k); // the last point, when the stride skipped it
  }
  // The bounds as the points go by: three's own bounding sphere (which the upload wants) walks them
  // all again, twice.
  const point = new THREE.Vector3();
  for (let k = 3 * start[from]; k < 3 * start[to]; k += 3) box.expandByPoint(point.fromArray(kept, k));
}

/**
 * The geometry of plain LineSegments, one group per [paths, material] entry of `groups`, over one
 * position attribute holding every `stride`-th point of each path of `reply` (a 'paths' reply) and
 * its last (see PLAIN_LINE_POINTS), with an index pair per segment. No picking data. Resolves with
 * { geometry, materials, stride }; pause() goes between slices (slices.js's inSlices: a pause that
 * rejects stops the building).
 */
export async function plainPathGeometry(reply, groups, pause) {
  const { offsets, count } = reply;
  const stride = Math.max(1, Math.ceil(offsets[count] / PLAIN_LINE_POINTS));
  const start = keptStarts(offsets, count, stride);
  const kept = new Float32Array(3 * start[count]);
  const box = new THREE.Box3();
  const copy = (from, to) => copyKept(reply, start, stride, kept, box, from, to);
  await inSlices(count, copy, { chunk: PATHS_PER_CHUNK, pause });

  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(kept, 3));
  geometry.boundingBox = box;
  geometry.boundingSphere = box.getBoundingSphere(new THREE.Sphere());
  const segmentsOf = (paths) => {
    let segments = 0;
    for (const i of paths) segments += Math.max(0, start[i + 1] - start[i] - 1);
    return segments;
  };
  const index = new Uint32Array(2 * groups.reduce((total, [paths]) => total + segmentsOf(paths), 0));
  const materials = [];
  let s = 0;
  for (const [paths, material] of groups) {
    const first = s;
    const pairs = (from, to) => {
      for (let p = from; p < to; p++) {
        const i = paths[p];
        for (let j = start[i]; j + 1 < start[i + 1]; j++) {
          index[s++] = j;
          index[s++] = j + 1;
        }
      }
    };
    await inSlices(paths.length, pairs, { chunk: PATHS_PER_CHUNK, pause });
    if (s > first) geometry.addGroup(first, s - first, materials.push(material) - 1);
  }
  geometry.setIndex(new THREE.BufferAttribute(index, 1));
  return { geometry, materials, stride };
}
