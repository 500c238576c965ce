// libFuzzer harness: parameterize() on random disks (height-field grids with random heights and
// jitter, spherical caps; rotated and scaled), sometimes with triangles removed (a notched disk, or
// not a disk any more), with a random boundary (measured / circle / square / free / auto), weights
// (shape-preserving / mean-value / uniform / cotan), source (automatic, an interior vertex or face
// point, or a boundary vertex) and solver. Also textureStretch on random uv.
// Invariants: a result or an error with a known category (Topology / InvalidArgument) and a message;
// not a disk ⇒ Topology error; a result has one finite uv per vertex in [0, 1]², the boundary loop
// of the mesh, its polygon at the loop's uv; stretch is finite iff the map is bijective
// (no flipped, no degenerate triangle) and then L2 ≥ 1 and L∞ ≥ L2; with convex-combination weights
// (not cotan) the uv solve u_i = Σ λ_ij u_j, and with a circle or measured boundary the map is bijective
// (Tutte/Floater): flipped == 0. Free (a few refinement iterations, to stay fast): a start named
// (measured or circle), iterations within the cap, a map reported bijective has no flipped, degenerate
// or overlapping-boundary element, and the energy never rises from a start that did not fold.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdlib>
#include <limits>

#include "fuzz_meshes.hpp"
#include "straightest/param/parameterize.hpp"

using namespace straightest;

