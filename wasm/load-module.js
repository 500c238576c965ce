// Which of the package's two WebAssembly modules runs here, and starting it: the threaded one
// (Emscripten pthreads, wasm/dist/threads/) where memory can be shared with workers — Node, and pages
// or workers that are cross-origin isolated (served with COOP/COEP) — and the single-threaded one
// otherwise, or when one thread is asked for. Both have the same bindings; the core's results do not
// depend on the thread count (threads.hpp).
import createSingleThreadedModule from './dist/straightest-core.mjs';
import { StraightestError } from './straightest-error.js';
import { checkWasm, isNode, nodeModule, readWasm, wasmLocation } from './load-wasm.js';

const MAX_THREADS = 64; // threads.hpp's cap

/**
 * Whether a threaded module can run here: SharedArrayBuffer and Atomics, and in a browser cross-origin
 * isolation; in Node process.getBuiltinModule (≥ 20.16), which wasm/node-commonjs-names.js needs.
 */
export function threadsUsable() {
  if (typeof SharedArrayBuffer !== 'function' || typeof Atomics !== 'object') return false;
  return isNode() ? typeof process.getBuiltinModule === 'function' : globalThis.crossOriginIsolated === true;
}

async function hardwareThreads() {
  if (isNode()) {
    const os = await nodeModule('os');
    return os.availableParallelism?.() ?? os.cpus().length;
  }
  return globalThis.navigator?.hardwareConcurrency ?? 1;
}

/** options.threads as a count (0: every core), or StraightestError 'invalid_argument'. */
function requestedThreads(threads) {
  if (threads === undefined || threads === null) return 0;
  if (!Number.isInteger(threads) || threads < 0) {
    throw new StraightestError(
      `threads must be a whole number (0: every core, 1: one thread), got ${threads}`,
      'invalid_argument',
    );
  }
  return Math.min(threads, MAX_THREADS);
}

/**
 * Runs start() and then, in Node, undoes what Emscripten's loader does to the host process there:
 * process handlers that rethrow, and a global Worker (worker_threads'). The loader needs Worker again
 * only to grow its worker pool, which the pool sized at load time makes unnecessary.
 */
async function leavingNodeGlobalsAlone(start) {
  if (!isNode()) return start();
  const events = ['uncaughtException', 'unhandledRejection'];
  const listeners = events.map((event) => new Set(process.listeners(event)));
  const hadWorker = Object.hasOwn(globalThis, 'Worker');
  const worker = globalThis.Worker;
  try {
    return await start();
  } finally {
    events.forEach((event, i) => {
      for (const listener of process.listeners(event)) if (!listeners[i].has(listener)) process.off(event, listener);
    });
    if (hadWorker) globalThis.Worker = worker;
    else delete globalThis.Worker;
  }
}

/**
 * The threaded module, or null when it cannot be had here. Its loader is imported by a URL computed
 * at run time, which bundlers leave alone: a bundle that does not serve the package's
 * wasm/dist/threads/ next to this file gets the single-threaded module instead of a build error.
 */
async function startThreaded(options, threads) {
  const url = wasmLocation(options, new URL('./dist/threads/straightest-core-threads.wasm', import.meta.url));
  let module;
  try {
    const wasmBinary = await readWasm(url);
    const loader = new URL('./dist/threads/straightest-core-threads.mjs', import.meta.url).href;
    const { default: createThreadedModule } = await import(/* @vite-ignore */ /* webpackIgnore: true */ loader);
    // The pool of threads.cpp has threads − 1 workers (the calling thread is the last): every Web Worker
    // they run on is started here, since one started while the calling thread waits would never run.
    module = await leavingNodeGlobalsAlone(() =>
      createThreadedModule({ wasmBinary, printErr: () => {}, pthreadPoolSize: threads - 1 }),
    );
  } catch {
    return null;
  }
  // Idle workers must not keep a Node process alive (in a browser they end with their page or worker).
  if (isNode())
    for (const worker of [...module.PThread.unusedWorkers, ...module.PThread.runningWorkers]) worker.unref();
  module.setThreadCount(threads);
  return module;
}

async function startSingleThreaded(options) {
  const url = options.wasmBinary
    ? null
    : wasmLocation(options, new URL('./dist/straightest-core.wasm', import.meta.url));
  const wasmBinary = options.wasmBinary
    ? checkWasm(new Uint8Array(options.wasmBinary), 'wasmBinary')
    : await readWasm(url);
  try {
    const module = await createSingleThreadedModule({ wasmBinary, printErr: () => {} });
    module.setThreadCount(1);
    return module;
  } catch (error) {
    const from = url ? `from ${url}` : 'given as wasmBinary';
    throw new StraightestError(
      `the WebAssembly module ${from} could not be started: ${error?.message ?? error}`,
      'io',
      { cause: error },
    );
  }
}

/**
 * The started Embind module for createStraightest's options: the threaded one when more than one
 * thread is asked for (options.threads; default every core), threads are usable here, no bytes of the
 * single-threaded module are given (wasmBinary, wasmUrl) and the threaded one loads; the
 * single-threaded one otherwise.
 */
export async function startModule(options) {
  const requested = requestedThreads(options.threads);
  const threads = Math.min(requested || (await hardwareThreads()), MAX_THREADS);
  const threaded = threads > 1 && threadsUsable() && !options.wasmBinary && !options.wasmUrl;
  return (threaded && (await startThreaded(options, threads))) || startSingleThreaded(options);
}
