// The package where the bundler emits no assets (esbuild, Rollup): the .wasm copied next to the bundle
// and named by wasmUrl (a URL object).
import { createStraightest } from 'straightest';
import { capResult, report } from './report.js';

async function run() {
  const st = await createStraightest({ wasmUrl: new URL('./straightest-core.wasm', import.meta.url) });
  return capResult(st);
}

report(run());
