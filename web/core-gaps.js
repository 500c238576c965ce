// What the page still derives itself although it is the core's to compute: each piece behind one
// small function here, called by the worker only (the page draws the worker's replies), so that
// switching a piece to the core's own call is a one-line change in worker.js and this file can
// shrink to nothing. No DOM, no three.js.

// ------------------------------------------------------------------ enum name lists

/** The boundary kinds of mesh.parameterize() ('auto' aside), in the page's display order. */
export const BOUNDARY_KINDS = ['measured', 'circle', 'square'];
/** The interior weights of mesh.parameterize(). */
export const WEIGHT_KINDS = ['shape-preserving', 'mean-value', 'cotan', 'uniform'];

// ------------------------------------------------------------------ files (worker)

/** The loadMesh format of a file name: 'obj' or 'off' by its extension, else 'auto' (sniffed). */
export function formatFromFileName(name) {
  const ext = /\.([^.]+)$/.exec(name ?? '')?.[1]?.toLowerCase();
  return ext === 'obj' || ext === 'off' ? ext : 'auto';
}

// ------------------------------------------------------------------ mesh data (worker)

/** Area-weighted vertex normals of `mesh`, unit length (zero for unreferenced vertices), as Float32. */
export function vertexNormals(mesh) {
  const positions = mesh.positions();
  const indices = mesh.indices();
  const sums = new Float64Array(positions.length);
  for (let f = 0; f < indices.length; f += 3) {
    const a = 3 * indices[f];
    const b = 3 * indices[f + 1];
    const c = 3 * indices[f + 2];
    const ux = positions[b] - positions[a];
    const uy = positions[b + 1] - positions[a + 1];
    const uz = positions[b + 2] - positions[a + 2];
    const vx = positions[c] - positions[a];
    const vy = positions[c + 1] - positions[a + 1];
    const vz = positions[c + 2] - positions[a + 2];
    // The cross product's length is twice the face area: the sum weights the faces by area.
    const nx = uy * vz - uz * vy;
    const ny = uz * vx - ux * vz;
    const nz = ux * vy - uy * vx;
    sums[a] += nx; sums[a + 1] += ny; sums[a + 2] += nz;
    sums[b] += nx; sums[b + 1] += ny; sums[b + 2] += nz;
    sums[c] += nx; sums[c + 1] += ny; sums[c + 2] += nz;
  }
  const normals = new Float32Array(positions.length);
  for (let v = 0; v < sums.length; v += 3) {
    const length = Math.hypot(sums[v], sums[v + 1], sums[v + 2]);
    if (length > 0) for (let c = 0; c < 3; c++) normals[v + c] = sums[v + c] / length;
  }
  return normals;
}

/**
 * The vertices of the longest boundary loop of a mesh with a boundary: the targets the core's
 * 'boundary' stands for. Learned here by tracing every boundary path once without points.
 */
export function boundaryVertices(mesh, source) {
  return mesh.straightestPaths({ source, targets: 'boundary', points: false }).targets;
}

/**
 * The boundary polygons of `kinds` around `source` in the [0,1]² frame of the parameterization:
 * [{ boundary, polygon: Float32Array | null, error: string | null }]. A polygon depends only on the
 * boundary kind and the source, so this solves once per kind with the cheapest weights; `known`
 * ({ boundary, polygon } of a parameterization already made) saves its solve. onStep(done, total)
 * is told before each solve.
 */
export function boundaryPolygons(mesh, source, kinds, known, onStep) {
  const others = kinds.filter((kind) => kind !== known?.boundary).length;
  let done = 0;
  return kinds.map((boundary) => {
    if (boundary === known?.boundary) return { boundary, polygon: Float32Array.from(known.polygon), error: null };
    onStep(done++, others);
    try {
      const { boundaryPolygon } = mesh.parameterize({ source, boundary, weights: 'uniform' });
      return { boundary, polygon: Float32Array.from(boundaryPolygon), error: null };
    } catch (err) {
      return { boundary, polygon: null, error: err?.message ?? String(err) };
    }
  });
}

