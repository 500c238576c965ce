// parameterize.hpp — a disk mesh mapped to the plane: a boundary map (measured, circle, square,
// free, or auto: all four, keeping the preferred one by preferredMap) and interior convex-combination
// weights, solved for u and v together (linear_solve.hpp: multigrid-preconditioned BiCGSTAB by
// default); judged with texture stretch. The free boundary starts from a fixed one — the measured
// map where it is bijective, otherwise the circle's (reported as `init`) — and lets every vertex,
// boundary included, move to lower the symmetric Dirichlet energy without ever folding
// (free_boundary.hpp).
//
// Topology: every manifold mesh. A single connected disk (one boundary loop, Euler characteristic 1)
// is mapped as it is; anything else is first made a disk by disk_cut.hpp (the largest component; holes
// filled virtually with the longest loop as the outer boundary; closed and higher-genus surfaces cut
// along a seam) and the disk is parameterized, virtual vertices and faces dropped from the output. The
// result then says how (`cut`), and its map is per face corner (`cornerUv`: a seam vertex has one uv per
// side). The source (measured and free boundaries) must be an interior point of the mesh and of the disk
// (not on the seam: an InvalidArgument error); the default source is the disk's (defaultSource), or when
// that is a filled hole's centre, the real vertex farthest inside the disk. The stretch is measured on
// the real faces only; the free boundary refines the real faces from the filled solve's map, holes free
// (free_boundary.hpp says why that stays bijective). boundaryPolygons and compareParameterizations cut
// the same way. Progress stage "cut" comes first (and the timing "cut", 0 for a disk). UVs are scaled into [0, 1]² by
// their bounding box (aspect kept); unreferenced vertices get (0, 0). With convex-combination weights (all but cotan)
// and a fixed boundary the interior lies inside the convex boundary polygon, so that box is the polygon's
// (unitSquareFrame): boundary_polygons.hpp gives every fixed polygon in this frame without a solve. The free boundary's
// polygon is the refined loop's uv (not convex), known only after the refinement.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "straightest/base/timings.hpp"
#include "straightest/cut/disk_cut.hpp"
#include "straightest/param/boundary_map.hpp"
#include "straightest/param/free_boundary.hpp"
#include "straightest/param/interior_weights.hpp"
#include "straightest/param/texture_stretch.hpp"
#include "straightest/solver/linear_solve.hpp"

namespace straightest {

struct ParamOptions {
  std::optional<SurfacePoint> source;                             // nullopt: the default source
  std::optional<BoundaryKind> boundary = BoundaryKind::Measured;  // nullopt: auto
  WeightKind weights = WeightKind::ShapePreserving;
  LinearSolver solver = LinearSolver::Multigrid;
  FreeBoundaryOptions free;  // the refinement's iteration cap, tolerance and time budget (boundary free and auto)
  /// When set, receives "cut", "source", "trace", "boundary", "weights", "solve", "refine", "metrics"
  /// and "total" (every one, 0 for a stage that did not run).
  Timings* timings = nullptr;
};

struct BoundaryCandidate {
  BoundaryKind kind;
  double l2, linf;
  int64_t flipped, degenerate;
  int64_t overlaps;  // crossing pairs of boundary edges (only a free boundary can have any)
};

/// The one rule that picks a map among candidates (boundary 'auto' and the comparison's best): a
/// bijective map (finite L2 stretch) beats any other; among bijective maps the lower L2 stretch wins;
/// among non-bijective ones the fewer flipped + degenerate triangles. Ties keep the incumbent (so
/// the earlier candidate in measured, circle, square, free order).
bool preferredMap(double l2, int64_t badTriangles, double incumbentL2, int64_t incumbentBadTriangles);

struct Parameterization {
  SurfacePoint source;
  BoundaryKind boundary = BoundaryKind::Measured;
  WeightKind weights = WeightKind::ShapePreserving;
  std::vector<Vec2> uv;               // per vertex, in [0, 1]²
  std::vector<Vec2> boundaryPolygon;  // the chosen boundary, in the same [0, 1]² frame as uv
  std::vector<int32_t> boundaryLoop;
  StretchMetrics metrics;
  int64_t fallbacks = 0;                      // failed traces that used the geodesic-estimate radius (measured)
  int64_t outliers = 0;                       // reached traces too long to trust, radius replaced (measured)
  int64_t weightFallbacks = 0;                // vertices whose weights fell back to uniform
  double residual = 0;                        // relative residual of the linear solve
  std::vector<BoundaryCandidate> candidates;  // every map solved: auto's four; free's start(s) and itself
  // The free-boundary refinement (boundary free, or auto when it kept the free map); init is nullopt
  // for a fixed boundary and the other fields are then meaningless.
  std::optional<BoundaryKind> init;  // the fixed boundary the refinement started from: measured or circle
  int32_t iterations = 0;            // refinement iterations (FreeBoundaryResult)
  double energyInitial = 0;          // symmetric Dirichlet energy per unit area of the start (+inf if it folds)
  double energyFinal = 0;            // of the result: 4 for an isometry
  bool converged = false;            // stopped by the relative-decrease rule (not the cap or the time budget)
  bool untangled = false;            // the start had flipped or degenerate triangles and was untangled first

