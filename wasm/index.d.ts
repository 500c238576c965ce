// Types of the straightest npm package (ESM). See README.md for usage.

// `using mesh = ...` (TypeScript ≥ 5.2) needs Symbol.dispose, and `await using` on straightest/worker's
// objects Symbol.asyncDispose; declared here too so that projects whose `lib` predates
// esnext.disposable still type-check this file.
declare global {
  interface SymbolConstructor {
    readonly dispose: unique symbol;
    readonly asyncDispose: unique symbol;
  }
}

/** loadMesh's formats: 'auto' detects OBJ, OFF, PLY (magic line) or STL (binary by its size, ASCII by 'solid') from the contents. */
export type MeshFormat = 'auto' | 'obj' | 'off' | 'ply' | 'stl';

/** Caps checked before building a mesh (defaults: 50M vertices, 100M faces). */
export interface BuildLimits {
  /** Largest vertex count accepted (default 50M); more throws 'too_large'. */
  maxVertices?: number;
  /** Largest face count accepted (default 100M); more throws 'too_large'. */
  maxFaces?: number;
}

/** What mesh.info() reports: sizes, topology and what validation repaired. */
export interface MeshInfo {
  /** Vertex count (unreferenced vertices included). */
  vertices: number;
  /** Triangle count (polygons are triangulated on load). */
  faces: number;
  /** Undirected edge count. */
  edges: number;
  /** Sizes of the boundary loops, longest first (empty for a closed mesh). */
  boundaryLoops: number[];
  /** V − E + F: 1 for a disk, 2 for a sphere. */
  eulerCharacteristic: number;
  /** Connected pieces (a non-indexed geometry whose triangles share no vertex has one per triangle). */
  components: number;
  /** Faces with (near) zero area, kept. */
  degenerateFaces: number;
  /** Faces flipped to agree with their neighbours' orientation. */
  reorientedFaces: number;
  /** Vertices no face uses. */
  unreferencedVertices: number;
  /** Axis-aligned bounding box of the vertices. */
  bbox: { min: [number, number, number]; max: [number, number, number] };
  /** Human-readable notes on what was found and repaired. */
  problems: string[];
}

/** Error categories: see core/include/straightest/error.hpp (also listed by `st.errorCategories`). */
export type ErrorCategory =
  | 'io'
  | 'unsupported_format'
  | 'parse'
  | 'empty'
  | 'too_large'
  | 'non_finite'
  | 'index_out_of_range'
  | 'invalid_face'
  | 'duplicate_face'
  | 'degenerate'
  | 'non_manifold_edge'
  | 'non_manifold_vertex'
  | 'non_orientable'
  | 'topology'
  | 'invalid_argument'
  | 'cancelled'
  | 'internal';

/**
 * The error every call of the package throws for bad input, a failed computation, a cancelled one
 * ('cancelled'), a module that could not be loaded ('io') or a deleted mesh ('invalid_argument').
 */
export class StraightestError extends Error {
  constructor(message?: string, category?: ErrorCategory, options?: { cause?: unknown });
  /** Machine-readable kind of failure; `message` says what was found and where. */
  readonly category: ErrorCategory;
}

/** A point on the surface as results give it: {vertex}, {face, bary: [a, b, c]} or {halfedge, t}. */
export type SurfacePointObject =
  { vertex: number } | { face: number; bary: [number, number, number] } | { halfedge: number; t: number };

/** A point on the surface as arguments take it: a vertex index or any SurfacePointObject. */
export type SurfacePoint = number | SurfacePointObject;

/** How a path ended: 'reached' is the only success (see README.md for each status). */
export type TraceStatus =
  'reached' | 'hit_boundary' | 'other_component' | 'loop' | 'step_limit' | 'no_exit' | 'degenerate_plane';

