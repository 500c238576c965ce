// Starting the single-threaded module (wasm/dist/straightest-core.mjs) from its bytes: options.wasmBinary,
// or read from options.wasmUrl / options.locateFile / the .wasm next to the module (wasm/load-wasm.js).
import createSingleThreadedModule from './dist/straightest-core.mjs';
import { StraightestError } from './straightest-error.js';
import { checkWasm, readWasm, wasmLocation } from './load-wasm.js';

/** The started Embind module; StraightestError 'io' when its bytes cannot be had or do not start. */
export async function startSingleThreaded(options) {
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
