// atlas_segmentation_test.cpp — charts of a texture atlas (issue 29, items 1–2): every face in exactly one
// edge-connected chart, every uv triangle counter-clockwise with positive area, isometric where the surface
// is developable, the stretch target kept, cancel and thread count honoured.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "geodesic_surfaces.hpp"
#include "straightest/atlas/chart_segmentation.hpp"
#include "straightest/base/threads.hpp"
#include "straightest/mesh/samples.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {
using testing::buildOrFail;

/// Whether the faces form one piece across shared edges (a breadth-first walk inside the chart).
bool edgeConnected(const TriMesh& mesh, const std::vector<int32_t>& faces, const std::vector<int32_t>& chartOfFace,
                   int32_t chart) {
  std::vector<uint8_t> seen(mesh.numFaces(), 0);
  std::vector<int32_t> stack{faces.front()};
  seen[faces.front()] = 1;
  size_t reached = 0;
  while (!stack.empty()) {
    const int32_t f = stack.back();
    stack.pop_back();
    ++reached;
    for (int k = 0; k < 3; ++k) {
      const int32_t h = mesh.twin(3 * f + k);
      if (h < 0) continue;
      const int32_t g = TriMesh::face(h);
      if (chartOfFace[g] == chart && !seen[g]) seen[g] = 1, stack.push_back(g);
    }
  }
  return reached == faces.size();
}

/// The invariants every chart set must have, whatever the mesh.
void expectValidCharts(const TriMesh& mesh, const ChartSet& set, double maxStretch) {
  ASSERT_EQ(set.chartOfFace.size(), static_cast<size_t>(mesh.numFaces()));
  std::vector<int32_t> covered(mesh.numFaces(), 0);
  int64_t flipped = 0;
  for (size_t c = 0; c < set.charts.size(); ++c) {
    const FlatChart& chart = set.charts[c];
    ASSERT_FALSE(chart.faces.empty());
    ASSERT_EQ(chart.cornerUv.size(), 3 * chart.faces.size());
    for (int32_t f : chart.faces) {
      ++covered[f];
      EXPECT_EQ(set.chartOfFace[f], static_cast<int32_t>(c));
    }
    EXPECT_TRUE(edgeConnected(mesh, chart.faces, set.chartOfFace, static_cast<int32_t>(c))) << "chart " << c;
    for (size_t i = 0; i < chart.faces.size(); ++i) {
      const Vec2 &a = chart.cornerUv[3 * i], &b = chart.cornerUv[3 * i + 1], &d = chart.cornerUv[3 * i + 2];
      ASSERT_TRUE(isFinite(a) && isFinite(b) && isFinite(d)) << "chart " << c << " face " << chart.faces[i];
      if (!(cross(b - a, d - a) > 0)) ++flipped;
    }
    EXPECT_TRUE(std::isfinite(chart.l2)) << "chart " << c;
    if (!set.capped) {
      EXPECT_LE(chart.l2, maxStretch) << "chart " << c;
    }
  }
  EXPECT_EQ(flipped, 0);
  for (int32_t f = 0; f < mesh.numFaces(); ++f) EXPECT_EQ(covered[f], 1) << "face " << f;
  EXPECT_TRUE(std::isfinite(set.l2));
  if (!set.capped) {
    EXPECT_LE(set.l2, maxStretch);
  }
}

ChartSet chartsOf(const TriMesh& mesh, const ChartOptions& options = {}) {
  Expected<ChartSet> set = makeCharts(mesh, options);
  EXPECT_TRUE(set.ok()) << (set.ok() ? "" : set.error().message);
  return set.ok() ? std::move(set.value()) : ChartSet{};
}

/// |uv edge| = |3D edge| on every edge of every face: the chart is an isometry up to `tolerance` (relative).
void expectIsometric(const TriMesh& mesh, const ChartSet& set, double tolerance) {
  for (const FlatChart& chart : set.charts)
    for (size_t i = 0; i < chart.faces.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const Triangle& t = mesh.triangle(chart.faces[i]);
        const double length3 = norm(mesh.position(t[(k + 1) % 3]) - mesh.position(t[k]));
        const double length2 = norm(chart.cornerUv[3 * i + (k + 1) % 3] - chart.cornerUv[3 * i + k]);
        EXPECT_NEAR(length2, length3, tolerance * length3);
      }
}