/** The plane every cutting plane at a source contains the normal of. */
export interface BasePlane {
  /** The source, resolved ('auto' becomes the vertex it chose). */
  source: SurfacePointObject;
  /** The source's 3D position. */
  origin: [number, number, number];
  /** Unit normal: mean of the virtual faces' normals (or the area-weighted normal when fallback). */
  normal: [number, number, number];
  /** The virtual faces were degenerate and the area-weighted normal was used. */
  fallback: boolean;
  /** Why the fallback was taken ('' when not). */
  note: string;
}

/** What a batch of paths amounts to (as the CLI's "summary"). */
export interface PathSummary {
  /** Paths traced. */
  paths: number;
  /** Paths with status 'reached'. */
  reached: number;
  /** Count of each failing status that occurred. */
  failures: Partial<Record<TraceStatus, number>>;
  /** Over reached paths (0 when none). */
  meanLength: number;
  maxLength: number;
  /** Faces crossed by all paths, and by the longest walk (any status). */
  facesCrossed: number;
  maxFacesCrossed: number;
  /** Paths that also reached their target the other way round the section (closed meshes). */
  otherArcs: number;
}

/** straightestPaths' result: one entry per target in every per-path array. */
export interface StraightestPaths {
  /** The source, resolved ('auto' becomes the vertex it chose). */
  source: SurfacePointObject;
  /** 3D position of the source (the base plane's origin). */
  sourcePosition: [number, number, number];
  /** The base plane's unit normal. */
  normal: [number, number, number];
  /** The base plane fell back to the area-weighted normal (see BasePlane.fallback). */
  baseFallback: boolean;
  /** Why it fell back ('' when not). */
  baseNote: string;
  /** The targets, resolved ('boundary' expanded into its vertices). */
  targets: SurfacePointObject[];
  /** 3D position of every target, x, y, z each. */
  targetPositions: Float64Array;
  /** Number of paths (= targets). */
  count: number;
  /** Paths with status 'reached' (the core's count). */
  reached: number;
  summary: PathSummary;
  /** Each path's status. */
  statuses: TraceStatus[];
  /**
   * Straightest distances (of the partial path when not reached). On a closed mesh the section through
   * the source is a closed curve walked both ways: this is the shorter arc to the target.
   */
  lengths: Float64Array;
  /** Faces each path crossed. */
  facesCrossed: Uint32Array;
  /** 1 where the path leaves the source away from its target (−directions[i]): 'backward'; 0 'forward'. */
  backward: Uint8Array;
  /** The other arc's length where both ways reach the target (closed meshes), NaN elsewhere. */
  otherArcLengths: Float64Array;
  /**
   * Per target, the unit direction t from the source toward it within the base plane (D − S without
   * its base-normal component): the cutting plane is spanned by t and `normal` through
   * `sourcePosition`. NaN, NaN, NaN where the plane is undefined (status 'degenerate_plane').
   */
  directions: Float64Array;
  /** Packed x, y, z of every path's points; path i is points [3·offsets[i], 3·offsets[i+1]). */
  points: Float32Array;
  /** count + 1 offsets into points (in points, not floats); empty when points: false. */
  offsets: Uint32Array;
  /** The other arcs, packed like points (empty where otherArcLengths is NaN, or when points: false). */
  otherPoints: Float32Array;
  /** count + 1 offsets into otherPoints (in points, not floats). */
  otherOffsets: Uint32Array;
  /** Milliseconds spent setting up and tracing. */
  timings: { prepare: number; trace: number };
}

/** Boundary vertices as targets: the longest loop's, or every loop's. */
export type TargetName = 'boundary' | 'all-boundaries';

export interface StraightestPathsOptions {
  /** Default 'auto': the interior vertex farthest from the boundary. */
  source?: SurfacePoint | 'auto';
  /**
   * Default 'boundary': every vertex of the longest boundary loop (in order); 'all-boundaries': every
   * loop's, longest loop first. An array may mix surface points and those names (each expanded in
   * place). Either name on a closed mesh throws category 'topology' ("name the targets").
   */
  targets?: TargetName | (SurfacePoint | TargetName)[];
  /** Return the points of each path (default true). */
  points?: boolean;
  /** Called with ('trace', fraction) while tracing; return false to cancel (throws 'cancelled'). */
  onProgress?: ProgressCallback;
}

