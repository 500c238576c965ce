// Types of the straightest npm package (ESM). See README.md for usage.

export type MeshFormat = 'auto' | 'obj' | 'off';

/** Caps checked before building a mesh (defaults: 50M vertices, 100M faces). */
export interface BuildLimits {
  maxVertices?: number;
  maxFaces?: number;
}

export interface MeshInfo {
  vertices: number;
  faces: number;
  edges: number;
  /** Sizes of the boundary loops, longest first (empty for a closed mesh). */
  boundaryLoops: number[];
  eulerCharacteristic: number;
  components: number;
  degenerateFaces: number;
  reorientedFaces: number;
  unreferencedVertices: number;
  bbox: { min: [number, number, number]; max: [number, number, number] };
  /** Human-readable notes on what was found and repaired. */
  problems: string[];
}

/** Error categories: see core/include/straightest/error.hpp. */
export type ErrorCategory =
  | 'io' | 'unsupported_format' | 'parse' | 'empty' | 'too_large' | 'non_finite' | 'index_out_of_range'
  | 'invalid_face' | 'duplicate_face' | 'non_manifold_edge' | 'non_manifold_vertex' | 'non_orientable'
  | 'topology' | 'invalid_argument' | 'internal';

export class StraightestError extends Error {
  readonly category: ErrorCategory;
}

export class Mesh {
  info(): MeshInfo;
  /** x, y, z per vertex (a copy). */
  positions(): Float64Array;
  /** 3 vertex indices per triangle (a copy). */
  indices(): Uint32Array;
  readonly deleted: boolean;
  /** Frees the WASM memory; any later call throws. */
  delete(): void;
}

export class Straightest {
  loadMesh(data: Uint8Array | ArrayBuffer | ArrayBufferView | string, format?: MeshFormat, limits?: BuildLimits): Mesh;
  meshFromArrays(positions: ArrayLike<number>, indices: ArrayLike<number>, limits?: BuildLimits): Mesh;
  sampleNames(): string[];
  sample(name: 'mountain' | 'cap' | 'saddle' | 'face' | string): Mesh;
  readonly memoryBytes: number;
}

export interface CreateOptions {
  /** URL of straightest-core.wasm when it is not served next to the module (bundlers, CDNs). */
  wasmUrl?: string | URL;
  /** Emscripten's locateFile hook. */
  locateFile?: (name: string, scriptDirectory: string) => string;
  /** The .wasm bytes, to skip fetching. */
  wasmBinary?: ArrayBuffer | Uint8Array;
}

export function createStraightest(options?: CreateOptions): Promise<Straightest>;
