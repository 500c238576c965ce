// straightest/single: the single-threaded module only, its .wasm emitted by the bundler beside the bundle.
import { createStraightest } from 'straightest/single';
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
