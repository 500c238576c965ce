// Free-boundary refinement: developable surfaces flatten isometrically, a curved cap beats every fixed
// boundary, and no result whose start was bijective (or could be untangled) ever folds or overlaps.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "straightest/mesh/samples.hpp"
#include "straightest/param/free_boundary.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/param/texture_stretch.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

using testing::GridPattern;

std::vector<Vec2> startMap(const TriMesh& mesh, BoundaryKind boundary, WeightKind weights = WeightKind::MeanValue) {
  ParamOptions o;
  o.boundary = boundary;
  o.weights = weights;
  auto r = parameterize(mesh, o);
  if (!r) ADD_FAILURE() << r.error().message;
  return r ? r.value().uv : std::vector<Vec2>(mesh.numVertices());
}

FreeBoundaryOptions tight() {
  FreeBoundaryOptions o;
  o.maxIterations = 500;
  o.relativeTolerance = 1e-12;
  return o;
}

FreeBoundaryResult refine(const TriMesh& mesh, const std::vector<Vec2>& start, const FreeBoundaryOptions& o = {}) {
  auto r = refineFreeBoundary(mesh, start, o);
  if (!r) ADD_FAILURE() << r.error().message;
  return r ? std::move(r).value() : FreeBoundaryResult{};
}

void expectBijective(const TriMesh& mesh, const std::vector<Vec2>& uv) {
  const StretchMetrics m = textureStretch(mesh, uv);
  EXPECT_EQ(m.flipped, 0);
  EXPECT_EQ(m.degenerate, 0);
  EXPECT_EQ(m.overlaps, 0);
  EXPECT_TRUE(m.bijective);
}

void expectIsometric(const TriMesh& mesh, const std::vector<Vec2>& start) {
  const FreeBoundaryResult r = refine(mesh, start, tight());
  expectBijective(mesh, r.uv);
  EXPECT_NEAR(textureStretch(mesh, r.uv).l2, 1.0, 1e-6);
  EXPECT_NEAR(r.energyFinal, 4.0, 1e-6);
  EXPECT_LE(r.energyFinal, r.energyInitial);
  EXPECT_FALSE(r.untangled);
  // The energy fixes the scale: an isometry has the surface's own size (an edge keeps its 3D length).
  const Triangle& t = mesh.triangle(0);
  EXPECT_NEAR(norm(r.uv[t[1]] - r.uv[t[0]]), norm(mesh.position(t[1]) - mesh.position(t[0])), 1e-4);
}

TEST(FreeBoundary, PlanePatchesInEveryTriangulationMapIsometricallyFromADistortedCircleMap) {
  for (GridPattern pattern : {GridPattern::Regular, GridPattern::UnionJack, GridPattern::Jittered}) {
    SCOPED_TRACE(static_cast<int>(pattern));
    const TriMesh mesh = testing::flatGrid(9, pattern);
    const std::vector<Vec2> start = startMap(mesh, BoundaryKind::Circle);
    EXPECT_GT(textureStretch(mesh, start).l2, 1.01);  // the circle distorts the square
    expectIsometric(mesh, start);
  }
}

TEST(FreeBoundary, AnLShapedPlaneFromTheMeasuredStartMapsIsometrically) {
  const TriMesh mesh = testing::lShape(4);
  expectIsometric(mesh, startMap(mesh, BoundaryKind::Measured, WeightKind::ShapePreserving));
}

TEST(FreeBoundary, ACylinderPatchMapsIsometrically) {
  // A quarter turn of a cylinder of radius 3, 8 × 8 cells.
  const TriMesh mesh = testing::grid(9, GridPattern::UnionJack, [](double x, double y) {
    const double angle = x / 8 * kPi / 2;
    return Vec3{3 * std::cos(angle), 3 * std::sin(angle), y};
  });
  expectIsometric(mesh, startMap(mesh, BoundaryKind::Circle));
}

TEST(FreeBoundary, AConePatchWithoutTheApexMapsIsometrically) {
  // Half-angle 30°, slant distances 1..3 from the apex, azimuth 0..150°.
  const double halfAngle = kPi / 6;
  const TriMesh mesh = testing::grid(9, GridPattern::Regular, [&](double x, double y) {
    const double slant = 1 + 2 * y / 8, azimuth = x / 8 * 5 * kPi / 6;
    return Vec3{slant * std::sin(halfAngle) * std::cos(azimuth), slant * std::sin(halfAngle) * std::sin(azimuth),
                slant * std::cos(halfAngle)};
  });
  expectIsometric(mesh, startMap(mesh, BoundaryKind::Circle));
}

