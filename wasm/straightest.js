// The package's API over a started Embind module, whichever module that is (wasm/index.js starts the
// threaded or the single-threaded one, wasm/inline.js the embedded single-threaded one): errors become
// StraightestErrors, arrays are copied out of WASM memory once, and meshes must be delete()d or
// `using`-disposed (a FinalizationRegistry frees forgotten ones eventually). It imports no module
// loader, so each entry brings only the modules it can start.
import {
  unwrap,
  isArrayLike,
  numberArray,
  checkedOptions,
  LIMITS,
  PATHS,
  SHOT,
  PARAMETERIZE,
  POLYGONS,
  COMPARE,
  ATLAS,
  CREATE,
  toBytes,
  withProgress,
} from './arguments.js';
import { StraightestError } from './straightest-error.js';

export { StraightestError };

// `using mesh = ...` calls Symbol.dispose; runtimes without it get the key TypeScript's downlevel
// `using` looks for.
const disposeSymbol = Symbol.dispose ?? Symbol.for('Symbol.dispose');

// Where the load's warm-up pays (scripts/bench-warm-up.mjs; docs/BENCHMARKS.md, "The load's warm-up").
// Its sample gets the hot code optimized while the first load parses: that pays once per module, on its
// first load of any size; later loads would only interrupt a sample that no longer helps, a cost of
// several times a small load's own time. Its memory touch pays for a mesh whose parameterization takes
// fresh memory worth touching, from the heap the core leaves alone below 16 MB: 65,536 vertices at
// 250 bytes each. A file's vertex count is not known before it is parsed: its size stands in, at the
// fewest bytes a vertex takes with its two faces (binary PLY: 12 + 2 × 13).
const WARM_UP_MIN_VERTICES = 65_536;
const WARM_UP_MIN_BYTES = 38 * WARM_UP_MIN_VERTICES;

/** The warmUp option, or a TypeError (checked before a module is started for it). */
function checkedWarmUp(on) {
  if (typeof on !== 'boolean') throw new TypeError('warmUp must be true or false');
  return on;
}

const finalizer =
  typeof FinalizationRegistry === 'function'
    ? new FinalizationRegistry((handle) => {
        try {
          handle.delete();
        } catch {
          /* already gone */
        }
      })
    : null;

// Only the library makes meshes and modules: their constructors take this token.
const internal = Symbol('straightest internal');

/**
 * A validated triangle mesh living in WASM memory. Free it with delete(), or declare it with `using`
 * (Symbol.dispose). A mesh that becomes unreachable without either is freed by a FinalizationRegistry
 * at some later garbage collection — a safety net with no timing guarantee, not a way to manage memory.
 */
export class Mesh {
  #handle;

  constructor(token, handle) {
    if (token !== internal)
      throw new TypeError('Mesh has no public constructor: use st.loadMesh, st.meshFromArrays or st.sample');
    this.#handle = handle;
    finalizer?.register(this, handle, this);
  }

  /**
   * A topology error's extra sentence when the surface is a triangle soup (more components than half its
   * faces): its triangles share no vertices, which is what a non-indexed geometry gives.
   */
  #hint = (category) => {
    if (category !== 'topology' || !this.#handle) return '';
    const { faces, components } = this.#handle.info();
    if (faces < 2 || components <= faces / 2) return '';
    return (
      ` (${components} components for ${faces} triangles: the triangles share no vertices, as in a non-indexed ` +
      "geometry such as STLLoader's; weld coincident vertices first, e.g. meshFromBufferGeometry(st, geometry, " +
      "{ weld: true }) from 'straightest/three')"
    );
  };

  #live() {
    if (!this.#handle)
      throw new StraightestError(
        'this mesh has been deleted (delete() or the end of its `using` scope)',
        'invalid_argument',
      );
    return this.#handle;
  }

  /** { vertices, faces, edges, boundaryLoops, eulerCharacteristic, components, degenerateFaces, ... } */
  info() {
    return this.#live().info();
  }

  /** Vertex positions, 3 per vertex, in the file's order (a copy). */
  positions() {
    return this.#live().positionsView().slice();
  }

  /** Triangle vertex indices, 3 per face (a copy; faces may have been reoriented for consistency). */
  indices() {
    return this.#live().indicesView().slice();
  }

