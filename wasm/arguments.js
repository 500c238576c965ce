// The npm API's calls check and convert their arguments here before the module sees them, and unwrap
// the module's {error, category} results into StraightestErrors: nothing that can throw in JavaScript
// runs inside the module's C++ frames, and a misspelt option is an error, never a silent default.
import { StraightestError } from './straightest-error.js';

/** The result, or its {error, category} thrown as a StraightestError (hint(category) may add a sentence). */
export function unwrap(result, hint = undefined) {
  if (result.error !== undefined)
    throw new StraightestError(result.error + (hint?.(result.category) ?? ''), result.category);
  return result;
}

/** An array, a typed array or another object with a numeric length (what the index.d.ts calls ArrayLike). */
export const isArrayLike = (a) => a !== null && typeof a === 'object' && typeof a.length === 'number';

/**
 * The numbers of an array-like as the module copies them without a JavaScript call that can throw: a
 * typed array of numbers as it is, anything else converted here (a BigInt, a Symbol or a throwing
 * getter fails in JavaScript, not inside the module's C++ frames).
 */
export const numberArray = (a) =>
  ArrayBuffer.isView(a) && !(a instanceof DataView) && !(a instanceof BigInt64Array) && !(a instanceof BigUint64Array)
    ? a
    : Float64Array.from(a);

/**
 * A call's options object as given (undefined: {}), or StraightestError 'invalid_argument' for anything
 * that is not a plain object and for a name the call does not take: a misspelt option would otherwise be
 * ignored, and the call would return a result for the default silently.
 */
export function checkedOptions(options, known, call) {
  if (options === undefined) return {};
  if (options === null || typeof options !== 'object' || Array.isArray(options)) {
    throw new StraightestError(
      `${call} takes an object of options, got ${Array.isArray(options) ? 'an array' : String(options)}`,
      'invalid_argument',
    );
  }
  for (const name of Object.keys(options)) {
    if (!known.includes(name)) {
      throw new StraightestError(
        `${call}: unknown option '${name}' (it takes ${known.join(', ')})`,
        'invalid_argument',
      );
    }
  }
  return options;
}

export const LIMITS = ['maxVertices', 'maxFaces'];
export const PATHS = ['source', 'targets', 'points', 'onProgress'];
export const SHOT = ['source', 'direction', 'angle', 'toward', 'length', 'points', 'onProgress'];
export const PARAMETERIZE = ['source', 'boundary', 'weights', 'solver', 'maxIterations', 'timeBudgetMs', 'onProgress'];
export const POLYGONS = ['source', 'kinds', 'onProgress'];
export const COMPARE = ['source', 'boundaries', 'weights', 'solver', 'maxIterations', 'timeBudgetMs', 'onProgress'];
export const ATLAS = [
  'maxStretch',
  'minHullFill',
  'maxCharts',
  'resolution',
  'width',
  'height',
  'padding',
  'texelsPerUnit',
  'rotate',
  'onProgress',
];
export const CREATE = ['threads', 'warmUp', 'wasmUrl', 'locateFile', 'wasmBinary'];

export function toBytes(data) {
  if (typeof data === 'string') return new TextEncoder().encode(data);
  if (data instanceof Uint8Array) return data;
  if (data instanceof ArrayBuffer) return new Uint8Array(data);
  if (ArrayBuffer.isView(data)) return new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
  throw new TypeError('loadMesh expects a Uint8Array, an ArrayBuffer or a string with the file contents');
}

/**
 * Runs call(progress) and unwraps its result. onProgress(stage, fraction) is called from inside the
 * WASM work (synchronously, ~100 times per stage at most); returning false cancels and the call
 * throws a StraightestError with category 'cancelled'. An exception thrown by onProgress never crosses
 * the WASM frames (unwinding them from JS would skip the core's destructors and leak): it is caught,
 * the work is cancelled like a `false`, and the same exception is rethrown here once the core has
 * returned cleanly.
 */
export function withProgress(onProgress, call, hint = undefined) {
  if (onProgress === undefined || onProgress === null) return unwrap(call(null), hint);
  if (typeof onProgress !== 'function')
    throw new TypeError('onProgress must be a function (stage, fraction) => boolean | void');
  let thrown = null;
  const result = call((stage, fraction) => {
    if (thrown) return false;
    try {
      return onProgress(stage, fraction) !== false;
    } catch (error) {
      thrown = { error };
      return false;
    }
  });
  if (thrown) throw thrown.error;
  return unwrap(result, hint);
}
