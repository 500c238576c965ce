// Types of straightest/inline: the package's API, with the WebAssembly module embedded.
export * from './index.js';
