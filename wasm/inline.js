// straightest/inline — the same API as 'straightest', with the single-threaded WebAssembly module
// embedded in the JavaScript (gzipped and base64-encoded, decoded once at the first createStraightest()):
// nothing to serve, copy or configure, for any bundler, at the cost of about half the module's size in
// the bundle and no streaming compilation. It imports neither the threaded module nor the .wasm files' URLs, so a bundle of it
// holds no other copy of the core.
import { createWith } from './straightest.js';
import { startSingleThreaded } from './start-single.js';
import embeddedWasm from './dist/straightest-core-embedded.js';

export { Mesh, Straightest, StraightestError } from './straightest.js';

const ONE_MODULE = "straightest/inline embeds the single-threaded module only (import 'straightest' for threads)";

let decoded = null;

/** The embedded module's bytes: base64-decoded and gunzipped once (DecompressionStream: every runtime the module runs in). */
function wasmBytes() {
  if (!decoded) {
    const text = atob(embeddedWasm);
    const gzipped = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) gzipped[i] = text.charCodeAt(i);
    const stream = new Blob([gzipped]).stream().pipeThrough(new DecompressionStream('gzip'));
    decoded = new Response(stream).arrayBuffer().then((buffer) => new Uint8Array(buffer));
  }
  return decoded;
}

async function startEmbedded(options) {
  const module = await startSingleThreaded({ ...options, wasmBinary: options.wasmBinary ?? (await wasmBytes()) });
  return { module, threadsUnavailable: options.threads === 1 ? null : ONE_MODULE };
}

/** Loads the embedded WebAssembly module (options.wasmBinary, if given, still wins). */
export function createStraightest(options) {
  return createWith(startEmbedded, options);
}
