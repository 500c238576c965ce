// Build step (scripts/build.sh): takes the one bundler-visible worker out of the threaded module's
// loader. Emscripten 3.1.6 writes `new Worker(new URL("…worker.js", import.meta.url))` for a caller that
// passes no locateFile; the package always passes one (wasm/start-threads.js), so that branch never
// runs, yet a bundler that processes the loader (Parcel) follows the pattern and fails on the classic
// worker script it names. The branch is rewritten to the locateFile call the other branch makes.
// Usage: node scripts/neutral-threads-loader.mjs <straightest-core-threads.mjs> (in place)
import { readFileSync, writeFileSync } from 'node:fs';

const [file] = process.argv.slice(2);
if (!file) {
  console.error('usage: node scripts/neutral-threads-loader.mjs <straightest-core-threads.mjs>');
  process.exit(2);
}
const pattern = /new Worker\(new URL\("([\w.-]+\.worker\.js)",import\.meta\.url\)\)/g;
const text = readFileSync(file, 'utf8');
const found = text.match(pattern)?.length ?? 0;
if (found !== 1) {
  console.error(`${file}: expected Emscripten's one new Worker(new URL(…worker.js)), found ${found}`);
  process.exit(1);
}
writeFileSync(
  file,
  text.replace(pattern, (_, name) => `new Worker(locateFile("${name}"))`),
);
