// The browser consumer app bundled by Vite (tests/js/consumer.test.mjs) with no configuration: the
// package on the main thread and in a module worker. The result is left on window.__result.
import { createStraightest } from 'straightest';
import { createStraightestWorker } from 'straightest/worker';

/** straightest/worker: a result with transferred arrays, progress, a cancel and a rebuilt mesh, the name lists. */
async function viaHelper() {
  const st = await createStraightestWorker();
  const mesh = await st.sample('cap');
  const stages = new Set();
  const p = await mesh.parameterize({
    onProgress: (stage) => {
      stages.add(stage);
    },
  });
  const controller = new AbortController();
  const big = await st.sample('mountain');
  const cancelled = big
    .compareParameterizations({ signal: controller.signal, onProgress: () => controller.abort() })
    .then(
      () => 'finished',
      (e) => e.category,
    );
  const afterCancel = await cancelled;
  const info = await mesh.info(); // rebuilt in the new worker
  const format = await st.formatFromFileName('Part.OFF');
  // The geodesics of issue 17, forwarded: a shot toward a boundary vertex and the exact shortest path to it.
  const [loop] = await mesh.boundaryLoops();
  const shot = await mesh.shootGeodesic({ toward: { vertex: loop[0] } });
  const exact = await mesh.exactShortestPaths({ targets: [loop[0]] });
  st.terminate();
  return {
    vertices: info.vertices,
    uvIsFloat32: p.uv instanceof Float32Array,
    uvLength: p.uv.length,
    bijective: p.bijective,
    stages: [...stages],
    afterCancel,
    format,
    geodesics: {
      target: loop[0],
      shotLength: shot.length,
      missDistance: shot.missDistance,
      shotPoints: shot.points instanceof Float64Array,
      exactDistance: exact.distances[0],
      exactPoints: exact.points instanceof Float32Array && exact.offsets.length === 2,
    },
    samples: st.sampleNames(),
    boundaryKinds: st.boundaryKinds,
    weightKinds: st.weightKinds,
  };
}

async function run() {
  const st = await createStraightest();
  const mesh = st.sample('cap');
  const main = { vertices: mesh.info().vertices, bijective: mesh.parameterize().bijective };
  mesh.delete();
  const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
  const fromWorker = await new Promise((resolve, reject) => {
    worker.onmessage = (event) => resolve(event.data);
    worker.onerror = (event) => reject(new Error(`worker: ${event.message}`));
  });
  return { main, worker: fromWorker, helper: await viaHelper() };
}

run().then(
  (result) => {
    window.__result = result;
  },
  (error) => {
    window.__result = { error: String(error?.stack ?? error) };
  },
);