/**
 * Every boundary kind with every weights on `mesh` from `source`: { rows, best } with rows
 * [{ boundary, weights, l2, linf, flipped, degenerate, bijective, timeMs, error }] (a cell that
 * fails has error set and no numbers) and best the row the page highlights (see bestRow).
 * onRow(done, total) is told after each cell.
 */
export function compareParameterizations(mesh, source, onRow) {
  const total = BOUNDARY_KINDS.length * WEIGHT_KINDS.length;
  const rows = [];
  for (const boundary of BOUNDARY_KINDS) {
    for (const weights of WEIGHT_KINDS) {
      const start = performance.now();
      try {
        const { stretch, flipped, degenerate, bijective } = mesh.parameterize({ source, boundary, weights });
        rows.push({
          boundary, weights, l2: stretch.l2, linf: stretch.linf, flipped, degenerate, bijective,
          timeMs: performance.now() - start, error: null,
        });
      } catch (err) {
        rows.push({ boundary, weights, timeMs: performance.now() - start, error: err?.message ?? String(err) });
      }
      onRow(rows.length, total);
    }
  }
  return { rows, best: bestRow(rows) };
}

/** The best row of a comparison: the least finite L2 stretch among the cells that worked. */
function bestRow(rows) {
  let best = null;
  for (const row of rows) if (!row.error && Number.isFinite(row.l2) && (!best || row.l2 < best.l2)) best = row;
  return best;
}

/** The core's stages of mesh.parameterize() for `boundary`, in order (the progress panel's plan). */
export function parameterizeStages(boundary) {
  const traced = ['measured', 'auto', undefined].includes(boundary); // only these trace paths
  return ['source', ...(traced ? ['trace'] : []), 'weights', 'solve', 'metrics'];
}

// ------------------------------------------------------------------ path data (worker)

/**
 * Per path, the in-plane direction of its cutting plane (x, y, z each; NaN × 3 where undefined): the
 * unit vector from the source S towards the destination D with its component along the base normal
 * n removed (the plane is spanned by n and it). D is the target's position, or the path's end when
 * the core could not place the target; D − S parallel to n (relative to `scale`) has none.
 */
export function pathDirections(result, scale) {
  const { sourcePosition: s, normal: n0, targetPositions, points, offsets, count } = result;
  const nLength = Math.hypot(...n0);
  const n = n0.map((c) => c / nLength);
  const directions = new Float32Array(3 * count).fill(NaN);
  for (let i = 0; i < count; i++) {
    const target = targetPositions.subarray(3 * i, 3 * i + 3);
    const end = 3 * offsets[i + 1];
    if (!Number.isFinite(target[0]) && end === 3 * offsets[i]) continue; // no point to aim at
    const d = Number.isFinite(target[0]) ? target : points.subarray(end - 3, end);
    const along = [d[0] - s[0], d[1] - s[1], d[2] - s[2]];
    const dot = along[0] * n[0] + along[1] * n[1] + along[2] * n[2];
    for (let c = 0; c < 3; c++) along[c] -= dot * n[c];
    const length = Math.hypot(...along);
    if (length < 1e-9 * scale) continue;
    for (let c = 0; c < 3; c++) directions[3 * i + c] = along[c] / length;
  }
  return directions;
}

/**
 * The summary of a set of paths: { count, reached, byStatus: { status: count } of the failed ones,
 * meanLength and maxLength of the reached paths (0 without any), facesCrossed sum and max }.
 */
export function pathSummary({ count, reached, statuses, lengths, facesCrossed }) {
  const byStatus = {};
  let sum = 0;
  let maxLength = 0;
  statuses.forEach((status, i) => {
    if (status !== 'reached') {
      byStatus[status] = (byStatus[status] ?? 0) + 1;
      return;
    }
    sum += lengths[i];
    maxLength = Math.max(maxLength, lengths[i]);
  });
  let facesSum = 0;
  let facesMax = 0;
  for (const n of facesCrossed) {
    facesSum += n;
    facesMax = Math.max(facesMax, n);
  }
  return { count, reached, byStatus, meanLength: reached ? sum / reached : 0, maxLength, facesSum, facesMax };
}