/// A and B as one mesh of two components.
TriMesh twoComponents(const TriMesh& a, const TriMesh& b, Vec3 offset) {
  std::vector<Vec3> p = a.positions();
  std::vector<Triangle> t = a.triangles();
  const int32_t base = static_cast<int32_t>(p.size());
  for (const Vec3& q : b.positions()) p.push_back(q + offset);
  for (Triangle tri : b.triangles()) t.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
  return buildOrFail(std::move(p), std::move(t));
}

TEST(AtlasCharts, CubeUnfoldsIsometricallyInAtMostSixCharts) {
  // A 2×2×2 block of voxels: each side of the cube is a planar 2×2 grid of squares. Two sides sharing an
  // edge unfold flat without stretch, so a chart may hold several sides.
  const TriMesh cube = testing::voxelSurface(
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}});
  const ChartSet set = chartsOf(cube);
  expectValidCharts(cube, set, 1.02);
  EXPECT_LE(set.charts.size(), 6u);
  for (const FlatChart& chart : set.charts) {
    EXPECT_NEAR(chart.l2, 1, 1e-6);
    EXPECT_NEAR(chart.linf, 1, 1e-6);
  }
  expectIsometric(cube, set, 1e-6);
  EXPECT_NEAR(set.l2, 1, 1e-6);
}

TEST(AtlasCharts, OpenCylinderFlattensIsometrically) {
  const TriMesh cylinder = testing::prism(24, 12, 1.0, 0.25).mesh;
  const ChartSet set = chartsOf(cylinder);
  expectValidCharts(cylinder, set, 1.02);
  for (const FlatChart& chart : set.charts) EXPECT_NEAR(chart.l2, 1, 1e-6);
  expectIsometric(cylinder, set, 1e-4);
}

TEST(AtlasCharts, DevelopableSheetFlattensIsometrically) {
  // z depends on x only: every quad of the grid is planar and no vertex has an angle deficit.
  const TriMesh sheet = makeGrid(
      24,
      [](int i, int j) {
        return Vec3{i / 8.0, j / 8.0, 0.6 * std::sin(i / 4.0)};
      },
      GridDiagonals::Alternating);
  const ChartSet set = chartsOf(sheet);
  expectValidCharts(sheet, set, 1.02);
  for (const FlatChart& chart : set.charts) EXPECT_NEAR(chart.l2, 1, 1e-6);
  expectIsometric(sheet, set, 1e-4);
}

TEST(AtlasCharts, ClosedSurfacesOfGenusZeroToThree) {
  const std::vector<std::pair<std::string, TriMesh>> meshes = {
      {"sphere", makeIcosphere(1.0, 3)},
      {"torus", makeTorus(1, 0.4, 48, 24)},
      {"genus 2", testing::genusSlab(2)},
      {"genus 3", testing::genusSlab(3)},
  };
  for (const auto& [name, mesh] : meshes) {
    SCOPED_TRACE(name);
    const ChartSet set = chartsOf(mesh);
    expectValidCharts(mesh, set, 1.02);
    EXPECT_GE(set.charts.size(), 2u);  // a closed surface never lies flat in one piece
  }
}

TEST(AtlasCharts, MeshWithHolesAndTwoComponents) {
  const TriMesh holes = makeSample("holes").value();
  expectValidCharts(holes, chartsOf(holes), 1.02);
  const TriMesh both = twoComponents(makeIcosphere(1.0, 2), makeTorus(1, 0.4, 32, 16), {4, 0, 0});
  const ChartSet set = chartsOf(both);
  expectValidCharts(both, set, 1.02);
  const int32_t sphereFaces = makeIcosphere(1.0, 2).numFaces();
  for (const FlatChart& chart : set.charts)  // no chart spans both components
    EXPECT_EQ(chart.faces.front() < sphereFaces, chart.faces.back() < sphereFaces);
}

TEST(AtlasCharts, ZeroAreaFacesGetFiniteCounterClockwiseUv) {
  // A bumpy grid with one vertex moved onto its neighbour: the faces on the edge between them have zero area.
  std::vector<Vec3> p;
  std::vector<Triangle> t;
  const int n = 8;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) p.push_back({double(i), double(j), 0.3 * std::sin(i + 2.0 * j)});
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i;
      t.push_back({a, a + 1, a + n + 1});
      t.push_back({a, a + n + 1, a + n});
    }
  p[3 * n + 3] = p[3 * n + 4];
  const TriMesh mesh = buildOrFail(std::move(p), std::move(t));
  ASSERT_GT(mesh.summary().degenerateFaces, 0);
  expectValidCharts(mesh, chartsOf(mesh), 1.02);
}

