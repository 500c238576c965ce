// The page's geometry worker: it owns the straightest WASM module and the current mesh, so the main
// thread only renders. It calls the same npm API a user imports (`straightest`).
//
// Import maps do not apply inside workers, so the page resolves the bare specifier `straightest`
// with its import map (import.meta.resolve) and passes the URL in the 'init' request.
//
// Protocol (every request carries an `id`; the reply echoes it; 'init' comes first):
//   → { id, type: 'init', moduleUrl }   ← { id, type: 'ready', samples: string[], boundaryKinds }
//        (the boundary names mesh.parameterize() takes, 'auto' aside, in the core's order; 'free'
//        among them)
//   → { id, type: 'sample', name, restore? }                 ← { id, type: 'mesh', ... } (below)
//   → { id, type: 'file', name, bytes: ArrayBuffer, restore? }  ← { id, type: 'mesh', ... }
//        (the format follows the file name's extension, else the content)
//        'mesh' replies: { id, type: 'mesh', label, positions: Float32Array, indices: Uint32Array,
//                          normals: Float32Array, info, timeMs }  (buffers transferred)
//        normals: the core's area-weighted unit vertex normals for smooth shading.
//        restore: true when the page still shows this mesh and only the worker must load it again
//        (after a restart): the reply then has no positions and indices.
//   → { id, type: 'paths', source, targets }                 ← { id, type: 'paths', ... } (below)
//        source: a SurfacePoint or 'auto' (the default source);
//        targets: 'boundary' | Array<SurfacePoint | 'boundary'> — a 'boundary' entry stands for every
//        vertex of the longest boundary loop (the core expands it; nothing on a closed mesh), so the
//        page can combine the boundary with points the user picked.
//        'paths' replies: { source, sourcePosition: [x,y,z], normal, baseFallback, baseNote,
//                           targets, targetPositions: Float32Array (xyz per target, from the core),
//                           count, reached, statuses, lengths: Float64Array,
//                           facesCrossed: Uint32Array, points: Float32Array, offsets: Uint32Array,
//                           directions: Float64Array (per path the unit in-plane direction of its
//                           cutting plane, NaN × 3 where there is none), backward: Uint8Array (1
//                           where the path leaves the source away from its destination),
//                           otherArcLengths: Float64Array (closed surfaces: the other way round the
//                           section, NaN where there is none), otherPoints: Float32Array and
//                           otherOffsets: Uint32Array (those arcs, packed like points), summary (the
//                           core's: { paths, reached, failures, meanLength, maxLength, facesCrossed,
//                           otherArcs }),
//                           timings: { prepare, trace }, timeMs }  (buffers transferred)
//   → { id, type: 'distances', source }                      ← { id, type: 'distances', source,
//        distances: Float32Array (heat method, one per vertex), max, timeMs }
//   → { id, type: 'parameterize', source, boundary, weights } ← { id, type: 'parameterization', ... }
//        source: a SurfacePoint or 'auto'; boundary: one of boundaryKinds or 'auto';
//        weights: 'shape-preserving' | 'mean-value' | 'cotan' | 'uniform'.
//        The reply holds every field of mesh.parameterize() (uv, cornerUv, seam, faceStretch,
//        boundaryPolygon and boundaryLoop transferred; a mesh that is not a disk is cut or filled first:
//        cut, seam, filledLoops, genus...) plus timeMs and `overlays`: [{ boundary, polygon, error }], one per
//        boundary kind — each boundary's polygon in the same [0,1]² frame (or polygon null and the
//        core's message when that boundary failed), for the layout overlay: the chosen one from the
//        parameterization, the others from mesh.boundaryPolygons() (no solve; the free boundary has no
//        polygon before its refinement, so it is there only when it is the parameterization's).
//   → { id, type: 'compare', source }                        ← { id, type: 'progress', stage:
//        'compare', fraction, done, total } after each cell, then { id, type: 'comparison', source,
//        rows: [{ boundary, weights, l2, linf, flipped, degenerate, bijective, timeMs, error,
//        category }], best } — mesh.compareParameterizations(): every boundary kind × every weights
//        (a cell that fails has error set and no numbers); best: the index of the preferred row (the
//        rule of boundary 'auto'), -1 when every row failed
//   → { id, type: 'exportObj', uv: Float32Array }            ← { id, type: 'obj', text }
//        OBJ of the current mesh in its input vertex order, with the given uv as `vt` lines (2 per
//        vertex, or a cut mesh's cornerUv: 2 per face corner, the seam split).
//   any failure                                              ← { id, type: 'error', message, category }
// A request answers with exactly one final reply; only 'progress' messages may come before it.
//
// Progress: while a request runs the worker posts { id, type: 'progress', stage, fraction } (0…1),
// the first one with `stages`, the request's planned stages in order:
//   sample, file: 'load' (parsing and checks: one call, so only 0 and 1), 'upload'
//   paths: 'trace', 'upload'          distances: 'heat', 'upload'
//   parameterize: 'cut' (a mesh that is not a disk), 'source', 'trace' (measured, free and auto
//                 boundaries), 'weights', 'solve',
//                 'metrics', 'refine' (free and auto) (the core's stages), 'overlays' (the other
//                 boundaries' polygons), 'upload'
//   compare: 'compare'                exportObj: 'export'
// 'upload' is packing the results into transferable arrays and posting them. The core's callbacks
// (≤ ~100 per stage) are throttled to one message per 50 ms; a stage's start and its final 1.0 are
// always posted, and a stage the core did not report (e.g. 'solve' when the solver converged within
// its first check) is completed when a later one starts.
//
// Cancelling: the work runs inside synchronous WASM calls, so the worker cannot read a message that
// would stop it; the page terminates the worker instead and starts a new one (see session.js).

