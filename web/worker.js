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
//   → { id, type: 'paths', source, targets }                 ← { id, type: 'paths', ... } (below)
//        source: a SurfacePoint or 'auto' (the default source);
//        targets: 'boundary' | Array<SurfacePoint | 'boundary'> — a 'boundary' entry stands for every
//        vertex of the longest boundary loop (nothing on a closed mesh), so the page can combine the
//        boundary with points the user picked.
//        'paths' replies: { source, sourcePosition: [x,y,z], normal, baseFallback, baseNote,
//                           targets, targetPositions: Float32Array (xyz per target, from the core),
//                           count, reached, statuses, lengths: Float64Array,
//                           facesCrossed: Uint32Array, points: Float32Array, offsets: Uint32Array,
//                           timings: { prepare, trace }, timeMs }  (buffers transferred)
//   → { id, type: 'distances', source }                      ← { id, type: 'distances', source,
//        distances: Float32Array (heat method, one per vertex), max, timeMs }
//   → { id, type: 'parameterize', source, boundary, weights } ← { id, type: 'parameterization', ... }
//        source: a SurfacePoint or 'auto'; boundary: 'measured' | 'circle' | 'square' | 'auto';
//        weights: 'shape-preserving' | 'mean-value' | 'cotan' | 'uniform'.
//        The reply holds every field of mesh.parameterize() (uv, faceStretch, boundaryPolygon and
//        boundaryLoop transferred) plus timeMs and `overlays`: [{ boundary, polygon, error }] for
//        'measured', 'circle' and 'square' — each boundary's polygon in the same [0,1]² frame (or
//        polygon null and the core's message when that boundary failed), for the layout overlay.
//   → { id, type: 'compare', source }                        ← { id, type: 'progress', done, total }
//        after each cell, then { id, type: 'comparison', source, rows: [{ boundary, weights, l2,
//        linf, flipped, degenerate, bijective, timeMs, error }] } (3 boundaries × 4 weights; a cell
//        that fails has error set and no numbers)
//   → { id, type: 'exportObj', uv: Float32Array }            ← { id, type: 'obj', text }
//        OBJ of the current mesh in its input vertex order, with the given uv as `vt` lines.
//   any failure                                              ← { id, type: 'error', message, category }
// A request answers with exactly one final reply; only 'progress' messages may come before it.

let modulePromise = null; // resolves to the object returned by createStraightest()
let currentMesh = null; // the mesh later operations will work on; deleted when replaced
// Per-mesh data the handlers reuse: vertex positions and triangles (to place the targets the
// reply lists), whether the mesh has a boundary, and the boundary targets once known.
let currentData = null; // { positions: Float64Array, indices: Uint32Array, closed, boundary, polygons }

const BOUNDARIES = ['measured', 'circle', 'square'];
const WEIGHTS = ['shape-preserving', 'mean-value', 'cotan', 'uniform'];

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
  currentData = {
    positions: mesh.positions(),
    indices: indices.slice(), // `indices` itself is transferred to the page
    closed: (info.boundaryLoops ?? []).length === 0,
    boundary: null,
    polygons: new Map(), // source key -> overlays (see boundaryOverlays)
  };
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

function requireMesh() {
  if (!currentMesh) throw new Error('no mesh is loaded');
  return currentMesh;
}

/** A typed array that owns its whole buffer, so transferring it detaches nothing else. */
function owned(array) {
  return array.byteOffset === 0 && array.byteLength === array.buffer.byteLength ? array : array.slice();
}

/** The vertices of the longest boundary loop as targets (computed once per mesh). */
function boundaryTargets(mesh, source) {
  if (currentData.closed) return [];
  currentData.boundary ??= mesh.straightestPaths({ source, targets: 'boundary', points: false }).targets;
  return currentData.boundary;
}

/** Expands the request's targets into what straightestPaths takes. */
function resolveTargets(mesh, source, targets) {
  if (targets === 'boundary') return currentData.closed ? [] : 'boundary';
  if (!Array.isArray(targets)) throw new Error("targets must be 'boundary' or an array");
  if (targets.length === 1 && targets[0] === 'boundary') return resolveTargets(mesh, source, 'boundary');
  return targets.flatMap((t) => (t === 'boundary' ? boundaryTargets(mesh, source) : [t]));
}

/** Error → { message, category } as the page shows it. */
function describeError(err) {
  if (err instanceof Error) {
    return { message: err.message || String(err), category: err.category ?? err.name ?? 'error' };
  }
  return { message: String(err), category: 'error' };
}

