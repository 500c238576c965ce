// straightest — the npm package's ESM face. Loads the WebAssembly core once per createStraightest()
// and wraps its Embind objects: errors become JS Errors, arrays are copied out of WASM memory once,
// and meshes must be delete()d (a FinalizationRegistry frees forgotten ones eventually).
import createStraightestModule from './dist/straightest-core.mjs';

const isNode = typeof process !== 'undefined' && !!process.versions?.node && typeof window === 'undefined';

/** An error from the core: `message` says what was found and where; `category` is machine-readable. */
export class StraightestError extends Error {
  constructor(message, category) {
    super(message);
    this.name = 'StraightestError';
    this.category = category;
  }
}

function unwrap(result) {
  if (result.error !== undefined) throw new StraightestError(result.error, result.category);
  return result;
}

function toBytes(data) {
  if (typeof data === 'string') return new TextEncoder().encode(data);
  if (data instanceof Uint8Array) return data;
  if (data instanceof ArrayBuffer) return new Uint8Array(data);
  if (ArrayBuffer.isView(data)) return new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
  throw new TypeError('loadMesh expects a Uint8Array, an ArrayBuffer or a string with the file contents');
}

/**
 * onProgress(stage, fraction) is called from inside the WASM work (synchronously, ~100 times per stage
 * at most); returning false cancels and the call throws a StraightestError with category 'cancelled'.
 */
function progressCallback(onProgress) {
  if (onProgress === undefined || onProgress === null) return null;
  if (typeof onProgress !== 'function') throw new TypeError('onProgress must be a function (stage, fraction) => boolean | void');
  return (stage, fraction) => onProgress(stage, fraction) !== false;
}

const finalizer = typeof FinalizationRegistry === 'function'
  ? new FinalizationRegistry((handle) => { try { handle.delete(); } catch { /* already gone */ } })
  : null;

/** A validated triangle mesh living in WASM memory. Call delete() when done. */
export class Mesh {
  #handle;

  constructor(handle) {
    this.#handle = handle;
    finalizer?.register(this, handle, this);
  }

  #live() {
    if (!this.#handle) throw new Error('straightest: this mesh has been deleted');
    return this.#handle;
  }

