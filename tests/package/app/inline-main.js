// The single-file variant bundled by esbuild (tests/js/consumer.test.mjs): nothing to copy or configure.
import { createStraightest } from 'straightest/inline';

createStraightest().then(
  (st) => {
    const mesh = st.sample('cap');
    window.__result = { vertices: mesh.info().vertices, bijective: mesh.parameterize().bijective };
    mesh.delete();
  },
  (error) => {
    window.__result = { error: String(error?.stack ?? error) };
  },
);
