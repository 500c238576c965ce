// Which of the package's two WebAssembly modules runs here: the threaded one (Emscripten pthreads,
// wasm/start-threads.js) where memory can be shared with workers — Node, and pages or workers that are
// cross-origin isolated (served with COOP/COEP) — and the single-threaded one (wasm/start-single.js)
// otherwise, when one thread is asked for, or when the threaded one cannot start; then the reason is
// kept (st.threadsUnavailable) and, for a failure rather than a page that is not isolated, said once
// on the console. Both have the same bindings; the core's results do not depend on the thread count
// (threads.hpp).
import { startSingleThreaded } from './start-single.js';
import { hardwareThreads, startThreaded, threadsUnusableReason } from './start-threads.js';

const MAX_THREADS = 64; // threads.hpp's cap
let warned = false;

/** The reason the threaded module is not even tried, or null to try it. */
function skipReason(options) {
  if (options.wasmBinary || options.wasmUrl) return 'wasmUrl and wasmBinary name the single-threaded module';
  return threadsUnusableReason();
}

/**
 * { module, threadsUnavailable }: the started Embind module for createStraightest's checked options,
 * and why it is the single-threaded one although more than one thread was asked for (null otherwise).
 */
export async function startModule(options) {
  const threads = Math.min(options.threads || (await hardwareThreads()), MAX_THREADS);
  if (threads <= 1) return { module: await startSingleThreaded(options), threadsUnavailable: null };
  const skipped = skipReason(options);
  const threaded = skipped ? { reason: skipped } : await startThreaded(options, threads);
  if (threaded.module) return { module: threaded.module, threadsUnavailable: null };
  if (!skipped && !warned) {
    warned = true;
    console.warn(`straightest: running on one thread: ${threaded.reason}`);
  }
  return { module: await startSingleThreaded(options), threadsUnavailable: threaded.reason };
}
