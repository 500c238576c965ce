// The page's geometry worker: it owns the straightest WASM module and the current mesh, so the main
// thread only renders. It calls the same npm API a user imports (`straightest`).
//
// Import maps do not apply inside workers, so the page resolves the bare specifier `straightest`
// with its import map (import.meta.resolve) and passes the URL in the 'init' request.
//
// Protocol (every request carries an `id`; the reply echoes it; 'init' comes first):
//   → { id, type: 'init', moduleUrl }                        ← { id, type: 'ready', samples: string[] }
//   → { id, type: 'sample', name }                           ← { id, type: 'mesh', ... } (below)
//   → { id, type: 'file', name, format, bytes: ArrayBuffer } ← { id, type: 'mesh', ... }
//        'mesh' replies: { id, type: 'mesh', label, positions: Float32Array, indices: Uint32Array,
//                          info, timeMs }  (buffers transferred)
//   any failure                                              ← { id, type: 'error', message, category }
// Later operations on the current mesh (straightest paths, parameterization) are new `type`s in
// `handlers` below.

let modulePromise = null; // resolves to the object returned by createStraightest()
let currentMesh = null; // the mesh later operations will work on; deleted when replaced

function straightest() {
  if (!modulePromise) throw new Error('the geometry worker was not initialized');
  return modulePromise;
}

function formatFromName(name) {
  const ext = /\.([^.]+)$/.exec(name ?? '')?.[1]?.toLowerCase();
  return ext === 'obj' || ext === 'off' ? ext : 'auto';
}

/** Replaces the current mesh and builds the 'mesh' reply (positions as Float32 for WebGL). */
function meshReply(mesh, label, startTime) {
  let info;
  let positions;
  let indices;
  try {
    info = mesh.info();
    positions = Float32Array.from(mesh.positions());
    indices = mesh.indices();
  } catch (err) {
    mesh.delete();
    throw err;
  }
  currentMesh?.delete();
  currentMesh = mesh;
  const reply = {
    type: 'mesh',
    label,
    positions,
    indices,
    info,
    timeMs: performance.now() - startTime,
  };
  return { reply, transfer: [positions.buffer, indices.buffer] };
}

const handlers = {
  async init({ moduleUrl }) {
    modulePromise ??= import(moduleUrl).then(({ createStraightest }) => createStraightest());
    const st = await straightest();
    return { reply: { type: 'ready', samples: st.sampleNames() } };
  },

  async sample({ name }) {
    const st = await straightest();
    const start = performance.now();
    return meshReply(st.sample(name), name, start);
  },

  async file({ name, format, bytes }) {
    const st = await straightest();
    const start = performance.now();
    const mesh = st.loadMesh(new Uint8Array(bytes), format ?? formatFromName(name));
    return meshReply(mesh, name, start);
  },
};

function describeError(err) {
  if (err instanceof Error) {
    return { message: err.message || String(err), category: err.category ?? err.name ?? 'error' };
  }
  return { message: String(err), category: 'error' };
}

// Requests are handled one at a time, in order, so replies never overtake each other.
let queue = Promise.resolve();

self.addEventListener('message', (event) => {
  const request = event.data ?? {};
  queue = queue.then(async () => {
    const handler = handlers[request.type];
    try {
      if (!handler) throw new Error(`unknown request type: ${request.type}`);
      const { reply, transfer = [] } = await handler(request);
      self.postMessage({ id: request.id, ...reply }, transfer);
    } catch (err) {
      self.postMessage({ id: request.id, type: 'error', ...describeError(err) });
    }
  });
});
