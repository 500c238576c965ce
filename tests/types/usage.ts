// The package's public API used as a consumer uses it, checked by `tsc -p tests/types` (strict) against
// wasm/index.d.ts and wasm/three.d.ts: a declaration that is wrong, missing or too loose fails the check.
// Each `@ts-expect-error` line is a misuse the declarations must refuse (tsc fails if it type-checks).
// Never run: only type-checked.
import {
  createStraightest,
  type Atlas,
  type AtlasOptions,
  type SharedAtlas,
  Mesh,
  StraightestError,
  type Straightest,
  type BasePlane,
  type BoundaryKind,
  type CutMethod,
  type ErrorCategory,
  type ExactShortestPaths,
  type GeodesicShot,
  type MeshFormat,
  type MeshInfo,
  type Parameterization,
  type ProgressCallback,
  type ProgressStage,
  type ShootStatus,
  type SurfacePoint,
  type TraceStatus,
} from 'straightest';
import {
  applyUV,
  meshFromBufferGeometry,
  packAtlas,
  toBufferGeometry,
  toSeamSplitGeometry,
  unwrap,
} from 'straightest/three';
import * as inline from 'straightest/inline';
import * as single from 'straightest/single';
import { createStraightestWorker, type WorkerMesh } from 'straightest/worker';
import { BufferGeometry } from 'three';

/** Compiles only when A and B are the same type (not merely assignable). */
type Equal<A, B> = (<T>() => T extends A ? 1 : 2) extends <T>() => T extends B ? 1 : 2 ? true : false;
function assertType<T extends true>(): T | void {}

/** A consumer's exhaustive switch: a status added to or removed from TraceStatus breaks it. */
function describe(status: TraceStatus): string {
  switch (status) {
    case 'reached':
      return 'reached';
    case 'hit_boundary':
      return 'the section left the surface';
    case 'other_component':
      return 'a closed loop through the source';
    case 'loop':
      return 'the walk revisited a crossing';
    case 'step_limit':
      return 'too many steps';
    case 'no_exit':
      return 'no face continues the section';
    case 'degenerate_plane':
      return 'no cutting plane';
    default: {
      const unreachable: never = status;
      return unreachable;
    }
  }
}

