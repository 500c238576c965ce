#include "straightest/parameterize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "straightest/geodesic_distance.hpp"
#include "straightest/straightest_path.hpp"

namespace straightest {
namespace {

/// Solves u_i = Σ λ_ij u_j for the interior with the boundary fixed; u and v together. Returns the
/// relative residual.
Expected<double> solveInterior(const TriMesh& mesh, const InteriorWeights& W, const BoundaryMap& boundary,
                               LinearSolver solver, std::vector<Vec2>& uv, const Progress& progress) {
  const int32_t nv = mesh.numVertices();
  uv.assign(nv, Vec2{0, 0});
  for (size_t i = 0; i < boundary.loop.size(); ++i) uv[boundary.loop[i]] = boundary.polygon[i];
  const auto n = static_cast<int32_t>(W.rows.size());
  if (n == 0) return 0.0;
  InteriorSystem system = assembleInteriorSystem(W, uv);
  // Initial guess for iterative solvers: the boundary's centroid (inside the convex polygon).
  std::vector<double> x(2 * static_cast<size_t>(n));
  double cx = 0, cy = 0;
  for (const Vec2& q : boundary.polygon) {
    cx += q[0];
    cy += q[1];
  }
  for (int32_t r = 0; r < n; ++r) {
    x[2 * r] = cx / boundary.polygon.size();
    x[2 * r + 1] = cy / boundary.polygon.size();
  }
  auto solved = solve(std::move(system.A), system.rhs, x, solver, progress);
  if (!solved) return solved.error();
  for (int32_t r = 0; r < n; ++r) uv[W.rows[r]] = {x[2 * r], x[2 * r + 1]};
  return solved.value().residual;
}

/// Scales uv (and the polygon) into [0, 1]² keeping the aspect ratio, over referenced vertices.
void normalizeIntoUnitSquare(const TriMesh& mesh, std::vector<Vec2>& uv, std::vector<Vec2>& polygon) {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    if (mesh.vertexHalfedge(v) < 0) continue;
    for (int c = 0; c < 2; ++c) {
      lo[c] = std::min(lo[c], uv[v][c]);
      hi[c] = std::max(hi[c], uv[v][c]);
    }
  }
  const double scale = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(scale > 0)) return;
  auto map = [&](Vec2& q) { q = {(q[0] - lo[0]) / scale, (q[1] - lo[1]) / scale}; };
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    if (mesh.vertexHalfedge(v) < 0) uv[v] = {0, 0};
    else map(uv[v]);
  }
  for (Vec2& q : polygon) map(q);
}

}  // namespace

Expected<bool> requireDisk(const TriMesh& mesh) {
  const MeshSummary& s = mesh.summary();
  if (s.boundaryLoopSizes.size() == 1 && s.eulerCharacteristic == 1 && s.components == 1) return true;
  std::string found = std::to_string(s.boundaryLoopSizes.size()) + " boundary loop" +
                      (s.boundaryLoopSizes.size() == 1 ? "" : "s") + ", Euler characteristic " +
                      std::to_string(s.eulerCharacteristic) + ", " + std::to_string(s.components) + " component" +
                      (s.components == 1 ? "" : "s");
  if (s.boundaryLoopSizes.empty()) found = "a closed surface (" + found + ")";
  return Error{ErrorCode::Topology,
               "parameterization needs a disk (one boundary loop, Euler characteristic 1, "
               "one component); found " +
                   found};
}

bool preferredMap(double l2, int64_t badTriangles, double incumbentL2, int64_t incumbentBadTriangles) {
  const bool bijective = std::isfinite(l2), incumbentBijective = std::isfinite(incumbentL2);
  if (bijective != incumbentBijective) return bijective;
  if (bijective) return l2 < incumbentL2;
  return badTriangles < incumbentBadTriangles;
}