TEST(FreeBoundary, AHemisphereBeatsEveryFixedBoundaryButNoIsometryExists) {
  const TriMesh mesh = makeSphericalCap(1.0, kPi / 2, 10);
  double bestFixed = std::numeric_limits<double>::infinity();
  for (BoundaryKind kind : {BoundaryKind::Measured, BoundaryKind::Circle, BoundaryKind::Square})
    for (WeightKind weights : {WeightKind::ShapePreserving, WeightKind::MeanValue})
      bestFixed = std::min(bestFixed, textureStretch(mesh, startMap(mesh, kind, weights)).l2);
  const FreeBoundaryResult r = refine(mesh, startMap(mesh, BoundaryKind::Circle));
  expectBijective(mesh, r.uv);
  const double l2 = textureStretch(mesh, r.uv).l2;
  EXPECT_LT(l2, bestFixed);
  EXPECT_GT(l2, 1.0 + 1e-3);
  EXPECT_GT(r.energyFinal, 4.0 + 1e-3);
  EXPECT_LT(r.energyFinal, r.energyInitial);
}

/// A bumpy disk: a jittered grid under a random sum of Gaussian bumps, some border cells cut away.
TriMesh randomDisk(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  struct Bump {
    double x, y, height, width;
  };
  std::vector<Bump> bumps;
  for (int k = 0; k < 4; ++k) bumps.push_back({10 * unit(rng), 10 * unit(rng), 6 * unit(rng) - 3, 1 + 2 * unit(rng)});
  return testing::grid(
      11, GridPattern::Jittered,
      [&](double x, double y) {
        double z = 0;
        for (const Bump& b : bumps)
          z += b.height * std::exp(-((x - b.x) * (x - b.x) + (y - b.y) * (y - b.y)) / (b.width * b.width));
        return Vec3{x, y, z};
      },
      seed);
}

TEST(FreeBoundary, RandomBumpyDisksNeverFoldAndTheEnergyNeverRises) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE(seed);
    const TriMesh mesh = randomDisk(seed);
    for (BoundaryKind kind : {BoundaryKind::Circle, BoundaryKind::Measured}) {
      const std::vector<Vec2> start = startMap(mesh, kind);
      if (!textureStretch(mesh, start).bijective) continue;
      const FreeBoundaryResult r = refine(mesh, start);
      expectBijective(mesh, r.uv);
      EXPECT_LE(r.energyFinal, r.energyInitial);
      EXPECT_GE(r.energyFinal, 4.0);
      EXPECT_LE(textureStretch(mesh, r.uv).l2, textureStretch(mesh, start).l2 + 1e-9);
    }
  }
}

/// A flat plus sign: a 4 × 4 block of cells with four arms 2 cells wide and `arm` cells long.
TriMesh plusWithLongArms(int arm) {
  const int n = 2 * arm + 5;
  return testing::gridOfCells(n, [&](int i, int j) {
    const bool centreColumn = i >= arm && i < arm + 4 && (i == arm + 1 || i == arm + 2 || true);
    const bool centreRow = j >= arm && j < arm + 4;
    const bool verticalArm = i >= arm + 1 && i < arm + 3;
    const bool horizontalArm = j >= arm + 1 && j < arm + 3;
    return (centreColumn && centreRow) || verticalArm || horizontalArm;
  });
}

TEST(FreeBoundary, AStarWithLongArmsIsUntangledAndUnrolled) {
  const TriMesh mesh = plusWithLongArms(24);
  const std::vector<Vec2> start = startMap(mesh, BoundaryKind::Circle, WeightKind::Uniform);
  const FreeBoundaryResult r = refine(mesh, start);
  expectBijective(mesh, r.uv);
  EXPECT_EQ(r.untangled, !textureStretch(mesh, start).bijective);
  EXPECT_LT(textureStretch(mesh, r.uv).l2, 1.01);  // flat: it unfolds back towards itself
}

TEST(FreeBoundary, AFoldedStartIsUntangledThenRefined) {
  // Interior vertices thrown about at random: many faces flipped, the convex boundary left in place.
  const TriMesh mesh = testing::almostFlatGrid(10, 0.3);
  std::vector<Vec2> start = startMap(mesh, BoundaryKind::Circle);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> shift(-0.15, 0.15);
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (!mesh.isBoundaryVertex(v)) start[v] += Vec2{shift(rng), shift(rng)};
  ASSERT_GT(textureStretch(mesh, start).flipped, 0);
  const FreeBoundaryResult r = refine(mesh, start);
  EXPECT_TRUE(r.untangled);
  EXPECT_TRUE(std::isinf(r.energyInitial));
  expectBijective(mesh, r.uv);
  EXPECT_LT(r.energyFinal, 4.2);
}