TEST(AtlasCharts, MaxChartsStopsSplittingAndSaysSo) {
  const TriMesh sphere = makeIcosphere(1.0, 3);
  ChartOptions options;
  options.maxStretch = 1.0001;  // a sphere needs dozens of charts for that
  options.maxCharts = 12;
  const ChartSet set = chartsOf(sphere, options);
  EXPECT_EQ(set.charts.size(), 12u);
  EXPECT_TRUE(set.capped);
  EXPECT_GT(set.overStretch, 0);
}

TEST(AtlasCharts, MaxChartsMergesDownToTheCap) {
  // A torus's segmentation makes more charts than the cap asks for: merging brings them down to it, each
  // still a flat, unfolded disk (the stretch is what the fewer charts cost).
  const TriMesh torus = makeTorus(1, 0.4, 32, 16);
  const ChartSet uncapped = chartsOf(torus);
  ASSERT_GT(uncapped.charts.size(), 5u);
  for (const int32_t cap : {5, 4}) {
    ChartOptions options;
    options.maxCharts = cap;
    const ChartSet set = chartsOf(torus, options);
    expectValidCharts(torus, set, options.maxStretch);
    EXPECT_LE(set.charts.size(), static_cast<size_t>(cap));
    EXPECT_TRUE(set.capped);
    EXPECT_GT(set.merges, 0);
  }
}

TEST(AtlasCharts, MaxChartFacesCapsEveryChart) {
  // One near-flat region of 6962 faces: nothing in its shape asks for a cut, so only the cap divides it.
  const TriMesh sheet = testing::almostFlatGrid(60, 1e-3);
  ASSERT_GT(sheet.numFaces(), ChartOptions{}.maxChartFaces);
  for (const int32_t cap : {ChartOptions{}.maxChartFaces, 900}) {
    ChartOptions options;
    options.maxChartFaces = cap;
    const ChartSet set = chartsOf(sheet, options);
    expectValidCharts(sheet, set, options.maxStretch);
    EXPECT_GE(set.charts.size(), static_cast<size_t>((sheet.numFaces() + cap - 1) / cap));
    for (size_t c = 0; c < set.charts.size(); ++c)
      EXPECT_LE(set.charts[c].faces.size(), static_cast<size_t>(cap)) << "cap " << cap << ", chart " << c;
  }
  ChartOptions uncapped;
  uncapped.maxChartFaces = 0;
  EXPECT_EQ(chartsOf(sheet, uncapped).charts.size(), 1u) << "the sheet itself needs no cut";
}

/// Twice the area of the convex hull of `points` (gift wrapping: the test's own hull, not the atlas's).
double twiceHullArea(const std::vector<Vec2>& points) {
  size_t start = 0;
  for (size_t i = 1; i < points.size(); ++i)
    if (points[i].x < points[start].x || (points[i].x == points[start].x && points[i].y < points[start].y)) start = i;
  std::vector<Vec2> hull;
  size_t current = start;
  do {
    hull.push_back(points[current]);
    size_t next = current == 0 ? 1 : 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const double turn = cross(points[next] - points[current], points[i] - points[current]);
      const bool farther = norm(points[i] - points[current]) > norm(points[next] - points[current]);
      if (turn < 0 || (turn == 0 && farther)) next = i;
    }
    current = next;
  } while (current != start && hull.size() <= points.size());
  double twice = 0;
  for (size_t i = 0; i < hull.size(); ++i) twice += cross(hull[i], hull[(i + 1) % hull.size()]);
  return std::fabs(twice);
}