/**
 * The boundary polygons of 'measured', 'circle' and 'square' for the layout overlay, one
 * parameterization each. A polygon depends only on the boundary and the source, not on the weights,
 * so the cheapest weights do and the result is kept per source; `known` (the reply's own
 * boundary and polygon) saves one of the three solves.
 */
function boundaryOverlays(mesh, source, known) {
  const key = JSON.stringify(source);
  let overlays = currentData.polygons.get(key);
  if (!overlays) {
    overlays = BOUNDARIES.map((boundary) => {
      if (boundary === known.boundary) return { boundary, polygon: known.polygon.slice(), error: null };
      try {
        const { boundaryPolygon } = mesh.parameterize({ source, boundary, weights: 'uniform' });
        return { boundary, polygon: Float32Array.from(boundaryPolygon), error: null };
      } catch (err) {
        return { boundary, polygon: null, error: describeError(err).message };
      }
    });
    currentData.polygons.set(key, overlays);
  }
  // Copies: the cached polygons stay here when the reply's buffers are transferred.
  return overlays.map((o) => ({ ...o, polygon: o.polygon?.slice() ?? null }));
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

  async paths({ source = 'auto', targets = 'boundary' }) {
    const mesh = requireMesh();
    const start = performance.now();
    const resolved = resolveTargets(mesh, source, targets);
    const result = mesh.straightestPaths({ source, targets: resolved });
    if (resolved === 'boundary') currentData.boundary ??= result.targets;
    const reply = {
      type: 'paths',
      source: result.source,
      sourcePosition: result.sourcePosition,
      normal: result.normal,
      baseFallback: result.baseFallback,
      baseNote: result.baseNote,
      targets: result.targets,
      targetPositions: Float32Array.from(result.targetPositions),
      count: result.count,
      reached: result.reached,
      statuses: result.statuses,
      lengths: owned(result.lengths),
      facesCrossed: owned(result.facesCrossed),
      points: owned(result.points),
      offsets: owned(result.offsets),
      timings: result.timings,
      timeMs: performance.now() - start,
    };
    const transfer = [reply.targetPositions, reply.lengths, reply.facesCrossed, reply.points, reply.offsets];
    return { reply, transfer: transfer.map((a) => a.buffer) };
  },

  async distances({ source = 'auto' }) {
    const mesh = requireMesh();
    const start = performance.now();
    const distances = Float32Array.from(mesh.geodesicDistances(source, 'heat'));
    let max = 0;
    for (const d of distances) if (Number.isFinite(d) && d > max) max = d;
    const reply = { type: 'distances', source, distances, max, timeMs: performance.now() - start };
    return { reply, transfer: [distances.buffer] };
  },

  async parameterize({ source = 'auto', boundary = 'measured', weights = 'shape-preserving' }) {
    const mesh = requireMesh();
    const start = performance.now();
    const result = mesh.parameterize({ source, boundary, weights });
    const timeMs = performance.now() - start;
    const reply = {
      ...result,
      type: 'parameterization',
      uv: owned(result.uv),
      faceStretch: owned(result.faceStretch),
      boundaryPolygon: owned(result.boundaryPolygon),
      boundaryLoop: owned(result.boundaryLoop),
      timeMs,
    };
    reply.overlays = boundaryOverlays(mesh, result.source, {
      boundary: result.boundary, polygon: result.boundaryPolygon,
    });
    const buffers = [reply.uv, reply.faceStretch, reply.boundaryPolygon, reply.boundaryLoop,
      ...reply.overlays.map((o) => o.polygon).filter(Boolean)];
    return { reply, transfer: buffers.map((a) => a.buffer) };
  },

  async compare({ id, source = 'auto' }) {
    const mesh = requireMesh();
    const total = BOUNDARIES.length * WEIGHTS.length;
    const rows = [];
    for (const boundary of BOUNDARIES) {
      for (const weights of WEIGHTS) {
        const start = performance.now();
        try {
          const { stretch, flipped, degenerate, bijective } = mesh.parameterize({ source, boundary, weights });
          rows.push({
            boundary, weights, l2: stretch.l2, linf: stretch.linf, flipped, degenerate, bijective,
            timeMs: performance.now() - start, error: null,
          });
        } catch (err) {
          rows.push({ boundary, weights, timeMs: performance.now() - start, error: describeError(err).message });
        }
        self.postMessage({ id, type: 'progress', done: rows.length, total });
      }
    }
    return { reply: { type: 'comparison', source, rows } };
  },

  async exportObj({ uv }) {
    const mesh = requireMesh();
    return { reply: { type: 'obj', text: mesh.toOBJ(uv) } };
  },
};

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