let modulePromise = null; // resolves to the object returned by createStraightest()
let currentMesh = null; // the mesh later operations will work on; deleted when replaced
let currentClosed = false; // the current mesh has no boundary (its 'boundary' targets are none)
let currentDisk = true; // the current mesh is one disk (parameterize cuts or fills anything else first)
let boundaryKinds = []; // the core's boundary and weight kinds (st.boundaryKinds, st.weightKinds),
let weightKinds = []; // once initialized
let polygonKinds = []; // the kinds with a polygon without a solve (st.polygonBoundaryKinds: all but free)

function straightest() {
  if (!modulePromise) throw new Error('the geometry worker was not initialized');
  return modulePromise;
}

// ------------------------------------------------------------------ progress

const THROTTLE_MS = 50; // at most one intermediate 'progress' message per 50 ms and request

/**
 * The core's stages of mesh.parameterize() for `boundary`, in order: measured, free and auto trace;
 * free and auto refine after the fixed map's metrics (whose second 'metrics', of the refined map,
 * counts as that stage again).
 */
function parameterizeStages(boundary) {
  const traced = ['measured', 'free', 'auto', undefined].includes(boundary);
  const refined = ['free', 'auto'].includes(boundary);
  return ['source', ...(traced ? ['trace'] : []), 'weights', 'solve', 'metrics', ...(refined ? ['refine'] : [])];
}

/** The stages a request goes through, in order (see the protocol above). */
function plannedStages(request) {
  switch (request.type) {
    case 'sample':
    case 'file':
      return request.restore ? ['load'] : ['load', 'upload'];
    case 'paths':
      return ['trace', 'upload'];
    case 'distances':
      return ['heat', 'upload'];
    case 'parameterize': {
      return [...(currentDisk ? [] : ['cut']), ...parameterizeStages(request.boundary), 'overlays', 'upload'];
    }
    case 'compare':
      return ['compare'];
    case 'exportObj':
      return ['export'];
    default:
      return [];
  }
}

/**
 * Posts a request's 'progress' messages. update(stage, fraction) takes the core's callbacks and the
 * worker's own stages: a later stage completes every earlier one; within a stage, fractions only
 * grow and are throttled. finish() completes every stage (before the final reply).
 */
class StageProgress {
  constructor(id, stages) {
    this.id = id;
    this.stages = stages;
    this.fractions = stages.map(() => -1); // -1: not posted yet
    this.current = -1; // index of the running stage
    this.lastPost = 0;
    this.callback = (stage, fraction) => {
      this.update(stage, fraction);
      return true; // never cancels: the page cancels by terminating the worker
    };
    if (stages.length) this.update(stages[0], 0);
  }

