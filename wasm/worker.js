// straightest/worker — the package's API in a module worker (wasm/worker-entry.js), as promises: the
// main thread stays free while the core works. Results arrive with their typed arrays transferred;
// onProgress is called as the worker reports; an AbortSignal (or worker.cancel()) cancels. Because the
// work runs inside synchronous WASM calls, cancelling terminates the worker and starts a new one: every
// pending call rejects with StraightestError 'cancelled', and meshes are rebuilt in the new worker from
// what made them the next time they are used.
import { StraightestError } from './straightest-error.js';

// Each WorkerMesh's number in its worker, for the calls that take several meshes (st.atlas).
const meshIds = new WeakMap();

// `await using` calls Symbol.asyncDispose; runtimes without it get the key TypeScript's downlevel
// `await using` looks for.
const asyncDisposeSymbol = Symbol.asyncDispose ?? Symbol.for('Symbol.asyncDispose');

/** A mesh living in the worker; every method returns a promise of what Mesh's returns. */
class WorkerMesh {
  #client;
  #id;

  constructor(client, id) {
    this.#client = client;
    this.#id = id;
    meshIds.set(this, id);
  }

  /** Whether delete() has been called. */
  get deleted() {
    return this.#client.isDeleted(this.#id);
  }

  info() {
    return this.#client.call(this.#id, 'info', []);
  }
  positions() {
    return this.#client.call(this.#id, 'positions', []);
  }
  indices() {
    return this.#client.call(this.#id, 'indices', []);
  }
  boundaryLoops() {
    return this.#client.call(this.#id, 'boundaryLoops', []);
  }
  vertexNormals() {
    return this.#client.call(this.#id, 'vertexNormals', []);
  }
  defaultSource() {
    return this.#client.call(this.#id, 'defaultSource', []);
  }
  basePlane(source = 'auto') {
    return this.#client.call(this.#id, 'basePlane', [source]);
  }
  geodesicDistances(source = 'auto', method = 'heat') {
    return this.#client.call(this.#id, 'geodesicDistances', [source, method]);
  }
  toOBJ(uv) {
    return this.#client.call(this.#id, 'toOBJ', [uv]);
  }
  // The long calls: options as Mesh's, plus `signal` (an AbortSignal that cancels).
  straightestPaths(options = {}) {
    return this.#client.callWithOptions(this.#id, 'straightestPaths', options);
  }
  parameterize(options = {}) {
    return this.#client.callWithOptions(this.#id, 'parameterize', options);
  }
  boundaryPolygons(options = {}) {
    return this.#client.callWithOptions(this.#id, 'boundaryPolygons', options);
  }
  compareParameterizations(options = {}) {
    return this.#client.callWithOptions(this.#id, 'compareParameterizations', options);
  }
  shootGeodesic(options = {}) {
    return this.#client.callWithOptions(this.#id, 'shootGeodesic', options);
  }
  exactShortestPaths(options = {}) {
    return this.#client.callWithOptions(this.#id, 'exactShortestPaths', options);
  }
  atlas(options = {}) {
    return this.#client.callWithOptions(this.#id, 'atlas', options);
  }

  /** Frees the mesh in the worker; later calls reject with StraightestError 'invalid_argument'. */
  delete() {
    return this.#client.deleteMesh(this.#id);
  }

  /** The same as delete(): `await using mesh = await st.sample('cap')` frees it at the end of the scope. */
  [asyncDisposeSymbol]() {
    return this.delete();
  }
}

function defaultWorker() {
  if (typeof Worker !== 'function')
    throw new TypeError(
      'createStraightestWorker needs Web Workers (a browser, or Deno), which Node lacks: in Node call ' +
        'createStraightest, or pass createWorker that makes a Worker-like object',
    );
  return new Worker(new URL('./worker-entry.js', import.meta.url), { type: 'module' });
}

/**
 * createWorker() run while the global Worker records the script URL it is given, so that a worker
 * that cannot load can be named (a Worker does not say where it came from, and a bundler rewrites
 * the URL of the default one).
 */
function startWorker(createWorker) {
  const Original = globalThis.Worker;
  let url = null;
  if (typeof Original === 'function') {
    globalThis.Worker = class extends Original {
      constructor(scriptUrl, options) {
        super(scriptUrl, options);
        url = String(scriptUrl);
      }
    };
  }
  try {
    const worker = createWorker();
    return { worker, url };
  } finally {
    globalThis.Worker = Original;
  }
}

