// Types of the straightest npm package (ESM). See README.md for usage.

export type MeshFormat = 'auto' | 'obj' | 'off';

/** Caps checked before building a mesh (defaults: 50M vertices, 100M faces). */
export interface BuildLimits {
  maxVertices?: number;
  maxFaces?: number;
}

export interface MeshInfo {
  vertices: number;
  faces: number;
  edges: number;
  /** Sizes of the boundary loops, longest first (empty for a closed mesh). */
  boundaryLoops: number[];
  eulerCharacteristic: number;
  components: number;
  degenerateFaces: number;
  reorientedFaces: number;
  unreferencedVertices: number;
  bbox: { min: [number, number, number]; max: [number, number, number] };
  /** Human-readable notes on what was found and repaired. */
  problems: string[];
}

/** Error categories: see core/include/straightest/error.hpp (also listed by `st.errorCategories`). */
export type ErrorCategory =
  | 'io' | 'unsupported_format' | 'parse' | 'empty' | 'too_large' | 'non_finite' | 'index_out_of_range'
  | 'invalid_face' | 'duplicate_face' | 'degenerate' | 'non_manifold_edge' | 'non_manifold_vertex' | 'non_orientable'
  | 'topology' | 'invalid_argument' | 'cancelled' | 'internal';

export class StraightestError extends Error {
  readonly category: ErrorCategory;
}

/** A point on the surface: a vertex index, {vertex}, {face, bary: [a, b, c]} or {halfedge, t}. */
export type SurfacePoint =
  | number
  | { vertex: number }
  | { face: number; bary: [number, number, number] }
  | { halfedge: number; t: number };

export type TraceStatus =
  | 'reached' | 'hit_boundary' | 'other_component' | 'loop' | 'step_limit' | 'no_exit' | 'degenerate_plane';

export interface BasePlane {
  source: SurfacePoint;
  origin: [number, number, number];
  /** Unit normal: mean of the virtual faces' normals (or the area-weighted normal when fallback). */
  normal: [number, number, number];
  fallback: boolean;
  note: string;
}

/** What a batch of paths amounts to (as the CLI's "summary"). */
export interface PathSummary {
  paths: number;
  reached: number;
  /** Count of each failing status that occurred. */
  failures: Partial<Record<TraceStatus, number>>;
  /** Over reached paths (0 when none). */
  meanLength: number;
  maxLength: number;
  /** Faces crossed by all paths, and by the longest walk (any status). */
  facesCrossed: number;
  maxFacesCrossed: number;
}

export interface StraightestPaths {
  source: SurfacePoint;
  /** 3D position of the source (the base plane's origin). */
  sourcePosition: [number, number, number];
  normal: [number, number, number];
  baseFallback: boolean;
  baseNote: string;
  targets: SurfacePoint[];
  /** 3D position of every target, x, y, z each. */
  targetPositions: Float64Array;
  /** Number of paths (= targets). */
  count: number;
  /** Paths with status 'reached' (the core's count). */
  reached: number;
  summary: PathSummary;
  statuses: TraceStatus[];
  /** Straightest distances (of the partial path when not reached). */
  lengths: Float64Array;
  facesCrossed: Uint32Array;
  /**
   * Per target, the unit direction t from the source toward it within the base plane (D − S without
   * its base-normal component): the cutting plane is spanned by t and `normal` through
   * `sourcePosition`. NaN, NaN, NaN where the plane is undefined (status 'degenerate_plane').
   */
  directions: Float64Array;
  /** Packed x, y, z of every path's points; path i is points [3·offsets[i], 3·offsets[i+1]). */
  points: Float32Array;
  offsets: Uint32Array;
  timings: { prepare: number; trace: number };
}

export interface StraightestPathsOptions {
  /** Default 'auto': the interior vertex farthest from the boundary. */
  source?: SurfacePoint | 'auto';
  /**
   * Default 'boundary': every vertex of the longest boundary loop (in order). An array may mix surface
   * points and 'boundary' entries (each expanded in place). 'boundary' on a closed mesh throws
   * category 'topology'.
   */
  targets?: 'boundary' | (SurfacePoint | 'boundary')[];
  /** Return the points of each path (default true). */
  points?: boolean;
  /** Called with ('trace', fraction) while tracing; return false to cancel (throws 'cancelled'). */
  onProgress?: ProgressCallback;
}

/** (stage, fraction in [0, 1]) → return false to cancel. Called synchronously from the WASM work. */
export type ProgressCallback = (stage: string, fraction: number) => boolean | void;

/**
 * Where the boundary goes: 'measured' (the paper's straightest distances and angles), 'circle',
 * 'square', or 'free' (the measured map — the circle's when the measured one is not bijective —
 * refined with every vertex, boundary included, free to move; it never folds).
 */
