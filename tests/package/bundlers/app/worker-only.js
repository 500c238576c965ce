// straightest/worker alone, with its defaults: the bundler bundles the package's module worker.
import { createStraightestWorker } from 'straightest/worker';
import { report } from './report.js';

async function run() {
  const st = await createStraightestWorker();
  const mesh = await st.sample('cap');
  const result = { threads: st.threads, bijective: (await mesh.parameterize()).bijective };
  st.terminate();
  return result;
}

report(run());
