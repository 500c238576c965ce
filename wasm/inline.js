// straightest/inline — the same API as 'straightest', with the WebAssembly module embedded in the
// JavaScript (base64, decoded once at createStraightest()): nothing to serve, copy or configure, for
// any bundler, at the cost of ~1.33× the module's size in the bundle and no streaming compilation.
import { createStraightest as createFromBinary } from './index.js';
import embeddedWasm from './dist/straightest-core-embedded.js';

export * from './index.js';

let decoded = null;

function wasmBytes() {
  if (!decoded) {
    const text = atob(embeddedWasm);
    decoded = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) decoded[i] = text.charCodeAt(i);
  }
  return decoded;
}

/** Loads the embedded WebAssembly module (options.wasmBinary, if given, still wins). */
export function createStraightest(options = {}) {
  return createFromBinary({ ...options, wasmBinary: options.wasmBinary ?? wasmBytes() });
}