  /** Every boundary loop's vertices in order (the surface on the left), longest first. */
  boundaryLoops() {
    return this.#live().boundaryLoops();
  }

  /** Area-weighted unit vertex normals, 3 floats per vertex (zero for unreferenced vertices). */
  vertexNormals() {
    return unwrap(this.#live().vertexNormals(), this.#hint).normals;
  }

  /**
   * The default source: the interior vertex farthest from the boundary ("center of the mesh"); 'topology'
   * when every vertex lies on the boundary (there an 'auto' source is the middle of the largest face).
   */
  defaultSource() {
    return unwrap(this.#live().defaultSource(), this.#hint).vertex;
  }

  /** The base plane at a source: { source, origin, normal, fallback, note }. */
  basePlane(source = 'auto') {
    return unwrap(this.#live().basePlane(source), this.#hint);
  }

  /**
   * Straightest paths from one source to many targets (shared setup). targets: 'boundary' (every
   * vertex of the longest boundary loop), 'all-boundaries' (every loop's) or an array of surface
   * points and such entries. Returns per-path lengths, statuses, faces crossed, in-plane directions,
   * and one packed Float32Array of points with offsets (path i is points offsets[i]..offsets[i+1], 3
   * floats each). On a closed mesh both ways round the section are walked: the shorter arc is the
   * path, `backward` says which way it leaves, otherArcLengths/otherPoints/otherOffsets the other arc.
   */
  straightestPaths(options) {
    const {
      source = 'auto',
      targets = 'boundary',
      points = true,
      onProgress,
    } = checkedOptions(options, PATHS, 'straightestPaths');
    const handle = this.#live();
    return withProgress(
      onProgress,
      (progress) => handle.straightestPaths(source, targets, !!points, progress),
      this.#hint,
    );
  }

  /**
   * Shortest distances from a source to every vertex: 'heat' (factored once per mesh), 'dijkstra' or
   * 'exact' (window propagation; exactShortestPaths also gives the paths).
   */
  geodesicDistances(source = 'auto', method = 'heat') {
    return unwrap(this.#live().geodesicDistances(source, String(method)), this.#hint).distances;
  }

  /**
   * A straightest geodesic as an initial value problem (Polthier–Schmies): from the source, walk
   * straight for `length`, aimed by exactly one of `direction` ([x, y, z], projected onto the tangent
   * plane), `angle` (radians in the source's tangent frame) or `toward` (a surface point: the direction
   * the cutting plane would take; length defaults to its straightest distance). Returns points (packed
   * x, y, z), length, facesCrossed, end, status and, with `toward`, missDistance.
   */
  shootGeodesic(options) {
    const {
      source = 'auto',
      direction,
      angle,
      toward,
      length,
      points = true,
      onProgress,
    } = checkedOptions(options, SHOT, 'shootGeodesic');
    const handle = this.#live();
    return withProgress(
      onProgress,
      (progress) => handle.shootGeodesic(source, { direction, angle, toward, length }, !!points, progress),
      this.#hint,
    );
  }

  /**
   * Exact shortest paths (window propagation) from a source to vertex targets: 'boundary' (default),
   * 'all-boundaries' or an array of vertices (and such names). Returns targets, distances, and the
   * polylines packed like straightestPaths' (path i is points offsets[i]..offsets[i+1], 3 floats each).
   */
  exactShortestPaths(options) {
    const {
      source = 'auto',
      targets = 'boundary',
      points = true,
      onProgress,
    } = checkedOptions(options, PATHS, 'exactShortestPaths');
    const handle = this.#live();
    return withProgress(
      onProgress,
      (progress) => handle.exactShortestPaths(source, targets, !!points, progress),
      this.#hint,
    );
  }

  /**
   * Flattens any manifold mesh (a disk as it is; otherwise its largest component cut or filled into a
   * disk first: `cut`, `seam`, `cornerUv`, `filledLoops`, `genus` say how): boundary 'measured'
   * (default), 'circle', 'square', 'free' (the measured map — or
   * the circle's when the measured one is not bijective — refined with its boundary free to move,
   * never folding) or 'auto' (the preferred map of the four); weights 'shape-preserving' (default),
   * 'mean-value', 'cotan' or 'uniform'. maxIterations and timeBudgetMs cap the free refinement.
   * Returns uv (2 floats per vertex, in [0, 1]²; one copy's for a seam vertex), cornerUv (2 floats per
   * face corner: the map to texture with, split along the seam), per-face stretch and the metrics.
   */
  parameterize(options) {
    const {
      source = 'auto',
      boundary = 'measured',
      weights = 'shape-preserving',
      solver = 'multigrid',
      maxIterations,
      timeBudgetMs,
      onProgress,
    } = checkedOptions(options, PARAMETERIZE, 'parameterize');
    const handle = this.#live();
    return withProgress(
      onProgress,
      (progress) =>
        handle.parameterize(
          source,
          String(boundary),
          String(weights),
          String(solver),
          { maxIterations, timeBudgetMs },
          progress,
        ),
      this.#hint,
    );
  }

  /**
   * The boundary polygon of each kind, without solving: in the [0, 1]² frame parameterize with that
   * boundary puts its uv in. One entry per kind: { boundary, polygon (2 floats per loop vertex, or
   * null), loop, error, category }. Default kinds: every kind but 'free' (st.polygonBoundaryKinds),
   * whose boundary exists only after its refinement; asking for 'free' throws 'invalid_argument'.
   */
  boundaryPolygons(options) {
    const { source = 'auto', kinds, onProgress } = checkedOptions(options, POLYGONS, 'boundaryPolygons');
    const handle = this.#live();
    return withProgress(onProgress, (progress) => handle.boundaryPolygons(source, kinds, progress), this.#hint)
      .polygons;
  }

  /**
   * Every boundary × weights, parameterized and judged: { rows: [{ boundary, weights, l2, linf,
   * flipped, degenerate, overlaps, bijective, init, iterations, converged, timeMs, error, category }],
   * best } (best: the row boundary 'auto' would prefer, -1 when every row failed). Free rows refine
   * their weights' measured (or circle) map; maxIterations and timeBudgetMs cap that refinement.
   */
  compareParameterizations(options) {
    const {
      source = 'auto',
      boundaries,
      weights,
      solver = 'multigrid',
      maxIterations,
      timeBudgetMs,
      onProgress,
    } = checkedOptions(options, COMPARE, 'compareParameterizations');
    const handle = this.#live();
    return withProgress(
      onProgress,
      (progress) =>
        handle.compareParameterizations(
          source,
          boundaries,
          weights,
          String(solver),
          { maxIterations, timeBudgetMs },
          progress,
        ),
      this.#hint,
    );
  }

  /**
   * A texture atlas: the mesh split into charts that are topological disks, each flattened with the free
   * boundary (never folding, never mirrored) until its stretch is at most maxStretch, packed into one
   * texture of resolution² (or width × height) texels with `padding` texels between charts. Returns
   * cornerUv (2 floats per face corner in [0, 1]²), chartOfFace, the seam, and the measurement of that uv
   * (stretch, utilization, flipped, mirrored, overlaps, padding violations, …); stages 'segment', 'flatten',
   * 'pack', 'measure'.
   */
  atlas(options) {
    const { onProgress, ...rest } = checkedOptions(options, ATLAS, 'atlas');
    const handle = this.#live();
    return withProgress(onProgress, (progress) => handle.atlas(rest, progress), this.#hint);
  }

  /** The live Embind handle, for Straightest.atlas (the token keeps it from the public API). */
  [internal]() {
    return this.#live();
  }

  /**
   * The mesh as OBJ text (input vertex order); with uv also `vt` lines: 2 numbers per vertex (a vt per
   * vertex), or 2 per face corner (a parameterization's cornerUv: a vt per distinct uv, so seams split).
   */
  toOBJ(uv) {
    return unwrap(this.#live().toObj(uv === undefined || uv === null ? null : numberArray(uv))).text;
  }

  get deleted() {
    return !this.#handle;
  }

  /** Frees the WASM memory of this mesh. Idempotent. */
  delete() {
    if (!this.#handle) return;
    finalizer?.unregister(this);
    this.#handle.delete();
    this.#handle = null;
  }

  /** The same as delete(): `using mesh = st.sample('cap')` frees the mesh at the end of the scope. */
  [disposeSymbol]() {
    this.delete();
  }
}

/**
 * The loaded library. Create with `await createStraightest()`. Its WASM memory lives as long as the
 * object is reachable (there is nothing to dispose: meshes are what hold memory inside it).
 */
export class Straightest {
  #module;
  #names;
  #loadedThreads; // the threads the module was started for: its workers
  #warmUp = true;
  #warmedUp = false; // a load has warmed up this module: its hot code is optimized or on the way
  #threadsUnavailable;

  constructor(token, module, { warmUp = true, threadsUnavailable = null } = {}) {
    if (token !== internal) throw new TypeError('Straightest has no public constructor: use await createStraightest()');
    this.#module = module;
    this.#names = module.nameLists();
    this.#loadedThreads = module.threadCount();
    this.#threadsUnavailable = threadsUnavailable;
    this.warmUp = warmUp;
  }

  /**
   * Why the single-threaded module runs although more than one thread was asked for (or by default):
   * e.g. the page is not cross-origin isolated, or the threaded module's files could not be loaded or
   * its workers did not start in time. null when the threaded module runs or one thread was asked for.
   */
  get threadsUnavailable() {
    return this.#threadsUnavailable;
  }

  /**
   * Whether loadMesh and meshFromArrays use a spare thread, while they parse and build, to make the
   * first call on the mesh run like a repeat: they touch the memory a parameterization of the mesh
   * will take (an estimate from its size, capped by maxVertices and by half of what the memory can
   * still grow by; the module's memory does not shrink) and, until once it ran to the end, run a small
   * sample so the engine optimizes the hot code. Only where that pays: the module's first load, and
   * loads of at least 65,536 vertices (arrays) or 2.5 MB (files); other loads run as with false. The
   * threaded module only (with at least 2 threads); it never makes a load slower than one step of it,
   * and changes no result. Default true.
   */
  get warmUp() {
    return this.#warmUp;
  }

  set warmUp(on) {
    this.#warmUp = checkedWarmUp(on);
  }

  /** Whether a load of this size warms up (warmUp's rule): the module's first load, and large ones. */
  #warmsUp(large) {
    const on = this.#warmUp && (large || !this.#warmedUp);
    if (on) this.#warmedUp = true;
    return on;
  }

  /** The trace statuses, in the core's order: 'reached' is the only success. */
  get traceStatuses() {
    return [...this.#names.traceStatuses];
  }

  /** shootGeodesic's statuses, in the core's order: 'reached_length' is the only success. */
  get shootStatuses() {
    return [...this.#names.shootStatuses];
  }

  /** The boundary kinds: ['measured', 'circle', 'square', 'free']. */
  get boundaryKinds() {
    return [...this.#names.boundaryKinds];
  }

  /** The kinds boundaryPolygons gives without a solve: every kind but 'free'. */
  get polygonBoundaryKinds() {
    return [...this.#names.polygonBoundaryKinds];
  }

  /** What parameterize's `boundary` takes: the kinds and 'auto'. */
  get boundaryChoices() {
    return [...this.#names.boundaryChoices];
  }

  /** The interior weight kinds: ['shape-preserving', 'mean-value', 'cotan', 'uniform']. */
  get weightKinds() {
    return [...this.#names.weightKinds];
  }

  /** The linear solvers: ['multigrid', 'lu', 'bicgstab']. */
  get solvers() {
    return [...this.#names.solvers];
  }

  /** geodesicDistances' methods: ['heat', 'dijkstra', 'exact']. */
  get distanceMethods() {
    return [...this.#names.distanceMethods];
  }

  /** loadMesh's formats: ['obj', 'off', 'ply', 'stl', 'auto']. */
  get meshFormats() {
    return [...this.#names.meshFormats];
  }

  /** Every StraightestError category. */
  get errorCategories() {
    return [...this.#names.errorCategories];
  }

  /** The format a file name asks for: 'obj', 'off', 'ply', 'stl' (by extension, any case) or 'auto'. */
  formatFromFileName(name) {
    return this.#module.formatFromFileName(String(name ?? ''));
  }

  /** Parses an OBJ, OFF, PLY or STL file (PLY and STL ascii or binary) given as bytes (Uint8Array/ArrayBuffer) or text. */
  loadMesh(data, format = 'auto', limits) {
    const checked = checkedOptions(limits, LIMITS, 'loadMesh');
    const bytes = toBytes(data);
    const warmUp = this.#warmsUp(bytes.length >= WARM_UP_MIN_BYTES);
    return new Mesh(internal, unwrap(this.#module.loadMeshBytes(bytes, String(format), checked, warmUp)).mesh);
  }

  /** Builds a mesh from flat arrays: positions (x, y, z per vertex) and indices (3 per triangle). */
  meshFromArrays(positions, indices, limits) {
    // Checked here: a JavaScript error thrown inside the module would unwind its C++ frames unfinished.
    if (!isArrayLike(positions) || !isArrayLike(indices))
      throw new TypeError('meshFromArrays expects positions and indices as arrays (or typed arrays) of numbers');
    const [xyz, triangles] = [numberArray(positions), numberArray(indices)];
    const checked = checkedOptions(limits, LIMITS, 'meshFromArrays');
    const warmUp = this.#warmsUp(xyz.length >= 3 * WARM_UP_MIN_VERTICES);
    return new Mesh(internal, unwrap(this.#module.meshFromArrays(xyz, triangles, checked, warmUp)).mesh);
  }

  /**
   * One texture atlas shared by several meshes (lightmaps): mesh.atlas's options and result for all of
   * them together (charts never span two meshes), plus `meshes`, each mesh's { cornerUv, chartOfFace }
   * in the order given. An empty array throws 'empty'.
   */
  atlas(meshes, options) {
    if (!Array.isArray(meshes) || !meshes.every((m) => m instanceof Mesh)) {
      throw new TypeError('atlas expects an array of meshes (st.loadMesh, st.meshFromArrays, st.sample)');
    }
    const { onProgress, ...rest } = checkedOptions(options, ATLAS, 'atlas');
    const handles = meshes.map((m) => m[internal]());
    return withProgress(onProgress, (progress) => this.#module.atlas(handles, rest, progress));
  }

  /** Names of the built-in sample meshes. */
  sampleNames() {
    return this.#module.sampleNames();
  }

  /** A built-in sample mesh ('mountain', 'cap', 'saddle', 'face': disks; 'holes', 'sphere', 'torus'). */
  sample(name) {
    return new Mesh(internal, unwrap(this.#module.sample(String(name))).mesh);
  }

  /**
   * How many threads the core runs on: 1 in the single-threaded module, the count asked for (or every
   * core) in the threaded one.
   */
  get threads() {
    return this.#module.threadCount();
  }

  /**
   * Changes the thread count for later calls, from 1 to the count the module was loaded with (its Web
   * Workers are started at load time); anything else throws StraightestError 'invalid_argument'.
   */
  set threads(count) {
    if (!Number.isInteger(count) || count < 1 || count > this.#loadedThreads) {
      throw new StraightestError(
        `threads must be a whole number from 1 to ${this.#loadedThreads} (the count this module ` +
          `was loaded with), got ${count}`,
        'invalid_argument',
      );
    }
    this.#module.setThreadCount(count);
  }

  /** Bytes of WASM memory currently reserved (grows, never shrinks; shared memory may grow on any thread). */
  get memoryBytes() {
    return (this.#module.wasmMemory?.buffer ?? this.#module.HEAPU8).byteLength;
  }

  /** Bytes currently allocated inside WASM memory (returns to its baseline when meshes are deleted). */
  get heapUsedBytes() {
    return this.#module.heapUsedBytes();
  }
}

/**
 * createStraightest's work for an entry point: checks the options (before any module or worker
 * starts: `threads` a whole number or absent), then `start(options)` → { module, threadsUnavailable }
 * makes the Straightest.
 */
export async function createWith(start, options) {
  const checked = checkedOptions(options, CREATE, 'createStraightest');
  checkedWarmUp(checked.warmUp ?? true);
  const { threads } = checked;
  if (threads !== undefined && threads !== null && (!Number.isInteger(threads) || threads < 0)) {
    throw new StraightestError(
      `threads must be a whole number (0: every core, 1: one thread), got ${threads}`,
      'invalid_argument',
    );
  }
  const { module, threadsUnavailable } = await start(checked);
  return new Straightest(internal, module, { ...checked, threadsUnavailable });
}
