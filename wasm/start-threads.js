// Starting the threaded module (Emscripten pthreads, wasm/dist/threads/), or saying why it cannot run
// here. In a browser its pthread workers run the worker script embedded in the package
// (dist/threads/straightest-core-threads-worker-source.mjs) from a blob: URL, so no bundler has to
// emit a worker file; they import the loader from where the page imported it. Whatever keeps the
// module from starting — its files not served, a worker that fails, or workers that stay silent past
// a bound — ends in a reason instead of a rejection or a hang, and the caller loads the
// single-threaded module.
import { isNode, nodeModule, readWasm, wasmLocation } from './load-wasm.js';
import pthreadWorkerSource from './dist/threads/straightest-core-threads-worker-source.mjs';

// How long a browser waits for the threaded module's workers to start before it gives up on them: a
// liveness bound (a worker whose loader never arrives would otherwise hang createStraightest), far
// above what starting them takes.
export const THREADS_START_BOUND_MS = 10_000;

const ISOLATION =
  'serve the page with Cross-Origin-Opener-Policy: same-origin and Cross-Origin-Embedder-Policy: require-corp';

/** Why the threaded module cannot run here, or null when it can. */
export function threadsUnusableReason() {
  const node = globalThis.process;
  if (isNode()) {
    if (typeof node.getBuiltinModule !== 'function')
      return `Node ${node.versions.node} has no process.getBuiltinModule (Node ≥ 20.16 has)`;
    return typeof SharedArrayBuffer === 'function' ? null : 'SharedArrayBuffer is not available';
  }
  if (globalThis.crossOriginIsolated !== true || typeof SharedArrayBuffer !== 'function')
    return `this page is not cross-origin isolated, so memory cannot be shared with workers (${ISOLATION})`;
  return null;
}

/**
 * Runs start() and then, in Node, undoes what Emscripten's loader does to the host process there:
 * process handlers that rethrow, and a global Worker (worker_threads'). The loader needs Worker again
 * only to grow its worker pool, which the pool sized at load time makes unnecessary.
 */
async function leavingNodeGlobalsAlone(start) {
  if (!isNode()) return start();
  const node = globalThis.process;
  const events = ['uncaughtException', 'unhandledRejection'];
  const listeners = events.map((event) => new Set(node.listeners(event)));
  const hadWorker = Object.hasOwn(globalThis, 'Worker');
  const worker = globalThis.Worker;
  try {
    return await start();
  } finally {
    events.forEach((event, i) => {
      for (const listener of node.listeners(event)) if (!listeners[i].has(listener)) node.off(event, listener);
    });
    if (hadWorker) globalThis.Worker = worker;
    else delete globalThis.Worker;
  }
}

/**
 * { failed, detach }: failed rejects when one of the module's workers reports an error while it starts
 * (its script or the loader it imports failed). The listener comes before Emscripten's own, which would
 * rethrow the event where nothing can catch it ("Uncaught [object Event]"); detach() removes it once
 * the start is decided, so that later errors reach Emscripten as before.
 */
function workerFailure(moduleArg) {
  const workers = [...(moduleArg.PThread?.unusedWorkers ?? [])];
  let listener;
  const failed = new Promise((_, reject) => {
    listener = (event) => {
      event.preventDefault();
      event.stopImmediatePropagation();
      reject(new Error(`a worker failed: ${event.message || 'its script or the loader it imports did not load'}`));
    };
    for (const worker of workers) worker.addEventListener('error', listener);
  });
  return { failed, detach: () => workers.forEach((worker) => worker.removeEventListener('error', listener)) };
}

/** Rejects after `ms` milliseconds; cancel() clears the timer. */
function deadline(ms) {
  let timer;
  const expired = new Promise((_, reject) => {
    timer = setTimeout(() => reject(new Error(`its workers did not start within ${ms / 1000} s`)), ms);
  });
  return { expired, cancel: () => clearTimeout(timer) };
}

