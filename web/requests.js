// The page's requests, each a short composition of calls to the package's worker helper
// (straightest/worker, which owns the WASM module in a module worker and transfers the results'
// arrays): loading a mesh and fetching what is drawn of it, tracing paths, heat distances,
// parameterizing with the other boundaries' polygons for the overlay, comparing, exporting. The
// geometry is the core's; here are only the page's choices (which calls, in which order, which
// stages the progress panel shows) and the conversions WebGL wants (Float32 positions).
//
// Requests (request(type, payload, onProgress) resolves with the reply, rejects with an Error whose
// `category` is the core's, or 'cancelled' after cancel()):
//   'sample' { name }, 'file' { name, file: Blob } (OBJ, OFF by the core, the worker reading the file
//        itself: its bytes never pass through the page's thread; STL, PLY, glTF/GLB by three's loaders
//        here, welded: mesh-files.js)   → { type: 'mesh', mesh (the WorkerMesh,
//        for adopt()), label, positions: Float32Array, indices: Uint32Array, normals: Float32Array (the
//        core's area-weighted unit vertex normals), info, timeMs, note (a file read by three: what was merged or left out, or empty) }
//   'paths' { source, targets }  → mesh.straightestPaths()'s fields + { type: 'paths', targetPositions:
//        Float32Array, timeMs }. source: a SurfacePoint or 'auto'; targets: 'boundary' |
//        Array<SurfacePoint | 'boundary'> (a 'boundary' entry is every vertex of the longest boundary
//        loop, expanded by the core; nothing on a closed mesh)
//   'distances' { source }       → { type: 'distances', source, distances: Float32Array (heat), max, timeMs }
//   'parameterize' { source, boundary, weights } → mesh.parameterize()'s fields + { type:
//        'parameterization', timeMs, overlays: [{ boundary, polygon, error }] } — every boundary kind's
//        polygon in the same [0,1]² frame for the layout overlay: the chosen one from the
//        parameterization, the others from mesh.boundaryPolygons() (no solve; the free boundary has
//        none before its refinement)
//   'compare' { source }         → { type: 'comparison', source, rows, best } (compareParameterizations;
//        its progress messages carry `done` and `total` cells)
//   'exportObj' { uv }           → { type: 'obj', text } (per-vertex uv, or a cut mesh's cornerUv)
//   'geodesics' { source, target: { vertex } } → { type: 'geodesics', target, exact, plane, shot }: the
//        three geodesics of issue 17 to one vertex: exact: exactShortestPaths' { distance, points }
//        (Float32Array), plane: the cutting plane's straightestPaths' { length, status, points }, shot:
//        shootGeodesic toward it (the plane's length when it reached, else the exact distance)
//   'atlas' { maxStretch, resolution, padding } → mesh.atlas()'s fields + { type: 'atlas', timeMs }: the
//        texture atlas of the whole mesh (charts, each flattened, packed at `resolution` texels with
//        `padding` texels between charts; cornerUv 6 per face in [0,1]², chartOfFace, seam, the metrics)
//   'exactRatio' { source }      → { type: 'exactRatio', source, targets: Int32Array (the longest
//        boundary loop's vertices, in order), distances (exact), lengths (straightest), statuses, ratios:
//        Float64Array (lengths ÷ distances; NaN where the trace failed) }: exactShortestPaths and
//        straightestPaths to 'boundary', without points
// The mesh requests work on the adopted mesh (the one on display).
//
// Progress: every request reports { stage, fraction } (0…1) to the observer's task and to
// onProgress, the first message with `stages`, the request's planned stages in order:
//   sample, file: 'load' (parsing and checks: one call, so only 0 and 1), 'upload'
//   paths: 'trace', 'upload'          distances: 'heat', 'upload'
//   parameterize: 'cut' (a mesh that is not a disk), 'source', 'trace' (measured, free and auto
//                 boundaries), 'weights', 'solve', 'metrics', 'refine' (free and auto) (the core's
//                 stages), 'overlays' (the other boundaries' polygons), 'upload'
//   compare: 'compare'                exportObj: 'export'
//   atlas: 'segment', 'flatten', 'pack', 'measure' (the core's stages)
//   geodesics: 'distances' (exact), 'trace' (cutting plane), 'shoot'
//   exactRatio: 'distances' (exact), 'trace' (cutting plane)
// 'upload' is fetching the arrays the page draws (a mesh) or unpacking the reply. The core's callbacks
// (≤ ~100 per stage) are throttled to one update per 50 ms; a stage's start and its final 1.0 always
// pass, and a stage the core did not report (e.g. 'solve' when the solver converged within its first
// check) is completed when a later one starts.
//
// Warming up: a fresh WebAssembly module compiles each function on its first call (in baseline code)
// and tiers hot ones up to optimized code in the background as they run, so a module's first
// parameterization costs several times its later ones (in Node at 22.5k vertices: 851 ms of CPU
// against 125) — and a page user often makes exactly one. So once the worker has been idle for
// WARM_UP_IDLE_MS (after the page's first mesh and its paths, while the user looks or picks a file),
// it parameterizes a small built-in sample a few times and makes an atlas of another (the charts' growth
// and the packer are code a parameterization never runs), unobserved (no progress panel). A request
// sent meanwhile waits for the call under way (the worker serves requests in order; a fraction of a
// second); one that fails or is cancelled is dropped. It runs once per worker (not again after a cancel).
//
// Cancelling: the work runs inside synchronous WASM calls, so the helper terminates its worker and
// starts a new one; pending calls reject as 'cancelled', and a request that was between two calls
// stops before its next one. The adopted mesh is rebuilt in the new worker by restore().