export type {
  ShootStatus,
  ShootGeodesicOptions,
  GeodesicShot,
  ExactShortestPathsOptions,
  ExactGeodesicStats,
  ExactShortestPaths,
} from './geodesics.js';
import type {
  ShootStatus,
  ShootGeodesicOptions,
  GeodesicShot,
  ExactShortestPathsOptions,
  ExactGeodesicStats,
  ExactShortestPaths,
} from './geodesics.js';
export type { AtlasOptions, Atlas, SharedAtlas } from './atlas.js';
import type { AtlasOptions, Atlas, SharedAtlas } from './atlas.js';
export type {
  BoundaryPolygonsOptions,
  PolygonBoundaryKind,
  BoundaryPolygon,
  CompareOptions,
  ComparisonRow,
  Comparison,
} from './compare.js';
import type {
  BoundaryPolygonsOptions,
  PolygonBoundaryKind,
  BoundaryPolygon,
  CompareOptions,
  ComparisonRow,
  Comparison,
} from './compare.js';

/**
 * The stages progress reports: straightestPaths 'trace'; parameterize 'source', 'trace', 'weights',
 * 'solve', 'refine', 'metrics'; boundaryPolygons 'trace'; compareParameterizations 'compare';
 * shootGeodesic 'shoot'; exactShortestPaths 'distances'; atlas 'segment', 'flatten', 'pack', 'measure'.
 * Each stage reports its own fraction, from 0 to 1. Other names may come with new versions.
 */
export type ProgressStage =
  | 'source'
  | 'trace'
  | 'weights'
  | 'solve'
  | 'refine'
  | 'metrics'
  | 'compare'
  | 'shoot'
  | 'distances'
  | 'segment'
  | 'flatten'
  | 'pack'
  | 'measure'
  | (string & {});

/**
 * (stage, fraction in [0, 1]) → return false to cancel (the call then throws 'cancelled'). Called
 * synchronously from the WASM work. An exception it throws cancels the work too and is rethrown, as
 * is, by the call once the core has unwound.
 */
export type ProgressCallback = (stage: ProgressStage, fraction: number) => boolean | void;

/**
 * Where the boundary goes: 'measured' (the paper's straightest distances and angles), 'circle',
 * 'square', or 'free' (the measured map — the circle's when the measured one is not bijective —
 * refined with every vertex, boundary included, free to move; it never folds).
 */
export type BoundaryKind = 'measured' | 'circle' | 'square' | 'free';
/** The fixed boundaries a free refinement starts from. */
export type InitBoundary = 'measured' | 'circle';
/** How interior vertices are placed: the convex-combination weights ('cotan' may fold). */
export type WeightKind = 'shape-preserving' | 'mean-value' | 'cotan' | 'uniform';
/** The sparse solver: 'multigrid' (BiCGSTAB + algebraic multigrid), 'lu' (direct), 'bicgstab' (ILUT). */
export type LinearSolver = 'multigrid' | 'lu' | 'bicgstab';
/**
 * Geodesic distances: 'heat' (the heat method, factored once per mesh, approximate), 'dijkstra' (along
 * edges, an upper bound) or 'exact' (window propagation: the exact polyhedral geodesic distance).
 */
export type DistanceMethod = 'heat' | 'dijkstra' | 'exact';
/** The built-in sample meshes (st.sampleNames() lists them). */
export type SampleName = 'mountain' | 'cap' | 'saddle' | 'face' | 'holes' | 'sphere' | 'torus' | (string & {});

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
  /** Default 'shape-preserving'. */
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
  /** The boundary this map used. */
  boundary: BoundaryKind;
  /** L2 texture stretch (Infinity when not bijective). */
  l2: number;
  /** Worst per-face stretch. */
  linf: number;
  /** Triangles turned over in the plane. */
  flipped: number;
  /** Triangles of (near) zero area in the plane. */
  degenerate: number;
  /** Pairs of boundary edges that cross in the plane (only a free boundary can have any). */
  overlaps: number;
}