/** What fetching the worker's script gives: its status and type, the usual cause of a worker that cannot load. */
async function whyNotLoaded(url, event) {
  if (!url) return event.message || 'its script did not load or failed (createWorker made it)';
  try {
    const response = await fetch(url);
    const type = response.headers.get('content-type') ?? 'no content type';
    const html = /html/i.test(type)
      ? ' (an HTML page: the bundle has no worker script at that URL; see docs/API.md for your bundler)'
      : '';
    const failed = event.message ? `; the worker said: ${event.message}` : '';
    return `HTTP ${response.status} ${response.statusText}, ${type}${html}${failed}`;
  } catch (error) {
    return `fetching it failed too: ${error?.message ?? error}`;
  }
}

/**
 * createStraightest's options as the worker gets them: a URL (object or relative) as an absolute
 * string, resolved against this page rather than the worker's script; locateFile refused (a function
 * cannot be sent to a worker).
 */
function optionsForWorker(options) {
  if (options.locateFile !== undefined) {
    throw new TypeError('createStraightestWorker cannot send locateFile (a function) to the worker: pass wasmUrl');
  }
  if (options.wasmUrl === undefined || options.wasmUrl === null) return options;
  const base = globalThis.document?.baseURI ?? globalThis.location?.href;
  return { ...options, wasmUrl: base ? new URL(String(options.wasmUrl), base).href : String(options.wasmUrl) };
}

/**
 * Starts the worker. options: `createWorker` (() => a module Worker running the package's
 * wasm/worker-entry.js, for bundlers that do not bundle `new Worker(new URL(…))` themselves; called
 * again after each cancel), plus createStraightest's `threads` / `wasmUrl` / `wasmBinary` / `warmUp`, handed to the
 * worker (the threaded module runs there when the worker is cross-origin isolated).
 */