import { createStraightestWorker } from 'straightest/worker';
import { meshFromBufferGeometry } from 'straightest/three';
import { geometryFromFile, threeFormatOf } from './mesh-files.js';
import { inSlices, nextTask } from './slices.js';

export function isCancelled(err) {
  return err?.category === 'cancelled';
}

/** An Error with a machine-readable category, as the package's StraightestError has. */
export function categorizedError(message, category) {
  return Object.assign(new Error(message), { category });
}

const THROTTLE_MS = 50; // at most one intermediate progress update per 50 ms and request

const WARM_UP_SAMPLE = 'mountain'; // a 2500-vertex height field: every hot loop of a parameterization
const WARM_UP_CALLS = 3; // measured-boundary parameterizations of it (one left most functions in baseline code)
const WARM_UP_ATLAS_SAMPLE = 'sphere'; // closed: grown into several charts, split and packed
const WARM_UP_ATLAS_CALLS = 2; // atlases of it (after one, the packer still ran partly in baseline code)
const WARM_UP_IDLE_MS = 300;

/** Runs `calls` times `work(mesh)` on the built-in sample `name` in `target`, then frees the mesh. */
async function onSample(target, name, calls, work) {
  const made = await target.sample(name);
  try {
    for (let k = 0; k < calls; k++) await work(made);
  } finally {
    made.delete().catch(() => {});
  }
}

/** Parameterizes one warm-up sample and makes atlases of another in `target` (a StraightestWorker). */
async function warmUp(target) {
  await onSample(target, WARM_UP_SAMPLE, WARM_UP_CALLS, (made) => made.parameterize({ boundary: 'measured' }));
  await onSample(target, WARM_UP_ATLAS_SAMPLE, WARM_UP_ATLAS_CALLS, (made) => made.atlas());
}

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

/**
 * Reports a request's progress. update(stage, fraction) takes the core's callbacks and the page's
 * own stages: a later stage completes every earlier one; within a stage, fractions only grow and are
 * throttled. finish() completes every stage (before the reply).
 */
class StageProgress {
  constructor(stages, report) {
    this.stages = stages;
    this.report = report;
    this.fractions = stages.map(() => -1); // -1: not reported yet
    this.current = -1; // index of the running stage
    this.lastReport = 0;
    this.callback = (stage, fraction) => {
      this.update(stage, fraction);
    };
    if (stages.length) this.update(stages[0], 0);
  }

  update(stage, fraction, extra = undefined) {
    const k = this.stages.indexOf(stage);
    if (k < 0) return; // a stage this request does not show
    if (k > this.current) {
      for (let j = Math.max(this.current, 0); j < k; j++) this.#report(j, 1, true);
      this.current = k;
      this.#report(k, fraction, true, extra);
    } else {
      // The running stage, or an earlier one again ('auto' solves once per boundary candidate).
      this.#report(k, fraction, false, extra);
    }
  }

