// parameterize.hpp — a disk mesh mapped to the plane: a boundary map (measured, circle, square, or
// auto: all three, keeping the preferred one by preferredMap) and interior convex-combination
// weights, solved for u and v together (linear_solve.hpp: multigrid-preconditioned BiCGSTAB by
// default); judged with texture stretch.
//
// Topology: a single connected disk (one boundary loop, Euler characteristic 1); anything else is a
// Topology error naming what was found. The source (measured boundary) must be an interior point.
// UVs are scaled into [0, 1]² by their bounding box (aspect kept); unreferenced vertices get (0, 0).
// With convex-combination weights (all but cotan) the interior lies inside the convex boundary
// polygon, so that box is the polygon's (unitSquareFrame): boundary_polygons.hpp gives every
// polygon in this frame without a solve.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "straightest/boundary_map.hpp"
#include "straightest/interior_weights.hpp"
#include "straightest/linear_solve.hpp"
#include "straightest/texture_stretch.hpp"
#include "straightest/timings.hpp"

namespace straightest {

/// A boundary kind, or "auto" (nullopt: try every kind and keep the preferred map). One enum plus
/// "auto" rather than a second enum that repeats the kinds: every list of kinds (name tables, the
/// comparison, the polygons) is then a list of BoundaryKind, and "auto" reads the same as the
/// source's "auto" (nullopt).
Expected<std::optional<BoundaryKind>> parseBoundaryChoice(const std::string& name);
Expected<WeightKind> parseWeightKind(const std::string& name);

struct ParamOptions {
  std::optional<SurfacePoint> source;                             // nullopt: the default source
  std::optional<BoundaryKind> boundary = BoundaryKind::Measured;  // nullopt: auto
  WeightKind weights = WeightKind::ShapePreserving;
  LinearSolver solver = LinearSolver::Multigrid;
  /// When set, receives "source", "trace", "boundary", "weights", "solve", "metrics" and "total"
  /// (every one, 0 for a stage that did not run).
  Timings* timings = nullptr;
};

struct BoundaryCandidate {
  BoundaryKind kind;
  double l2, linf;
  int64_t flipped, degenerate;
};

/// The one rule that picks a map among candidates (boundary 'auto' and the comparison's best): a
/// bijective map (finite L2 stretch) beats any other; among bijective maps the lower L2 stretch wins;
/// among non-bijective ones the fewer flipped + degenerate triangles. Ties keep the incumbent (so
/// the earlier candidate in measured, circle, square order).
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
  std::vector<BoundaryCandidate> candidates;  // auto: every boundary tried
};

/// Checks that the mesh is a single disk (message says what was found otherwise).
Expected<bool> requireDisk(const TriMesh& mesh);

/// The source the measured boundary is centred on: resolveSource, then moved onto an edge or vertex
/// within kSnapSource as the tracer will; an InvalidArgument error when that point is on the boundary.
Expected<SurfacePoint> interiorSource(const TriMesh& mesh, const std::optional<SurfacePoint>& source);

/// Progress stages: "source", "trace", "weights", "solve", "metrics" (auto: "trace" once, then "solve"
/// and "metrics" per candidate). Cancelling returns a Cancelled error.
Expected<Parameterization> parameterize(const TriMesh& mesh, const ParamOptions& options,
                                        const Progress& progress = {});

}  // namespace straightest