export async function createStraightestWorker(options = {}) {
  const { createWorker = defaultWorker, ...rest } = options;
  const loadOptions = optionsForWorker(rest);
  let current = null; // { worker, pending: Map(id → { resolve, reject, onProgress }), meshes: Map(id → built promise) }
  let names = null; // the module's name lists, from 'init'
  let nextId = 1;
  let nextMesh = 1;
  let terminated = false;
  const recipes = new Map(); // mesh id → { method, args } that made it

  function start() {
    const { worker, url } = startWorker(createWorker);
    const instance = { worker, pending: new Map(), meshes: new Map(), ready: null, heard: false };
    worker.addEventListener('message', ({ data }) => {
      instance.heard = true;
      const entry = instance.pending.get(data.id);
      if (!entry) return;
      if (data.type === 'progress') {
        entry.onProgress?.(data.stage, data.fraction);
        return;
      }
      instance.pending.delete(data.id);
      if (data.type === 'error') entry.reject(new StraightestError(data.message, data.category));
      else entry.resolve(data.value);
    });
    worker.addEventListener('error', (event) => {
      event.preventDefault?.();
      if (instance.heard) {
        const where = event.filename ? ` (${event.filename}:${event.lineno})` : '';
        fail(instance, `the straightest worker failed: ${event.message || 'script error'}${where}`, 'internal');
        return;
      }
      // Nothing came from it yet: its script did not load (or failed at once).
      worker.terminate();
      whyNotLoaded(url, event).then((why) => {
        fail(instance, `the straightest worker could not be started${url ? ` from ${url}` : ''}: ${why}`, 'io');
      });
    });
    current = instance;
    instance.ready = send(instance, { type: 'init', options: loadOptions }).then((value) => {
      names = value;
    });
    return instance;
  }

  function fail(instance, message, category) {
    for (const entry of instance.pending.values()) entry.reject(new StraightestError(message, category));
    instance.pending.clear();
  }

  function send(instance, message, transfer = [], onProgress = null) {
    const id = nextId++;
    if (terminated) return Promise.reject(new StraightestError('the straightest worker was terminated', 'cancelled'));
    return new Promise((resolve, reject) => {
      instance.pending.set(id, { resolve, reject, onProgress });
      instance.worker.postMessage({ id, ...message }, transfer);
    });
  }

  /** Terminates the worker: pending calls reject as 'cancelled'; a new worker takes over. */
  function cancel() {
    const old = current;
    if (terminated) return;
    old.worker.terminate();
    start();
    fail(old, 'cancelled', 'cancelled');
  }

  /** Builds mesh `id` in the worker unless it is there already (or being built: calls share one build). */
  function ensureMesh(instance, id) {
    if (!recipes.has(id)) return Promise.reject(new StraightestError('this mesh has been deleted', 'invalid_argument'));
    if (!instance.meshes.has(id)) {
      const { method, args } = recipes.get(id);
      const built = send(instance, { type: 'create', mesh: id, method, args });
      built.catch(() => {
        if (instance.meshes.get(id) === built) instance.meshes.delete(id);
      });
      instance.meshes.set(id, built);
    }
    return instance.meshes.get(id);
  }

  async function create(method, args) {
    const id = nextMesh++;
    recipes.set(id, { method, args });
    const instance = current;
    await instance.ready;
    try {
      await ensureMesh(instance, id);
    } catch (error) {
      recipes.delete(id);
      throw error;
    }
    return new WorkerMesh(client, id);
  }

  /** Sends `message` once the meshes `ids` are built in the current worker; `signal` cancels. */
  async function run(ids, message, onProgress, signal) {
    if (signal?.aborted) throw new StraightestError('cancelled', 'cancelled');
    const instance = current;
    const onAbort = () => {
      if (current === instance) cancel();
    };
    signal?.addEventListener('abort', onAbort, { once: true });
    try {
      await instance.ready;
      await Promise.all(ids.map((id) => ensureMesh(instance, id)));
      return await send(instance, { ...message, progress: !!onProgress }, [], onProgress);
    } finally {
      signal?.removeEventListener('abort', onAbort);
    }
  }

  /** A long call: `options` without onProgress and signal go to the worker as the call's last argument. */
  function runWithOptions(ids, message, { onProgress, signal, ...options }) {
    if (onProgress !== undefined && typeof onProgress !== 'function')
      throw new TypeError('onProgress must be a function');
    return run(ids, { ...message, args: [options] }, onProgress ?? null, signal ?? null);
  }

  const client = {
    isDeleted: (id) => !recipes.has(id),
    call: (id, method, args) => run([id], { type: 'call', mesh: id, method, args }, null, null),
    callWithOptions(id, method, options) {
      return runWithOptions([id], { type: 'call', mesh: id, method }, options);
    },
    async deleteMesh(id) {
      if (!recipes.delete(id)) return;
      const instance = current;
      // A terminated worker took its meshes with it.
      if (instance.meshes.delete(id) && !terminated) await send(instance, { type: 'delete', mesh: id });
    },
  };

  function terminate() {
    if (terminated) return;
    terminated = true;
    current.worker.terminate();
    fail(current, 'the straightest worker was terminated', 'cancelled');
  }

  start();
  await current.ready;

  const list = (name) => [...names[name]];
  return {
    /** Names of the built-in sample meshes. */
    sampleNames: () => list('sampleNames'),
    /** The name lists of Straightest (read once when the worker started). */
    get threads() {
      return names.threads;
    },
    /** Why the worker's module is the single-threaded one although more threads were asked for (or null). */
    get threadsUnavailable() {
      return names.threadsUnavailable;
    },
    get traceStatuses() {
      return list('traceStatuses');
    },
    get boundaryKinds() {
      return list('boundaryKinds');
    },
    get polygonBoundaryKinds() {
      return list('polygonBoundaryKinds');
    },
    get boundaryChoices() {
      return list('boundaryChoices');
    },
    get weightKinds() {
      return list('weightKinds');
    },
    get solvers() {
      return list('solvers');
    },
    get distanceMethods() {
      return list('distanceMethods');
    },
    get meshFormats() {
      return list('meshFormats');
    },
    get errorCategories() {
      return list('errorCategories');
    },
    /** The format a file name asks for: 'obj', 'off', 'ply', 'stl' (by extension, any case) or 'auto'. */
    async formatFromFileName(name) {
      const instance = current;
      await instance.ready;
      return send(instance, { type: 'module', method: 'formatFromFileName', args: [String(name ?? '')] });
    },
    /** Parses an OBJ, OFF, PLY or STL file (bytes or text) in the worker. */
    loadMesh: (data, format = 'auto', limits = {}) => create('loadMesh', [data, format, limits]),
    /** A mesh from flat arrays, built in the worker. */
    meshFromArrays: (positions, indices, limits = {}) => create('meshFromArrays', [positions, indices, limits]),
    /** A built-in sample mesh, built in the worker. */
    sample: (name) => create('sample', [name]),
    /**
     * One atlas shared by several WorkerMeshes (Straightest.atlas): options as Mesh.atlas's, plus `signal`.
     */
    atlas(meshes, options = {}) {
      if (!Array.isArray(meshes) || !meshes.every((m) => meshIds.has(m))) {
        throw new TypeError('atlas expects an array of meshes made by this worker API');
      }
      return runWithOptions(
        meshes.map((m) => meshIds.get(m)),
        { type: 'atlas', meshes: meshes.map((m) => meshIds.get(m)) },
        options,
      );
    },
    /** Stops the running work: pending calls reject with 'cancelled'; meshes stay usable. */
    cancel,
    /** Ends the worker for good: pending and later calls reject with 'cancelled'. */
    terminate,
    /** The same as terminate(): `await using st = await createStraightestWorker()` ends it with the scope. */
    async [asyncDisposeSymbol]() {
      terminate();
    },
  };
}
