// parameterize.hpp — a disk mesh mapped to the plane: a boundary map (measured, circle, square, or
// auto: all three, keeping the one with the lowest L2 stretch) and interior convex-combination
// weights, solved for u and v together (linear_solve.hpp: multigrid by default); judged with texture
// stretch.
//
// Topology: a single connected disk (one boundary loop, Euler characteristic 1); anything else is a
// Topology error naming what was found. The source (measured boundary) must be an interior point.
// UVs are scaled into [0, 1]² keeping the aspect ratio; unreferenced vertices get (0, 0).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "straightest/boundary_map.hpp"
#include "straightest/interior_weights.hpp"
#include "straightest/linear_solve.hpp"
#include "straightest/texture_stretch.hpp"

namespace straightest {

enum class BoundaryChoice { Measured, Circle, Square, Auto };
Expected<BoundaryChoice> parseBoundaryChoice(const std::string& name);
Expected<WeightKind> parseWeightKind(const std::string& name);

struct ParamOptions {
  bool autoSource = true;
  SurfacePoint source;  // when !autoSource
  BoundaryChoice boundary = BoundaryChoice::Measured;
  WeightKind weights = WeightKind::ShapePreserving;
  LinearSolver solver = LinearSolver::Multigrid;
};

struct BoundaryCandidate {
  BoundaryKind kind;
  double l2, linf;
  int64_t flipped, degenerate;
};

struct ParamTimings {
  double source = 0, trace = 0, boundary = 0, weights = 0, solve = 0, metrics = 0, total = 0;
};

struct Parameterization {
  SurfacePoint source;
  BoundaryKind boundary = BoundaryKind::Measured;
  WeightKind weights = WeightKind::ShapePreserving;
  std::vector<Vec2> uv;               // per vertex, in [0, 1]²
  std::vector<Vec2> boundaryPolygon;  // the chosen boundary, in the same [0, 1]² frame as uv
  std::vector<int32_t> boundaryLoop;
  StretchMetrics metrics;
  int64_t fallbacks = 0;              // failed traces that used the Dijkstra radius (measured)
  int64_t weightFallbacks = 0;        // vertices whose weights fell back to uniform
  double residual = 0;                // relative residual of the linear solve
  std::vector<BoundaryCandidate> candidates;  // auto: every boundary tried
  ParamTimings timingsMs;
};

/// Checks that the mesh is a single disk (message says what was found otherwise).
Expected<bool> requireDisk(const TriMesh& mesh);

/// Progress stages: "source", "trace", "weights", "solve", "metrics" (auto: "trace" once, then "solve"
/// and "metrics" per candidate). Cancelling returns a Cancelled error.
Expected<Parameterization> parameterize(const TriMesh& mesh, const ParamOptions& options,
                                        const Progress& progress = {});

}  // namespace straightest
