// straightest/worker where the bundler does not bundle workers (esbuild): straightest/worker-entry
// bundled as a second entry (worker-entry.js) and started by createWorker, the .wasm copied next to the
// bundle and named by a URL object. Meshes and the worker are disposed by `await using`; a worker
// whose script is missing rejects naming its URL and status.
import { createStraightestWorker } from 'straightest/worker';
import { report } from './report.js';

const here = (file) => new URL(file, import.meta.url);

async function missingWorker() {
  try {
    await createStraightestWorker({ createWorker: () => new Worker(here('./no-such-worker.js'), { type: 'module' }) });
    return { rejected: false };
  } catch (error) {
    return { rejected: true, category: error.category, message: error.message };
  }
}

async function run() {
  let deletedAtScopeEnd;
  let vertices;
  {
    await using st = await createStraightestWorker({
      createWorker: () => new Worker(here('./worker-entry.js'), { type: 'module' }),
      wasmUrl: here('./straightest-core.wasm'),
    });
    await using mesh = await st.sample('cap');
    vertices = (await mesh.info()).vertices;
    deletedAtScopeEnd = mesh;
  }
  return { vertices, meshDeleted: deletedAtScopeEnd.deleted, missing: await missingWorker() };
}

report(run());
