// Types of straightest/inline: the package's API, with the single-threaded WebAssembly module embedded
// (it always runs on one thread: `threads` is ignored and st.threads is 1).
export * from './index.js';
