// Types of straightest/worker: the package's API in a module worker, as promises.
import type {
  Atlas,
  AtlasOptions,
  SharedAtlas,
  BasePlane,
  BoundaryPolygon,
  BoundaryPolygonsOptions,
  BuildLimits,
  CompareOptions,
  Comparison,
  CreateOptions,
  MeshFormat,
  MeshInfo,
  Parameterization,
  ParameterizeOptions,
  SampleName,
  StraightestPaths,
  StraightestPathsOptions,
  SurfacePoint,
  DistanceMethod,
  Straightest,
  ShootGeodesicOptions,
  GeodesicShot,
  ExactShortestPathsOptions,
  ExactShortestPaths,
} from './index.js';

/** What the long calls take in the worker: Mesh's options plus an AbortSignal that cancels the work. */
export type WorkerOptions<T> = T & { signal?: AbortSignal };

/** A mesh living in the worker: Mesh's methods, each returning a promise. */
export class WorkerMesh {
  private constructor();
  /** Whether delete() has been called. */
  readonly deleted: boolean;
  /** Sizes, topology and what validation repaired. */
  info(): Promise<MeshInfo>;
  /** x, y, z per vertex (transferred). */
  positions(): Promise<Float64Array>;
  /** 3 vertex indices per triangle (transferred). */
  indices(): Promise<Uint32Array>;
  /** Every boundary loop's vertices in order, longest first. */
  boundaryLoops(): Promise<Int32Array[]>;
  /** Area-weighted unit vertex normals. */
  vertexNormals(): Promise<Float32Array>;
  /** The interior vertex farthest from the boundary. */
  defaultSource(): Promise<number>;
  /** The base plane at a source. */
  basePlane(source?: SurfacePoint | 'auto'): Promise<BasePlane>;
  /** Distances from the source to every vertex. */
  geodesicDistances(source?: SurfacePoint | 'auto', method?: DistanceMethod): Promise<Float64Array>;
  /** OBJ text, with uv as `vt` lines when given. */
  toOBJ(uv?: ArrayLike<number>): Promise<string>;
  /** Straightest paths (see Mesh.straightestPaths); `signal` cancels. */
  straightestPaths(options?: WorkerOptions<StraightestPathsOptions>): Promise<StraightestPaths>;
  /** A parameterization (see Mesh.parameterize); `signal` cancels. */
  parameterize(options?: WorkerOptions<ParameterizeOptions>): Promise<Parameterization>;
  /** Every boundary kind's polygon without a solve; `signal` cancels. */
  boundaryPolygons(options?: WorkerOptions<BoundaryPolygonsOptions>): Promise<BoundaryPolygon[]>;
  /** Every boundary × weights; `signal` cancels. */
  compareParameterizations(options?: WorkerOptions<CompareOptions>): Promise<Comparison>;
  /** A straightest geodesic shot from a source (see Mesh.shootGeodesic); `signal` cancels. */
  shootGeodesic(options: WorkerOptions<ShootGeodesicOptions>): Promise<GeodesicShot>;
  /** Exact shortest paths to vertices (see Mesh.exactShortestPaths); `signal` cancels. */
  exactShortestPaths(options?: WorkerOptions<ExactShortestPathsOptions>): Promise<ExactShortestPaths>;
  /** A texture atlas (see Mesh.atlas); `signal` cancels. */
  atlas(options?: WorkerOptions<AtlasOptions>): Promise<Atlas>;
  /** Frees the mesh in the worker. */
  delete(): Promise<void>;
  /** The same as delete(): `await using mesh = await st.sample('cap')` frees it at the end of the scope. */
  [Symbol.asyncDispose](): Promise<void>;
}

/** The library in a worker, from `await createStraightestWorker()`. */
export interface StraightestWorker {
  /** Names of the built-in sample meshes. */
  sampleNames(): string[];
  /** The threads the worker's module runs on (Straightest's `threads`; read when the worker started). */
  readonly threads: number;
  /** Straightest's `threadsUnavailable`, read in the worker when it started. */
  readonly threadsUnavailable: string | null;
  /** The trace statuses, in the core's order (as Straightest's; read once when the worker started). */
  readonly traceStatuses: Straightest['traceStatuses'];
  /** The boundary kinds, in the core's order. */
  readonly boundaryKinds: Straightest['boundaryKinds'];
  /** The kinds boundaryPolygons gives without a solve: every kind but 'free'. */
  readonly polygonBoundaryKinds: Straightest['polygonBoundaryKinds'];
  /** What parameterize's `boundary` takes: the kinds and 'auto'. */
  readonly boundaryChoices: Straightest['boundaryChoices'];
  /** The interior weight kinds. */
  readonly weightKinds: Straightest['weightKinds'];
  /** The linear solvers. */
  readonly solvers: Straightest['solvers'];
  /** geodesicDistances' methods. */
  readonly distanceMethods: Straightest['distanceMethods'];
  /** loadMesh's formats. */
  readonly meshFormats: Straightest['meshFormats'];
  /** Every StraightestError category. */
  readonly errorCategories: Straightest['errorCategories'];
  /** The format a file name asks for: 'obj', 'off', 'ply', 'stl' (by extension, any case) or 'auto'. */
  formatFromFileName(name: string): Promise<MeshFormat>;
  /**
   * Parses an OBJ, OFF, PLY or STL file (bytes, text, or a Blob such as a File: the worker reads it, so
   * its bytes are never copied on the calling thread) in the worker.
   */
  loadMesh(
    data: Uint8Array | ArrayBuffer | ArrayBufferView | string | Blob,
    format?: MeshFormat,
    limits?: BuildLimits,
  ): Promise<WorkerMesh>;
  /** A mesh from flat arrays, built in the worker. */
  meshFromArrays(positions: ArrayLike<number>, indices: ArrayLike<number>, limits?: BuildLimits): Promise<WorkerMesh>;
  /** A built-in sample mesh. */
  sample(name: SampleName): Promise<WorkerMesh>;
  /** One atlas shared by several meshes of this worker (see Straightest.atlas); `signal` cancels. */
  atlas(meshes: WorkerMesh[], options?: WorkerOptions<AtlasOptions>): Promise<SharedAtlas>;
  /** Stops the running work: pending calls reject with 'cancelled'; meshes are rebuilt when next used. */
  cancel(): void;
  /** Ends the worker for good: pending and later calls reject with 'cancelled'. */
  terminate(): void;
  /** The same as terminate(): `await using st = await createStraightestWorker()` ends it with the scope. */
  [Symbol.asyncDispose](): Promise<void>;
}

/**
 * createStraightestWorker's options: where the worker and the WebAssembly module come from. A wasmUrl
 * (string or URL) is resolved against the page, not the worker's script.
 */
export interface WorkerCreateOptions extends Pick<CreateOptions, 'threads' | 'wasmUrl' | 'wasmBinary' | 'warmUp'> {
  /** Makes the module worker (running the package's wasm/worker-entry.js); called again after each cancel. */
  createWorker?: () => Worker;
}

/**
 * Starts the worker and loads the module in it. A worker whose script does not load rejects with
 * StraightestError 'io' naming its URL and what fetching it gives (status, content type).
 */
export function createStraightestWorker(options?: WorkerCreateOptions): Promise<StraightestWorker>;