/** parameterize's result: the uv map and how good it is. */
export interface Parameterization {
  /** The measured boundary's center, resolved. */
  source: SurfacePointObject;
  /** The boundary of this map ('auto' becomes the kind it chose). */
  boundary: BoundaryKind;
  /** The interior weights used. */
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
  /** Triangles turned over in the plane. */
  flipped: number;
  /** Triangles of (near) zero area in the plane. */
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
  /** Vertices whose weights fell back to uniform (e.g. cotan weights that would fold). */
  weightFallbacks: number;
  /** Angle distortion over the faces (0 for a conformal map). */
  angleDistortion: { mean: number; max: number };
  /** Area distortion over the faces (0 for an area-preserving map). */
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
  /**
   * How the mesh was made a disk: 'disk' (it was one), 'fill' (holes filled virtually, the longest loop
   * outside), 'path' (a closed genus-0 surface cut between two far-apart vertices) or 'cut-graph'
   * (genus ≥ 1: a tree–cotree cut graph, holes filled too).
   */
  cut: CutMethod;
  /**
   * u, v per face corner (6 numbers per face), in uv's frame: the map to texture with. Equal to uv at
   * the corner's vertex except at a seam vertex, which has one uv per side; NaN on faces outside the
   * parameterized component.
   */
  cornerUv: Float32Array;
  /** The mesh edges cut open, 2 vertex numbers each (empty for 'disk' and 'fill'). */
  seam: Int32Array;
  /** seam.length / 2. */
  seamEdges: number;
  /** 3D length of the seam. */
  seamLength: number;
  /** Indices into mesh.boundaryLoops() of the holes filled virtually (their filling is not in the output). */
  filledLoops: number[];
  /** Genus of the parameterized component. */
  genus: number;
  /** Which connected component was parameterized (the largest by faces), of `components`. */
  component: number;
  components: number;
  /** Vertices the filling added to the solve (never in uv or cornerUv). */
  virtualVertices: number;
  /** Milliseconds per stage; every stage is listed (0 when it did not run). */
  timings: {
    cut: number;
    source: number;
    trace: number;
    boundary: number;
    weights: number;
    solve: number;
    refine: number;
    metrics: number;
    total: number;
  };
}

/** How parameterize made the mesh a disk. */
export type CutMethod = 'disk' | 'fill' | 'path' | 'cut-graph';

/**
 * A validated triangle mesh in WASM memory, made by st.loadMesh, st.meshFromArrays or st.sample. Free
 * it with delete() or declare it with `using` (Symbol.dispose); any use afterwards throws
 * StraightestError 'invalid_argument'. A mesh dropped without either is freed by a FinalizationRegistry
 * at some later garbage collection: a safety net with no timing guarantee.
 */
