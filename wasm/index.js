// straightest — the npm package's ESM face, for browsers, bundlers and Node alike (it imports nothing
// from Node): createStraightest starts the threaded WebAssembly module where it can run and the
// single-threaded one otherwise (wasm/load-module.js); the API over either is wasm/straightest.js.
import { createWith } from './straightest.js';
import { startModule } from './load-module.js';

export { Mesh, Straightest, StraightestError } from './straightest.js';

/**
 * Loads the WebAssembly module. Options: `threads` (how many threads the core may use: default every
 * core; 1 loads the single-threaded module; more than one loads the threaded module where memory can
 * be shared with workers — Node, and cross-origin isolated pages — and the single-threaded one
 * elsewhere, or when the threaded one cannot start: st.threads says which, st.threadsUnavailable
 * why), `wasmUrl` (where the single-threaded .wasm is served, for bundlers and CDNs),
 * `locateFile(name, scriptDirectory)` (Emscripten's hook, for either module's .wasm), or `wasmBinary`
 * (the single-threaded module's bytes themselves; wasmUrl and wasmBinary load that module). By
 * default the .wasm files under wasm/dist/, read from disk for a file: URL in Node (also under jsdom)
 * and fetched otherwise. A module that cannot be loaded — not found, not WebAssembly, or refused by
 * the runtime — rejects with StraightestError 'io' naming the URL and what came back.
 */
export function createStraightest(options) {
  return createWith(startModule, options);
}