TEST(AtlasCharts, ConcaveChartsAreSplitUntilEachFillsItsHull) {
  // A flat C: three quarters of an annulus. It projects onto its plane isometrically as one chart, which fills
  // about 0.43 of its convex hull; the default splits it into pieces that each fill at least minHullFill.
  const TriMesh ring = makeGrid(
      24,
      [](int i, int j) {
        const double angle = 1.5 * testing::kPi * i / 24, radius = 1 + j / 24.0;
        return Vec3{radius * std::cos(angle), radius * std::sin(angle), 0};
      },
      GridDiagonals::Alternating);
  ChartOptions anyShape;
  anyShape.minHullFill = 0;
  EXPECT_EQ(chartsOf(ring, anyShape).charts.size(), 1u);
  const ChartSet set = chartsOf(ring);
  expectValidCharts(ring, set, 1.02);
  expectIsometric(ring, set, 1e-9);
  EXPECT_GE(set.charts.size(), 2u);
  for (const FlatChart& chart : set.charts) {
    double twiceArea = 0;
    for (size_t i = 0; i < chart.faces.size(); ++i)
      twiceArea += cross(chart.cornerUv[3 * i + 1] - chart.cornerUv[3 * i],
                         chart.cornerUv[3 * i + 2] - chart.cornerUv[3 * i]);
    EXPECT_GE(twiceArea, ChartOptions{}.minHullFill * twiceHullArea(chart.cornerUv)) << chart.faces.size() << " faces";
  }
}

TEST(AtlasCharts, SplitChartsSplitsTheChartsNamedAndKeepsTheRest) {
  const TriMesh torus = makeTorus(1, 0.4, 48, 24);
  ChartSet set = chartsOf(torus);
  ASSERT_GE(set.charts.size(), 3u);
  const size_t before = set.charts.size();
  const std::vector<int32_t> keptFaces = set.charts[1].faces, splitFaces = set.charts[0].faces;
  ASSERT_TRUE(splitCharts(torus, set, {0, 2}, ChartOptions{}).ok());
  expectValidCharts(torus, set, ChartOptions{}.maxStretch);
  EXPECT_GE(set.charts.size(), before + 2);
  EXPECT_EQ(set.charts[set.chartOfFace[keptFaces.front()]].faces, keptFaces) << "a chart not named is kept whole";
  std::set<int32_t> parts;  // the charts chart 0's faces are in now: two or more, each inside chart 0
  for (const int32_t f : splitFaces) parts.insert(set.chartOfFace[f]);
  EXPECT_GE(parts.size(), 2u);
  for (const int32_t c : parts)
    for (const int32_t f : set.charts[c].faces)
      EXPECT_TRUE(std::binary_search(splitFaces.begin(), splitFaces.end(), f)) << "face " << f;
}

TEST(AtlasCharts, RefusesBadOptions) {
  const TriMesh sphere = makeIcosphere(1.0, 1);
  ChartOptions options;
  options.maxStretch = 0.5;
  EXPECT_EQ(makeCharts(sphere, options).error().code, ErrorCode::InvalidArgument);
  options = {};
  options.maxCharts = -1;
  EXPECT_EQ(makeCharts(sphere, options).error().code, ErrorCode::InvalidArgument);
  for (const double fill : {-0.1, 1.5, std::nan("")}) {
    options = {};
    options.minHullFill = fill;
    EXPECT_EQ(makeCharts(sphere, options).error().code, ErrorCode::InvalidArgument) << fill;
  }
}

TEST(AtlasCharts, CancelDuringEachStage) {
  const TriMesh torus = makeTorus(1, 0.4, 48, 24);
  for (const std::string stage : {"segment", "flatten"}) {
    auto cancel = [&](const char* now, double) { return stage != now; };
    Expected<ChartSet> set = makeCharts(torus, {}, cancel);
    ASSERT_FALSE(set.ok()) << stage;
    EXPECT_EQ(set.error().code, ErrorCode::Cancelled) << stage;
  }
}

TEST(AtlasCharts, SameChartsForAnyThreadCount) {
  const TriMesh torus = makeTorus(1, 0.4, 48, 24);
  setThreadCount(1);
  const ChartSet one = chartsOf(torus);
  setThreadCount(2);
  const ChartSet two = chartsOf(torus);
  setThreadCount(0);
  EXPECT_EQ(one.chartOfFace, two.chartOfFace);
  ASSERT_EQ(one.charts.size(), two.charts.size());
  for (size_t c = 0; c < one.charts.size(); ++c) EXPECT_EQ(one.charts[c].cornerUv, two.charts[c].cornerUv);
  EXPECT_EQ(one.l2, two.l2);
}

}  // namespace
}  // namespace straightest
