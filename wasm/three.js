// straightest/three — three.js helpers, kept apart so the core package does not require three.
import { BufferAttribute, BufferGeometry } from 'three';

/**
 * Builds a straightest Mesh from a three.js BufferGeometry (indexed or not). options.weld merges
 * vertices whose positions agree (true: to 1e-7 of the bounding box's diagonal; a number: that
 * distance) before building, for non-indexed geometry such as STLLoader's, whose triangles otherwise
 * share no vertex (every triangle its own component). Positions only: uv, normals and groups are not
 * looked at. Welded meshes have fewer vertices than the geometry: use toBufferGeometry for the result.
 */
export function meshFromBufferGeometry(st, geometry, { weld = false } = {}) {
  const position = geometry.getAttribute('position');
  if (!position) throw new TypeError('meshFromBufferGeometry: the geometry has no position attribute');
  let positions = new Float64Array(position.count * 3);
  for (let i = 0; i < position.count; ++i) {
    positions[3 * i] = position.getX(i);
    positions[3 * i + 1] = position.getY(i);
    positions[3 * i + 2] = position.getZ(i);
  }
  const index = geometry.getIndex();
  let indices = index ? Uint32Array.from(index.array) : Uint32Array.from({ length: position.count }, (_, i) => i);
  if (weld !== false && weld !== null && weld !== undefined) {
    ({ positions, indices } = weldVertices(positions, indices, weldTolerance(positions, weld)));
  }
  return st.meshFromArrays(positions, indices);
}

function weldTolerance(positions, weld) {
  if (typeof weld === 'number') {
    if (!(weld >= 0) || !Number.isFinite(weld)) throw new RangeError(`meshFromBufferGeometry: weld must be true or a distance >= 0, got ${weld}`);
    return weld;
  }
  if (weld !== true) throw new TypeError('meshFromBufferGeometry: weld must be true, false or a distance');
  const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; ++i) {
    min[i % 3] = Math.min(min[i % 3], positions[i]);
    max[i % 3] = Math.max(max[i % 3], positions[i]);
  }
  const diagonal = Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
  return Number.isFinite(diagonal) ? 1e-7 * diagonal : 0;
}

/**
 * Merges vertices that fall in the same cell of a grid of spacing `tolerance` (exact equality for 0);
 * the first vertex of a cell stands for all of it. Unreferenced vertices are dropped.
 */
function weldVertices(positions, indices, tolerance) {
  const key = tolerance > 0
    ? (i) => `${Math.round(positions[3 * i] / tolerance)},${Math.round(positions[3 * i + 1] / tolerance)},${Math.round(positions[3 * i + 2] / tolerance)}`
    : (i) => `${positions[3 * i]},${positions[3 * i + 1]},${positions[3 * i + 2]}`;
  const cellVertex = new Map();
  const kept = [];
  const welded = new Uint32Array(indices.length);
  for (let k = 0; k < indices.length; ++k) {
    const v = indices[k];
    const cell = key(v);
    let w = cellVertex.get(cell);
    if (w === undefined) {
      w = kept.length;
      cellVertex.set(cell, w);
      kept.push(v);
    }
    welded[k] = w;
  }
  const out = new Float64Array(3 * kept.length);
  kept.forEach((v, w) => out.set(positions.subarray(3 * v, 3 * v + 3), 3 * w));
  return { positions: out, indices: welded };
}

/** A BufferGeometry (Float32 positions, the core's area-weighted vertex normals, Uint32 index) of a straightest Mesh. */
export function toBufferGeometry(mesh) {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(new Float32Array(mesh.positions()), 3));
  geometry.setAttribute('normal', new BufferAttribute(mesh.vertexNormals(), 3));
  geometry.setIndex(new BufferAttribute(mesh.indices(), 1));
  return geometry;
}

/** Sets a geometry's 'uv' attribute from straightest's per-vertex uv (2 floats per vertex). */
export function applyUV(geometry, uv) {
  const count = geometry.getAttribute('position')?.count;
  if (count !== undefined && uv.length !== 2 * count) {
    throw new RangeError(`applyUV: ${uv.length} numbers for ${count} vertices (expected ${2 * count})`);
  }
  geometry.setAttribute('uv', new BufferAttribute(uv instanceof Float32Array ? uv : new Float32Array(uv), 2));
  return geometry;
}

/**
 * A BufferGeometry textured by a parameterization, split along its seam: one geometry vertex per
 * distinct (mesh vertex, corner uv) pair, so a cut mesh's two sides of the seam get their own uv and no
 * triangle smears the texture across it (for a disk this is the mesh's own vertices). Faces outside the
 * parameterized component (NaN corner uv) get uv (0, 0). Attributes: position, normal (the core's
 * vertex normals), uv; index: Uint32. `vertexOrigin` (userData) gives each geometry vertex's mesh vertex.
 */
export function toSeamSplitGeometry(mesh, parameterization) {
  const positions = mesh.positions();
  const normals = mesh.vertexNormals();
  const indices = mesh.indices();
  const corner = parameterization.cornerUv;
  if (!corner || corner.length !== 2 * indices.length) {
    throw new RangeError(`toSeamSplitGeometry: cornerUv has ${corner?.length} numbers for ${indices.length / 3} ` +
      `faces (expected ${2 * indices.length})`);
  }
  const copies = new Map();  // mesh vertex → [[u, v, geometry vertex], ...]: a seam vertex has a few
  const origin = [];
  const uvs = [];
  const index = new Uint32Array(indices.length);
  for (let c = 0; c < indices.length; ++c) {
    const v = indices[c];
    let u = corner[2 * c], w = corner[2 * c + 1];
    if (!Number.isFinite(u) || !Number.isFinite(w)) u = w = 0;
    let list = copies.get(v);
    if (!list) copies.set(v, (list = []));
    let found = list.find((e) => e[0] === u && e[1] === w);
    if (!found) {
      found = [u, w, origin.length];
      list.push(found);
      origin.push(v);
      uvs.push(u, w);
    }
    index[c] = found[2];
  }
  const position = new Float32Array(3 * origin.length);
  const normal = new Float32Array(3 * origin.length);
  origin.forEach((v, i) => {
    for (let k = 0; k < 3; ++k) {
      position[3 * i + k] = positions[3 * v + k];
      normal[3 * i + k] = normals[3 * v + k];
    }
  });
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(position, 3));
  geometry.setAttribute('normal', new BufferAttribute(normal, 3));
  geometry.setAttribute('uv', new BufferAttribute(new Float32Array(uvs), 2));
  geometry.setIndex(new BufferAttribute(index, 1));
  geometry.userData.vertexOrigin = Uint32Array.from(origin);
  return geometry;
}
