// Measured-boundary parameterization and texture stretch: facts a flattening must satisfy.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "straightest/geodesic_distance.hpp"
#include "straightest/parameterize.hpp"
#include "straightest/samples.hpp"
#include "straightest/straightest_path.hpp"
#include "test_meshes.hpp"
#include "test_util.hpp"

namespace straightest {
namespace {

using testing::GridPattern;

std::vector<Vec2> planarUV(const TriMesh& mesh, double scale = 1, double shear = 0) {
  std::vector<Vec2> uv;
  for (const Vec3& p : mesh.positions()) uv.push_back({scale * (p.x + shear * p.y), scale * p.y});
  return uv;
}

Parameterization param(const TriMesh& mesh, std::optional<BoundaryKind> b, WeightKind w) {
  ParamOptions o;
  o.boundary = b;
  o.weights = w;
  auto r = parameterize(mesh, o);
  if (!r) ADD_FAILURE() << r.error().message;
  return std::move(r).value();
}

TEST(TextureStretch, IsometryScoresOne) {
  const TriMesh mesh = testing::flatGrid(8, GridPattern::Jittered);
  const StretchMetrics m = textureStretch(mesh, planarUV(mesh));
  EXPECT_NEAR(m.l2, 1, 1e-12);
  EXPECT_NEAR(m.linf, 1, 1e-12);
  EXPECT_NEAR(m.angleDistortionMax, 1, 1e-9);
  EXPECT_NEAR(m.areaDistortionMax, 1, 1e-9);
  EXPECT_TRUE(m.bijective);
}

TEST(TextureStretch, UniformScaleScoresOne) {
  const TriMesh mesh = testing::flatGrid(8, GridPattern::UnionJack);
  const StretchMetrics m = textureStretch(mesh, planarUV(mesh, 0.01));
  EXPECT_NEAR(m.l2, 1, 1e-12);
  EXPECT_NEAR(m.linf, 1, 1e-12);
}

TEST(TextureStretch, ShearHasTheSingularValuesOfItsInverse) {
  // uv = (x + k y, y): the inverse Jacobian has S_s = (1, 0, 0), S_t = (−k, 1, 0); area is preserved.
  const double k = 0.5;
  const TriMesh mesh = testing::flatGrid(6, GridPattern::Regular);
  const StretchMetrics m = textureStretch(mesh, planarUV(mesh, 1, k));
  const double a = 1, b = -k, c = 1 + k * k;
  EXPECT_NEAR(m.l2, std::sqrt((a + c) / 2), 1e-12);
  EXPECT_NEAR(m.linf, std::sqrt(((a + c) + std::sqrt((a - c) * (a - c) + 4 * b * b)) / 2), 1e-12);
  EXPECT_NEAR(m.areaDistortionMax, 1, 1e-9);
  EXPECT_GT(m.angleDistortionMean, 1.5);
}

TEST(TextureStretch, FlippedTriangleMakesStretchInfiniteAndIsCounted) {
  const TriMesh mesh = testing::flatGrid(5, GridPattern::Regular);
  std::vector<Vec2> uv = planarUV(mesh);
  uv[12] = {uv[12][0] + 1.6, uv[12][1] + 1.6};  // the centre vertex jumps over its neighbours
  const StretchMetrics m = textureStretch(mesh, uv);
  EXPECT_GT(m.flipped, 0);
  EXPECT_FALSE(m.bijective);
  EXPECT_TRUE(std::isinf(m.l2));
  EXPECT_TRUE(std::isinf(m.linf));
}

TEST(TextureStretch, DegenerateTriangleIsCountedAndNotBijective) {
  const TriMesh mesh = testing::flatGrid(3, GridPattern::Regular);
  std::vector<Vec2> uv = planarUV(mesh);
  uv[4] = {0.5, 0.0};  // the centre lands on the edge (0, 1): triangle (0, 1, 4) has zero area
  const StretchMetrics m = textureStretch(mesh, uv);
  EXPECT_GE(m.degenerate, 1);
  EXPECT_TRUE(std::isinf(m.l2));
}

/// uv is a similarity image of the flat mesh: every edge scaled by one factor, orientation kept.
void expectSimilarity(const TriMesh& mesh, const std::vector<Vec2>& uv) {
  const Triangle& t0 = mesh.triangle(0);
  const double k = std::hypot(uv[t0[1]][0] - uv[t0[0]][0], uv[t0[1]][1] - uv[t0[0]][1]) /
                   norm(mesh.position(t0[1]) - mesh.position(t0[0]));
  for (const Triangle& t : mesh.triangles())
    for (int c = 0; c < 3; ++c) {
      const int32_t i = t[c], j = t[(c + 1) % 3];
      const double d2 = std::hypot(uv[j][0] - uv[i][0], uv[j][1] - uv[i][1]);
      ASSERT_NEAR(d2, k * norm(mesh.position(j) - mesh.position(i)), 1e-9 * k) << "edge " << i << "-" << j;
    }
}

TEST(MeasuredBoundary, PlanarConvexPatchReproducesItselfWithEveryConvexCombination) {
  const TriMesh mesh = testing::flatGrid(15, GridPattern::Jittered);
  for (WeightKind w : {WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Cotan}) {
    const Parameterization p = param(mesh, BoundaryKind::Measured, w);
    EXPECT_NEAR(p.metrics.l2, 1, 1e-9) << weightKindName(w);
    EXPECT_NEAR(p.metrics.linf, 1, 1e-9) << weightKindName(w);
    EXPECT_EQ(p.fallbacks, 0);
    expectSimilarity(mesh, p.uv);
    for (const Vec2& q : p.uv) {  // scaled into [0, 1]² keeping the aspect ratio
      EXPECT_GE(q[0], -1e-12);
      EXPECT_LE(q[1], 1 + 1e-12);
    }
  }
}

TEST(MeasuredBoundary, DevelopableCylinderPatchIsNearlyIsometric) {
  const double R = 1.0;
  const int n = 41;
  const TriMesh mesh = testing::grid(n, GridPattern::UnionJack, [&](double i, double j) {
    const double theta = -1.2 + 2.4 * i / (n - 1), y = -1.0 + 2.0 * j / (n - 1);
    return Vec3{R * std::sin(theta), y, R * std::cos(theta)};
  });
  const Parameterization measured = param(mesh, BoundaryKind::Measured, WeightKind::ShapePreserving);
  const Parameterization circle = param(mesh, BoundaryKind::Circle, WeightKind::ShapePreserving);
  EXPECT_LT(measured.metrics.l2, 1.01);
  EXPECT_GT(circle.metrics.l2, measured.metrics.l2);
}

TEST(Parameterize, ConvexBoundaryWithConvexWeightsNeverFlipsOnTheSamples) {
  for (const std::string& name : sampleNames()) {
    const TriMesh mesh = makeSample(name).value();
    for (BoundaryKind b : {BoundaryKind::Measured, BoundaryKind::Circle, BoundaryKind::Square})
      for (WeightKind w : {WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Uniform}) {
        const Parameterization p = param(mesh, b, w);
        EXPECT_EQ(p.metrics.flipped, 0) << name << " " << boundaryKindName(p.boundary) << " " << weightKindName(w);
        EXPECT_EQ(p.metrics.degenerate, 0) << name << " " << boundaryKindName(p.boundary) << " " << weightKindName(w);
        EXPECT_TRUE(std::isfinite(p.metrics.l2));
        EXPECT_LT(p.residual, 1e-9);
      }
  }
}

TEST(Parameterize, AutoKeepsTheLeastStretchedCandidate) {
  const TriMesh mesh = makeSample("mountain").value();
  const Parameterization p = param(mesh, std::nullopt, WeightKind::ShapePreserving);
  ASSERT_EQ(p.candidates.size(), 3u);
  for (const BoundaryCandidate& c : p.candidates) EXPECT_LE(p.metrics.l2, c.l2);
}

TEST(Parameterize, EverySolverGivesTheSameMap) {
  const TriMesh mesh = makeSample("face").value();
  ParamOptions o;
  o.solver = LinearSolver::SparseLU;
  const Parameterization lu = parameterize(mesh, o).value();
  for (LinearSolver s : {LinearSolver::Multigrid, LinearSolver::BiCGSTAB}) {
    o.solver = s;
    const Parameterization it = parameterize(mesh, o).value();
    EXPECT_LT(it.residual, 1e-9);
    for (size_t v = 0; v < lu.uv.size(); ++v) {
      ASSERT_NEAR(lu.uv[v][0], it.uv[v][0], 1e-8);
      ASSERT_NEAR(lu.uv[v][1], it.uv[v][1], 1e-8);
    }
  }
}

TEST(Multigrid, PreconditionedSolveMatchesTheDirectSolveOnALargeSystem) {
  const TriMesh mesh = makeHeightField(120);
  ParamOptions o;
  o.solver = LinearSolver::SparseLU;
  const Parameterization lu = parameterize(mesh, o).value();
  o.solver = LinearSolver::Multigrid;
  const Parameterization mg = parameterize(mesh, o).value();
  EXPECT_LT(mg.residual, 1e-9);
  EXPECT_NEAR(mg.metrics.l2, lu.metrics.l2, 1e-9);
}

TEST(Parameterize, RefusesWhatIsNotADiskWithAMessage) {
  auto closed = parameterize(testing::loadGood("good/tetrahedron.off"), {});
  ASSERT_FALSE(closed.ok());
  EXPECT_EQ(closed.error().code, ErrorCode::Topology);
  EXPECT_NE(closed.error().message.find("closed"), std::string::npos) << closed.error().message;
  auto annulus = parameterize(testing::loadGood("good/annulus.off"), {});
  ASSERT_FALSE(annulus.ok());
  EXPECT_NE(annulus.error().message.find("2 boundary loops"), std::string::npos) << annulus.error().message;
}

TEST(Parameterize, RefusesASourceOnTheBoundaryOrOutOfRange) {
  const TriMesh mesh = makeSample("cap").value();
  ParamOptions o;
  o.source = SurfacePoint::vertex(mesh.boundaryLoops()[0][0]);
  auto onBoundary = parameterize(mesh, o);
  ASSERT_FALSE(onBoundary.ok());
  EXPECT_NE(onBoundary.error().message.find("on the boundary"), std::string::npos);
  o.source = SurfacePoint::vertex(mesh.numVertices());
  EXPECT_FALSE(parameterize(mesh, o).ok());
  EXPECT_FALSE(parseBoundaryChoice("ellipse").ok());
  EXPECT_FALSE(parseWeightKind("harmonic").ok());
}

TEST(ObjWriter, WritesOneVtPerVertexInTheInputOrder) {
  const TriMesh mesh = testing::loadGood("good/quad_grid.obj");
  const Parameterization p = param(mesh, BoundaryKind::Circle, WeightKind::Uniform);
  const std::string text = writeObj(mesh, &p.uv);
  auto reread = loadMesh(text, MeshFormat::Obj);
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  EXPECT_EQ(reread.value().positions()[5].x, mesh.positions()[5].x);
  EXPECT_EQ(reread.value().triangles(), mesh.triangles());
  EXPECT_NE(text.find(" 1/1"), std::string::npos);  // faces as v/vt with vt = v
  EXPECT_NE(text.find("\nvt "), std::string::npos);
}

}  // namespace
}  // namespace straightest

