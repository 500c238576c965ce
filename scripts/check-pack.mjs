// prepack guard (npm runs it from the package root): `npm pack` / `npm publish` refuse to run without the built WebAssembly modules, instead of
// silently shipping a package that cannot load (the modules are built, not committed: npm run build:wasm). Both
// modules ship: the single-threaded one and the threaded one (pthreads) with its worker script and the
// package.json that makes that script CommonJS for Node.
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const dist = fileURLToPath(new URL('../wasm/dist/', import.meta.url));
const modules = ['straightest-core.wasm', 'threads/straightest-core-threads.wasm'];
const needed = [
  'straightest-core.mjs',
  'straightest-core-embedded.js',
  'threads/straightest-core-threads.mjs',
  'threads/straightest-core-threads.worker.js',
  'threads/straightest-core-threads-worker-source.mjs',
  'threads/package.json',
  ...modules,
];
const missing = needed.filter((name) => !existsSync(dist + name));
const notWasm = modules.filter(
  (name) => existsSync(dist + name) && readFileSync(dist + name).readUInt32BE(0) !== 0x0061736d,
);
if (missing.length > 0 || notWasm.length > 0) {
  const what =
    missing.length > 0
      ? `missing ${missing.map((n) => 'wasm/dist/' + n).join(', ')}`
      : `${notWasm.map((n) => 'wasm/dist/' + n).join(', ')} is not WebAssembly`;
  console.error(
    `straightest: refusing to pack without the WebAssembly modules (${what}). Run \`npm run build:wasm\` first.`,
  );
  process.exit(1);
}