Expected<SurfacePoint> interiorSource(const TriMesh& mesh, const std::optional<SurfacePoint>& source) {
  auto given = resolveSource(mesh, source);
  if (!given || !source) return given;  // the default source is an interior vertex
  // The tracer moves a source within kSnapSource of an edge or vertex onto it; check the point it
  // will really use (a point 2e-8 from the boundary would otherwise become a boundary vertex).
  const SurfacePoint s = canonical(mesh, given.value(), kSnapSource);
  const bool onBoundary = (s.kind == SurfacePoint::Kind::Vertex && mesh.isBoundaryVertex(s.index)) ||
                          (s.kind == SurfacePoint::Kind::Edge && mesh.twin(s.index) < 0);
  if (onBoundary)
    return Error{ErrorCode::InvalidArgument,
                 std::string("the source must be an interior point: ") +
                     (s.kind == SurfacePoint::Kind::Vertex ? "vertex " : "edge ") + std::to_string(s.index) +
                     " is on the boundary" +
                     (s.kind != given.value().kind ? " (the given point is within 1e-6 of it)" : "")};
  return s;
}

Expected<Parameterization> parameterize(const TriMesh& mesh, const ParamOptions& options, const Progress& progress) {
  const Error cancelled = cancelledError("parameterization");
  Timings* timings = options.timings;
  for (const char* stage : {"source", "trace", "boundary", "weights", "solve", "metrics", "total"})
    record(timings, stage, 0);  // every stage listed, in this order, whether it runs or not
  const Stopwatch total;
  auto disk = requireDisk(mesh);
  if (!disk) return disk.error();
  Parameterization result;
  result.weights = options.weights;

  if (!report(progress, "source", 0)) return cancelled;
  Stopwatch stage;
  const bool needsSource = !options.boundary || *options.boundary == BoundaryKind::Measured;
  if (needsSource) {
    auto s = interiorSource(mesh, options.source);
    if (!s) return s.error();
    result.source = s.value();
  } else {
    auto s = resolveSource(mesh, options.source);
    if (!s) return s.error();
    result.source = options.source ? canonical(mesh, s.value(), kSnapSource) : s.value();
  }
  record(timings, "source", stage.lap());

  std::vector<BoundaryMap> boundaries;
  Timings traceTime;
  if (needsSource) {
    auto m = measuredBoundary(mesh, result.source, progress, &traceTime);
    if (!m && m.error().code == ErrorCode::Cancelled) return m.error();
    if (m) boundaries.push_back(std::move(m).value());
    else if (options.boundary) return m.error();
  }
  if (!options.boundary || *options.boundary == BoundaryKind::Circle) boundaries.push_back(circleBoundary(mesh));
  if (!options.boundary || *options.boundary == BoundaryKind::Square) boundaries.push_back(squareBoundary(mesh));
  record(timings, "trace", traceTime["trace"]);
  record(timings, "boundary", stage.lap() - traceTime["trace"]);

  if (!report(progress, "weights", 0)) return cancelled;
  const InteriorWeights W = interiorWeights(mesh, options.weights);
  result.weightFallbacks = W.uniformFallbacks;
  record(timings, "weights", stage.lap());

  bool haveBest = false;
  for (BoundaryMap& boundary : boundaries) {
    stage.lap();
    std::vector<Vec2> uv;
    const auto solved = solveInterior(mesh, W, boundary, options.solver, uv, progress);
    if (!solved) return solved.error().code == ErrorCode::Cancelled ? cancelled : solved.error();
    const double residual = solved.value();
    record(timings, "solve", stage.lap());
    if (!report(progress, "metrics", 0)) return cancelled;
    StretchMetrics metrics = textureStretch(mesh, uv);
    record(timings, "metrics", stage.lap());
    result.candidates.push_back({boundary.kind, metrics.l2, metrics.linf, metrics.flipped, metrics.degenerate});
    if (!haveBest || preferredMap(metrics.l2, metrics.flipped + metrics.degenerate, result.metrics.l2,
                                  result.metrics.flipped + result.metrics.degenerate)) {
      haveBest = true;
      result.boundary = boundary.kind;
      result.uv = std::move(uv);
      result.boundaryPolygon = boundary.polygon;
      result.boundaryLoop = boundary.loop;
      result.metrics = std::move(metrics);
      result.fallbacks = boundary.fallbacks;
      result.outliers = boundary.outliers;
      result.residual = residual;
    }
  }
  if (!haveBest) return Error{ErrorCode::Topology, "no boundary map could be built"};
  normalizeIntoUnitSquare(mesh, result.uv, result.boundaryPolygon);
  report(progress, "metrics", 1.0);
  record(timings, "total", total.ms());
  return result;
}

}  // namespace straightest