  // How the mesh was made a disk (disk_cut.hpp) and the map per face corner. For a disk: cut Disk,
  // cornerUv[3f + k] = uv[triangle(f)[k]], no seam. Otherwise uv holds, per mesh vertex, the uv of one of
  // its copies (a seam vertex has several: cornerUv has each face's own), (0, 0) for vertices outside
  // the parameterized component; boundaryLoop, boundaryPolygon and metrics.faceStretch are over the
  // mesh's vertices and faces (faces outside the component: stretch NaN, cornerUv NaN).
  CutMethod cut = CutMethod::Disk;
  std::vector<Vec2> cornerUv;                // 3 per mesh face, in [0, 1]² like uv
  std::vector<std::array<int32_t, 2>> seam;  // mesh edges cut open (vertex pairs)
  std::vector<int32_t> filledLoops;          // indices into mesh.boundaryLoops() filled virtually
  int32_t genus = 0;
  double seamLength = 0;
  int32_t component = 0, components = 1;  // which component was parameterized, of how many
  int64_t virtualVertices = 0;            // vertices added by filling (never in the output)
};

/// Checks that the mesh is a single disk (message says what was found otherwise): the fixed-boundary
/// polygons and the free refinement of a given start need one; parameterize does not.
Expected<void> requireDisk(const TriMesh& mesh);

/// The source the measured boundary is centred on: resolveSource, then moved onto an edge or vertex
/// within kSnapSource as the tracer will; an InvalidArgument error when that point is on the boundary.
Expected<SurfacePoint> interiorSource(const TriMesh& mesh, const std::optional<SurfacePoint>& source);

/// Progress stages: "source", "trace", "weights", "solve", "metrics" (auto: "trace" once, then "solve"
/// and "metrics" per fixed candidate), then for free and auto "refine" and "metrics". Free solves the
/// measured map, then the circle's only when the measured one is not bijective; auto refines the one
/// of its maps that rule picks (no second solve). Cancelling returns a Cancelled error.
Expected<Parameterization> parameterize(const TriMesh& mesh, const ParamOptions& options,
                                        const Progress& progress = {});

/// The free boundary refined from a fixed-boundary parameterization already computed (what
/// parameterize does after its solve, for a caller that holds the start, e.g. the comparison). The
/// result has boundary Free, init = start.boundary, the start's source, weights, loop, fallbacks
/// and residual, and its candidates plus the free one. Records "refine" and "metrics" in `timings`.
/// A start whose cut is not Disk (parameterize cut or filled the mesh) is refined on the same disk
/// (cutToDisk again: it is deterministic; its cornerUv placed on the disk, the real faces refined with
/// the holes free) and mapped back like parameterize's result. Errors: Topology (a start of cut Disk
/// on a mesh that is not one), InvalidArgument (a start that is itself free, or of the wrong size),
/// Cancelled.
Expected<Parameterization> refineParameterization(const TriMesh& mesh, const Parameterization& start,
                                                  const FreeBoundaryOptions& options = {},
                                                  const Progress& progress = {}, Timings* timings = nullptr);

}  // namespace straightest