export class Mesh {
  private constructor();
  /** Sizes, topology and what validation repaired. */
  info(): MeshInfo;
  /** Every boundary loop's vertices in order (the surface on the left), longest first. */
  boundaryLoops(): Int32Array[];
  /** Area-weighted unit vertex normals, x, y, z per vertex (zero for unreferenced vertices). */
  vertexNormals(): Float32Array;
  /** Every boundary kind's polygon without a solve (see BoundaryPolygon); a mesh that is not a disk is cut as parameterize cuts it. */
  boundaryPolygons(options?: BoundaryPolygonsOptions): BoundaryPolygon[];
  /** Every boundary × weights parameterized and judged (see Comparison); a mesh that is not a disk is cut as parameterize cuts it. */
  compareParameterizations(options?: CompareOptions): Comparison;
  /**
   * The interior vertex farthest from the boundary ("center of the mesh"). Throws 'topology' when every vertex
   * lies on the boundary; there 'auto' sources are the middle of the largest face instead.
   */
  defaultSource(): number;
  /** The base plane at a source (default 'auto'). */
  basePlane(source?: SurfacePoint | 'auto'): BasePlane;
  /** Straightest paths from one source to many targets (see StraightestPathsOptions, StraightestPaths). */
  straightestPaths(options?: StraightestPathsOptions): StraightestPaths;
  /** Distances from the source to every vertex; 'heat' factors once per mesh and reuses it; 'exact' is exact. */
  geodesicDistances(source?: SurfacePoint | 'auto', method?: DistanceMethod): Float64Array;
  /**
   * A straightest geodesic as an initial value problem (Polthier–Schmies): from the source, straight
   * across faces and through vertices with equal angles on both sides, for a length or to the
   * boundary (see ShootGeodesicOptions, GeodesicShot).
   */
  shootGeodesic(options: ShootGeodesicOptions): GeodesicShot;
  /**
   * Exact shortest paths (window propagation) from a source to vertices: distances and polylines
   * (see ExactShortestPathsOptions, ExactShortestPaths).
   */
  exactShortestPaths(options?: ExactShortestPathsOptions): ExactShortestPaths;
  /**
   * Flattens any manifold mesh into [0, 1]² (see ParameterizeOptions): a disk as it is, otherwise its largest
   * component made a disk first (Parameterization.cut).
   */
  parameterize(options?: ParameterizeOptions): Parameterization;
  /**
   * A texture atlas of any manifold mesh (closed, with holes, any genus, several components): charts packed
   * into one texture with padding, uv per face corner (see AtlasOptions, Atlas).
   */
  atlas(options?: AtlasOptions): Atlas;
  /**
   * OBJ text in the input's vertex order; with uv also `vt` lines (faces as v/vt): uv is 2 numbers per
   * vertex (finite: else 'non_finite'), or 2 per face corner (Parameterization.cornerUv: one vt per
   * distinct uv, the seam split; a NaN corner gets no vt).
   */
  toOBJ(uv?: ArrayLike<number>): string;
  /** x, y, z per vertex (a copy). */
  positions(): Float64Array;
  /** 3 vertex indices per triangle (a copy). */
  indices(): Uint32Array;
  /** Whether delete() (or disposal) has freed this mesh. */
  readonly deleted: boolean;
  /** Frees the WASM memory; any later call throws StraightestError 'invalid_argument'. Idempotent. */
  delete(): void;
  /** The same as delete(), for `using mesh = st.sample('cap')`. */
  [Symbol.dispose](): void;
}

/**
 * The loaded library, from `await createStraightest()`. Its WASM memory lives as long as the object is
 * reachable; the meshes it makes are what must be freed.
 */
