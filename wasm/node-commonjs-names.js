// node-commonjs-names.js — prepended (Emscripten --extern-pre-js) to the threaded module's ES module
// loader: in Node, Emscripten 3.1.6's pthreads code calls `require` (worker_threads, os, fs) and reads
// `__dirname`, names an ES module does not have; these module-scoped ones stand in for them (nothing is
// put on globalThis). Elsewhere both stay undefined, and the loader never reaches for them. They come
// from process.getBuiltinModule (Node ≥ 20.16), synchronous, so the module needs no top-level await
// (which bundlers would refuse in a lazily loaded module). `process` is the loader's own name for the
// same reason: a bundler that processes the loader (Parcel) finds no free `process` to polyfill.
var process = globalThis.process;
const nodeBuiltin = process?.getBuiltinModule?.bind(process);
// eslint-disable-next-line no-unused-vars -- read by the Emscripten loader that follows
var require = nodeBuiltin?.('module').createRequire(import.meta.url);
// eslint-disable-next-line no-unused-vars -- read by the Emscripten loader that follows
var __dirname = nodeBuiltin?.('path').dirname(nodeBuiltin('url').fileURLToPath(import.meta.url));