  update(stage, fraction, extra = undefined) {
    const k = this.stages.indexOf(stage);
    if (k < 0) return; // a stage this request does not show
    if (k > this.current) {
      for (let j = Math.max(this.current, 0); j < k; j++) this.#post(j, 1, true);
      this.current = k;
      this.#post(k, fraction, true, extra);
    } else {
      // The running stage, or an earlier one again ('auto' solves once per boundary candidate).
      this.#post(k, fraction, false, extra);
    }
  }

  finish() {
    for (let k = 0; k < this.stages.length; k++) this.#post(k, 1, true);
  }

  #post(k, fraction, force, extra) {
    const f = Math.min(Math.max(Number(fraction) || 0, 0), 1);
    if (f <= this.fractions[k]) return;
    const now = performance.now();
    if (!force && f < 1 && now - this.lastPost < THROTTLE_MS) return;
    const first = this.fractions.every((x) => x < 0);
    this.fractions[k] = f;
    this.lastPost = now;
    self.postMessage({
      id: this.id, type: 'progress', stage: this.stages[k], fraction: f,
      ...(first ? { stages: this.stages } : {}), ...extra,
    });
  }
}

// ------------------------------------------------------------------ meshes

/**
 * Replaces the current mesh and builds the 'mesh' reply (positions as Float32 for WebGL; none when
 * restoring a mesh the page still shows).
 */
function meshReply(mesh, label, startTime, progress, restore) {
  progress.update('upload', 0);
  let info;
  let positions;
  let indices;
  let normals;
  try {
    info = mesh.info();
    if (!restore) {
      positions = Float32Array.from(mesh.positions());
      indices = mesh.indices();
      normals = mesh.vertexNormals();
    }
  } catch (err) {
    mesh.delete();
    throw err;
  }
  currentMesh?.delete();
  currentMesh = mesh;
  currentClosed = (info.boundaryLoops ?? []).length === 0;
  currentDisk = info.boundaryLoops.length === 1 && info.eulerCharacteristic === 1 && info.components === 1;
  const reply = {
    type: 'mesh',
    label,
    positions,
    indices,
    normals,
    info,
    timeMs: performance.now() - startTime,
  };
  return { reply, transfer: restore ? [] : [positions.buffer, indices.buffer, normals.buffer] };
}

function requireMesh() {
  if (!currentMesh) throw new Error('no mesh is loaded');
  return currentMesh;
}

/** A typed array that owns its whole buffer, so transferring it detaches nothing else. */
function owned(array) {
  return array.byteOffset === 0 && array.byteLength === array.buffer.byteLength ? array : array.slice();
}

/** The request's targets as straightestPaths takes them: 'boundary' entries are none on a closed mesh. */
function resolveTargets(targets) {
  if (targets === 'boundary') return currentClosed ? [] : 'boundary';
  if (!Array.isArray(targets)) throw new Error("targets must be 'boundary' or an array");
  return currentClosed ? targets.filter((t) => t !== 'boundary') : targets;
}

/** Error → { message, category } as the page shows it. */
function describeError(err) {
  if (err instanceof Error) {
    return { message: err.message || String(err), category: err.category ?? err.name ?? 'error' };
  }
  return { message: String(err), category: 'error' };
}

/**
 * The boundary polygon of every kind for the layout overlay: `known` ({ boundary, polygon } of the
 * parameterization) and the others from the core, around the same source (no solve; only the
 * measured kind traces). Reports the 'overlays' stage.
 */
function boundaryOverlays(mesh, source, known, progress) {
  const kinds = polygonKinds.filter((kind) => kind !== known.boundary);
  const others = kinds.length === 0 ? [] : mesh.boundaryPolygons({
    source,
    kinds,
    onProgress: (stage, fraction) => progress.update('overlays', fraction),
  });
  return boundaryKinds.flatMap((boundary) => {
    if (boundary === known.boundary) return [{ boundary, polygon: known.polygon.slice(), error: null }];
    const other = others.find((o) => o.boundary === boundary);
    return other ? [{ boundary, polygon: other.polygon && owned(other.polygon), error: other.error }] : [];
  });
}

