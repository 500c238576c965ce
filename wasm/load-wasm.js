// Where the WebAssembly module comes from and getting its bytes: a file: URL is read from disk when
// running in Node (whatever else is defined: jsdom gives Node a `window`), anything else is fetched.
// Whatever goes wrong becomes StraightestError 'io' naming the URL and what came back, instead of
// Emscripten's bare `Aborted(...)`. Node's modules are imported by a name bundlers do not follow, so a
// browser bundle never sees them.
import { StraightestError } from './straightest-error.js';

const MAGIC = [0x00, 0x61, 0x73, 0x6d]; // "\0asm"

/**
 * The URL to load the module from: options.wasmUrl, options.locateFile(name, directory) (name: the
 * default URL's file name, e.g. 'straightest-core.wasm'), or the default.
 */
export function wasmLocation(options, defaultUrl) {
  if (options.wasmUrl) return String(options.wasmUrl);
  const name = defaultUrl.pathname.slice(defaultUrl.pathname.lastIndexOf('/') + 1);
  if (options.locateFile) return String(options.locateFile(name, new URL('.', defaultUrl).href));
  return defaultUrl.href;
}

export function isNode() {
  return typeof globalThis.process?.versions?.node === 'string';
}

/** Node's own module `name`, imported at run time only (bundlers leave a computed specifier alone). */
export function nodeModule(name) {
  return import(/* @vite-ignore */ /* webpackIgnore: true */ `node:${name}`);
}

function describeBytes(bytes) {
  const head = bytes.subarray(0, 16);
  const hex = Array.from(head, (b) => b.toString(16).padStart(2, '0')).join(' ');
  const text = String.fromCharCode(...head).replace(/[^\x20-\x7e]/g, '.');
  return bytes.length === 0 ? 'nothing (0 bytes)' : `${bytes.length} bytes starting with ${hex} ("${text}")`;
}

/** Throws StraightestError 'io' unless `bytes` start with WebAssembly's magic number. */
export function checkWasm(bytes, where) {
  if (MAGIC.every((b, i) => bytes[i] === b)) return bytes;
  const html = bytes[0] === 0x3c; // '<': a server's HTML page (a 404 page, or a dev server's index.html)
  const hint = html
    ? ': an HTML page, so the server has no module at that URL (with a dev server that pre-bundles dependencies, ' +
      "exclude 'straightest' from pre-bundling, pass wasmUrl, or use 'straightest/inline')"
    : '';
  throw new StraightestError(`${where} is not a WebAssembly module: got ${describeBytes(bytes)}${hint}`, 'io');
}

/** The module's bytes from `url` (a string); StraightestError 'io' when they cannot be had. */
export async function readWasm(url) {
  let bytes;
  try {
    if (url.startsWith('file:') && isNode()) {
      const [{ readFile }, { fileURLToPath }] = await Promise.all([nodeModule('fs/promises'), nodeModule('url')]);
      bytes = new Uint8Array(await readFile(fileURLToPath(url)));
    } else {
      const response = await fetch(url);
      const body = new Uint8Array(await response.arrayBuffer());
      if (!response.ok) {
        throw new StraightestError(
          `could not load the WebAssembly module from ${url}: HTTP ${response.status} ` +
            `${response.statusText}, body: ${describeBytes(body)}`,
          'io',
        );
      }
      bytes = body;
    }
  } catch (error) {
    if (error instanceof StraightestError) throw error;
    throw new StraightestError(`could not load the WebAssembly module from ${url}: ${error?.message ?? error}`, 'io', {
      cause: error,
    });
  }
  return checkWasm(bytes, url);
}
