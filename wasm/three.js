// straightest/three — three.js helpers, kept apart so the core package does not require three.
import { BufferAttribute, BufferGeometry } from 'three';
import { StraightestError } from './straightest-error.js';

/**
 * Builds a straightest Mesh from a three.js BufferGeometry (indexed or not). options.weld merges
 * vertices whose positions agree (true: to 1e-7 of the bounding box's diagonal; a number: that
 * distance) before building, for non-indexed geometry such as STLLoader's, whose triangles otherwise
 * share no vertex (every triangle its own component). Positions only: uv, normals and groups are not
 * looked at. Welded meshes have fewer vertices than the geometry: use toBufferGeometry for the result.
 */
export function meshFromBufferGeometry(st, geometry, { weld = false } = {}) {
  return meshOfArrays(st, meshArrays(geometry, weld, 'meshFromBufferGeometry'), weld);
}

const TOPOLOGY_ERRORS = ['non_manifold_edge', 'non_manifold_vertex'];

/** Whether the weld option asks for welding (true or a distance; false, null and undefined do not). */
const welds = (weld) => weld !== false && weld !== null && weld !== undefined;

/**
 * The Mesh of meshArrays' arrays. A topology error gets a sentence on welding: whether the geometry's
 * vertices are joined by position decides which surfaces touch where (three's CylinderGeometry and
 * ConeGeometry repeat a cap's centre once per segment: as they are, the cap's triangles only touch there).
 */
function meshOfArrays(st, { positions, indices }, weld) {
  try {
    return st.meshFromArrays(positions, indices);
  } catch (e) {
    if (!TOPOLOGY_ERRORS.includes(e?.category)) throw e;
    const hint = welds(weld)
      ? 'the vertices were welded by position: weld: false keeps the geometry’s own'
      : 'weld: true joins the geometry’s vertices that share a position (as three’s cylinder and cone caps need)';
    throw new StraightestError(`${e.message} (${hint})`, e.category, { cause: e });
  }
}

/**
 * The mesh arrays of a geometry: positions, indices (3 per triangle, welded when asked) and corners (the
 * geometry vertex of each triangle corner, in the same order).
 */
function meshArrays(geometry, weld, call) {
  const position = geometry.getAttribute('position');
  if (!position) throw new TypeError(`${call}: the geometry has no position attribute`);
  let positions = new Float64Array(position.count * 3);
  for (let i = 0; i < position.count; ++i) {
    positions[3 * i] = position.getX(i);
    positions[3 * i + 1] = position.getY(i);
    positions[3 * i + 2] = position.getZ(i);
  }
  const index = geometry.getIndex();
  const corners = index ? Uint32Array.from(index.array) : Uint32Array.from({ length: position.count }, (_, i) => i);
  let indices = corners;
  if (welds(weld)) {
    ({ positions, indices } = weldVertices(positions, indices, weldTolerance(positions, weld)));
  }
  return { positions, indices, corners };
}

