// Types of straightest/single: the package's API on the single-threaded WebAssembly module only (it always
// runs on one thread: `threads` is ignored and st.threads is 1; st.threadsUnavailable says why when more
// were asked for).
export * from './index.js';
