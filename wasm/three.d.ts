// Types of straightest/three. They import three's types: install `@types/three` next to `three`
// (three ships no declarations), or this file fails to type-check without skipLibCheck.
import type { BufferGeometry } from 'three';
import type { Mesh, Parameterization, Straightest } from './index.js';

/** meshFromBufferGeometry's options. */
export interface MeshFromBufferGeometryOptions {
  /**
   * Merge vertices whose positions agree before building: true (within 1e-7 of the bounding box's
   * diagonal) or a distance. For non-indexed geometry (STLLoader's, toNonIndexed()), whose triangles
   * otherwise share no vertex. Default false.
   */
  weld?: boolean | number;
}

/** Builds a straightest Mesh from a three.js BufferGeometry's positions and index (indexed or not). */
export function meshFromBufferGeometry(st: Straightest, geometry: BufferGeometry, options?: MeshFromBufferGeometryOptions): Mesh;
/** A BufferGeometry (Float32 positions, the core's area-weighted vertex normals, Uint32 index) of a straightest Mesh. */
export function toBufferGeometry(mesh: Mesh): BufferGeometry;
/** Sets geometry's 'uv' attribute from straightest's uv (2 floats per vertex); returns the geometry. */
export function applyUV(geometry: BufferGeometry, uv: ArrayLike<number>): BufferGeometry;
/**
 * A BufferGeometry textured by a parameterization and split along its seam (one vertex per distinct mesh
 * vertex and corner uv), so the texture does not smear across a cut mesh's seam. Needs cornerUv (every
 * parameterize result has it); userData.vertexOrigin maps each geometry vertex to its mesh vertex.
 */
export function toSeamSplitGeometry(mesh: Mesh, parameterization: Pick<Parameterization, 'cornerUv'>): BufferGeometry;
