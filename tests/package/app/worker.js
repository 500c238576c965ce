// The consumer app's module worker: loads the package inside the worker and answers with one fact.
import { createStraightest } from 'straightest';

createStraightest().then(
  (st) => {
    const mesh = st.sample('mountain');
    postMessage({ vertices: mesh.info().vertices, reached: mesh.straightestPaths().reached });
    mesh.delete();
  },
  (error) => postMessage({ error: String(error?.stack ?? error) }),
);
