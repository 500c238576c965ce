// The module worker behind straightest/worker (wasm/worker.js is its client): it owns a Straightest
// instance and the meshes made in it, runs each request through the same API a caller imports, and
// posts results back with their typed arrays' buffers transferred (not copied).
//
// Protocol (every request has an `id`; exactly one final reply echoes it; 'progress' may come before):
//   → { id, type: 'init', options }                      ← { id, type: 'result', value: names }
//        options: createStraightest's (threads, wasmUrl, wasmBinary, warmUp); the worker's own default otherwise;
//        names: the module's name lists ({ sampleNames, boundaryKinds, weightKinds, … }, see NAME_LISTS)
//        `threads` (the threads the module runs on) and `threadsUnavailable` (why not more, or null)
//   → { id, type: 'module', method, args }                ← { id, type: 'result', value }
//        a Straightest method that makes no mesh: 'formatFromFileName'
//   → { id, type: 'create', mesh, method, args }         ← { id, type: 'result', value: MeshInfo }
//        method: 'loadMesh' | 'meshFromArrays' | 'sample'; mesh: the client's number for it; loadMesh's
//        data may be a Blob (a File): posting one copies no bytes, the worker reads them here
//   → { id, type: 'call', mesh, method, args, progress }  ← { id, type: 'result', value }
//        a Mesh method; with progress true, its last argument's onProgress posts
//        { id, type: 'progress', stage, fraction }
//   → { id, type: 'atlas', meshes, args, progress }      ← { id, type: 'result', value }
//        Straightest.atlas over the meshes numbered `meshes`, progress as 'call'
//   → { id, type: 'delete', mesh }                       ← { id, type: 'result', value: null }
//   any failure                                          ← { id, type: 'error', message, category }
// Cancelling: the work runs inside synchronous WASM calls, so the client terminates the worker.
import { createStraightest } from './index.js';

let straightest = null;
const meshes = new Map();

const CREATORS = new Set(['loadMesh', 'meshFromArrays', 'sample']);
const MODULE_METHODS = new Set(['formatFromFileName']);
// The Straightest getters the client offers synchronously, read once at 'init'.
const NAME_LISTS = [
  'traceStatuses',
  'boundaryKinds',
  'polygonBoundaryKinds',
  'boundaryChoices',
  'weightKinds',
  'solvers',
  'distanceMethods',
  'meshFormats',
  'errorCategories',
];
const METHODS = new Set([
  'info',
  'positions',
  'indices',
  'boundaryLoops',
  'vertexNormals',
  'defaultSource',
  'basePlane',
  'straightestPaths',
  'geodesicDistances',
  'parameterize',
  'boundaryPolygons',
  'compareParameterizations',
  'toOBJ',
  'shootGeodesic',
  'exactShortestPaths',
  'atlas',
]);

/**
 * Every ArrayBuffer under `value` that a typed array owns whole (results are copies out of WASM memory;
 * a view into a larger buffer, such as that memory, is never transferred), to transfer, not copy.
 */
function buffers(value, found = new Set()) {
  if (ArrayBuffer.isView(value)) {
    if (value.byteOffset === 0 && value.byteLength === value.buffer.byteLength) found.add(value.buffer);
  } else if (Array.isArray(value)) for (const v of value) buffers(v, found);
  else if (value && typeof value === 'object') for (const v of Object.values(value)) buffers(v, found);
  return found;
}

function meshOf(number) {
  const mesh = meshes.get(number);
  if (!mesh) throw Object.assign(new Error('this mesh has been deleted'), { category: 'invalid_argument' });
  return mesh;
}

/** The request's arguments; with progress, its last one (the options) gets an onProgress that posts. */
function argumentsOf({ id, args, progress }) {
  if (!progress) return args;
  const onProgress = (stage, fraction) => {
    postMessage({ id, type: 'progress', stage, fraction });
  };
  return [...args.slice(0, -1), { ...args.at(-1), onProgress }];
}

/** A Blob's bytes (a Uint8Array), or `value` itself when it is not a Blob. */
async function bytesOfBlob(value) {
  return typeof Blob !== 'undefined' && value instanceof Blob ? new Uint8Array(await value.arrayBuffer()) : value;
}

async function handle(request) {
  const { type } = request;
  switch (type) {
    case 'init':
      straightest = await createStraightest(request.options ?? {});
      return Object.fromEntries([
        ['sampleNames', straightest.sampleNames()],
        ['threads', straightest.threads],
        ['threadsUnavailable', straightest.threadsUnavailable],
        ...NAME_LISTS.map((name) => [name, straightest[name]]),
      ]);
    case 'module':
      if (!MODULE_METHODS.has(request.method)) throw new TypeError(`unknown module method '${request.method}'`);
      return straightest[request.method](...request.args);
    case 'create': {
      if (!CREATORS.has(request.method)) throw new TypeError(`unknown mesh source '${request.method}'`);
      const args = await Promise.all(request.args.map(bytesOfBlob));
      const mesh = straightest[request.method](...args);
      meshes.set(request.mesh, mesh);
      return mesh.info();
    }
    case 'call': {
      const mesh = meshOf(request.mesh);
      if (!METHODS.has(request.method)) throw new TypeError(`unknown mesh method '${request.method}'`);
      return mesh[request.method](...argumentsOf(request));
    }
    case 'atlas':
      return straightest.atlas(request.meshes.map(meshOf), ...argumentsOf(request));
    case 'delete':
      meshes.get(request.mesh)?.delete();
      meshes.delete(request.mesh);
      return null;
    default:
      throw new TypeError(`unknown request '${type}'`);
  }
}

// Requests run one at a time, in order (each is one synchronous WASM call, 'init' aside).
let queue = Promise.resolve();
addEventListener('message', ({ data }) => {
  queue = queue.then(async () => {
    try {
      const value = await handle(data);
      postMessage({ id: data.id, type: 'result', value }, [...buffers(value)]);
    } catch (error) {
      postMessage({
        id: data.id,
        type: 'error',
        message: String(error?.message ?? error),
        category: error?.category ?? 'internal',
      });
    }
  });
});
