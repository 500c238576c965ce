// Run by tests/js/consumer.test.mjs: a jsdom-style environment (a `window` and a `document` defined, as
// Vitest's jsdom environment does, yet running in Node, where fetch cannot read file: URLs). The
// default createStraightest() must still find the module on disk.
globalThis.window = globalThis;
globalThis.document = { baseURI: 'http://localhost:3000/', currentScript: null };
const { createStraightest } = await import('straightest');
const st = await createStraightest();
const mesh = st.sample('mountain');
console.log(JSON.stringify({ vertices: mesh.info().vertices, reached: mesh.straightestPaths().reached }));
mesh.delete();
