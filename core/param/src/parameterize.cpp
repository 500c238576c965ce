// parameterize.cpp — the parameterization pipeline: boundary, weights, solve, stretch, and the best-map rule.
#include "straightest/param/parameterize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "parameterize_cut.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/paths/straightest_path.hpp"

namespace straightest {
namespace {

/// Solves u_i = Σ λ_ij u_j for the interior with the boundary fixed; u and v together. Returns the
/// relative residual. lastUse: no other boundary will be solved with W, so its matrix is freed once the
/// system is assembled, and the solver's arrays take memory the process has already touched (first
/// touching fresh memory is much of a first call's cost on a virtual machine).
Expected<double> solveInterior(const TriMesh& mesh, InteriorWeights& W, bool lastUse, const BoundaryMap& boundary,
                               LinearSolver solver, std::vector<Vec2>& uv, const Progress& progress) {
  const int32_t nv = mesh.numVertices();
  uv.assign(nv, Vec2{0, 0});
  for (size_t i = 0; i < boundary.loop.size(); ++i) uv[boundary.loop[i]] = boundary.polygon[i];
  const auto n = static_cast<int32_t>(W.rows.size());
  if (n == 0) return 0.0;
  InteriorSystem system = assembleInteriorSystem(W, uv);
  if (lastUse) W.weights = CsrMatrix();
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

Expected<void> requireDisk(const TriMesh& mesh) {
  const MeshSummary& s = mesh.summary();
  if (s.boundaryLoopSizes.size() == 1 && s.eulerCharacteristic == 1 && s.components == 1) return {};
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

namespace {

BoundaryCandidate candidateOf(BoundaryKind kind, const StretchMetrics& m) {
  return {kind, m.l2, m.linf, m.flipped, m.degenerate, m.overlaps};
}

/// One fixed boundary's solved map, before it is scaled into [0, 1]².
struct SolvedMap {
  BoundaryKind kind = BoundaryKind::Circle;
  std::vector<Vec2> uv, polygon;
  std::vector<int32_t> loop;
  StretchMetrics metrics;
  int64_t fallbacks = 0;
  int64_t outliers = 0;
  double residual = 0;
};

/// `result`'s map fields from `map` (the source, weights and candidates are the caller's).
void takeMap(Parameterization& result, SolvedMap map) {
  result.boundary = map.kind;
  result.uv = std::move(map.uv);
  result.boundaryPolygon = std::move(map.polygon);
  result.boundaryLoop = std::move(map.loop);
  result.metrics = std::move(map.metrics);
  result.fallbacks = map.fallbacks;
  result.outliers = map.outliers;
  result.residual = map.residual;
}

}  // namespace

Expected<Parameterization> parameterize(const TriMesh& mesh, const ParamOptions& options, const Progress& progress) {
  record(options.timings, "cut", 0);  // every stage listed, in this order, whether it runs or not
  if (!requireDisk(mesh)) return parameterizeByCut(mesh, options, progress);
  auto result = parameterizeDisk(mesh, mesh, {}, options, progress);
  if (!result) return result;
  Parameterization& p = result.value();
  p.cornerUv.reserve(3 * static_cast<size_t>(mesh.numFaces()));
  for (const Triangle& t : mesh.triangles())
    for (int32_t v : t) p.cornerUv.push_back(p.uv[v]);
  return result;
}

std::vector<Vec2> onRealVertices(std::vector<Vec2> uv, const std::vector<int32_t>& extraOrigin) {
  const size_t n = uv.size();
  for (int32_t v : extraOrigin) uv.push_back(uv[v < static_cast<int32_t>(n) ? v : 0]);
  return uv;
}

namespace {

/// The source: an interior point where a boundary is traced or refined, else wherever the caller put it.
Expected<SurfacePoint> diskSource(const TriMesh& mesh, const ParamOptions& options, bool needsSource) {
  if (needsSource) return interiorSource(mesh, options.source);
  auto s = resolveSource(mesh, options.source);
  if (!s) return s.error();
  return options.source ? canonical(mesh, s.value(), kSnapSource) : s.value();
}

/// The fixed boundaries to solve, in measured, circle, square order: the one asked for, every one for
/// auto, and for free the measured (when it can be traced) and the circle. `traceTime` gets the traces.
Expected<std::vector<BoundaryMap>> fixedBoundaries(const TriMesh& mesh, const SurfacePoint& source,
                                                   const ParamOptions& options, bool needsSource,
                                                   const Progress& progress, Timings& traceTime) {
  const bool chooses = !options.boundary;
  const bool free = options.boundary == BoundaryKind::Free;
  std::vector<BoundaryMap> boundaries;
  if (needsSource) {
    auto m = measuredBoundary(mesh, source, progress, &traceTime);
    if (!m && m.error().code == ErrorCode::Cancelled) return m.error();
    if (m) boundaries.push_back(std::move(m).value());
    else if (options.boundary == BoundaryKind::Measured) return m.error();
    // auto and free go on without it: free then starts from the circle.
  }
  if (chooses || free || *options.boundary == BoundaryKind::Circle) boundaries.push_back(circleBoundary(mesh));
  if (chooses || *options.boundary == BoundaryKind::Square) boundaries.push_back(squareBoundary(mesh));
  return boundaries;
}

/// One fixed boundary's map: the interior solved, the stretch measured on the real vertices, the
/// boundary's polygon and loop moved into it.
Expected<SolvedMap> solveBoundary(const TriMesh& mesh, const TriMesh& real, const std::vector<int32_t>& extraOrigin,
                                  InteriorWeights& W, bool lastUse, BoundaryMap& boundary, const ParamOptions& options,
                                  const Progress& progress, Stopwatch& stage) {
  const Error cancelled = cancelledError("parameterization");
  SolvedMap map;
  const auto solved = solveInterior(mesh, W, lastUse, boundary, options.solver, map.uv, progress);
  if (!solved) return solved.error().code == ErrorCode::Cancelled ? cancelled : solved.error();
  map.residual = solved.value();
  record(options.timings, "solve", stage.lap());
  if (!report(progress, "metrics", 0)) return cancelled;
  map.metrics = textureStretch(real, extraOrigin.empty() ? map.uv : onRealVertices(map.uv, extraOrigin));
  record(options.timings, "metrics", stage.lap());
  map.kind = boundary.kind;
  map.polygon = std::move(boundary.polygon);
  map.loop = std::move(boundary.loop);
  map.fallbacks = boundary.fallbacks;
  map.outliers = boundary.outliers;
  return map;
}

/// The free boundary's refinement of `start`, which takes `result`'s place for free, when there is no
/// fixed map, or when preferredMap prefers it (else only its candidates are kept).
Expected<void> refineStart(const TriMesh& mesh, const TriMesh& real, const std::vector<int32_t>& extraOrigin,
                           const ParamOptions& options, bool haveBest, SolvedMap start, Parameterization& result,
                           const Progress& progress) {
  const bool free = options.boundary == BoundaryKind::Free;
  Parameterization from;
  from.source = result.source;
  from.weights = result.weights;
  from.weightFallbacks = result.weightFallbacks;
  from.candidates = std::move(result.candidates);
  takeMap(from, std::move(start));
  // Refined from the start in [0, 1]², exactly as refineParameterization of parameterize's own
  // result would be (the comparison refines that way): the same map either way.
  normalizeIntoUnitSquare(mesh, from.uv, from.boundaryPolygon);
  if (!extraOrigin.empty()) from.uv = onRealVertices(std::move(from.uv), extraOrigin);
  auto refined = refineOnDisk(real, from, options.free, progress, options.timings);
  if (!refined) return refined.error();
  Parameterization& r = refined.value();
  if (free || !haveBest ||
      preferredMap(r.metrics.l2, r.metrics.flipped + r.metrics.degenerate, result.metrics.l2,
                   result.metrics.flipped + result.metrics.degenerate)) {
    result = std::move(r);
  } else {
    result.candidates = std::move(r.candidates);
  }
  return {};
}

}  // namespace

Expected<Parameterization> parameterizeDisk(const TriMesh& mesh, const TriMesh& real,
                                            const std::vector<int32_t>& extraOrigin, const ParamOptions& options,
                                            const Progress& progress) {
  const Error cancelled = cancelledError("parameterization");
  Timings* timings = options.timings;
  for (const char* stage : {"source", "trace", "boundary", "weights", "solve", "refine", "metrics", "total"})
    record(timings, stage, 0);  // every stage listed, in this order, whether it runs or not
  const Stopwatch total;
  Parameterization result;
  result.weights = options.weights;
  const bool chooses = !options.boundary;
  const bool free = options.boundary == BoundaryKind::Free;
  const bool refines = chooses || free;

  if (!report(progress, "source", 0)) return cancelled;
  Stopwatch stage;
  const bool needsSource = refines || *options.boundary == BoundaryKind::Measured;
  auto source = diskSource(mesh, options, needsSource);
  if (!source) return source.error();
  result.source = source.value();
  record(timings, "source", stage.lap());

  Timings traceTime;
  auto fixed = fixedBoundaries(mesh, result.source, options, needsSource, progress, traceTime);
  if (!fixed) return fixed.error();
  std::vector<BoundaryMap>& boundaries = fixed.value();
  record(timings, "trace", traceTime["trace"]);
  record(timings, "boundary", stage.lap() - traceTime["trace"]);

  if (!report(progress, "weights", 0)) return cancelled;
  InteriorWeights W = interiorWeights(mesh, options.weights);
  result.weightFallbacks = W.uniformFallbacks;
  record(timings, "weights", stage.lap());

  bool haveBest = false;
  std::optional<SolvedMap> start;  // the free boundary's: measured when bijective, else the circle's
  for (BoundaryMap& boundary : boundaries) {
    if (free && start) break;  // the measured map is bijective: no circle needed
    stage.lap();
    const bool lastUse = &boundary == &boundaries.back();
    auto solved = solveBoundary(mesh, real, extraOrigin, W, lastUse, boundary, options, progress, stage);
    if (!solved) return solved.error();
    SolvedMap& map = solved.value();
    result.candidates.push_back(candidateOf(map.kind, map.metrics));
    const bool startsFree = refines && !start &&
                            (map.kind == BoundaryKind::Circle ||
                             (map.kind == BoundaryKind::Measured && map.metrics.bijective));
    if (startsFree) start = map;
    if (free) continue;  // the result is the refined map, whatever the start's numbers
    if (!haveBest || preferredMap(map.metrics.l2, map.metrics.flipped + map.metrics.degenerate, result.metrics.l2,
                                  result.metrics.flipped + result.metrics.degenerate)) {
      haveBest = true;
      takeMap(result, std::move(map));
    }
  }
  if (haveBest) normalizeIntoUnitSquare(mesh, result.uv, result.boundaryPolygon);
  if (refines && start) {
    auto refined = refineStart(mesh, real, extraOrigin, options, haveBest, std::move(*start), result, progress);
    if (!refined) return refined.error();
    haveBest = true;
  }
  if (!haveBest) return Error{ErrorCode::Topology, "no boundary map could be built"};
  report(progress, "metrics", 1.0);
  record(timings, "total", total.ms());
  return result;
}

Expected<Parameterization> refineParameterization(const TriMesh& mesh, const Parameterization& start,
                                                  const FreeBoundaryOptions& options, const Progress& progress,
                                                  Timings* timings) {
  if (start.cut != CutMethod::Disk) return refineByCut(mesh, start, options, progress, timings);
  auto disk = requireDisk(mesh);
  if (!disk) return disk.error();
  auto refined = refineOnDisk(mesh, start, options, progress, timings);
  if (!refined) return refined;
  Parameterization& p = refined.value();
  p.cornerUv.reserve(3 * static_cast<size_t>(mesh.numFaces()));
  for (const Triangle& t : mesh.triangles())
    for (int32_t v : t) p.cornerUv.push_back(p.uv[v]);
  return refined;
}

Expected<Parameterization> refineOnDisk(const TriMesh& mesh, const Parameterization& start,
                                        const FreeBoundaryOptions& options, const Progress& progress,
                                        Timings* timings) {
  if (start.boundary == BoundaryKind::Free)
    return Error{ErrorCode::InvalidArgument,
                 "a free-boundary refinement starts from a fixed-boundary map (measured or circle), not a free one"};
  if (start.uv.size() != static_cast<size_t>(mesh.numVertices()))
    return Error{ErrorCode::InvalidArgument, "the start map has " + std::to_string(start.uv.size()) +
                                                 " uv for a mesh of " + std::to_string(mesh.numVertices()) +
                                                 " vertices"};
  const Error cancelled = cancelledError("parameterization");
  if (!report(progress, "refine", 0)) return cancelled;
  Stopwatch stage;
  auto refined = refineFreeBoundary(mesh, start.uv, options, progress);
  if (!refined) return refined.error().code == ErrorCode::Cancelled ? cancelled : refined.error();
  record(timings, "refine", stage.lap());
  if (!report(progress, "metrics", 0)) return cancelled;
  FreeBoundaryResult& free = refined.value();
  Parameterization p;
  p.source = start.source;
  p.boundary = BoundaryKind::Free;
  p.weights = start.weights;
  p.uv = std::move(free.uv);
  p.metrics = textureStretch(mesh, p.uv);  // scale-invariant: the same before and after normalizing
  record(timings, "metrics", stage.lap());
  p.boundaryLoop = start.boundaryLoop;
  normalizeIntoUnitSquare(mesh, p.uv, p.boundaryPolygon);
  p.boundaryPolygon.reserve(p.boundaryLoop.size());
  for (int32_t v : p.boundaryLoop) p.boundaryPolygon.push_back(p.uv[v]);
  p.fallbacks = start.fallbacks;
  p.outliers = start.outliers;
  p.weightFallbacks = start.weightFallbacks;
  p.residual = start.residual;
  p.candidates = start.candidates;
  p.candidates.push_back(candidateOf(BoundaryKind::Free, p.metrics));
  p.init = start.boundary;
  p.iterations = free.iterations;
  p.energyInitial = free.energyInitial;
  p.energyFinal = free.energyFinal;
  p.converged = free.converged;
  p.untangled = free.untangled;
  return p;
}

}  // namespace straightest