namespace straightest {
namespace {

TEST(Progress, ParameterizationReportsEveryStageAndCanBeCancelled) {
  const TriMesh mesh = makeHeightField(60);
  std::vector<std::string> stages;
  double lastSolve = -1;
  bool monotone = true;
  auto r = parameterize(mesh, {}, [&](const char* stage, double fraction) {
    if (stages.empty() || stages.back() != stage) stages.push_back(stage);
    if (std::string(stage) == "solve") {
      monotone = monotone && fraction >= lastSolve;
      lastSolve = fraction;
    }
    return true;
  });
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(monotone);
  EXPECT_EQ(stages.front(), "source");
  EXPECT_EQ(stages.back(), "metrics");
  EXPECT_NE(std::find(stages.begin(), stages.end(), "trace"), stages.end());
  EXPECT_NE(std::find(stages.begin(), stages.end(), "weights"), stages.end());
  for (const char* stop : {"source", "trace", "weights", "metrics"}) {
    auto cancelled = parameterize(mesh, {}, [&](const char* stage, double) { return std::string(stage) != stop; });
    ASSERT_FALSE(cancelled.ok()) << stop;
    EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled) << stop;
  }
}

TEST(Progress, CancellingATraceBatchIsACancelledErrorAtTheNextCheck) {
  const TriMesh mesh = makeHeightField(40);
  int calls = 0;
  auto batch = traceStraightestPaths(mesh, SurfacePoint::vertex(defaultSource(mesh).value()), boundaryTargets(mesh),
                                     TraceOptions{false}, [&](const char*, double) { return ++calls < 10; });
  ASSERT_FALSE(batch.ok());
  EXPECT_EQ(batch.error().code, ErrorCode::Cancelled);
  EXPECT_EQ(calls, 10);  // stopped at the check that said no, not later
}

}  // namespace
}  // namespace straightest