TEST(FreeBoundary, ALongFingerWhoseLinearMapUnderflowsIsUntangledAndBijective) {
  const TriMesh mesh = testing::finger(32);
  for (WeightKind weights : {WeightKind::MeanValue, WeightKind::Uniform}) {
    const std::vector<Vec2> start = startMap(mesh, BoundaryKind::Circle, weights);
    const StretchMetrics before = textureStretch(mesh, start);
    ASSERT_GT(before.degenerate, 50);  // underflow, not a fold
    EXPECT_EQ(before.flipped, 0);
    const FreeBoundaryResult r = refine(mesh, start);
    EXPECT_TRUE(r.untangled);
    EXPECT_TRUE(std::isfinite(r.energyFinal));
    expectBijective(mesh, r.uv);
  }
}

TEST(FreeBoundary, ACollapsedArmIsUntangled) {
  // Every vertex of one arm of the star put on one point (zero area: the underflow of a linear map).
  const TriMesh mesh = plusWithLongArms(10);
  std::vector<Vec2> start = startMap(mesh, BoundaryKind::Circle);
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (!mesh.isBoundaryVertex(v) && mesh.position(v).x > 15) start[v] = {0.5, 0.5};
  ASSERT_FALSE(textureStretch(mesh, start).bijective);
  const FreeBoundaryResult r = refine(mesh, start);
  EXPECT_TRUE(r.untangled);
  expectBijective(mesh, r.uv);
}

TEST(FreeBoundary, ACollapsedBoundaryEarIsOpened) {
  // Cells cut along their rising diagonals leave the grid's corners (5, 0) and (0, 5) in one triangle
  // each, an ear with all three corners on the boundary. Moving such a corner onto the segment between
  // its neighbours collapses the ear: only freeing the ear's corners can open it again.
  const TriMesh mesh = testing::gridOfCells(6, [](int, int) { return true; });
  std::vector<Vec2> start = startMap(mesh, BoundaryKind::Circle);
  int32_t ear = -1;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const Triangle& t = mesh.triangle(f);
    if (mesh.isBoundaryVertex(t[0]) && mesh.isBoundaryVertex(t[1]) && mesh.isBoundaryVertex(t[2])) ear = f;
  }
  ASSERT_GE(ear, 0);
  // The ear's corner that lies in no other face goes to the midpoint of the other two.
  const Triangle& t = mesh.triangle(ear);
  for (int k = 0; k < 3; ++k) {
    int faces = 0;
    for (int32_t f : mesh.vertexFaces(t[k])) faces += f >= 0;
    if (faces == 1) start[t[k]] = (start[t[(k + 1) % 3]] + start[t[(k + 2) % 3]]) * 0.5;
  }
  ASSERT_GT(textureStretch(mesh, start).degenerate, 0);
  const FreeBoundaryResult r = refine(mesh, start);
  EXPECT_TRUE(r.untangled);
  expectBijective(mesh, r.uv);
}

TEST(FreeBoundary, ARolledUpStripUnrolls) {
  // A strip 2 cells wide and 120 long, rolled into a spiral of 3 turns (developable).
  const int length = 120;
  std::vector<Vec3> p;
  std::vector<Triangle> t;
  for (int i = 0; i <= length; ++i) {
    // Arc length s along the spiral r = 1 + 0.05 θ is close enough to i·0.2 for a test mesh.
    const double theta = 6 * kPi * i / length, r = 1 + 0.05 * theta;
    for (int j = 0; j <= 2; ++j) p.push_back({r * std::cos(theta), r * std::sin(theta), 0.1 * j});
  }
  for (int i = 0; i < length; ++i)
    for (int j = 0; j < 2; ++j) {
      const int a = 3 * i + j, b = 3 * (i + 1) + j;
      t.push_back({a, b, b + 1});
      t.push_back({a, b + 1, a + 1});
    }
  const TriMesh mesh = testing::buildOrFail(p, t);
  const std::vector<Vec2> start = startMap(mesh, BoundaryKind::Circle);
  const FreeBoundaryResult r = refine(mesh, start, tight());
  expectBijective(mesh, r.uv);
  EXPECT_NEAR(textureStretch(mesh, r.uv).l2, 1.0, 1e-6);
}

