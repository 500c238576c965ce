/* global window, Worker, URL */
// The browser consumer app bundled by Vite (tests/js/consumer.test.mjs) with no configuration: the
// package on the main thread and in a module worker. The result is left on window.__result.
import { createStraightest } from 'straightest';

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
  return { main, worker: fromWorker };
}

run().then((result) => { window.__result = result; }, (error) => { window.__result = { error: String(error?.stack ?? error) }; });