namespace {

void checkMetrics(const TriMesh& m, const StretchMetrics& s, const char* what) {
  FUZZ_CHECK(s.flipped >= 0 && s.degenerate >= 0 && s.flipped + s.degenerate <= m.numFaces(), "%s: counts", what);
  FUZZ_CHECK(s.bijective == (s.flipped == 0 && s.degenerate == 0 && s.overlaps == 0),
             "%s: bijective=%d with %lld flipped, %lld degenerate, %lld boundary overlaps", what, s.bijective,
             (long long)s.flipped, (long long)s.degenerate, (long long)s.overlaps);
  FUZZ_CHECK(std::isfinite(s.l2) == s.bijective && std::isfinite(s.linf) == s.bijective,
             "%s: stretch L2 %g / Linf %g but bijective=%d", what, s.l2, s.linf, s.bijective);
  if (s.bijective) {
    FUZZ_CHECK(s.l2 >= 1 - 1e-9, "%s: L2 stretch %.17g below 1", what, s.l2);
    FUZZ_CHECK(s.linf >= s.l2 * (1 - 1e-9), "%s: Linf %.17g below L2 %.17g", what, s.linf, s.l2);
  }
  FUZZ_CHECK(static_cast<int32_t>(s.faceStretch.size()) == m.numFaces(), "%s: faceStretch size", what);
  FUZZ_CHECK(!std::isnan(s.angleDistortionMean) && !std::isnan(s.areaDistortionMean), "%s: NaN distortion", what);
}

void dump(const TriMesh& m, const ParamOptions& o, const Expected<Parameterization>& r) {
  std::fprintf(stderr, "mesh: %d vertices, %d faces\n", m.numVertices(), m.numFaces());
  for (int32_t v = 0; v < m.numVertices(); ++v)
    std::fprintf(stderr, "  v %d: %.17g %.17g %.17g%s\n", v, m.position(v).x, m.position(v).y, m.position(v).z,
                 m.isBoundaryVertex(v) ? " (boundary)" : "");
  for (int32_t f = 0; f < m.numFaces(); ++f)
    std::fprintf(stderr, "  f %d: %d %d %d\n", f, m.triangle(f)[0], m.triangle(f)[1], m.triangle(f)[2]);
  std::fprintf(stderr, "options: boundary %s, weights %s, source %s kind %d index %d\n",
               o.boundary ? boundaryKindName(*o.boundary) : "auto", weightKindName(o.weights),
               o.source ? "given" : "auto", o.source ? static_cast<int>(o.source->kind) : -1,
               o.source ? o.source->index : -1);
  if (!r.ok()) {
    std::fprintf(stderr, "error %s: %s\n", errorCodeName(r.error().code), r.error().message.c_str());
    return;
  }
  const Parameterization& p = r.value();
  std::fprintf(stderr, "source t %.17g bary %.17g %.17g %.17g\n", p.source.t, p.source.bary[0], p.source.bary[1],
               p.source.bary[2]);
  std::fprintf(stderr, "result: boundary %s, source kind %d index %d, l2 %g, flipped %lld, degenerate %lld\n",
               boundaryKindName(p.boundary), static_cast<int>(p.source.kind), p.source.index, p.metrics.l2,
               (long long)p.metrics.flipped, (long long)p.metrics.degenerate);
  for (size_t i = 0; i < p.boundaryLoop.size(); ++i)
    std::fprintf(stderr, "  loop %zu: vertex %d -> (%.17g, %.17g)\n", i, p.boundaryLoop[i], p.boundaryPolygon[i][0],
                 p.boundaryPolygon[i][1]);
  for (int32_t v = 0; v < m.numVertices(); ++v)
    std::fprintf(stderr, "  uv %d: %.17g %.17g\n", v, p.uv[v][0], p.uv[v][1]);
  for (int32_t f = 0; f < m.numFaces(); ++f)
    if (!(p.metrics.faceStretch[f] < std::numeric_limits<float>::infinity()))
      std::fprintf(stderr, "  bad face %d: %d %d %d\n", f, m.triangle(f)[0], m.triangle(f)[1], m.triangle(f)[2]);
}

bool isDisk(const TriMesh& m) {
  const MeshSummary& s = m.summary();
  return s.boundaryLoopSizes.size() == 1 && s.eulerCharacteristic == 1 && s.components == 1;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  fuzz::RandomMesh gen = in.ConsumeIntegralInRange(0, 4) == 0 ? fuzz::cap(in, false) : fuzz::heightGrid(in, 10);
  const int removals = in.ConsumeIntegralInRange(0, 7) == 0 ? in.ConsumeIntegralInRange(1, 4) : 0;
  for (int k = 0; k < removals && gen.T.size() > 1; ++k)
    gen.T.erase(gen.T.begin() + in.ConsumeIntegralInRange<std::ptrdiff_t>(0, gen.T.size() - 1));
  if (removals > 0) {  // may have made it non-manifold or disconnected: build decides
    auto built = TriMesh::build(gen.P, gen.T);
    if (!built.ok()) return 0;
  }
  const TriMesh mesh = fuzz::transformAndBuild(in, gen);

  ParamOptions options;
  static const std::optional<BoundaryKind> boundaries[] = {BoundaryKind::Measured, BoundaryKind::Circle,
                                                           BoundaryKind::Square, BoundaryKind::Free, std::nullopt};
  static const WeightKind weights[] = {WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Uniform,
                                       WeightKind::Cotan};
  options.boundary = boundaries[in.ConsumeIntegralInRange(0, 4)];
  options.free.maxIterations = in.ConsumeIntegralInRange(1, 8);
  options.free.timeBudgetMs = 2000;  // an untangling that cannot succeed stops here (its own caps are larger)
  options.weights = weights[in.ConsumeIntegralInRange(0, 7) == 0 ? 3 : in.ConsumeIntegralInRange(0, 2)];
  options.solver = in.ConsumeBool() ? LinearSolver::SparseLU : LinearSolver::BiCGSTAB;
  const bool autoSource = in.ConsumeBool();
  if (!autoSource) {
    SurfacePoint source = fuzz::randomPoint(in, mesh);
    if (in.ConsumeIntegralInRange(0, 3) > 0) {  // mostly an interior source
      for (int32_t v = 0; v < mesh.numVertices(); ++v) {
        const int32_t w = (v + source.index) % mesh.numVertices();
        if (source.kind == SurfacePoint::Kind::Vertex && !mesh.isBoundaryVertex(w)) {
          source.index = w;
          break;
        }
      }
    }
    options.source = source;
  }

  auto result = parameterize(mesh, options);
  if (std::getenv("FUZZ_VERBOSE")) {
    dump(mesh, options, result);
    if (options.boundary == std::nullopt)
      for (BoundaryKind b : {BoundaryKind::Measured, BoundaryKind::Circle}) {
        ParamOptions o = options;
        o.boundary = b;
        dump(mesh, o, parameterize(mesh, o));
      }
  }
  const bool disk = isDisk(mesh);
  if (!result.ok()) {
    fuzz::checkError(result.error(), "parameterize");
    const ErrorCode c = result.error().code;
    FUZZ_CHECK(c == ErrorCode::Topology || c == ErrorCode::InvalidArgument, "parameterize: unexpected %s: %s",
               errorCodeName(c), result.error().message.c_str());
    FUZZ_CHECK(!disk || c != ErrorCode::Topology || options.boundary == BoundaryKind::Measured ||
                   result.error().message.find("interior") != std::string::npos,
               "disk refused with a topology error (%s boundary): %s",
               options.boundary == std::nullopt ? "auto" : "fixed", result.error().message.c_str());
    return 0;
  }
  const Parameterization& p = result.value();
  // Every manifold mesh is parameterized: a non-disk is cut to a disk first (disk_cut_test and
  // parameterize_cut_test hold its geometry); here only the shape of its output is checked.
  FUZZ_CHECK(p.cornerUv.size() == 3 * static_cast<size_t>(mesh.numFaces()), "cornerUv size %zu for %d faces",
             p.cornerUv.size(), mesh.numFaces());
  FUZZ_CHECK(!disk || p.cut == CutMethod::Disk, "a disk was cut (%s)", cutMethodName(p.cut));
  if (!disk) return 0;
  const int32_t V = mesh.numVertices();
  FUZZ_CHECK(static_cast<int32_t>(p.uv.size()) == V, "uv size %zu for %d vertices", p.uv.size(), V);
  for (int32_t v = 0; v < V; ++v)
    FUZZ_CHECK(std::isfinite(p.uv[v][0]) && std::isfinite(p.uv[v][1]) && p.uv[v][0] >= -1e-12 &&
                   p.uv[v][0] <= 1 + 1e-12 && p.uv[v][1] >= -1e-12 && p.uv[v][1] <= 1 + 1e-12,
               "uv of vertex %d = (%.17g, %.17g) outside [0,1]^2", v, p.uv[v][0], p.uv[v][1]);
  FUZZ_CHECK(p.boundaryLoop == mesh.boundaryLoops()[0], "boundary loop differs from the mesh's");
  FUZZ_CHECK(p.boundaryPolygon.size() == p.boundaryLoop.size(), "polygon size");
  for (size_t i = 0; i < p.boundaryLoop.size(); ++i) {
    const Vec2 &a = p.uv[p.boundaryLoop[i]], &b = p.boundaryPolygon[i];
    FUZZ_CHECK(std::abs(a[0] - b[0]) <= 1e-9 && std::abs(a[1] - b[1]) <= 1e-9,
               "boundary vertex %zu: uv (%g, %g), polygon (%g, %g)", i, a[0], a[1], b[0], b[1]);
  }
  FUZZ_CHECK(p.weights == options.weights, "weights kind changed");
  if (options.boundary) {
    FUZZ_CHECK(p.boundary == *options.boundary, "boundary kind");
  } else {
    FUZZ_CHECK(p.candidates.size() >= 3 && p.candidates.size() <= 4, "auto: %zu candidates", p.candidates.size());
    FUZZ_CHECK(p.candidates.back().kind == BoundaryKind::Free, "auto: the free candidate comes last");
    for (const BoundaryCandidate& c : p.candidates)
      FUZZ_CHECK(!(c.l2 < p.metrics.l2), "auto kept L2 %.17g over a candidate with %.17g", p.metrics.l2, c.l2);
  }
  checkMetrics(mesh, p.metrics, "parameterize");
  FUZZ_CHECK(p.init.has_value() == (p.boundary == BoundaryKind::Free), "init set for a %s map",
             boundaryKindName(p.boundary));
  if (p.boundary == BoundaryKind::Free) {
    FUZZ_CHECK(*p.init == BoundaryKind::Measured || *p.init == BoundaryKind::Circle, "free started from %s",
               boundaryKindName(*p.init));
    FUZZ_CHECK(p.iterations >= 0 && p.iterations <= options.free.maxIterations, "%d iterations, cap %d", p.iterations,
               options.free.maxIterations);
    FUZZ_CHECK(p.candidates.back().kind == BoundaryKind::Free && p.candidates.back().l2 == p.metrics.l2,
               "free: the last candidate is the result");
    if (!p.untangled && std::isfinite(p.energyInitial))
      FUZZ_CHECK(p.energyFinal <= p.energyInitial * (1 + 1e-12), "free: energy rose from %.17g to %.17g",
                 p.energyInitial, p.energyFinal);
  }
  FUZZ_CHECK(p.fallbacks >= 0 && p.weightFallbacks >= 0, "negative fallback counts");
  const bool convexWeights = options.weights != WeightKind::Cotan;
  const char* weightName = weightKindName(options.weights);
  FUZZ_CHECK(std::isfinite(p.residual) && p.residual >= 0, "residual %g", p.residual);
  if (convexWeights) {
    // The uv solve the interior equations u_i = Σ λ_ij u_j (checked in the [0, 1]² frame: the reported
    // relative residual is meaningless when the right-hand side is ~0, e.g. a measured boundary
    // around a source that its weights reproduce exactly). Not a free map: it moved on from the solve.
    const InteriorWeights W = interiorWeights(mesh, options.weights);
    for (size_t r = 0; p.boundary != BoundaryKind::Free && r < W.rows.size(); ++r) {
      double u = 0, v = 0;
      for (int32_t k = W.weights.start[r]; k < W.weights.start[r + 1]; ++k) {
        u += W.weights.value[k] * p.uv[W.weights.col[k]][0];
        v += W.weights.value[k] * p.uv[W.weights.col[k]][1];
      }
      const Vec2& x = p.uv[W.rows[r]];
      FUZZ_CHECK(std::hypot(x[0] - u, x[1] - v) <= 1e-8,
                 "%s weights, %s solver: vertex %d is %.3g from the average of its neighbours", weightName,
                 options.solver == LinearSolver::SparseLU ? "LU" : "BiCGSTAB", W.rows[r],
                 std::hypot(x[0] - u, x[1] - v));
    }
    for (const BoundaryCandidate& c : p.candidates)
      if (c.kind == BoundaryKind::Circle || c.kind == BoundaryKind::Measured)
        FUZZ_CHECK(c.flipped == 0 && c.degenerate == 0,
                   "%s mesh, %s boundary, %s weights: %lld flipped and %lld degenerate triangles (must be bijective)",
                   gen.kind, boundaryKindName(c.kind), weightName, (long long)c.flipped, (long long)c.degenerate);
    if (p.boundary == BoundaryKind::Circle || p.boundary == BoundaryKind::Measured)
      FUZZ_CHECK(p.metrics.bijective && p.metrics.flipped == 0, "%s boundary, %s weights: not bijective",
                 boundaryKindName(p.boundary), weightName);
  }
  // textureStretch on the result's uv with some vertices moved: the metric invariants still hold.
  std::vector<Vec2> uv = p.uv;
  const int moves = in.ConsumeIntegralInRange(0, 3);
  for (int k = 0; k < moves; ++k)
    uv[in.ConsumeIntegralInRange<int32_t>(0, V - 1)] = {in.ConsumeProbability<double>(),
                                                        in.ConsumeProbability<double>()};
  checkMetrics(mesh, textureStretch(mesh, uv), "textureStretch");
  return 0;
}
