// straightest/inline alone: the embedded single-threaded module, nothing served beside the bundle.
import { createStraightest } from 'straightest/inline';
import { report } from './report.js';

async function run() {
  const st = await createStraightest();
  const mesh = st.sample('cap');
  const result = {
    threads: st.threads,
    threadsUnavailable: st.threadsUnavailable,
    bijective: mesh.parameterize().bijective,
  };
  mesh.delete();
  return result;
}

report(run());
