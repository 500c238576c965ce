// straightest/single — the same API as 'straightest' on the single-threaded WebAssembly module only: it
// imports neither the threaded module nor its worker, so a bundle of it emits one .wasm (served beside the
// bundle, as 'straightest''s is) and none of the threaded assets. For pages that will never be
// cross-origin isolated, or that want the smaller deployment.
import { createWith } from './straightest.js';
import { startSingleThreaded } from './start-single.js';

export { Mesh, Straightest, StraightestError } from './straightest.js';

const ONE_MODULE = "straightest/single loads the single-threaded module only (import 'straightest' for threads)";

async function startSingle(options) {
  const module = await startSingleThreaded(options);
  return { module, threadsUnavailable: options.threads === 1 ? null : ONE_MODULE };
}

/** Loads the single-threaded module (options as 'straightest''s: wasmUrl, locateFile, wasmBinary). */
export function createStraightest(options) {
  return createWith(startSingle, options);
}
