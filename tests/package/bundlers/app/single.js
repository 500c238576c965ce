// straightest/single: the single-threaded module only, its .wasm emitted by the bundler beside the bundle.
import { createStraightest } from 'straightest/single';
import { capResult, report } from './report.js';

async function run() {
  const st = await createStraightest();
  return capResult(st);
}

report(run());