export type BoundaryKind = 'measured' | 'circle' | 'square' | 'free';
/** The fixed boundaries a free refinement starts from. */
export type InitBoundary = 'measured' | 'circle';
export type WeightKind = 'shape-preserving' | 'mean-value' | 'cotan' | 'uniform';
export type LinearSolver = 'multigrid' | 'lu' | 'bicgstab';
/** 'exact': window propagation (exact polyhedral geodesic distance). */
export type DistanceMethod = 'heat' | 'dijkstra' | 'exact';

export interface ParameterizeOptions {
  /** Center of the measured boundary (default 'auto'); must be interior (also for 'free' and 'auto'). */
  source?: SurfacePoint | 'auto';
  /**
   * Default 'measured'; 'auto' tries measured, circle, square and free (refined from measured when its
   * map is bijective, else from circle, without a second solve) and keeps the preferred map: a
   * bijective map beats any other, then the lower L2 stretch; among non-bijective maps the fewer
   * flipped + degenerate triangles; ties keep the earlier kind (the same rule as
   * compareParameterizations' `best`).
   */
  boundary?: BoundaryKind | 'auto';
  weights?: WeightKind;
  /** Default 'multigrid' (BiCGSTAB + algebraic multigrid); 'lu' direct; 'bicgstab' with ILUT. */
  solver?: LinearSolver;
  /** Free boundary: refinement iterations at most (default 200; a positive integer). */
  maxIterations?: number;
  /** Free boundary: stop refining after this many milliseconds (default 60000); then converged is false. */
  timeBudgetMs?: number;
  /**
   * Stages 'source', 'trace', 'weights', 'solve', 'metrics', and for 'free' and 'auto' 'refine' (then
   * 'metrics' again); return false to cancel (throws 'cancelled'; the mesh stays usable).
   */
  onProgress?: ProgressCallback;
}

/** A map parameterize tried: its stretch and bad-triangle counts. */
export interface BoundaryCandidate {
  boundary: BoundaryKind;
  l2: number;
  linf: number;
  flipped: number;
  degenerate: number;
  /** Pairs of boundary edges that cross in the plane (only a free boundary can have any). */
  overlaps: number;
}

export interface Parameterization {
  source: SurfacePoint;
  boundary: BoundaryKind;
  weights: WeightKind;
  /** u, v per vertex in [0, 1]² (aspect ratio kept). */
  uv: Float32Array;
  /** L2 texture stretch per face (Infinity for flipped or degenerate faces). */
  faceStretch: Float32Array;
  /**
   * The boundary polygon (u, v per boundary vertex) in the uv frame, and its vertices. For 'free' it
   * is the refined loop's uv: not convex.
   */
  boundaryPolygon: Float32Array;
  boundaryLoop: Int32Array;
  /** Sander et al.'s stretch, 1 for an isometry; Infinity when the map is not bijective. */
  stretch: { l2: number; linf: number };
  /** No flipped, no degenerate triangle and no boundary self-overlap. */
  bijective: boolean;
  flipped: number;
  degenerate: number;
  /** Pairs of boundary edges that cross in the plane (the texture would be sampled twice there). */
  overlaps: number;
  /**
   * Measured boundary: traces that failed; their radius is the heat-method distance clamped between the
   * straight-line and the edge-graph distance.
   */
  fallbacks: number;
  /**
   * Measured boundary: reached traces longer than 1.5× the edge-graph distance (an upper bound of the
   * geodesic distance); their radius is replaced like a failed trace's.
   */
  outliers: number;
  weightFallbacks: number;
  angleDistortion: { mean: number; max: number };
  areaDistortion: { mean: number; max: number };
  /** Relative residual of the linear solve (the start's, for 'free'). */
  residual: number;
  /**
   * The free refinement's start: 'measured' when its map is bijective, else 'circle'. null (and so
   * are the five fields below) when the result's boundary is fixed.
   */
  init: InitBoundary | null;
  /** Refinement iterations run (at most maxIterations). */
  iterations: number | null;
  /** Symmetric Dirichlet energy per unit area of the start (4 for an isometry; Infinity if it folds). */
  energyInitial: number | null;
  /** The same energy of the result (never above energyInitial when the start was bijective). */
  energyFinal: number | null;
  /** The relative-decrease rule stopped it (false: the iteration cap or the time budget did). */
  converged: boolean | null;
  /** The start had flipped or degenerate triangles and was untangled first. */
  untangled: boolean | null;
  /** Every map solved: 'auto' lists all four kinds; 'free' its start(s) and itself last. */
  candidates: BoundaryCandidate[];
  /** Milliseconds per stage; every stage is listed (0 when it did not run). */
  timings: {
    source: number; trace: number; boundary: number; weights: number; solve: number; refine: number;
    metrics: number; total: number;
  };
}

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

export interface BoundaryPolygon {
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
  category: ErrorCategory | null;
}