function weldTolerance(positions, weld) {
  if (typeof weld === 'number') {
    if (!(weld >= 0) || !Number.isFinite(weld))
      throw new RangeError(`meshFromBufferGeometry: weld must be true or a distance >= 0, got ${weld}`);
    return weld;
  }
  if (weld !== true) throw new TypeError('meshFromBufferGeometry: weld must be true, false or a distance');
  const min = [Infinity, Infinity, Infinity],
    max = [-Infinity, -Infinity, -Infinity];
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
  const key =
    tolerance > 0
      ? (i) =>
          `${Math.round(positions[3 * i] / tolerance)},${Math.round(positions[3 * i + 1] / tolerance)},${Math.round(positions[3 * i + 2] / tolerance)}`
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

/**
 * Sets a geometry's 'uv' attribute from straightest's per-vertex uv (2 floats per vertex): the geometry
 * must have the mesh's vertices. A mesh made with `weld` has fewer vertices than the geometry it came
 * from; texture toBufferGeometry(mesh) (or toSeamSplitGeometry(mesh, p) for a cut mesh) instead.
 */
export function applyUV(geometry, uv) {
  const count = geometry.getAttribute('position')?.count;
  if (count !== undefined && uv.length !== 2 * count) {
    const fewer = uv.length < 2 * count;
    const hint = fewer
      ? ': the mesh has fewer vertices than the geometry (made with weld?); apply the uv to toBufferGeometry(mesh), ' +
        'or to toSeamSplitGeometry(mesh, p) for a cut mesh'
      : '';
    throw new RangeError(`applyUV: ${uv.length} numbers for ${count} vertices (expected ${2 * count})${hint}`);
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
    throw new RangeError(
      `toSeamSplitGeometry: cornerUv has ${corner?.length} numbers for ${indices.length / 3} ` +
        `faces (expected ${2 * indices.length})`,
    );
  }
  const copies = new Map(); // mesh vertex → [[u, v, geometry vertex], ...]: a seam vertex has a few
  const origin = [];
  const uvs = [];
  const index = new Uint32Array(indices.length);
  for (let c = 0; c < indices.length; ++c) {
    const v = indices[c];
    let u = corner[2 * c],
      w = corner[2 * c + 1];
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

const UV_CHANNELS = ['uv', 'uv1'];

/**
 * Unwraps a geometry into a texture atlas (mesh.atlas): returns { geometry, atlas }, a new geometry split
 * along the atlas's seams with the atlas uv on `channel` ('uv', default, or 'uv1', e.g. for a lightmap), and
 * the Atlas itself. options: channel, weld (as meshFromBufferGeometry's, default true: the charts are the
 * atlas's own, so they may cross the geometry's uv and normal seams, where its vertices are repeated; the
 * new geometry still keeps the geometry's own vertices) and mesh.atlas's options. See splitGeometry for
 * what the new geometry keeps.
 */
export function unwrap(st, geometry, options = {}) {
  const { channel = 'uv', weld = true, ...atlasOptions } = options;
  checkedChannel(channel, 'unwrap');
  const arrays = meshArrays(geometry, weld, 'unwrap');
  const mesh = meshOfArrays(st, arrays, weld);
  try {
    const atlas = mesh.atlas(atlasOptions);
    return { geometry: splitGeometry(geometry, arrays, mesh.indices(), atlas.cornerUv, channel), atlas };
  } finally {
    mesh.delete();
  }
}

/**
 * One texture atlas shared by several geometries (st.atlas; e.g. a scene's lightmap): returns
 * { geometries, atlas }, a new geometry per given one (in order, as unwrap's) and the SharedAtlas.
 * options: as unwrap's.
 */
export function packAtlas(st, geometries, options = {}) {
  if (!Array.isArray(geometries)) throw new TypeError('packAtlas: expects an array of BufferGeometry');
  const { channel = 'uv', weld = true, ...atlasOptions } = options;
  checkedChannel(channel, 'packAtlas');
  const arrays = geometries.map((g) => meshArrays(g, weld, 'packAtlas'));
  const meshes = [];
  try {
    for (const a of arrays) meshes.push(meshOfArrays(st, a, weld));
    const atlas = st.atlas(meshes, atlasOptions);
    return {
      geometries: geometries.map((g, i) =>
        splitGeometry(g, arrays[i], meshes[i].indices(), atlas.meshes[i].cornerUv, channel),
      ),
      atlas,
    };
  } finally {
    for (const mesh of meshes) mesh.delete();
  }
}

function checkedChannel(channel, call) {
  if (!UV_CHANNELS.includes(channel))
    throw new TypeError(`${call}: channel must be 'uv' or 'uv1', got ${String(channel)}`);
}

/**
 * The geometry split along the seams of cornerUv: one vertex per distinct (geometry vertex, uv), so every
 * attribute (position, normal, colour, the other uv channel, morph targets) is carried over as it was and
 * only seam vertices are duplicated; the triangles, their order and corner order, and the groups are the
 * geometry's. The index is Uint32; userData.vertexOrigin gives each new vertex's geometry vertex.
 * meshIndices are the mesh's (its faces may be reoriented: a corner is matched by its vertex, not its slot).
 */
function splitGeometry(geometry, { indices, corners }, meshIndices, cornerUv, channel) {
  const origin = [];
  const uvs = [];
  const index = new Uint32Array(corners.length);
  const copies = new Map(); // geometry vertex → [[u, v, new vertex], ...]: a seam vertex has a few
  for (let c = 0; c < corners.length; ++c) {
    const k = meshCorner(indices, meshIndices, c);
    const u = cornerUv[2 * k],
      v = cornerUv[2 * k + 1];
    let list = copies.get(corners[c]);
    if (!list) copies.set(corners[c], (list = []));
    let found = list.find((e) => e[0] === u && e[1] === v);
    if (!found) {
      found = [u, v, origin.length];
      list.push(found);
      origin.push(corners[c]);
      uvs.push(u, v);
    }
    index[c] = found[2];
  }
  const split = new BufferGeometry();
  split.name = geometry.name;
  for (const [name, attribute] of Object.entries(geometry.attributes)) {
    if (name !== channel) split.setAttribute(name, pickVertices(attribute, origin));
  }
  for (const [name, targets] of Object.entries(geometry.morphAttributes)) {
    split.morphAttributes[name] = targets.map((a) => pickVertices(a, origin));
  }
  split.morphTargetsRelative = geometry.morphTargetsRelative;
  split.setAttribute(channel, new BufferAttribute(new Float32Array(uvs), 2));
  split.setIndex(new BufferAttribute(index, 1));
  for (const { start, count, materialIndex } of geometry.groups) split.addGroup(start, count, materialIndex);
  split.userData.vertexOrigin = Uint32Array.from(origin);
  return split;
}

/** The mesh corner of geometry corner c: the corner of the same face with the same (welded) vertex. */
function meshCorner(indices, meshIndices, c) {
  const face = c - (c % 3);
  for (let k = face; k < face + 3; ++k) if (meshIndices[k] === indices[c]) return k;
  throw new RangeError(`the mesh's face ${face / 3} does not have the geometry's vertex ${indices[c]}`);
}

const GET = ['getX', 'getY', 'getZ', 'getW'];
const SET = ['setX', 'setY', 'setZ', 'setW'];

/** A new attribute with the given vertices of `attribute`, in order (same array type and normalization). */
function pickVertices(attribute, vertices) {
  const size = attribute.itemSize;
  const out = new BufferAttribute(new attribute.array.constructor(vertices.length * size), size, attribute.normalized);
  if (!attribute.isInterleavedBufferAttribute) {
    vertices.forEach((v, i) => out.array.set(attribute.array.subarray(v * size, v * size + size), i * size));
  } else {
    // getX…getW read through the interleaving (and denormalize; setX…setW normalize back).
    vertices.forEach((v, i) => {
      for (let k = 0; k < size; ++k) out[SET[k]](i, attribute[GET[k]](v));
    });
  }
  return out;
}
