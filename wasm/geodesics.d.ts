// The npm package's types for the two comparison geodesics of the paper: Polthier–Schmies shooting
// (Mesh.shootGeodesic) and exact shortest paths (Mesh.exactShortestPaths). Re-exported by index.d.ts.
import type { ProgressCallback, SurfacePoint, SurfacePointObject, TargetName } from './index.js';

/**
 * How a geodesic shot ended: 'reached_length' (walked the whole length: the only success),
 * 'hit_boundary' (met a boundary edge or vertex first), 'step_limit' (more steps than the bound),
 * 'no_exit' (no face continues the path: a degenerate neighbourhood).
 */
export type ShootStatus = 'reached_length' | 'hit_boundary' | 'step_limit' | 'no_exit';

/**
 * How shootGeodesic is aimed: exactly one of direction, angle or toward (more or none throws
 * 'invalid_argument', as do a zero or non-finite direction, a non-finite angle and a length ≤ 0).
 */
export interface ShootGeodesicOptions {
  /** Default 'auto': the interior vertex farthest from the boundary. */
  source?: SurfacePoint | 'auto';
  /** A 3D direction [x, y, z], projected onto the tangent plane at the source (its normal: `normal`). */
  direction?: [number, number, number];
  /**
   * Radians in the source's tangent frame, counter-clockwise about the normal; 0 is the reference edge
   * projected (a vertex's first outgoing halfedge, an edge point's halfedge, a face's first edge).
   */
  angle?: number;
  /**
   * A destination: the path starts where the cutting plane toward it would (the base plane's direction
   * to it) and the result says how close it passes (missDistance).
   */
  toward?: SurfacePoint;
  /**
   * The length to walk: required with direction or angle; with toward it defaults to the cutting
   * plane's straightest distance to the destination (throws 'invalid_argument' if the plane does not
   * reach it: then give a length).
   */
  length?: number;
  /** Return the path's points (default true). */
  points?: boolean;
  /** Called with ('shoot', fraction of the length) on long walks; return false to cancel (throws 'cancelled'). */
  onProgress?: ProgressCallback;
}

/** shootGeodesic's result: a straightest geodesic (Polthier–Schmies) walked from a source. */
export interface GeodesicShot {
  /** The source used ('auto' resolved; snapped onto a vertex or edge as the tracer snaps). */
  source: SurfacePointObject;
  /** 3D position of the source. */
  sourcePosition: [number, number, number];
  /** Unit normal of the tangent plane at the source (the base plane's with toward). */
  normal: [number, number, number];
  /** The unit direction the path leaves in (3D, in the plane of the first face). */
  direction: [number, number, number];
  status: ShootStatus;
  /** The length asked for (toward without a length: the cutting plane's straightest distance). */
  requestedLength: number;
  /** The length walked: requestedLength unless the walk stopped early (see status). */
  length: number;
  /** Segments walked (one per face crossed). */
  facesCrossed: number;
  /** Times the path went through a vertex (leaving with equal angles on both sides). */
  vertexPassings: number;
  /** Where the walk ended. */
  end: SurfacePointObject;
  /** 3D position of the end. */
  endPosition: [number, number, number];
  /** With toward: the destination's 3D position; null otherwise. */
  target: [number, number, number] | null;
  /**
   * With toward: the cutting plane's straightest distance to the destination (NaN when a length was
   * given and the plane does not reach it); null otherwise.
   */
  straightestDistance: number | null;
  /** With toward: the closest 3D distance of the path to the destination (0 when it passes through); null otherwise. */
  missDistance: number | null;
  /** Packed x, y, z of the path: the source, every edge crossing and vertex passed, the end (empty when points: false). */
  points: Float64Array;
  /** Milliseconds spent (with toward, including the cutting-plane trace it starts from). */
  timings: { shoot: number };
}

export interface ExactShortestPathsOptions {
  /** Default 'auto': the interior vertex farthest from the boundary. */
  source?: SurfacePoint | 'auto';
  /**
   * Vertices only: default 'boundary' (the longest loop's), 'all-boundaries', or an array of vertex
   * indices / {vertex} and those names; a face or edge point throws 'invalid_argument'.
   */
  targets?: TargetName | (number | { vertex: number } | TargetName)[];
  /** Return each target's polyline (default true). */
  points?: boolean;
  /** Called with ('distances', fraction of the vertices reached); return false to cancel (throws 'cancelled'). */
  onProgress?: ProgressCallback;
}

/** What the window propagation behind exactShortestPaths cost. */
export interface ExactGeodesicStats {
  /** Windows created (after the filter). */
  windows: number;
  /** Windows the filter dropped (a face corner offered a shorter route to all of it). */
  filtered: number;
  /** The queue's peak (windows and pseudo-source events): the memory that matters. */
  maxQueue: number;
  /** Pseudo-source (saddle or boundary vertex) emissions. */
  pseudoSources: number;
}

/** exactShortestPaths' result: one entry per target in targets and distances. */
export interface ExactShortestPaths {
  /** The source, resolved ('auto' becomes the vertex it chose). */
  source: SurfacePointObject;
  method: 'exact';
  /** The target vertices ('boundary' expanded). */
  targets: Int32Array;
  /** The exact geodesic distance to each target (the polyline's length; Infinity where unreachable). */
  distances: Float64Array;
  /** Number of targets. */
  count: number;
  /**
   * Packed x, y, z of every shortest path (the source, edge crossings and the saddle or boundary
   * vertices it bends at, the target); path i is points [3·offsets[i], 3·offsets[i+1]) — empty where
   * unreachable, and all empty when points: false.
   */
  points: Float32Array;
  /** count + 1 offsets into points (in points, not floats); empty when points: false. */
  offsets: Uint32Array;
  exact: ExactGeodesicStats;
  /** Milliseconds: the propagation, and the back-tracing (absent when points: false). */
  timings: { distances: number; paths?: number };
}