TEST(FreeBoundary, AMirroredStartIsMirroredBackNotUntangled) {
  const TriMesh mesh = makeSphericalCap(1.0, kPi / 2, 8);
  std::vector<Vec2> start = startMap(mesh, BoundaryKind::Circle);
  for (Vec2& q : start) q.y = -q.y;
  ASSERT_EQ(textureStretch(mesh, start).flipped, mesh.numFaces());
  const FreeBoundaryResult r = refine(mesh, start);
  EXPECT_FALSE(r.untangled);
  expectBijective(mesh, r.uv);
}

TEST(FreeBoundary, AZeroAreaFaceGivesNoNaN) {
  // A sliver face (b, a, m) on a boundary edge a → b with m its midpoint: zero 3D area, still a disk.
  const TriMesh grid = testing::flatGrid(6, GridPattern::Regular);
  std::vector<Vec3> p = grid.positions();
  std::vector<Triangle> t = grid.triangles();
  const int32_t a = 0, b = 1;  // the bottom row's first edge
  p.push_back((p[a] + p[b]) * 0.5);
  t.push_back({b, a, static_cast<int32_t>(p.size()) - 1});
  const TriMesh mesh = testing::buildOrFail(p, t);
  ASSERT_TRUE(mesh.isDegenerateFace(mesh.numFaces() - 1));
  const FreeBoundaryResult r = refine(mesh, startMap(mesh, BoundaryKind::Circle));
  for (const Vec2& q : r.uv) EXPECT_TRUE(isFinite(q));
  EXPECT_TRUE(std::isfinite(r.energyFinal));
  EXPECT_LE(r.energyFinal, r.energyInitial);
}

TEST(FreeBoundary, CancellingStopsWithCancelled) {
  const TriMesh mesh = makeSphericalCap(1.0, kPi / 2, 10);
  int calls = 0;
  auto r = refineFreeBoundary(mesh, startMap(mesh, BoundaryKind::Circle), {}, [&](const char* stage, double) {
    EXPECT_STREQ(stage, "refine");
    return ++calls < 3;
  });
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::Cancelled);
}

TEST(FreeBoundary, ProgressIsMonotoneAndReachesOne) {
  const TriMesh mesh = makeSphericalCap(1.0, kPi / 3, 6);
  std::vector<double> fractions;
  auto r = refineFreeBoundary(mesh, startMap(mesh, BoundaryKind::Circle), {}, [&](const char*, double f) {
    fractions.push_back(f);
    return true;
  });
  ASSERT_TRUE(r);
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  EXPECT_LE(fractions.size(), 102u);
}

TEST(FreeBoundary, TheIterationCapStopsWithoutConverging) {
  const TriMesh mesh = makeSphericalCap(1.0, kPi / 2, 10);
  FreeBoundaryOptions o;
  o.maxIterations = 2;
  o.relativeTolerance = 0;
  const FreeBoundaryResult r = refine(mesh, startMap(mesh, BoundaryKind::Circle), o);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_FALSE(r.converged);
  expectBijective(mesh, r.uv);
  EXPECT_LT(r.energyFinal, r.energyInitial);
}

TEST(FreeBoundary, AnExhaustedTimeBudgetReturnsTheRescaledStartUnconverged) {
  const TriMesh mesh = makeSphericalCap(1.0, kPi / 2, 10);
  const std::vector<Vec2> start = startMap(mesh, BoundaryKind::Circle);
  FreeBoundaryOptions o;
  o.timeBudgetMs = 0;
  const FreeBoundaryResult r = refine(mesh, start, o);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.energyFinal, r.energyInitial);
  expectBijective(mesh, r.uv);
  // The start, scaled about the origin to the energy's best scale: same shape, same stretch.
  EXPECT_NEAR(textureStretch(mesh, r.uv).l2, textureStretch(mesh, start).l2, 1e-12);
}

TEST(FreeBoundary, AStartOfTheWrongSizeOrNotFiniteIsAnInvalidArgument) {
  const TriMesh mesh = testing::flatGrid(4, GridPattern::Regular);
  auto shortStart = refineFreeBoundary(mesh, std::vector<Vec2>(3));
  ASSERT_FALSE(shortStart);
  EXPECT_EQ(shortStart.error().code, ErrorCode::InvalidArgument);
  std::vector<Vec2> start = startMap(mesh, BoundaryKind::Circle);
  start[5].x = std::nan("");
  auto notFinite = refineFreeBoundary(mesh, start);
  ASSERT_FALSE(notFinite);
  EXPECT_EQ(notFinite.error().code, ErrorCode::InvalidArgument);
}

}  // namespace
}  // namespace straightest
