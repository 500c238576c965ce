// The npm package's types for the texture atlas (Mesh.atlas, Straightest.atlas, straightest/three's
// unwrap and packAtlas). Re-exported by index.d.ts.
import type { ProgressCallback } from './index.js';
/** mesh.atlas's and st.atlas's options; each may be left out (the default). Out-of-range values throw 'invalid_argument'. */
export interface AtlasOptions {
  /** Largest Sander L2 stretch of a chart (≥ 1, default 1.02): a chart above it is split. */
  maxStretch?: number;
  /**
   * Least fraction of its convex hull a chart's uv fills (0..1, default 0.75): a chart below it (an L, a body
   * with its legs) is split, so the charts pack tighter for a little more seam; 0 keeps any shape.
   */
  minHullFill?: number;
  /**
   * Most charts (an integer; default 0: no cap), where the surface allows: splits for stretch or shape stop at it and
   * more charts are merged down to it whatever their stretch (Atlas.capped). A chart with no flat map is split
   * anyway and merges only make disks, so a closed surface keeps two or more.
   */
  maxCharts?: number;
  /**
   * Side of the square atlas in texels (1..16384, default 1024) when width and height are 0. Above 4096 the
   * charts are packed on a grid k = ceil(side / 4096) times coarser and placed k times larger.
   */
  resolution?: number;
  /** Atlas width in texels (1..16384; default 0: resolution); set with height. */
  width?: number;
  /** Atlas height in texels (1..16384; default 0: resolution); set with width. */
  height?: number;
  /** Texels between any two charts (≥ 0, default 2); charts keep half of it from the border. */
  padding?: number;
  /**
   * Texels per unit of 3D length (default 0: the largest density at which every chart fits); one that
   * does not fit throws 'too_large'.
   */
  texelsPerUnit?: number;
  /** Turn charts (default true): 16 turns of each chart from its minimum-area rotation (its right angles among them); never a mirror. */
  rotate?: boolean;
  /** Stages 'segment', 'flatten', 'pack', 'measure'; return false to cancel (throws 'cancelled'; the mesh stays usable). */
  onProgress?: ProgressCallback;
}

/**
 * A texture atlas: charts (topological disks, each flattened without folding or mirroring) packed into
 * one texture. Every quality number is measured on cornerUv itself, not taken from the packer.
 */
export interface Atlas {
  /** u, v per face corner (6 floats per face, corners in mesh.indices() order), in [0, 1]² (u right, v up); texels are u × width, v × height. */
  cornerUv: Float32Array;
  /** The chart of each face (0 .. charts − 1). */
  chartOfFace: Int32Array;
  /** Mesh edges whose two sides have different uv, 2 vertex numbers each. */
  seam: Int32Array;
  /** Sander L2 stretch of each chart (1 for an isometry), chart by chart as measured from the uv. */
  chartStretch: Float64Array;
  /** Number of charts. */
  charts: number;
  /** Sander stretch of the whole atlas, uv scaled to the mesh's area (1 for an isometry; Infinity if a face is flipped or degenerate). */
  stretch: { l2: number; linf: number };
  /** Area of the uv triangles / area of the atlas (0..1). */
  utilization: number;
  /** Atlas width in texels. */
  width: number;
  /** Atlas height in texels. */
  height: number;
  /** Texels per unit of 3D length (every chart at this one density). */
  texelsPerUnit: number;
  /** seam.length / 2. */
  seamEdges: number;
  /** 3D length of the seam (mesh units). */
  seamLength: number;
  /** Faces wound against the rest of their chart (0 by construction). */
  flipped: number;
  /** Charts wound clockwise, against their 3D faces (0 by construction: normal maps' tangent frames stay right-handed). */
  mirrored: number;
  /** Faces of zero uv area with a non-zero 3D area. */
  degenerate: number;
  /** Pairs of charts that overlap, plus charts whose boundary crosses itself (0 by construction). */
  overlaps: number;
  /** Charts that are not topological disks (0 by construction). */
  nonDiskCharts: number;
  /** Smallest distance between two charts, in texels (Infinity for one chart). */
  minGapTexels: number;
  /** Pairs of charts closer than `padding` texels (0 by construction). */
  paddingViolations: number;
  /** Charts split because their stretch exceeded maxStretch. */
  splits: number;
  /** Pairs of neighbouring charts merged because the union stayed under maxStretch. */
  merges: number;
  /** maxCharts stopped a split or merged charts: some chart may exceed maxStretch. */
  capped: boolean;
  /** Milliseconds per stage: charts (segment and flatten), pack, measure, total. */
  timings: { charts: number; pack: number; measure: number; total: number };
}

/** st.atlas's result: the atlas of every mesh together, and each mesh's share of it. */
export interface SharedAtlas extends Atlas {
  /**
   * One entry per mesh, in the order given: its cornerUv (6 floats per face of that mesh) and chartOfFace
   * (chart numbers of the shared atlas). The whole's cornerUv, chartOfFace and seam (vertex numbers offset
   * by the vertices of the meshes before) are these in order.
   */
  meshes: { cornerUv: Float32Array; chartOfFace: Int32Array }[];
}
