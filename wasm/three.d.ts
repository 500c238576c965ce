// Types of straightest/three. They import three's types: install `@types/three` next to `three`
// (three ships no declarations), or this file fails to type-check without skipLibCheck.
import type { BufferGeometry } from 'three';
import type { Atlas, AtlasOptions, Mesh, Parameterization, SharedAtlas, Straightest } from './index.js';

/** meshFromBufferGeometry's options. */
export interface MeshFromBufferGeometryOptions {
  /**
   * Merge vertices whose positions agree before building: true (within 1e-7 of the bounding box's
   * diagonal) or a distance. For non-indexed geometry (STLLoader's, toNonIndexed()), whose triangles
   * otherwise share no vertex. Default false. A welded mesh has fewer vertices than the geometry, so its
   * uv does not fit the geometry (applyUV throws a RangeError): texture toBufferGeometry(mesh), or
   * toSeamSplitGeometry(mesh, p) for a cut mesh.
   */
  weld?: boolean | number;
}

/** Builds a straightest Mesh from a three.js BufferGeometry's positions and index (indexed or not). */
export function meshFromBufferGeometry(
  st: Straightest,
  geometry: BufferGeometry,
  options?: MeshFromBufferGeometryOptions,
): Mesh;
/** A BufferGeometry (Float32 positions, the core's area-weighted vertex normals, Uint32 index) of a straightest Mesh. */
export function toBufferGeometry(mesh: Mesh): BufferGeometry;
/**
 * Sets geometry's 'uv' attribute from straightest's uv (2 floats per vertex); returns the geometry. The
 * geometry must have the mesh's vertices (else a RangeError): after `weld`, use toBufferGeometry(mesh)
 * (or toSeamSplitGeometry(mesh, p) for a cut mesh) as the geometry to texture.
 */
export function applyUV(geometry: BufferGeometry, uv: ArrayLike<number>): BufferGeometry;
/**
 * A BufferGeometry textured by a parameterization and split along its seam (one vertex per distinct mesh
 * vertex and corner uv), so the texture does not smear across a cut mesh's seam. Needs cornerUv (every
 * parameterize result has it); userData.vertexOrigin maps each geometry vertex to its mesh vertex.
 */
export function toSeamSplitGeometry(mesh: Mesh, parameterization: Pick<Parameterization, 'cornerUv'>): BufferGeometry;

/** unwrap's and packAtlas' options: where the uv goes, welding, and mesh.atlas's options. */
export interface UnwrapOptions extends AtlasOptions, MeshFromBufferGeometryOptions {
  /** The attribute that receives the atlas uv: 'uv' (default) or 'uv1' (three's second set, e.g. for a lightmap). */
  channel?: 'uv' | 'uv1';
  /**
   * Merge vertices whose positions agree before the atlas is made: true (the default here: within 1e-7 of the
   * bounding box's diagonal), a distance, or false. The geometry keeps its own vertices either way; welding
   * only lets the charts cross its uv and normal seams (and three's cylinder and cone caps, whose centre repeats).
   */
  weld?: boolean | number;
}

/**
 * Unwraps a geometry into a texture atlas (Mesh.atlas). weld defaults to true (as in packAtlas): the atlas's charts
 * may cross the geometry's uv and normal seams, where its vertices repeat; the new geometry keeps its own vertices.
 * The new geometry is split along the atlas's seams (one vertex per distinct geometry vertex and uv), keeps
 * every other attribute, morph target, group and the triangles' order, and has the atlas uv on `channel`;
 * userData.vertexOrigin maps each of its vertices to the geometry's. Every triangle of the geometry is unwrapped
 * (drawRange is not looked at).
 */
export function unwrap(
  st: Straightest,
  geometry: BufferGeometry,
  options?: UnwrapOptions,
): { geometry: BufferGeometry; atlas: Atlas };
/** One atlas shared by several geometries (Straightest.atlas): a new geometry per given one, as unwrap's, in order. */
export function packAtlas(
  st: Straightest,
  geometries: BufferGeometry[],
  options?: UnwrapOptions,
): { geometries: BufferGeometry[]; atlas: SharedAtlas };