const handlers = {
  async init({ moduleUrl }) {
    modulePromise ??= import(moduleUrl).then(({ createStraightest }) => createStraightest());
    const st = await straightest();
    ({ boundaryKinds, weightKinds, polygonBoundaryKinds: polygonKinds } = st);
    return { reply: { type: 'ready', samples: st.sampleNames(), boundaryKinds } };
  },

  async sample({ name, restore }, progress) {
    const st = await straightest();
    const start = performance.now();
    return meshReply(st.sample(name), name, start, progress, restore);
  },

  async file({ name, bytes, restore }, progress) {
    const st = await straightest();
    const start = performance.now();
    // One synchronous call: no progress inside it ('load' is 0 before and 1 after).
    const mesh = st.loadMesh(new Uint8Array(bytes), st.formatFromFileName(name));
    return meshReply(mesh, name, start, progress, restore);
  },

  async paths({ source = 'auto', targets = 'boundary' }, progress) {
    const mesh = requireMesh();
    const start = performance.now();
    const result = mesh.straightestPaths({ source, targets: resolveTargets(targets), onProgress: progress.callback });
    progress.update('upload', 0);
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
      directions: owned(result.directions),
      backward: owned(result.backward),
      otherArcLengths: owned(result.otherArcLengths),
      otherPoints: owned(result.otherPoints),
      otherOffsets: owned(result.otherOffsets),
      summary: result.summary,
      timings: result.timings,
      timeMs: performance.now() - start,
    };
    const transfer = [reply.targetPositions, reply.lengths, reply.facesCrossed, reply.points, reply.offsets, reply.directions,
      reply.backward, reply.otherArcLengths, reply.otherPoints, reply.otherOffsets];
    return { reply, transfer: transfer.map((a) => a.buffer) };
  },

  async distances({ source = 'auto' }, progress) {
    const mesh = requireMesh();
    const start = performance.now();
    const heat = mesh.geodesicDistances(source, 'heat'); // no progress callback in the API
    progress.update('upload', 0);
    const distances = Float32Array.from(heat);
    let max = 0;
    for (const d of distances) if (Number.isFinite(d) && d > max) max = d;
    const reply = { type: 'distances', source, distances, max, timeMs: performance.now() - start };
    return { reply, transfer: [distances.buffer] };
  },

  async parameterize({ source = 'auto', boundary = 'measured', weights = 'shape-preserving' }, progress) {
    const mesh = requireMesh();
    const start = performance.now();
    const result = mesh.parameterize({ source, boundary, weights, onProgress: progress.callback });
    const timeMs = performance.now() - start;
    const reply = {
      ...result,
      type: 'parameterization',
      uv: owned(result.uv),
      cornerUv: owned(result.cornerUv),
      seam: owned(result.seam),
      faceStretch: owned(result.faceStretch),
      boundaryPolygon: owned(result.boundaryPolygon),
      boundaryLoop: owned(result.boundaryLoop),
      timeMs,
    };
    reply.overlays = boundaryOverlays(mesh, result.source, {
      boundary: result.boundary, polygon: result.boundaryPolygon,
    }, progress);
    progress.update('upload', 0);
    const buffers = [reply.uv, reply.cornerUv, reply.seam, reply.faceStretch, reply.boundaryPolygon, reply.boundaryLoop,
      ...reply.overlays.map((o) => o.polygon).filter(Boolean)];
    return { reply, transfer: buffers.map((a) => a.buffer) };
  },

  async compare({ source = 'auto' }, progress) {
    const mesh = requireMesh();
    const total = boundaryKinds.length * weightKinds.length; // the core's default cells
    const { rows, best } = mesh.compareParameterizations({
      source,
      onProgress: (stage, fraction) => {
        progress.update('compare', fraction, { done: Math.round(fraction * total), total });
      },
    });
    return { reply: { type: 'comparison', source, rows, best } };
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
      const progress = new StageProgress(request.id, plannedStages(request));
      const { reply, transfer = [] } = await handler(request, progress);
      progress.finish();
      self.postMessage({ id: request.id, ...reply }, transfer);
    } catch (err) {
      self.postMessage({ id: request.id, type: 'error', ...describeError(err) });
    }
  });
});
