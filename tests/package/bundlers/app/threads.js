// The package with its defaults on the main thread and through straightest/worker, reporting which
// module runs (threads) and why not more (threadsUnavailable). Built by Vite, webpack and Parcel
// without configuration (tests/js/bundlers.test.mjs) and served cross-origin isolated, it starts
// threads; with the threaded module's files broken, it falls back to one thread and says why.
import { createStraightest } from 'straightest';
import { createStraightestWorker } from 'straightest/worker';
import { capResult, report } from './report.js';

async function onMainThread() {
  const st = await createStraightest();
  return capResult(st);
}

async function inWorker() {
  const st = await createStraightestWorker();
  const mesh = await st.sample('cap');
  const result = {
    threads: st.threads,
    threadsUnavailable: st.threadsUnavailable,
    bijective: (await mesh.parameterize()).bijective,
  };
  st.terminate();
  return result;
}

// Both at once: where the threaded module cannot start, each waits out its own bound.
async function run() {
  const [main, worker] = await Promise.all([onMainThread(), inWorker()]);
  return { isolated: globalThis.crossOriginIsolated === true, main, worker };
}

report(run());
