// measureAtlas on hand-built atlases, one defect each: overlaps (a sliver, containment, a chart wrapping
// over itself), touching charts, a mirrored chart, a flipped face, an annulus, known gaps and padding, and an
// isometric cube.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/atlas/atlas_quality.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTau = 2 * testing::kPi;

/// Flat charts, each its own mesh component, with their corner uv: the 3D position is the uv itself (z = 0),
/// so each chart is an isometry unless its uv is changed afterwards.
struct FlatAtlas {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<Vec2> cornerUv;

  /// Adds a chart of the given vertices (uv) and triangles (indices into them, counter-clockwise).
  void addChart(const std::vector<Vec2>& uv, const std::vector<Triangle>& faces) {
    const int32_t base = static_cast<int32_t>(positions.size());
    for (const Vec2& p : uv) positions.push_back({p.x, p.y, 0});
    for (const Triangle& t : faces) {
      triangles.push_back({base + t[0], base + t[1], base + t[2]});
      for (int32_t v : t) cornerUv.push_back(uv[v]);
    }
  }
  /// An axis-aligned rectangle as two triangles.
  void addRectangle(double x0, double y0, double x1, double y1) {
    addChart({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {{0, 1, 2}, {0, 2, 3}});
  }
  TriMesh mesh() const { return testing::buildOrFail(positions, triangles); }
  AtlasQuality measure(const QualityOptions& options = {}) const { return measureAtlas(mesh(), cornerUv, options); }
};

TEST(AtlasQuality, SeparateChartsAreCleanWithTheirAreaAndGap) {
  FlatAtlas atlas;
  atlas.addRectangle(0.1, 0.1, 0.4, 0.4);
  atlas.addRectangle(0.5, 0.1, 0.9, 0.3);
  const AtlasQuality q = atlas.measure();
  EXPECT_EQ(q.charts, 2);
  EXPECT_EQ(q.nonDiskCharts, 0);
  EXPECT_EQ(q.overlaps, 0);
  EXPECT_EQ(q.flipped, 0);
  EXPECT_EQ(q.mirroredCharts, 0);
  EXPECT_NEAR(q.l2, 1, 1e-12);
  EXPECT_NEAR(q.linf, 1, 1e-12);
  EXPECT_NEAR(q.utilization, 0.09 + 0.08, 1e-12);
  EXPECT_NEAR(q.minGapTexels, 0.1 * 1024, 1e-4);  // snapping moves a uv by up to 2^-25 (3e-5 texels)
  EXPECT_EQ(q.outside, 0);
  EXPECT_EQ(q.seamEdges, 0);
  EXPECT_TRUE(q.overlappingFaces.empty());
}

TEST(AtlasQuality, SliverOverlapThroughCrossingEdges) {
  FlatAtlas atlas;
  atlas.addRectangle(0.1, 0.1, 0.4, 0.4);
  // A tilted square whose left corner reaches 0.001 into the first.
  atlas.addChart({{0.399, 0.25}, {0.55, 0.1}, {0.7, 0.25}, {0.55, 0.4}}, {{0, 1, 2}, {0, 2, 3}});
  const AtlasQuality q = atlas.measure({1024, 1024, 2});
  EXPECT_EQ(q.overlaps, 1);
  EXPECT_EQ(q.minGapTexels, 0);
  EXPECT_EQ(q.paddingViolations, 1);
  EXPECT_EQ(q.overlappingFaces, (std::vector<int32_t>{0, 2}));  // each chart by its first face
}

TEST(AtlasQuality, SliverOverlapAlongCollinearEdges) {
  // No boundary edges cross properly and no vertex is strictly inside the other chart: the overlap is the
  // strip [0.399, 0.4] × [0.1, 0.4]; the second chart's left edge runs through the first one's interior.
  FlatAtlas atlas;
  atlas.addRectangle(0.1, 0.1, 0.4, 0.4);
  atlas.addRectangle(0.399, 0.1, 0.7, 0.4);
  EXPECT_EQ(atlas.measure().overlaps, 1);
}

TEST(AtlasQuality, ContainedChartOverlapsWithoutCrossing) {
  FlatAtlas atlas;
  atlas.addRectangle(0.1, 0.1, 0.9, 0.9);
  atlas.addRectangle(0.4, 0.4, 0.6, 0.6);
  const AtlasQuality q = atlas.measure();
  EXPECT_EQ(q.charts, 2);
  EXPECT_EQ(q.overlaps, 1);
  EXPECT_EQ(q.minGapTexels, 0);
}

TEST(AtlasQuality, IdenticalChartsOverlap) {
  FlatAtlas atlas;
  atlas.addRectangle(0.1, 0.1, 0.5, 0.5);
  atlas.addRectangle(0.1, 0.1, 0.5, 0.5);
  EXPECT_EQ(atlas.measure().overlaps, 1);
}

TEST(AtlasQuality, TouchingChartsHaveGapZeroAndNoOverlap) {
  FlatAtlas atlas;
  atlas.addRectangle(0.1, 0.1, 0.4, 0.4);
  atlas.addRectangle(0.4, 0.2, 0.7, 0.5);  // shares part of the edge x = 0.4
  atlas.addRectangle(0.7, 0.5, 0.9, 0.9);  // touches the second at one corner
  const AtlasQuality q = atlas.measure({1024, 1024, 1});
  EXPECT_EQ(q.charts, 3);
  EXPECT_EQ(q.overlaps, 0);
  EXPECT_EQ(q.minGapTexels, 0);
  EXPECT_EQ(q.paddingViolations, 2);
}

TEST(AtlasQuality, MirroredChartIsCountedButNotFlipped) {
  FlatAtlas mirrored;
  mirrored.addRectangle(0.1, 0.1, 0.4, 0.4);
  mirrored.addRectangle(0.5, 0.1, 0.8, 0.4);
  for (size_t c = 0; c < 6; ++c) mirrored.cornerUv[c].x = 0.5 - mirrored.cornerUv[c].x;  // the first, about x = 0.25
  const AtlasQuality q = mirrored.measure();
  EXPECT_EQ(q.charts, 2);
  EXPECT_EQ(q.mirroredCharts, 1);
  EXPECT_EQ(q.flipped, 0);
  EXPECT_EQ(q.overlaps, 0);
  EXPECT_NEAR(q.l2, 1, 1e-12);  // a reflection is an isometry
}

TEST(AtlasQuality, FlippedFaceMakesTheStretchInfinite) {
  // A square fanned around its centre; the centre's uv is moved below the bottom edge, which flips the
  // bottom triangle only.
  FlatAtlas atlas;
  atlas.addChart({{0.2, 0.2}, {0.6, 0.2}, {0.6, 0.6}, {0.2, 0.6}, {0.4, 0.4}},
                 {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  for (Vec2& uv : atlas.cornerUv)
    if (uv.x == 0.4 && uv.y == 0.4) uv = {0.4, 0.12};
  const AtlasQuality q = atlas.measure();
  EXPECT_EQ(q.charts, 1);
  EXPECT_EQ(q.flipped, 1);
  EXPECT_EQ(q.mirroredCharts, 0);
  EXPECT_EQ(q.l2, kInf);
  EXPECT_EQ(q.chartL2[0], kInf);
}

TEST(AtlasQuality, DegenerateFaceIsCounted) {
  FlatAtlas atlas;
  atlas.addRectangle(0.1, 0.1, 0.4, 0.4);
  atlas.cornerUv[1] = {0.25, 0.25};  // the first triangle's middle corner onto its other two's diagonal
  const AtlasQuality q = atlas.measure();
  EXPECT_EQ(q.degenerate, 1);
  EXPECT_EQ(q.l2, kInf);
}

TEST(AtlasQuality, SliverThinnerThanTheGridIsMappedNotDegenerate) {
  // A needle face at its true shape, 1e-9 high (the exact predicates' grid is 2^-24 ≈ 6e-8): its snapped corners
  // are collinear, but its orientation in double precision is certain, so it is mapped (and isometric).
  FlatAtlas atlas;
  atlas.addRectangle(0.1, 0.1, 0.4, 0.4);
  atlas.addChart({{0.5, 0.5}, {0.8, 0.5}, {0.65, 0.5 + 1e-9}}, {{0, 1, 2}});
  const AtlasQuality q = atlas.measure();
  EXPECT_EQ(q.degenerate, 0);
  EXPECT_EQ(q.flipped, 0);
  EXPECT_EQ(q.mirroredCharts, 0);
  EXPECT_NEAR(q.l2, 1, 1e-6);
  FlatAtlas mirrored = atlas;
  std::swap(mirrored.cornerUv[7], mirrored.cornerUv[8]);  // the needle clockwise: a mirrored chart, still mapped
  EXPECT_EQ(mirrored.measure().mirroredCharts, 1);
  EXPECT_EQ(mirrored.measure().degenerate, 0);
}

TEST(AtlasQuality, AnnulusIsNotADisk) {
  FlatAtlas atlas;
  const std::vector<Vec2> uv = {{0.1, 0.1}, {0.7, 0.1}, {0.7, 0.7}, {0.1, 0.7},
                                {0.3, 0.3}, {0.5, 0.3}, {0.5, 0.5}, {0.3, 0.5}};
  std::vector<Triangle> faces;
  for (int32_t k = 0; k < 4; ++k) {
    const int32_t next = (k + 1) % 4;
    faces.push_back({k, next, 4 + next});
    faces.push_back({k, 4 + next, 4 + k});
  }
  atlas.addChart(uv, faces);
  atlas.addRectangle(0.75, 0.75, 0.95, 0.95);
  const AtlasQuality q = atlas.measure();
  EXPECT_EQ(q.charts, 2);
  EXPECT_EQ(q.nonDiskCharts, 1);
  EXPECT_EQ(q.overlaps, 0);
}

/// A strip of `segments` quads laid along a spiral of 1.25 turns in uv, so its last quarter turn lies over
/// its first; 3D is a flat strip of unit squares.
FlatAtlas spiralStrip(int32_t segments) {
  FlatAtlas atlas;
  for (int32_t i = 0; i <= segments; ++i) {
    const double t = static_cast<double>(i) / segments, angle = 1.25 * kTau * t, inner = 0.15 + 0.05 * t;
    for (double r : {inner, inner + 0.1}) {
      atlas.positions.push_back({static_cast<double>(i), r == inner ? 0.0 : 1.0, 0});
      atlas.cornerUv.push_back({0.5 + r * std::cos(angle), 0.5 + r * std::sin(angle)});
    }
  }
  const std::vector<Vec2> vertexUv = atlas.cornerUv;
  atlas.cornerUv.clear();
  for (int32_t i = 0; i < segments; ++i) {
    const int32_t a = 2 * i, b = 2 * i + 2, c = 2 * i + 3, d = 2 * i + 1;
    for (const Triangle& t : {Triangle{a, b, c}, Triangle{a, c, d}}) {
      atlas.triangles.push_back(t);
      for (int32_t v : t) atlas.cornerUv.push_back(vertexUv[v]);
    }
  }
  return atlas;
}

TEST(AtlasQuality, StripWrappingOverItselfOverlapsItself) {
  const AtlasQuality q = spiralStrip(47).measure();
  EXPECT_EQ(q.charts, 1);
  EXPECT_EQ(q.nonDiskCharts, 0);
  EXPECT_EQ(q.flipped, 0);
  EXPECT_EQ(q.overlaps, 1);
  EXPECT_EQ(q.overlappingFaces, std::vector<int32_t>{0});
}

TEST(AtlasQuality, StripOfOneTurnDoesNotOverlap) {
  FlatAtlas atlas = spiralStrip(47);
  // Keep the first 0.9 turn only (faces in strip order).
  const size_t keep = 2 * static_cast<size_t>(47 * 0.9 / 1.25);
  atlas.triangles.resize(keep);
  atlas.cornerUv.resize(3 * keep);
  EXPECT_EQ(atlas.measure().overlaps, 0);
}

TEST(AtlasQuality, GapsAndPaddingAtKnownDistances) {
  // Texel-aligned at 1024: A and B are 10 texels apart, C's corner is 5 texels (3-4-5) from A's and B's.
  const double t = 1.0 / 1024;
  FlatAtlas atlas;
  atlas.addRectangle(128 * t, 128 * t, 384 * t, 384 * t);
  atlas.addRectangle(394 * t, 128 * t, 600 * t, 384 * t);
  atlas.addRectangle(387 * t, 388 * t, 391 * t, 392 * t);
  EXPECT_NEAR(atlas.measure().minGapTexels, 5, 1e-9);
  EXPECT_EQ(atlas.measure({1024, 1024, 5}).paddingViolations, 0);
  EXPECT_EQ(atlas.measure({1024, 1024, 6}).paddingViolations, 2);
  EXPECT_EQ(atlas.measure({1024, 1024, 11}).paddingViolations, 3);
  // At 2048 × 1024 the horizontal distances double: A–B 20, C–A √(6² + 4²), C–B √(6² + 4²).
  EXPECT_NEAR(atlas.measure({2048, 1024, 0}).minGapTexels, std::sqrt(52.0), 1e-9);
}

TEST(AtlasQuality, PaddingIsJudgedWithinTheGridsRounding) {
  // A gap of 5 texels less a millionth (under the 2^-24 grid's rounding at 1024: 8.6e-5 texels) is the padding;
  // a hundredth of a texel less is not.
  const double t = 1.0 / 1024;
  for (const auto& [gap, violations] : {std::pair{5 - 1e-6, 0}, std::pair{5 - 1e-2, 1}}) {
    FlatAtlas atlas;
    atlas.addRectangle(128 * t, 128 * t, 384 * t, 384 * t);
    atlas.addRectangle((384 + gap) * t, 128 * t, 600 * t, 384 * t);
    EXPECT_EQ(atlas.measure({1024, 1024, 5}).paddingViolations, violations) << gap;
  }
}

TEST(AtlasQuality, FarApartChartsStillHaveTheirGap) {
  FlatAtlas atlas;
  atlas.addRectangle(0.01, 0.01, 0.02, 0.02);
  atlas.addRectangle(0.9, 0.01, 0.95, 0.02);
  EXPECT_NEAR(atlas.measure({1000, 1000, 0}).minGapTexels, 880, 1e-4);  // not texel-aligned: snapped
}

TEST(AtlasQuality, OutsideAndNonFiniteCornersAreCounted) {
  FlatAtlas atlas;
  atlas.addRectangle(0.1, 0.1, 0.4, 0.4);
  atlas.addRectangle(0.5, 0.5, 1.2, 0.9);
  atlas.cornerUv[0].x = std::numeric_limits<double>::quiet_NaN();
  const AtlasQuality q = atlas.measure();
  EXPECT_EQ(q.nonFinite, 1);
  EXPECT_EQ(q.outside, 3);  // (1.2, 0.5) once, (1.2, 0.9) twice
  EXPECT_EQ(q.l2, kInf);
}

/// The unit cube, 12 outward triangles.
TriMesh unitCube() {
  std::vector<Vec3> p;
  for (int32_t i = 0; i < 8; ++i) p.push_back({double(i & 1), double(i >> 1 & 1), double(i >> 2 & 1)});
  const std::vector<Triangle> t = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return testing::buildOrFail(p, t);
}

/// Each cube face flattened isometrically (scaled by 0.3) into its own cell of a 3 × 2 grid, counter-clockwise.
std::vector<Vec2> cubeFacesAtlas(const TriMesh& cube) {
  std::vector<Vec2> uv(3 * cube.numFaces());
  for (int32_t f = 0; f < cube.numFaces(); ++f) {
    const Vec3 n = cube.faceNormal(f);
    const int axis = std::abs(n.x) > 0.5 ? 0 : std::abs(n.y) > 0.5 ? 1 : 2;
    const int side = 2 * axis + ((axis == 0 ? n.x : axis == 1 ? n.y : n.z) > 0);
    const Vec3 e1 = axis == 0 ? Vec3{0, 1, 0} : Vec3{1, 0, 0}, e2 = cross(n, e1);
    const Vec2 origin{0.05 + 0.32 * (side % 3), 0.05 + 0.45 * (side / 3)};
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = cube.position(cube.triangle(f)[k]) - Vec3{0.5, 0.5, 0.5};
      uv[3 * f + k] = origin + Vec2{dot(p, e1) + 0.5, dot(p, e2) + 0.5} * 0.3;
    }
  }
  return uv;
}

TEST(AtlasQuality, CubeFacesAsSixIsometricCharts) {
  const TriMesh cube = unitCube();
  const AtlasQuality q = measureAtlas(cube, cubeFacesAtlas(cube));
  EXPECT_EQ(q.charts, 6);
  EXPECT_EQ(q.nonDiskCharts, 0);
  EXPECT_NEAR(q.l2, 1, 1e-9);
  EXPECT_NEAR(q.linf, 1, 1e-9);
  for (int32_t c = 0; c < 6; ++c) EXPECT_NEAR(q.chartL2[c], 1, 1e-9);
  EXPECT_EQ(q.flipped, 0);
  EXPECT_EQ(q.mirroredCharts, 0);
  EXPECT_EQ(q.overlaps, 0);
  EXPECT_EQ(q.seamEdges, 12);  // the cube's edges; the six diagonals are inside charts
  EXPECT_NEAR(q.seamLength, 12, 1e-12);
  EXPECT_NEAR(q.utilization, 6 * 0.09, 1e-12);
}

TEST(AtlasQuality, CubeInOneUvPointIsOneClosedChart) {
  const TriMesh cube = unitCube();
  const AtlasQuality q = measureAtlas(cube, std::vector<Vec2>(36, Vec2{0.5, 0.5}));
  EXPECT_EQ(q.charts, 1);
  EXPECT_EQ(q.nonDiskCharts, 1);
  EXPECT_EQ(q.seamEdges, 0);
  EXPECT_EQ(q.degenerate, 12);
}

TEST(AtlasQuality, RefusesAWrongNumberOfCorners) {
  const TriMesh cube = unitCube();
  EXPECT_THROW(measureAtlas(cube, std::vector<Vec2>(35)), std::invalid_argument);
}

}  // namespace
}  // namespace straightest
