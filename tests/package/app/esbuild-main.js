// The browser consumer app bundled by esbuild (tests/js/consumer.test.mjs) with no configuration:
// esbuild does not emit assets, so the .wasm is copied next to the bundle and named by wasmUrl.
import { createStraightest } from 'straightest';

createStraightest({ wasmUrl: new URL('./straightest-core.wasm', import.meta.url) }).then(
  (st) => {
    const mesh = st.sample('cap');
    window.__result = { vertices: mesh.info().vertices, bijective: mesh.parameterize().bijective };
    mesh.delete();
  },
  (error) => {
    window.__result = { error: String(error?.stack ?? error) };
  },
);