export interface CompareOptions {
  /** One source for every cell (default 'auto'). */
  source?: SurfacePoint | 'auto';
  /** Default ['measured', 'circle', 'square', 'free']. */
  boundaries?: BoundaryKind[];
  /** Default ['shape-preserving', 'mean-value', 'cotan', 'uniform']. */
  weights?: WeightKind[];
  solver?: LinearSolver;
  /** Free rows: refinement iterations at most (default 200). */
  maxIterations?: number;
  /** Free rows: refinement time budget in milliseconds (default 60000). */
  timeBudgetMs?: number;
  /** Stage 'compare': the fraction of cells done; return false to cancel (throws 'cancelled'). */
  onProgress?: ProgressCallback;
}

export interface ComparisonRow {
  boundary: BoundaryKind;
  weights: WeightKind;
  /** null when the cell failed (error set); Infinity when not bijective. */
  l2: number | null;
  linf: number | null;
  flipped: number | null;
  degenerate: number | null;
  /** Pairs of boundary edges that cross in the plane. */
  overlaps: number | null;
  bijective: boolean | null;
  /** Free rows: the refinement's start ('measured' if its map is bijective, else 'circle'); else null. */
  init: InitBoundary | null;
  /** Free rows: refinement iterations; else null. */
  iterations: number | null;
  /** Free rows: whether the relative-decrease rule stopped the refinement; else null. */
  converged: boolean | null;
  /** Wall time of this cell's parameterization (a free row includes its start's solve). */
  timeMs: number;
  error: string | null;
  category: ErrorCategory | null;
}

export interface Comparison {
  /** Boundary-major: for each boundary, every weights in the given order. */
  rows: ComparisonRow[];
  /** Index of the preferred row (the rule of boundary 'auto'), -1 when every row failed. */
  best: number;
}

export class Mesh {
  info(): MeshInfo;
  /** Every boundary loop's vertices in order (the surface on the left), longest first. */
  boundaryLoops(): Int32Array[];
  /** Area-weighted unit vertex normals, x, y, z per vertex (zero for unreferenced vertices). */
  vertexNormals(): Float32Array;
  /** Every boundary kind's polygon without a solve (see BoundaryPolygon). Throws 'topology' unless a disk. */
  boundaryPolygons(options?: BoundaryPolygonsOptions): BoundaryPolygon[];
  /** Every boundary × weights parameterized and judged (see Comparison). Throws 'topology' unless a disk. */
  compareParameterizations(options?: CompareOptions): Comparison;
  /** The interior vertex farthest from the boundary ("center of the mesh"). */
  defaultSource(): number;
  basePlane(source?: SurfacePoint | 'auto'): BasePlane;
  straightestPaths(options?: StraightestPathsOptions): StraightestPaths;
  /** Distances from the source to every vertex; 'heat' factors once per mesh and reuses it. */
  geodesicDistances(source?: SurfacePoint | 'auto', method?: DistanceMethod): Float64Array;
  parameterize(options?: ParameterizeOptions): Parameterization;
  /** OBJ text in the input's vertex order; with uv also `vt` lines (faces as v/vt). */
  toOBJ(uv?: ArrayLike<number>): string;
  /** x, y, z per vertex (a copy). */
  positions(): Float64Array;
  /** 3 vertex indices per triangle (a copy). */
  indices(): Uint32Array;
  readonly deleted: boolean;
  /** Frees the WASM memory; any later call throws. */
  delete(): void;
}

export class Straightest {
  loadMesh(data: Uint8Array | ArrayBuffer | ArrayBufferView | string, format?: MeshFormat, limits?: BuildLimits): Mesh;
  meshFromArrays(positions: ArrayLike<number>, indices: ArrayLike<number>, limits?: BuildLimits): Mesh;
  sampleNames(): string[];
  sample(name: 'mountain' | 'cap' | 'saddle' | 'face' | string): Mesh;
  readonly memoryBytes: number;
  /** Bytes currently allocated inside WASM memory. */
  readonly heapUsedBytes: number;
  readonly traceStatuses: TraceStatus[];
  /** ['measured', 'circle', 'square', 'free'] */
  readonly boundaryKinds: BoundaryKind[];
  /** The kinds boundaryPolygons gives without a solve: ['measured', 'circle', 'square']. */
  readonly polygonBoundaryKinds: PolygonBoundaryKind[];
  /** The kinds and 'auto'. */
  readonly boundaryChoices: (BoundaryKind | 'auto')[];
  readonly weightKinds: WeightKind[];
  readonly solvers: LinearSolver[];
  readonly distanceMethods: DistanceMethod[];
  /** ['obj', 'off', 'auto'] */
  readonly meshFormats: MeshFormat[];
  readonly errorCategories: ErrorCategory[];
  /** 'obj' or 'off' by the name's extension (any case), else 'auto'. */
  formatFromFileName(name: string): MeshFormat;
}

export interface CreateOptions {
  /** URL of straightest-core.wasm when it is not served next to the module (bundlers, CDNs). */
  wasmUrl?: string | URL;
  /** Emscripten's locateFile hook. */
  locateFile?: (name: string, scriptDirectory: string) => string;
  /** The .wasm bytes, to skip fetching. */
  wasmBinary?: ArrayBuffer | Uint8Array;
}

export function createStraightest(options?: CreateOptions): Promise<Straightest>;
