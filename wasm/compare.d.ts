// The npm package's types for comparing maps: Mesh.boundaryPolygons (every boundary kind's polygon) and
// Mesh.compareParameterizations (every boundary × weights, side by side). Re-exported by index.d.ts.
import type {
  BoundaryKind,
  ErrorCategory,
  InitBoundary,
  LinearSolver,
  ProgressCallback,
  SurfacePoint,
  WeightKind,
} from './index.js';

export interface BoundaryPolygonsOptions {
  /** Center of the measured boundary (default 'auto'); must be interior. */
  source?: SurfacePoint | 'auto';
  /**
   * Default: every kind with a polygon, ['measured', 'circle', 'square'] (st.polygonBoundaryKinds).
   * 'free' has no polygon before its refinement: asking for it throws 'invalid_argument'.
   */
  kinds?: PolygonBoundaryKind[];
  /** Stage 'trace' (measured); return false to cancel (throws 'cancelled'). */
  onProgress?: ProgressCallback;
}

/** The boundary kinds with a polygon without a solve. */
export type PolygonBoundaryKind = Exclude<BoundaryKind, 'free'>;

/** One boundary kind's polygon, computed without a solve. */
export interface BoundaryPolygon {
  /** The kind of this polygon. */
  boundary: PolygonBoundaryKind;
  /**
   * u, v per loop vertex in exactly the [0, 1]² frame `parameterize({ boundary })` puts its uv and
   * boundaryPolygon in (for the convex-combination weights; cotan may leave the polygon's box); null
   * when this kind failed.
   */
  polygon: Float32Array | null;
  /** The boundary vertices in order (the longest loop). */
  loop: Int32Array;
  /** Why this kind has no polygon (e.g. measured with a source on the boundary), else null. */
  error: string | null;
  /** The failure's category, else null. */
  category: ErrorCategory | null;
}

export interface CompareOptions {
  /** One source for every cell (default 'auto'). */
  source?: SurfacePoint | 'auto';
  /** Default ['measured', 'circle', 'square', 'free']. */
  boundaries?: BoundaryKind[];
  /** Default ['shape-preserving', 'mean-value', 'cotan', 'uniform']. */
  weights?: WeightKind[];
  /** Default 'multigrid'. */
  solver?: LinearSolver;
  /** Free rows: refinement iterations at most (default 200). */
  maxIterations?: number;
  /** Free rows: refinement time budget in milliseconds (default 60000). */
  timeBudgetMs?: number;
  /** Stage 'compare': the fraction of cells done; return false to cancel (throws 'cancelled'). */
  onProgress?: ProgressCallback;
}

/** One cell of compareParameterizations: a boundary × weights map and its measures. */
export interface ComparisonRow {
  /** The cell's boundary. */
  boundary: BoundaryKind;
  /** The cell's interior weights. */
  weights: WeightKind;
  /** null when the cell failed (error set); Infinity when not bijective. */
  l2: number | null;
  /** Worst per-face stretch; null when the cell failed. */
  linf: number | null;
  /** Triangles turned over; null when the cell failed. */
  flipped: number | null;
  /** Triangles of (near) zero area; null when the cell failed. */
  degenerate: number | null;
  /** Pairs of boundary edges that cross in the plane. */
  overlaps: number | null;
  /** No flipped, degenerate or overlapping parts; null when the cell failed. */
  bijective: boolean | null;
  /** Free rows: the refinement's start ('measured' if its map is bijective, else 'circle'); else null. */
  init: InitBoundary | null;
  /** Free rows: refinement iterations; else null. */
  iterations: number | null;
  /** Free rows: whether the relative-decrease rule stopped the refinement; else null. */
  converged: boolean | null;
  /** Wall time of this cell's parameterization (a free row includes its start's solve). */
  timeMs: number;
  /** Why the cell failed, else null. */
  error: string | null;
  /** The failure's category, else null. */
  category: ErrorCategory | null;
}

/** compareParameterizations' result. */
export interface Comparison {
  /** Boundary-major: for each boundary, every weights in the given order. */
  rows: ComparisonRow[];
  /** Index of the preferred row (the rule of boundary 'auto'), -1 when every row failed. */
  best: number;
}