function terminateWorkers(moduleArg) {
  const pool = moduleArg.PThread;
  for (const worker of [...(pool?.unusedWorkers ?? []), ...(pool?.runningWorkers ?? [])]) worker.terminate();
}

/**
 * The loader's factory. A bundler that rebuilds the loader as a bundle of its own (Parcel) drops its
 * export, which nothing in the bundle imports.
 */
async function importLoader(loaderUrl) {
  const { default: factory } = await import(/* @vite-ignore */ /* webpackIgnore: true */ loaderUrl);
  if (typeof factory !== 'function')
    throw new Error(`its loader ${loaderUrl} exports no factory (a bundler rewrote it as a bundle of its own)`);
  return factory;
}

/** The module started in Node: its workers run the package's worker script file. */
async function startInNode(loaderUrl, moduleArg) {
  const createThreadedModule = await importLoader(loaderUrl);
  moduleArg.locateFile = (name, directory) => directory + name;
  const module = await leavingNodeGlobalsAlone(() => createThreadedModule(moduleArg));
  // Idle workers must not keep a Node process alive (in a browser they end with their page or worker).
  for (const worker of [...module.PThread.unusedWorkers, ...module.PThread.runningWorkers]) worker.unref();
  return module;
}

/**
 * The module started in a browser: its loader imported and its workers started from the embedded
 * script, within THREADS_START_BOUND_MS, a worker's error ending the wait at once.
 */
async function startInBrowser(loaderUrl, moduleArg) {
  const workerUrl = URL.createObjectURL(new Blob([pthreadWorkerSource], { type: 'text/javascript' }));
  moduleArg.mainScriptUrlOrBlob = loaderUrl; // what each worker imports
  moduleArg.locateFile = (name, directory) => (name.endsWith('.worker.js') ? workerUrl : directory + name);
  const bound = deadline(THREADS_START_BOUND_MS);
  let abandoned = false; // past the bound: a loader that arrives late must start no workers
  let failure = null;
  const start = async () => {
    const createThreadedModule = await importLoader(loaderUrl);
    if (abandoned) throw new Error('abandoned');
    const started = createThreadedModule(moduleArg);
    failure = workerFailure(moduleArg);
    return Promise.race([started, failure.failed]);
  };
  try {
    return await Promise.race([start(), bound.expired]);
  } catch (error) {
    abandoned = true;
    terminateWorkers(moduleArg);
    throw error;
  } finally {
    bound.cancel();
    failure?.detach();
    URL.revokeObjectURL(workerUrl);
  }
}

/**
 * { module } started on `threads` threads, or { reason } it could not be. Its loader is imported by a
 * URL computed at run time, which bundlers leave alone (webpack and Vite emit the file that
 * `new URL(…, import.meta.url)` names): a bundle that does not serve wasm/dist/threads/ gets a reason.
 */
export async function startThreaded(options, threads) {
  try {
    const url = wasmLocation(options, new URL('./dist/threads/straightest-core-threads.wasm', import.meta.url));
    const wasmBinary = await readWasm(url);
    const loaderUrl = new URL('./dist/threads/straightest-core-threads.mjs', import.meta.url).href;
    // The pool of threads.cpp has threads − 1 workers (the calling thread is the last): every Web Worker
    // they run on is started here, since one started while the calling thread waits would never run.
    const moduleArg = { wasmBinary, printErr: () => {}, pthreadPoolSize: threads - 1 };
    const module = isNode() ? await startInNode(loaderUrl, moduleArg) : await startInBrowser(loaderUrl, moduleArg);
    module.setThreadCount(threads);
    return { module };
  } catch (error) {
    return { reason: `the threaded module could not be started: ${error?.message ?? error}` };
  }
}

/** How many threads the hardware runs at once. */
export async function hardwareThreads() {
  if (isNode()) {
    const os = await nodeModule('os');
    return os.availableParallelism?.() ?? os.cpus().length;
  }
  return globalThis.navigator?.hardwareConcurrency ?? 1;
}
