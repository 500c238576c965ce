// prepack guard (npm runs it from the package root): `npm pack` / `npm publish` refuse to run without the built WebAssembly module, instead of
// silently shipping a package that cannot load (the module is built, not committed: npm run build:wasm).
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const dist = fileURLToPath(new URL('../wasm/dist/', import.meta.url));
const needed = ['straightest-core.mjs', 'straightest-core.wasm', 'straightest-core-embedded.js'];
const missing = needed.filter((name) => !existsSync(dist + name));
const wasm = existsSync(dist + 'straightest-core.wasm') ? readFileSync(dist + 'straightest-core.wasm') : null;
if (missing.length > 0 || (wasm && wasm.readUInt32BE(0) !== 0x0061736d)) {
  const what = missing.length > 0 ? `missing ${missing.map((n) => 'wasm/dist/' + n).join(', ')}` : 'wasm/dist/straightest-core.wasm is not WebAssembly';
  console.error(`straightest: refusing to pack without the WebAssembly module (${what}). Run \`npm run build:wasm\` first.`);
  process.exit(1);
}
