// straightest/three — three.js helpers, kept apart so the core package does not require three.
import { BufferAttribute, BufferGeometry } from 'three';

/** Builds a straightest Mesh from a three.js BufferGeometry (indexed or not). */
export function meshFromBufferGeometry(st, geometry) {
  const position = geometry.getAttribute('position');
  if (!position) throw new TypeError('meshFromBufferGeometry: the geometry has no position attribute');
  const positions = new Float64Array(position.count * 3);
  for (let i = 0; i < position.count; ++i) {
    positions[3 * i] = position.getX(i);
    positions[3 * i + 1] = position.getY(i);
    positions[3 * i + 2] = position.getZ(i);
  }
  const index = geometry.getIndex();
  const indices = index ? Uint32Array.from(index.array) : Uint32Array.from({ length: position.count }, (_, i) => i);
  return st.meshFromArrays(positions, indices);
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