  /** { vertices, faces, edges, boundaryLoops, eulerCharacteristic, components, degenerateFaces, ... } */
  info() { return this.#live().info(); }

  /** Vertex positions, 3 per vertex, in the file's order (a copy). */
  positions() { return this.#live().positionsView().slice(); }

  /** Triangle vertex indices, 3 per face (a copy; faces may have been reoriented for consistency). */
  indices() { return this.#live().indicesView().slice(); }

  /** Every boundary loop's vertices in order (the surface on the left), longest first. */
  boundaryLoops() { return this.#live().boundaryLoops(); }

  /** Area-weighted unit vertex normals, 3 floats per vertex (zero for unreferenced vertices). */
  vertexNormals() { return unwrap(this.#live().vertexNormals()).normals; }

  /** The default source: the interior vertex farthest from the boundary ("center of the mesh"). */
  defaultSource() { return unwrap(this.#live().defaultSource()).vertex; }

  /** The base plane at a source: { source, origin, normal, fallback, note }. */
  basePlane(source = 'auto') { return unwrap(this.#live().basePlane(source)); }

  /**
   * Straightest paths from one source to many targets (shared setup). targets: 'boundary' (every
   * vertex of the longest boundary loop) or an array of surface points and 'boundary' entries.
   * Returns per-path lengths, statuses, faces crossed, in-plane directions, and one packed
   * Float32Array of points with offsets (path i is points offsets[i]..offsets[i+1], 3 floats each).
   */
  straightestPaths({ source = 'auto', targets = 'boundary', points = true, onProgress } = {}) {
    return unwrap(this.#live().straightestPaths(source, targets, !!points, progressCallback(onProgress)));
  }

  /** Shortest distances from a source to every vertex: 'heat' (factored once per mesh) or 'dijkstra'. */
  geodesicDistances(source = 'auto', method = 'heat') {
    return unwrap(this.#live().geodesicDistances(source, String(method))).distances;
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
  parameterize({
    source = 'auto', boundary = 'measured', weights = 'shape-preserving', solver = 'multigrid',
    maxIterations, timeBudgetMs, onProgress,
  } = {}) {
    return unwrap(this.#live().parameterize(source, String(boundary), String(weights), String(solver),
      { maxIterations, timeBudgetMs }, progressCallback(onProgress)));
  }

  /**
   * The boundary polygon of each kind, without solving: in the [0, 1]² frame parameterize with that
   * boundary puts its uv in. One entry per kind: { boundary, polygon (2 floats per loop vertex, or
   * null), loop, error, category }. Default kinds: every kind but 'free' (st.polygonBoundaryKinds),
   * whose boundary exists only after its refinement; asking for 'free' throws 'invalid_argument'.
   */
  boundaryPolygons({ source = 'auto', kinds, onProgress } = {}) {
    return unwrap(this.#live().boundaryPolygons(source, kinds, progressCallback(onProgress))).polygons;
  }

  /**
   * Every boundary × weights, parameterized and judged: { rows: [{ boundary, weights, l2, linf,
   * flipped, degenerate, overlaps, bijective, init, iterations, converged, timeMs, error, category }],
   * best } (best: the row boundary 'auto' would prefer, -1 when every row failed). Free rows refine
   * their weights' measured (or circle) map; maxIterations and timeBudgetMs cap that refinement.
   */
  compareParameterizations({
    source = 'auto', boundaries, weights, solver = 'multigrid', maxIterations, timeBudgetMs, onProgress,
  } = {}) {
    return unwrap(this.#live().compareParameterizations(source, boundaries, weights, String(solver),
      { maxIterations, timeBudgetMs }, progressCallback(onProgress)));
  }

  /**
   * The mesh as OBJ text (input vertex order); with uv also `vt` lines: 2 numbers per vertex (a vt per
   * vertex), or 2 per face corner (a parameterization's cornerUv: a vt per distinct uv, so seams split).
   */
  toOBJ(uv) { return unwrap(this.#live().toObj(uv ?? null)).text; }

  get deleted() { return !this.#handle; }

  /** Frees the WASM memory of this mesh. Idempotent. */
  delete() {
    if (!this.#handle) return;
    finalizer?.unregister(this);
    this.#handle.delete();
    this.#handle = null;
  }
}

/** The loaded library. Create with `await createStraightest()`. */
export class Straightest {
  #module;
  #names;

  constructor(module) {
    this.#module = module;
    this.#names = module.nameLists();
  }

  /** The trace statuses, in the core's order: 'reached' is the only success. */
  get traceStatuses() { return [...this.#names.traceStatuses]; }

  /** The boundary kinds: ['measured', 'circle', 'square', 'free']. */
  get boundaryKinds() { return [...this.#names.boundaryKinds]; }

  /** The kinds boundaryPolygons gives without a solve: every kind but 'free'. */
  get polygonBoundaryKinds() { return [...this.#names.polygonBoundaryKinds]; }

  /** What parameterize's `boundary` takes: the kinds and 'auto'. */
  get boundaryChoices() { return [...this.#names.boundaryChoices]; }

  /** The interior weight kinds: ['shape-preserving', 'mean-value', 'cotan', 'uniform']. */
  get weightKinds() { return [...this.#names.weightKinds]; }

  /** The linear solvers: ['multigrid', 'lu', 'bicgstab']. */
  get solvers() { return [...this.#names.solvers]; }

  /** geodesicDistances' methods: ['heat', 'dijkstra']. */
  get distanceMethods() { return [...this.#names.distanceMethods]; }

  /** loadMesh's formats: ['obj', 'off', 'auto']. */
  get meshFormats() { return [...this.#names.meshFormats]; }

  /** Every StraightestError category. */
  get errorCategories() { return [...this.#names.errorCategories]; }

  /** The format a file name asks for: 'obj', 'off' (by extension, any case) or 'auto'. */
  formatFromFileName(name) { return this.#module.formatFromFileName(String(name ?? '')); }

  /** Parses an OBJ or OFF file given as bytes (Uint8Array/ArrayBuffer) or text. */
  loadMesh(data, format = 'auto', limits = {}) {
    return new Mesh(unwrap(this.#module.loadMeshBytes(toBytes(data), String(format), limits)).mesh);
  }

  /** Builds a mesh from flat arrays: positions (x, y, z per vertex) and indices (3 per triangle). */
  meshFromArrays(positions, indices, limits = {}) {
    return new Mesh(unwrap(this.#module.meshFromArrays(positions, indices, limits)).mesh);
  }

  /** Names of the built-in sample meshes. */
  sampleNames() { return this.#module.sampleNames(); }

  /** A built-in sample mesh ('mountain', 'cap', 'saddle', 'face': disks; 'holes', 'sphere', 'torus'). */
  sample(name) { return new Mesh(unwrap(this.#module.sample(String(name))).mesh); }

  /** Bytes of WASM memory currently reserved (grows, never shrinks). */
  get memoryBytes() { return this.#module.HEAPU8.length; }

  /** Bytes currently allocated inside WASM memory (returns to its baseline when meshes are deleted). */
  get heapUsedBytes() { return this.#module.heapUsedBytes(); }
}

/**
 * Loads the WebAssembly module. Options: `wasmUrl` (where the .wasm is served, for bundlers and
 * CDNs), `locateFile(name)` (Emscripten's hook), or `wasmBinary` (the bytes themselves).
 */
export async function createStraightest(options = {}) {
  const args = {};
  if (options.wasmBinary) {
    args.wasmBinary = options.wasmBinary;
  } else if (options.wasmUrl) {
    args.locateFile = () => String(options.wasmUrl);
  } else if (options.locateFile) {
    args.locateFile = options.locateFile;
  } else if (isNode) {
    // The loader is built for web and workers; in Node hand it the bytes next to this file.
    const { readFile } = await import('node:fs/promises');
    args.wasmBinary = await readFile(new URL('./dist/straightest-core.wasm', import.meta.url));
  }
  return new Straightest(await createStraightestModule(args));
}