  finish() {
    for (let k = 0; k < this.stages.length; k++) this.#report(k, 1, true);
  }

  #report(k, fraction, force, extra) {
    const f = Math.min(Math.max(Number(fraction) || 0, 0), 1);
    if (f <= this.fractions[k]) return;
    const now = performance.now();
    if (!force && f < 1 && now - this.lastReport < THROTTLE_MS) return;
    const first = this.fractions.every((x) => x < 0);
    this.fractions[k] = f;
    this.lastReport = now;
    this.report({ stage: this.stages[k], fraction: f, ...(first ? { stages: this.stages } : {}), ...extra });
  }
}

/**
 * `array` as a Float32Array, converted in slices (slices.js): a large mesh's positions take longer
 * than a task on the page's main thread should. Between slices, step() stops a cancelled request.
 */
async function float32(array, step) {
  const converted = new Float32Array(array.length);
  const convert = (from, to) => converted.set(array.subarray(from, to), from);
  await inSlices(array.length, convert, { pause: () => step(nextTask) });
  return converted;
}

/** observer (optional): begin(type, payload) → { update(progress), end() } or null (the progress panel). */
export function createRequests({ observer = null } = {}) {
  let worker = null; // the StraightestWorker, once started
  let mesh = null; // the adopted WorkerMesh (the mesh on display)
  let info = null; // its mesh.info()
  let generation = 0; // advances with every cancel: a request of an older one stops at its next call
  let warmUpState = 'waiting'; // 'waiting' for an idle worker, then 'started'
  let running = 0; // requests in progress
  let idleTimer = null;

  /** Starts the warm-up (see the top of this file) once the worker has been idle for WARM_UP_IDLE_MS. */
  function warmUpWhenIdle() {
    clearTimeout(idleTimer);
    if (warmUpState !== 'waiting' || running > 0 || !worker) return;
    idleTimer = setTimeout(() => {
      if (warmUpState !== 'waiting' || running > 0) return;
      warmUpState = 'started';
      warmUp(worker).catch(() => {});
    }, WARM_UP_IDLE_MS);
  }

  function requireMesh() {
    if (!mesh) throw new Error('no mesh is loaded');
    return mesh;
  }

  const closed = () => (info?.boundaryLoops ?? []).length === 0;
  const disk = () => info?.boundaryLoops.length === 1 && info.eulerCharacteristic === 1 && info.components === 1;

  /** The targets as straightestPaths takes them: 'boundary' entries are none on a closed mesh. */
  function resolveTargets(targets) {
    if (targets === 'boundary') return closed() ? [] : 'boundary';
    if (!Array.isArray(targets)) throw new Error("targets must be 'boundary' or an array");
    return closed() ? targets.filter((t) => t !== 'boundary') : targets;
  }

  /** The stages a request goes through, in order (see the top of this file). */
  function plannedStages(type, payload) {
    switch (type) {
      case 'sample':
      case 'file':
        return payload.restore ? ['load'] : ['load', 'upload'];
      case 'paths':
        return ['trace', 'upload'];
      case 'distances':
        return ['heat', 'upload'];
      case 'parameterize':
        return [...(disk() ? [] : ['cut']), ...parameterizeStages(payload.boundary), 'overlays', 'upload'];
      case 'compare':
        return ['compare'];
      case 'exportObj':
        return ['export'];
      case 'atlas':
        return ['segment', 'flatten', 'pack', 'measure'];
      case 'geodesics':
        return ['distances', 'trace', 'shoot'];
      case 'exactRatio':
        return ['distances', 'trace'];
      default:
        return [];
    }
  }

  /** A new mesh and the arrays the page draws of it (deleted again if fetching them fails). */
  async function meshReply(made, label, start, progress, step) {
    progress.update('upload', 0);
    try {
      const [meshInfo, positions, indices, normals] = await step(() =>
        Promise.all([made.info(), made.positions(), made.indices(), made.vertexNormals()]),
      );
      return {
        type: 'mesh',
        mesh: made,
        label,
        positions: await float32(positions, step), // (WebGL draws no doubles)
        indices,
        normals,
        info: meshInfo,
        timeMs: performance.now() - start,
      };
    } catch (err) {
      made.delete().catch(() => {});
      throw err;
    }
  }

  const handlers = {
    async sample({ name }, progress, step) {
      const start = performance.now();
      return meshReply(await step(() => worker.sample(name)), name, start, progress, step);
    },

    async file({ name, file }, progress, step) {
      const start = performance.now();
      if (threeFormatOf(name)) {
        // STL, PLY, glTF: three's loaders here, then the positions welded into a mesh in the worker.
        const bytes = await step(() => file.arrayBuffer());
        const { geometry, note } = await step(() => geometryFromFile(name, bytes));
        const made = await step(() => meshFromBufferGeometry(worker, geometry, { weld: true }));
        geometry.dispose();
        const reply = await meshReply(made, name, start, progress, step);
        return { ...reply, note };
      }
      const format = await step(() => worker.formatFromFileName(name));
      // One synchronous call in the worker: no progress inside it ('load' is 0 before and 1 after).
      const made = await step(() => worker.loadMesh(file, format)); // (a Blob: the worker reads it)
      return meshReply(made, name, start, progress, step);
    },

    async paths({ source = 'auto', targets = 'boundary' }, progress, step) {
      const start = performance.now();
      const options = { source, targets: resolveTargets(targets), onProgress: progress.callback };
      const result = await step(() => requireMesh().straightestPaths(options));
      progress.update('upload', 0);
      return {
        ...result,
        type: 'paths',
        targetPositions: new Float32Array(result.targetPositions),
        timeMs: performance.now() - start,
      };
    },

    async distances({ source = 'auto' }, progress, step) {
      const start = performance.now();
      const heat = await step(() => requireMesh().geodesicDistances(source, 'heat')); // no progress in the API
      progress.update('upload', 0);
      const distances = new Float32Array(heat); // (a typed array's own copy: far faster than from())
      let max = 0;
      for (const d of distances) if (Number.isFinite(d) && d > max) max = d;
      return { type: 'distances', source, distances, max, timeMs: performance.now() - start };
    },

    async parameterize({ source = 'auto', boundary = 'measured', weights = 'shape-preserving' }, progress, step) {
      const target = requireMesh();
      const start = performance.now();
      const result = await step(() =>
        target.parameterize({ source, boundary, weights, onProgress: progress.callback }),
      );
      const timeMs = performance.now() - start;
      const kinds = worker.polygonBoundaryKinds.filter((kind) => kind !== result.boundary);
      const others =
        kinds.length === 0
          ? []
          : await step(() =>
              target.boundaryPolygons({
                source: result.source,
                kinds,
                onProgress: (stage, fraction) => progress.update('overlays', fraction),
              }),
            );
      progress.update('upload', 0);
      const overlays = worker.boundaryKinds.flatMap((kind) => {
        if (kind === result.boundary) return [{ boundary: kind, polygon: result.boundaryPolygon.slice(), error: null }];
        const other = others.find((o) => o.boundary === kind);
        return other ? [{ boundary: kind, polygon: other.polygon, error: other.error }] : [];
      });
      return { ...result, type: 'parameterization', timeMs, overlays };
    },

    async compare({ source = 'auto' }, progress, step) {
      const total = worker.boundaryKinds.length * worker.weightKinds.length; // the core's default cells
      const { rows, best } = await step(() =>
        requireMesh().compareParameterizations({
          source,
          onProgress: (stage, fraction) =>
            progress.update('compare', fraction, { done: Math.round(fraction * total), total }),
        }),
      );
      return { type: 'comparison', source, rows, best };
    },

    async geodesics({ source, target }, progress, step) {
      const onDisplay = requireMesh();
      const onProgress = progress.callback;
      const exact = await step(() => onDisplay.exactShortestPaths({ source, targets: [target], onProgress }));
      const plane = await step(() => onDisplay.straightestPaths({ source, targets: [target], onProgress }));
      const reached = plane.statuses[0] === 'reached';
      const length = reached ? {} : { length: exact.distances[0] };
      const shot = await step(() => onDisplay.shootGeodesic({ source, toward: target, ...length, onProgress }));
      return {
        type: 'geodesics',
        target,
        exact: { distance: exact.distances[0], points: exact.points.slice(3 * exact.offsets[0], 3 * exact.offsets[1]) },
        plane: {
          length: plane.lengths[0],
          status: plane.statuses[0],
          points: plane.points.slice(3 * plane.offsets[0], 3 * plane.offsets[1]),
        },
        shot,
      };
    },

    async exactRatio({ source = 'auto' }, progress, step) {
      if (closed()) throw categorizedError('a closed mesh has no boundary to compare against', 'topology');
      const onDisplay = requireMesh();
      const onProgress = progress.callback;
      const exact = await step(() =>
        onDisplay.exactShortestPaths({ source, targets: 'boundary', points: false, onProgress }),
      );
      const plane = await step(() =>
        onDisplay.straightestPaths({ source, targets: 'boundary', points: false, onProgress }),
      );
      // Both expand 'boundary' into the same loop in the same order.
      const ratios = Float64Array.from(plane.lengths, (length, i) =>
        plane.statuses[i] === 'reached' ? length / exact.distances[i] : NaN,
      );
      return {
        type: 'exactRatio',
        source: plane.source,
        targets: exact.targets,
        distances: exact.distances,
        lengths: plane.lengths,
        statuses: plane.statuses,
        ratios,
      };
    },

    async atlas({ maxStretch, resolution, padding }, progress, step) {
      const start = performance.now();
      const options = { maxStretch, resolution, padding, onProgress: progress.callback };
      const reply = await step(() => requireMesh().atlas(options));
      return { ...reply, type: 'atlas', timeMs: performance.now() - start };
    },

    async exportObj({ uv }, progress, step) {
      return { type: 'obj', text: await step(() => requireMesh().toOBJ(uv)) };
    },
  };

  /** Runs `type` with the progress panel's task; rejects as 'cancelled' once cancel() is called. */
  async function run(type, payload, onProgress, handler) {
    const task = observer?.begin(type, payload) ?? null;
    const epoch = generation;
    running += 1;
    clearTimeout(idleTimer);
    // Each call to the worker goes through step(): none starts after a cancel.
    const step = (call) => {
      if (epoch !== generation) return Promise.reject(categorizedError('cancelled', 'cancelled'));
      return call();
    };
    try {
      const progress = new StageProgress(plannedStages(type, payload), (message) => {
        if (epoch !== generation) return;
        task?.update(message);
        onProgress?.(message);
      });
      const reply = await handler(payload, progress, step);
      if (epoch !== generation) {
        reply?.mesh?.delete().catch(() => {});
        throw categorizedError('cancelled', 'cancelled');
      }
      progress.finish();
      return reply;
    } finally {
      task?.end();
      running -= 1;
      warmUpWhenIdle();
    }
  }

  return {
    /**
     * Starts the worker; resolves with its sample names, the parameterization's boundary kinds and the
     * threads its WebAssembly module runs on (more than 1 when the page is cross-origin isolated).
     */
    async start() {
      worker = await createStraightestWorker();
      warmUpWhenIdle();
      return { samples: worker.sampleNames(), boundaryKinds: worker.boundaryKinds, threads: worker.threads };
    },

    /** Runs a request (see the top of this file). */
    request(type, payload = {}, onProgress = null) {
      const handler = handlers[type];
      if (!handler) return Promise.reject(new Error(`unknown request type: ${type}`));
      if (!worker) return Promise.reject(categorizedError('the geometry worker has not started', 'worker'));
      return run(type, payload, onProgress, handler);
    },

    /** Makes `made` (a 'mesh' reply's mesh) the mesh later requests work on; the previous one is freed. */
    adopt(made, madeInfo) {
      if (mesh && mesh !== made) mesh.delete().catch(() => {});
      mesh = made;
      info = madeInfo;
    },

    /** Frees the adopted mesh: no mesh is on display. */
    drop() {
      mesh?.delete().catch(() => {});
      mesh = null;
      info = null;
    },

    /**
     * Rebuilds the adopted mesh in the worker that replaced a cancelled one (the helper keeps what
     * made it), as a 'sample' or 'file' request with `restore` for the progress panel.
     */
    restore(type, name) {
      const target = mesh;
      return run(type, { name, restore: true }, null, async (payload, progress, step) => {
        if (target) await step(() => target.info());
      });
    },

    /** Stops whatever the worker is doing: pending requests reject with category 'cancelled'. */
    cancel() {
      generation += 1;
      worker?.cancel();
    },
  };
}