export async function consumer(bytes: Uint8Array, text: string, geometry: BufferGeometry): Promise<void> {
  const st = await createStraightest();
  await createStraightest({ wasmUrl: new URL('https://example.org/straightest-core.wasm') });
  await createStraightest({ wasmUrl: '/assets/straightest-core.wasm', wasmBinary: new ArrayBuffer(8) });
  await createStraightest({ locateFile: (name, dir) => dir + name });
  const embedded: Straightest = await inline.createStraightest();
  const singleThreaded: Straightest = await single.createStraightest({ threads: 1 });
  singleThreaded.threadsUnavailable satisfies string | null;
  void embedded;
  // straightest/worker: the same calls as promises; a signal cancels.
  const inWorker = await createStraightestWorker({ wasmUrl: '/straightest-core.wasm' });
  const remote: WorkerMesh = await inWorker.sample('cap');
  const controller = new AbortController();
  const remoteUv: Float32Array = (
    await remote.parameterize({ boundary: 'free', signal: controller.signal, onProgress: () => {} })
  ).uv;
  const remoteInfo: MeshInfo = await remote.info();
  const remoteAtlas: Atlas = await remote.atlas({
    padding: 4,
    signal: controller.signal,
    onProgress: (stage) => stage !== 'pack',
  });
  const remoteShared: SharedAtlas = await inWorker.atlas([remote, remote], { resolution: 512 });
  // @ts-expect-error the worker's shared atlas takes the worker's meshes
  await inWorker.atlas([st.sample('cap')]);
  void [remoteUv, remoteInfo, remoteAtlas, remoteShared];
  // @ts-expect-error the worker's results are promises
  const notAwaited: MeshInfo = remote.info();
  void notAwaited;
  await remote.delete();
  const workerKinds: BoundaryKind[] = inWorker.boundaryKinds;
  const workerFormat: MeshFormat = await inWorker.formatFromFileName('a.obj');
  const workerSamples: string[] = inWorker.sampleNames();
  void [workerKinds, workerFormat, workerSamples];
  inWorker.cancel();
  inWorker.terminate();
  {
    // `await using` frees a worker mesh, then ends its worker; a URL object names the .wasm.
    await using scoped = await createStraightestWorker({ wasmUrl: new URL('./straightest-core.wasm', 'https://x/') });
    await using scopedMesh = await scoped.sample('cap');
    const why: string | null = scoped.threadsUnavailable;
    void [why, await scopedMesh.info()];
  }
  const threadsWhy: string | null = st.threadsUnavailable;
  void threadsWhy;
  // @ts-expect-error the options are an object, not a URL string
  await createStraightest('/straightest-core.wasm');

  // Loading: bytes, ArrayBuffer, views or text, a format name, caps.
  const mesh: Mesh = st.loadMesh(bytes, 'obj');
  st.loadMesh(new ArrayBuffer(64), 'off', { maxVertices: 1e6, maxFaces: 2e6 });
  st.loadMesh(new DataView(bytes.buffer), 'auto');
  st.loadMesh(text);
  st.meshFromArrays(new Float64Array(9), new Uint32Array([0, 1, 2]));
  st.meshFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2], { maxFaces: 1 });
  st.loadMesh(bytes, 'stl');
  st.loadMesh(bytes, 'ply');
  // @ts-expect-error glTF is read by three's GLTFLoader, not by loadMesh
  st.loadMesh(bytes, 'gltf');
  // @ts-expect-error a SharedArrayBuffer is refused at run time (toBytes), so the types refuse it too
  st.loadMesh(new SharedArrayBuffer(64));
  // @ts-expect-error a mesh is read from its contents, not from a number
  st.loadMesh(42);
  for (const name of st.sampleNames()) st.sample(name).delete();
  st.sample('mountain');
  const memory: number = st.memoryBytes + st.heapUsedBytes;
  const statuses: TraceStatus[] = st.traceStatuses;
  void memory;
  void statuses;

  const info: MeshInfo = mesh.info();
  const loops: number[] = info.boundaryLoops;
  const corner: [number, number, number] = info.bbox.min;
  const notes: string[] = info.problems;
  void [loops, corner, notes];
  assertType<Equal<typeof info.eulerCharacteristic, number>>();
  const positions: Float64Array = mesh.positions();
  const indices: Uint32Array = mesh.indices();
  void [positions, indices];

  // Surface points in every form.
  const points: SurfacePoint[] = [3, { vertex: 3 }, { face: 0, bary: [0.2, 0.3, 0.5] }, { halfedge: 4, t: 0.25 }];
  // @ts-expect-error barycentric coordinates are three numbers
  const twoBary: SurfacePoint = { face: 0, bary: [0.5, 0.5] };
  // @ts-expect-error an edge point is a halfedge and a parameter t
  const edgeWithoutT: SurfacePoint = { halfedge: 4 };
  void [twoBary, edgeWithoutT];

  const source: number = mesh.defaultSource();
  const base: BasePlane = mesh.basePlane(source);
  mesh.basePlane('auto');
  mesh.basePlane();
  const normal: [number, number, number] = base.normal;
  const fallback: boolean = base.fallback;
  void [normal, fallback];

  // Straightest paths, with progress and cancellation.
  const onProgress: ProgressCallback = (stage, fraction) => {
    if (stage === 'trace' && fraction > 0.5) return false;
  };
  const paths = mesh.straightestPaths({ source: 'auto', targets: 'boundary', points: true, onProgress });
  mesh.straightestPaths({ source: { face: 2, bary: [1 / 3, 1 / 3, 1 / 3] }, targets: points, points: false });
  mesh.straightestPaths();
  const lengths: Float64Array = paths.lengths;
  const packed: Float32Array = paths.points;
  const offsets: Uint32Array = paths.offsets;
  const facesCrossed: Uint32Array = paths.facesCrossed;
  const reachedAll: boolean = paths.reached === paths.count;
  const trace: number = paths.timings.prepare + paths.timings.trace;
  void [lengths, packed, offsets, facesCrossed, reachedAll, trace, paths.targetPositions, paths.sourcePosition];
  // Closed meshes: the other arc round the section, and which way the returned one leaves the source.
  const backward: Uint8Array = paths.backward;
  const otherLengths: Float64Array = paths.otherArcLengths;
  const otherPoints: Float32Array = paths.otherPoints;
  const otherOffsets: Uint32Array = paths.otherOffsets;
  const otherArcs: number = paths.summary.otherArcs;
  const elsewhere: TraceStatus = 'other_component';
  void [backward, otherLengths, otherPoints, otherOffsets, otherArcs, elsewhere];
  mesh.straightestPaths({ targets: 'all-boundaries' });
  mesh.straightestPaths({ targets: [0, 'all-boundaries', 'boundary'] });
  // @ts-expect-error the other lengths are a Float64Array (NaN where there is none), not numbers or null
  const otherList: (number | null)[] = paths.otherArcLengths;
  // @ts-expect-error 'returned_to_source' was renamed 'other_component'
  const returned: TraceStatus = 'returned_to_source';
  void [otherList, returned];
  for (const status of paths.statuses) describe(status);
  // @ts-expect-error lengths are a Float64Array, not an array
  const lengthList: number[] = paths.lengths;
  // @ts-expect-error targets are 'boundary', 'all-boundaries' or a list of surface points
  mesh.straightestPaths({ targets: 'all' });
  // @ts-expect-error a progress callback answers with a boolean (or nothing), not a string
  mesh.straightestPaths({ onProgress: () => 'stop' });
  // @ts-expect-error 'arrived' is not a trace status
  const arrived: TraceStatus = 'arrived';
  void [lengthList, arrived];

  const heat: Float64Array = mesh.geodesicDistances(source, 'heat');
  mesh.geodesicDistances({ vertex: 0 }, 'dijkstra');
  mesh.geodesicDistances();
  mesh.geodesicDistances(source, 'exact');
  // @ts-expect-error the distance methods are 'heat', 'dijkstra' and 'exact'
  mesh.geodesicDistances(source, 'mmp');
  void heat;

  // Geodesics shot from a direction (initial value problem) and exact shortest paths.
  const shot: GeodesicShot = mesh.shootGeodesic({ source: 'auto', direction: [1, 0, 0], length: 0.5, onProgress });
  const shotPoints: Float64Array = shot.points;
  const shotStatus: ShootStatus = shot.status;
  const miss: number | null = mesh.shootGeodesic({ toward: { vertex: 3 } }).missDistance;
  mesh.shootGeodesic({ source: { halfedge: 4, t: 0.5 }, angle: Math.PI / 3, length: 1, points: false });
  mesh.shootGeodesic({ toward: 7, length: 2 });
  // @ts-expect-error shootGeodesic needs its aim
  mesh.shootGeodesic();
  // @ts-expect-error a direction is 3 numbers
  mesh.shootGeodesic({ direction: [1, 0], length: 1 });
  // @ts-expect-error 'reached' is a trace status, not a shot's
  const notShot: ShootStatus = 'reached';
  const shootStatuses: ShootStatus[] = st.shootStatuses;
  const exact: ExactShortestPaths = mesh.exactShortestPaths({
    source,
    targets: [3, { vertex: 4 }, 'boundary'],
    onProgress,
  });
  const exactPoints: Float32Array = exact.points;
  const exactOffsets: Uint32Array = exact.offsets;
  const exactTargets: Int32Array = exact.targets;
  const windows: number = exact.exact.windows;
  mesh.exactShortestPaths();
  mesh.exactShortestPaths({ targets: 'all-boundaries', points: false });
  // @ts-expect-error exact shortest paths end at vertices
  mesh.exactShortestPaths({ targets: [{ face: 0, bary: [1, 0, 0] }] });
  const stages: ProgressStage[] = ['shoot', 'distances'];
  void [shotPoints, shotStatus, miss, notShot, shootStatuses, exactPoints, exactOffsets, exactTargets, windows, stages];

  // Parameterization.
  const p: Parameterization = mesh.parameterize({
    source: 'auto',
    boundary: 'auto',
    weights: 'shape-preserving',
    solver: 'multigrid',
    onProgress: (stage: string, fraction: number) => stage !== 'solve' || fraction < 1,
  });
  for (const weights of ['shape-preserving', 'mean-value', 'cotan', 'uniform'] as const)
    for (const boundary of ['measured', 'circle', 'square', 'free'] as const)
      for (const solver of ['multigrid', 'lu', 'bicgstab'] as const) mesh.parameterize({ weights, boundary, solver });
  const uv: Float32Array = p.uv;
  const stretch: number = p.stretch.l2 + p.stretch.linf;
  const bijective: boolean = p.bijective;
  const best = p.candidates.reduce((a, b) => (b.l2 < a.l2 ? b : a));
  assertType<Equal<typeof best.boundary, 'measured' | 'circle' | 'square' | 'free'>>();
  const overlaps: number = p.overlaps + best.overlaps;
  // The free boundary: its refinement's options and fields (null for a fixed boundary).
  const free: Parameterization = mesh.parameterize({ boundary: 'free', maxIterations: 50, timeBudgetMs: 2000 });
  const init: 'measured' | 'circle' | null = free.init;
  const iterations: number | null = free.iterations;
  const energies: (number | null)[] = [free.energyInitial, free.energyFinal];
  const stops: (boolean | null)[] = [free.converged, free.untangled];
  const refineMs: number = free.timings.refine;
  void [overlaps, init, iterations, energies, stops, refineMs];
  // @ts-expect-error a free refinement never starts from the square
  const squareStart: 'square' | null = free.init;
  void squareStart;
  // @ts-expect-error the iteration cap is a number
  mesh.parameterize({ boundary: 'free', maxIterations: '10' });
  const polygon: Float32Array = p.boundaryPolygon;
  const loop: Int32Array = p.boundaryLoop;
  const total: number = p.timings.total;
  void [stretch, bijective, polygon, loop, total, p.faceStretch, p.residual];
  // Every manifold mesh: how it was made a disk, and the map per face corner.
  const cut: CutMethod = p.cut;
  assertType<Equal<typeof p.cut, 'disk' | 'fill' | 'path' | 'cut-graph'>>();
  const cornerUv: Float32Array = p.cornerUv;
  const seam: Int32Array = p.seam;
  const filled: number[] = p.filledLoops;
  const counts: number[] = [p.genus, p.seamEdges, p.seamLength, p.component, p.components, p.virtualVertices];
  const cutMs: number = p.timings.cut;
  const splitObj: string = mesh.toOBJ(p.cornerUv);
  void [cut, cornerUv, seam, filled, counts, cutMs, splitObj];
  // @ts-expect-error a cut is one of four methods
  const spiral: CutMethod = 'spiral';
  void spiral;
  // @ts-expect-error no 'ellipse' boundary
  mesh.parameterize({ boundary: 'ellipse' });
  // @ts-expect-error no 'harmonic' weights
  mesh.parameterize({ weights: 'harmonic' });
  // @ts-expect-error no 'cg' solver
  mesh.parameterize({ solver: 'cg' });
  // @ts-expect-error the chosen boundary is never 'auto' (that is only a request)
  const chosen: 'auto' = p.boundary;
  void chosen;

  // Data the core owns: boundary loops, normals, polygons without a solve, the comparison, names.
  const loopVertices: Int32Array[] = mesh.boundaryLoops();
  const normals: Float32Array = mesh.vertexNormals();
  for (const b of mesh.boundaryPolygons({ source: 'auto', kinds: ['measured', 'circle'], onProgress })) {
    const kind: 'measured' | 'circle' | 'square' = b.boundary;
    const polygon: Float32Array | null = b.polygon;
    const loop: Int32Array = b.loop;
    const why: string | null = b.error;
    void [kind, polygon, loop, why];
  }
  // @ts-expect-error 'auto' is a request, not a boundary kind with a polygon
  mesh.boundaryPolygons({ kinds: ['auto'] });
  // @ts-expect-error the free boundary has no polygon without its refinement
  mesh.boundaryPolygons({ kinds: ['free'] });
  const polygonKinds: ('measured' | 'circle' | 'square')[] = st.polygonBoundaryKinds;
  const freeRows = mesh.compareParameterizations({ boundaries: ['free'], maxIterations: 20, timeBudgetMs: 500 }).rows;
  const rowInit: 'measured' | 'circle' | null = freeRows[0].init;
  const rowFacts: [number | null, number | null, boolean | null] = [
    freeRows[0].iterations,
    freeRows[0].overlaps,
    freeRows[0].converged,
  ];
  void [polygonKinds, rowInit, rowFacts];
  const comparison = mesh.compareParameterizations({ boundaries: ['circle'], weights: ['uniform', 'cotan'] });
  const bestRow: number = comparison.best;
  const l2: number | null = comparison.rows[0].l2;
  // @ts-expect-error a failed cell has no numbers: l2 may be null
  const l2Number: number = comparison.rows[0].l2;
  const directions: Float64Array = paths.directions;
  const kinds: ('measured' | 'circle' | 'square' | 'free')[] = st.boundaryKinds;
  const format: 'obj' | 'off' | 'ply' | 'stl' | 'auto' = st.formatFromFileName('bunny.OBJ');
  mesh.straightestPaths({ targets: ['boundary', 3, { vertex: 4 }] });
  void [loopVertices, normals, bestRow, l2, l2Number, directions, kinds, format];

  const obj: string = mesh.toOBJ(uv);
  mesh.toOBJ();
  void obj;

  // Errors: a StraightestError is an Error with a machine-readable category.
  try {
    st.loadMesh('v 0 0 0\n', 'obj');
  } catch (e) {
    if (e instanceof StraightestError) {
      const category: ErrorCategory = e.category;
      const message: string = e.message;
      const asError: Error = e;
      void [category, message, asError];
      if (e.category === 'cancelled' || e.category === 'too_large' || e.category === 'invalid_argument') throw e;
      // @ts-expect-error 'usage' is the CLI's word; the package says 'invalid_argument'
      if (e.category === 'usage') throw e;
    }
  }
  // @ts-expect-error the category is read-only
  new StraightestError().category = 'parse';

  // three.js helpers.
  const fromThree: Mesh = meshFromBufferGeometry(st, geometry);
  meshFromBufferGeometry(st, geometry, { weld: true }).delete();
  meshFromBufferGeometry(st, geometry, { weld: 1e-6 }).delete();
  // @ts-expect-error weld is true/false or a distance
  meshFromBufferGeometry(st, geometry, { weld: 'yes' });
  const toThree: BufferGeometry = toBufferGeometry(fromThree);
  const textured: BufferGeometry = applyUV(toThree, p.uv);
  applyUV(geometry, [0, 0, 1, 0, 0, 1]);
  // @ts-expect-error uv is numbers, two per vertex
  applyUV(geometry, 'uv');
  // @ts-expect-error the straightest instance comes first
  meshFromBufferGeometry(geometry);
  const split: BufferGeometry = toSeamSplitGeometry(fromThree, p);
  toSeamSplitGeometry(fromThree, { cornerUv: new Float32Array(6) });
  // @ts-expect-error it needs the parameterization (its cornerUv), not the per-vertex uv
  toSeamSplitGeometry(fromThree, p.uv);
  void [textured, split];

  // Texture atlases: one mesh, several meshes in one texture, and the three.js helpers.
  const atlasOptions: AtlasOptions = { maxStretch: 1.05, maxCharts: 64, resolution: 2048, padding: 4, rotate: false };
  const atlas: Atlas = mesh.atlas(atlasOptions);
  const atlasUv: Float32Array = atlas.cornerUv;
  const charts: Int32Array = atlas.chartOfFace;
  const quality: number =
    atlas.stretch.l2 +
    atlas.utilization +
    atlas.flipped +
    atlas.mirrored +
    atlas.overlaps +
    atlas.paddingViolations +
    atlas.minGapTexels +
    atlas.texelsPerUnit +
    atlas.timings.pack;
  const capped: boolean = atlas.capped;
  mesh.atlas({ width: 1024, height: 512, texelsPerUnit: 100, onProgress: (stage) => stage !== 'flatten' });
  mesh.toOBJ(atlas.cornerUv);
  const shared: SharedAtlas = st.atlas([mesh, fromThree], { resolution: 4096 });
  const perMesh: Float32Array = shared.meshes[1].cornerUv;
  // @ts-expect-error the shared atlas takes an array of meshes
  st.atlas(mesh);
  // @ts-expect-error rotate is true or false
  mesh.atlas({ rotate: 'yes' });
  // @ts-expect-error the resolution is a number of texels
  mesh.atlas({ resolution: '1k' });
  // @ts-expect-error the shared atlas's per-mesh parts are on `meshes`, not on a plain atlas
  void atlas.meshes;
  const unwrapped: { geometry: BufferGeometry; atlas: Atlas } = unwrap(st, geometry, {
    channel: 'uv1',
    weld: true,
    padding: 2,
  });
  const packedGeometries: BufferGeometry[] = packAtlas(st, [geometry, toThree], { resolution: 1024 }).geometries;
  const packedAtlas: SharedAtlas = packAtlas(st, [geometry]).atlas;
  // @ts-expect-error three's uv channels are 'uv' and 'uv1' (the second set was 'uv2' before r151)
  unwrap(st, geometry, { channel: 'uv2' });
  // @ts-expect-error the straightest instance comes first
  unwrap(geometry);
  void [atlasUv, charts, quality, capped, perMesh, unwrapped, packedGeometries, packedAtlas];

  // Lifetime: `using` frees a mesh at the end of its scope; constructors are the library's own.
  {
    using scoped = st.sample('cap');
    const faces: number = scoped.info().faces;
    void faces;
  }
  // @ts-expect-error meshes come from st.loadMesh, st.meshFromArrays or st.sample
  new Mesh();
  // Results give surface points in object form, never a bare index.
  const resolved = paths.targets[0];
  if ('vertex' in resolved) void resolved.vertex;
  // @ts-expect-error a result's source is an object
  const bareSource: number = paths.source;
  void bareSource;
  // Progress stages are named; unknown future stages still type-check.
  mesh.parameterize({ onProgress: (stage) => stage === 'refine' || stage === 'some-later-stage' });
  st.sample('face');
  const error = new StraightestError('message', 'io', { cause: new Error('inner') });
  void error;

  // Meshes hold WASM memory until deleted.
  const deleted: boolean = mesh.deleted;
  // @ts-expect-error deleted is read-only
  mesh.deleted = true;
  mesh.delete();
  fromThree.delete();
  void deleted;
}