export class Straightest {
  private constructor();
  /** Parses an OBJ, OFF, PLY or STL file given as bytes or text; throws a StraightestError saying what is wrong where. */
  loadMesh(data: Uint8Array | ArrayBuffer | ArrayBufferView | string, format?: MeshFormat, limits?: BuildLimits): Mesh;
  /** A mesh from flat arrays: x, y, z per vertex and 3 vertex indices per triangle. */
  meshFromArrays(positions: ArrayLike<number>, indices: ArrayLike<number>, limits?: BuildLimits): Mesh;
  /** Names of the built-in sample meshes. */
  sampleNames(): string[];
  /** A built-in sample mesh; an unknown name throws 'invalid_argument'. */
  sample(name: SampleName): Mesh;
  /**
   * One atlas shared by several meshes (lightmaps): charts never span two meshes; `meshes` splits the
   * result per mesh. Not an array of meshes: TypeError; an empty one: 'empty'.
   */
  atlas(meshes: Mesh[], options?: AtlasOptions): SharedAtlas;
  /**
   * The threads the core runs on: 1 in the single-threaded module, else the count asked for (or every core).
   * Assignable from 1 up to the count the module was loaded with; other values throw 'invalid_argument'.
   */
  threads: number;
  /**
   * Why the single-threaded module runs although more than one thread was asked for (or by default):
   * the page is not cross-origin isolated, wasmUrl/wasmBinary/straightest/inline name the
   * single-threaded module, or the threaded module could not start (its files not served, a worker
   * that failed, or workers silent for 10 s; said once on the console too). null when the threaded
   * module runs or one thread was asked for.
   */
  readonly threadsUnavailable: string | null;
  /**
   * Whether loadMesh and meshFromArrays warm up for the first call on a spare thread while they parse and
   * build (the threaded module with 2 or more threads): they touch the memory a parameterization of the
   * mesh will take, estimated from its size (at most maxVertices' worth and half of what the memory can
   * still grow by), and until once it ran to the end a small sample so the engine optimizes the hot
   * code. Only where that pays: the module's first load, and loads of at least 65,536 vertices (arrays)
   * or 2.5 MB (files); other loads run as with false. Never slows a load by more than a step; changes
   * no result. The module's memory keeps the size
   * the warm-up grew it to (WebAssembly memory never shrinks). Default true; a value that is not a
   * boolean throws a TypeError.
   */
  warmUp: boolean;
  /** Bytes of WASM memory reserved (grows, never shrinks). */
  readonly memoryBytes: number;
  /** Bytes currently allocated inside WASM memory. */
  readonly heapUsedBytes: number;
  /** The trace statuses in the core's order ('reached' first). */
  readonly traceStatuses: TraceStatus[];
  /** ['measured', 'circle', 'square', 'free'] */
  readonly boundaryKinds: BoundaryKind[];
  /** The kinds boundaryPolygons gives without a solve: ['measured', 'circle', 'square']. */
  readonly polygonBoundaryKinds: PolygonBoundaryKind[];
  /** The kinds and 'auto'. */
  readonly boundaryChoices: (BoundaryKind | 'auto')[];
  /** ['shape-preserving', 'mean-value', 'cotan', 'uniform'] */
  readonly weightKinds: WeightKind[];
  /** ['multigrid', 'lu', 'bicgstab'] */
  readonly solvers: LinearSolver[];
  /** ['heat', 'dijkstra', 'exact'] */
  readonly distanceMethods: DistanceMethod[];
  /** shootGeodesic's statuses in the core's order ('reached_length' first). */
  readonly shootStatuses: ShootStatus[];
  /** ['obj', 'off', 'ply', 'stl', 'auto'] */
  readonly meshFormats: MeshFormat[];
  /** Every StraightestError category, in the core's order. */
  readonly errorCategories: ErrorCategory[];
  /** 'obj' or 'off' by the name's extension (any case), else 'auto'. */
  formatFromFileName(name: string): MeshFormat;
}

/** Which module createStraightest loads and where from (by default the .wasm files under wasm/dist/). */
export interface CreateOptions {
  /**
   * Threads for the core (default 0: every core; capped at 64). More than one loads the threaded module
   * where memory can be shared with workers (Node; pages and workers that are crossOriginIsolated), the
   * single-threaded one elsewhere or when the threaded one cannot start (Straightest.threadsUnavailable
   * says why); 1 always loads the single-threaded one. Results do not depend on it.
   */
  threads?: number;
  /** The initial value of Straightest.warmUp (default true; not a boolean: createStraightest rejects with a TypeError). */
  warmUp?: boolean;
  /** URL of straightest-core.wasm when it is not served next to the module; loads the single-threaded module. */
  wasmUrl?: string | URL;
  /** Emscripten's locateFile hook (name: 'straightest-core.wasm' or 'straightest-core-threads.wasm'). */
  locateFile?: (name: string, scriptDirectory: string) => string;
  /** The single-threaded module's .wasm bytes, to skip fetching; loads that module. */
  wasmBinary?: ArrayBuffer | Uint8Array;
}

/**
 * Loads the WebAssembly module: in Node a file: URL is read from disk, anything else is fetched. A
 * module that cannot be loaded rejects with StraightestError 'io' naming the URL and what came back.
 */
export function createStraightest(options?: CreateOptions): Promise<Straightest>;
