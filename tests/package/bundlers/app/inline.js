// straightest/inline alone: the embedded single-threaded module, nothing served beside the bundle.
import { createStraightest } from 'straightest/inline';
import { capResult, report } from './report.js';

async function run() {
  const st = await createStraightest();
  return capResult(st);
}

report(run());
