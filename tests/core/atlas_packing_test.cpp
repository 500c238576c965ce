// atlas_packing_test.cpp — specifications of packCharts, checked on exact geometry (nothing rasterized here):
// charts never overlap and keep the padding, stay inside the atlas, are rotated but never mirrored, and the
// scale is the largest that fits.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "atlas_chart_shapes.hpp"
#include "straightest/atlas/chart_packing.hpp"
#include "straightest/atlas/chart_segmentation.hpp"
#include "straightest/mesh/samples.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

using testing::fanChart;
using testing::mixedCharts;

struct PlacedTriangle {
  Vec2 corner[3];
  Vec2 lo, hi;  // bounding box
};

/// Every chart's triangles placed, in texels.
std::vector<std::vector<PlacedTriangle>> placedCharts(const Packing& packing, const std::vector<ChartShape>& charts) {
  std::vector<std::vector<PlacedTriangle>> placed(charts.size());
  for (size_t c = 0; c < charts.size(); ++c) {
    const auto& points = charts[c].triangles;
    for (size_t t = 0; t + 2 < points.size(); t += 3) {
      PlacedTriangle triangle;
      for (int k = 0; k < 3; ++k) triangle.corner[k] = placeInTexels(packing, static_cast<int32_t>(c), points[t + k]);
      triangle.lo = {std::min({triangle.corner[0].x, triangle.corner[1].x, triangle.corner[2].x}),
                     std::min({triangle.corner[0].y, triangle.corner[1].y, triangle.corner[2].y})};
      triangle.hi = {std::max({triangle.corner[0].x, triangle.corner[1].x, triangle.corner[2].x}),
                     std::max({triangle.corner[0].y, triangle.corner[1].y, triangle.corner[2].y})};
      placed[c].push_back(triangle);
    }
  }
  return placed;
}

double orientation(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double length2 = squaredNorm(ab);
  const double t = length2 > 0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return norm(p - (a + ab * t));
}

bool onSegment(Vec2 p, Vec2 a, Vec2 b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/// Exact predicate (up to rounding) for closed segments ab and cd sharing a point.
bool segmentsMeet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double o1 = orientation(a, b, c), o2 = orientation(a, b, d), o3 = orientation(c, d, a),
               o4 = orientation(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  return (o1 == 0 && onSegment(c, a, b)) || (o2 == 0 && onSegment(d, a, b)) || (o3 == 0 && onSegment(a, c, d)) ||
         (o4 == 0 && onSegment(b, c, d));
}

double segmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (segmentsMeet(a, b, c, d)) return 0;
  return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d), pointSegmentDistance(c, a, b),
                   pointSegmentDistance(d, a, b)});
}

/// Whether p lies in the closed triangle t; a zero-area triangle holds nothing (its edges are measured instead).
bool insideTriangle(Vec2 p, const PlacedTriangle& t) {
  const double area = orientation(t.corner[0], t.corner[1], t.corner[2]);
  if (area == 0) return false;
  const double sign = area > 0 ? 1 : -1;
  return sign * orientation(t.corner[0], t.corner[1], p) >= 0 && sign * orientation(t.corner[1], t.corner[2], p) >= 0 &&
         sign * orientation(t.corner[2], t.corner[0], p) >= 0;
}

/// The distance between two closed triangles: 0 when one holds a corner of the other or their edges meet,
/// otherwise the closest pair of edges.
double triangleDistance(const PlacedTriangle& s, const PlacedTriangle& t) {
  for (int k = 0; k < 3; ++k) {
    if (insideTriangle(s.corner[k], t) || insideTriangle(t.corner[k], s)) return 0;
  }
  double distance = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      distance = std::min(distance,
                          segmentDistance(s.corner[i], s.corner[(i + 1) % 3], t.corner[j], t.corner[(j + 1) % 3]));
  return distance;
}

/// The smallest distance (texels) between triangles of different charts; pairs whose boxes are farther apart
/// than `horizon` are skipped (they are farther than that anyway).
double closestChartsDistance(const Packing& packing, const std::vector<ChartShape>& charts, double horizon) {
  const auto placed = placedCharts(packing, charts);
  double closest = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < placed.size(); ++a)
    for (size_t b = a + 1; b < placed.size(); ++b)
      for (const PlacedTriangle& s : placed[a])
        for (const PlacedTriangle& t : placed[b]) {
          if (s.lo.x > t.hi.x + horizon || t.lo.x > s.hi.x + horizon || s.lo.y > t.hi.y + horizon ||
              t.lo.y > s.hi.y + horizon)
            continue;
          closest = std::min(closest, triangleDistance(s, t));
        }
  return closest;
}

/// Every chart point inside the atlas, at least its border of ceil(padding / 2) texels from each side (so
/// that tiled copies of the atlas keep the padding too).
void expectInsideTheBorder(const Packing& packing, const std::vector<ChartShape>& charts, double padding) {
  const double border = std::ceil(padding / 2) - 1e-7;
  for (size_t c = 0; c < charts.size(); ++c)
    for (const Vec2& uv : charts[c].triangles) {
      const Vec2 p = placeInTexels(packing, static_cast<int32_t>(c), uv);
      ASSERT_TRUE(p.x >= border && p.x <= packing.width - border && p.y >= border && p.y <= packing.height - border)
          << "chart " << c << " at " << p.x << ", " << p.y << " texels, padding " << padding;
    }
}

Packing packOrFail(const std::vector<ChartShape>& charts, const PackOptions& options) {
  auto packing = packCharts(charts, options);
  if (!packing) throw std::runtime_error("packCharts failed: " + packing.error().message);
  return std::move(packing).value();
}

/// Charts of every kind the packer meets, degenerate ones included: a point, a segment, a sliver.
std::vector<ChartShape> testCharts(int count, uint32_t seed) {
  std::vector<ChartShape> charts = mixedCharts(count, seed);
  charts.push_back(ChartShape{{{1, 1}, {1, 1}, {1, 1}}});                              // a point
  charts.push_back(ChartShape{{{0, 0}, {0.7, 0.3}, {1.4, 0.6}}});                      // a segment
  charts.push_back(ChartShape{{{0, 0}, {1, 0}, {0.5, 1e-9}}});                         // a sliver
  charts.push_back(ChartShape{{{0, 0}, {1, 0}, {1, 1}, {0, 0}, {0, 0}, {0.2, 0.9}}});  // a triangle and a point
  return charts;
}

void expectPaddingKept(const std::vector<ChartShape>& charts, const PackOptions& options) {
  const Packing packing = packOrFail(charts, options);
  ASSERT_EQ(packing.placements.size(), charts.size());
  expectInsideTheBorder(packing, charts, options.padding);
  const double closest = closestChartsDistance(packing, charts, options.padding + 1);
  EXPECT_GE(closest, options.padding - 1e-7) << "padding " << options.padding;
  EXPECT_GT(closest, 0) << "charts meet";
}

TEST(AtlasPackOverlap, MixedChartsKeepTheDefaultPadding) { expectPaddingKept(testCharts(60, 1), PackOptions{}); }

TEST(AtlasPackOverlap, SmallAtlasFractionalAndWidePadding) {
  for (const double padding : {0.5, 1.0, 3.5}) {
    PackOptions options;
    options.resolution = 256;
    options.padding = padding;
    expectPaddingKept(testCharts(40, 2), options);
  }
}

TEST(AtlasPackOverlap, RectangularAtlasWithoutRotation) {
  PackOptions options;
  options.width = 512;
  options.height = 128;
  options.rotate = false;
  options.padding = 2;
  expectPaddingKept(testCharts(40, 3), options);
}

TEST(AtlasPackOverlap, AnAtlasWiderThan4096IsPackedOnACoarserGridAndScaledUp) {
  // Past 4096 texels a side the packer works on a grid k times coarser (its cost grows with the texels): a
  // 4100-texel atlas is the 2050-texel packing at twice the scale, its gaps and border twice as wide, so the
  // padding asked for is kept (and more).
  const auto charts = testCharts(20, 6);
  PackOptions wide;
  wide.resolution = 4100;
  wide.padding = 3;
  expectPaddingKept(charts, wide);
  PackOptions half = wide;
  half.resolution = 2050;
  half.padding = 1.5;
  const Packing big = packOrFail(charts, wide), small = packOrFail(charts, half);
  EXPECT_EQ(big.width, 4100);
  EXPECT_DOUBLE_EQ(big.texelsPerUnit, 2 * small.texelsPerUnit);
  EXPECT_DOUBLE_EQ(big.utilization, small.utilization);
  for (size_t c = 0; c < charts.size(); ++c) {
    EXPECT_EQ(big.placements[c].angle, small.placements[c].angle);
    EXPECT_EQ(big.placements[c].offset.x, 2 * small.placements[c].offset.x);
    EXPECT_EQ(big.placements[c].offset.y, 2 * small.placements[c].offset.y);
  }
}

TEST(AtlasPackOverlap, AThinAtlasWiderThan4096KeepsARowForTheCharts) {
  // 16384 × 6 at padding 2: a grid 4 times coarser would be 1 texel high, all border; a coarser grid is
  // taken only as far as its short side keeps a free row.
  PackOptions options;
  options.width = 16384;
  options.height = 6;
  expectPaddingKept({fanChart({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), fanChart({{0, 0}, {2, 0}, {2, 1}, {0, 1}})}, options);
}

TEST(AtlasPackOverlap, ZeroPaddingChartsNeverOverlap) {
  PackOptions options;
  options.resolution = 128;
  options.padding = 0;
  const auto charts = testCharts(30, 4);
  const Packing packing = packOrFail(charts, options);
  expectInsideTheBorder(packing, charts, options.padding);
  // Charts may touch along texel edges; their interiors never overlap: any triangle's centroid lies outside every
  // other chart's triangles (shrunk slightly, so that touching edges do not count).
  const auto placed = placedCharts(packing, charts);
  for (size_t a = 0; a < placed.size(); ++a)
    for (const PlacedTriangle& s : placed[a]) {
      const Vec2 centroid = (s.corner[0] + s.corner[1] + s.corner[2]) / 3;
      for (size_t b = 0; b < placed.size(); ++b) {
        if (b == a) continue;
        for (const PlacedTriangle& t : placed[b]) {
          const double area = orientation(t.corner[0], t.corner[1], t.corner[2]);
          if (area <= 1e-9) continue;
          const double margin = 1e-9 * area;
          const bool inside = orientation(t.corner[0], t.corner[1], centroid) > margin &&
                              orientation(t.corner[1], t.corner[2], centroid) > margin &&
                              orientation(t.corner[2], t.corner[0], centroid) > margin;
          ASSERT_FALSE(inside) << "chart " << a << " inside chart " << b;
        }
      }
    }
}

TEST(AtlasPackPlacement, RotationKeepsAreaAndOrientation) {
  const auto charts = mixedCharts(50, 5);
  const Packing packing = packOrFail(charts, PackOptions{});
  const double s2 = packing.texelsPerUnit * packing.texelsPerUnit;
  bool turned = false;
  for (size_t c = 0; c < charts.size(); ++c) {
    turned = turned || std::abs(std::remainder(packing.placements[c].angle, 2 * kPi)) > 1e-6;
    const auto& points = charts[c].triangles;
    for (size_t t = 0; t < points.size(); t += 3) {
      const double before = orientation(points[t], points[t + 1], points[t + 2]);
      const auto at = [&](size_t k) { return placeInTexels(packing, static_cast<int32_t>(c), points[t + k]); };
      const double after = orientation(at(0), at(1), at(2));
      ASSERT_GT(before, 0);
      EXPECT_GT(after, 0) << "chart " << c << " mirrored";
      EXPECT_NEAR(after, before * s2, 1e-9 * before * s2) << "chart " << c;
    }
  }
  EXPECT_TRUE(turned) << "no chart was rotated";
}

TEST(AtlasPackPlacement, UtilizationIsTheScaledAreaOverTheAtlas) {
  const auto charts = mixedCharts(80, 6);
  PackOptions options;
  options.width = 1024;
  options.height = 512;
  const Packing packing = packOrFail(charts, options);
  double area = 0;
  for (size_t c = 0; c < charts.size(); ++c)
    for (size_t t = 0; t < charts[c].triangles.size(); t += 3) {
      const auto at = [&](size_t k) {
        return placeInTexels(packing, static_cast<int32_t>(c), charts[c].triangles[t + k]);
      };
      area += orientation(at(0), at(1), at(2)) / 2;
    }
  EXPECT_EQ(packing.width, 1024);
  EXPECT_EQ(packing.height, 512);
  EXPECT_NEAR(packing.utilization, area / (1024.0 * 512.0), 1e-9);
}

TEST(AtlasPackScale, SingleChartFillsTheAtlas) {
  // Usable: 1024 − 2 × ceil(2 / 2) = 1022 texels; a conservative raster of a side of s texels takes s + 1 of them,
  // so 1021 texels per unit fit; the scale search stops within 0.5 % of the largest that fits.
  const double best = 1021 / 1.005;
  const auto square = fanChart({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  EXPECT_GE(packOrFail({square}, PackOptions{}).texelsPerUnit, best);
  const double c = std::cos(0.5), s = std::sin(0.5);  // the same square turned by 0.5 radian
  const auto turned = fanChart({{0, 0}, {c, s}, {c - s, s + c}, {-s, c}});
  EXPECT_GE(packOrFail({turned}, PackOptions{}).texelsPerUnit, best);
  const auto long_rectangle = fanChart({{0, 0}, {2, 0}, {2, 1}, {0, 1}});
  const Packing packing = packOrFail({long_rectangle}, PackOptions{});
  EXPECT_GE(packing.texelsPerUnit, best / 2);
  EXPECT_LE(packing.texelsPerUnit, 511.0);
  EXPECT_NEAR(packing.utilization, 2 * packing.texelsPerUnit * packing.texelsPerUnit / (1024.0 * 1024.0), 1e-12);
}

TEST(AtlasPackScale, LongStripLiesAlongTheDiagonal) {
  // A 1.3 × 0.1 strip spans at most 1022 texels upright (786 per unit), but turned by 45° its bounding square
  // has side (1.3 + 0.1) / √2 = 0.99 units: 1032 per unit less the texel its conservative raster adds.
  const auto strip = fanChart({{0, 0}, {1.3, 0}, {1.3, 0.1}, {0, 0.1}});
  const Packing packing = packOrFail({strip}, PackOptions{});
  EXPECT_GE(packing.texelsPerUnit, 1025.0);
  EXPECT_LE(packing.texelsPerUnit, 1022 / ((1.3 + 0.1) / std::sqrt(2.0)));
  expectInsideTheBorder(packing, {strip}, PackOptions{}.padding);
}

TEST(AtlasPackScale, GivenDensityIsKeptOrRefused) {
  const auto charts = mixedCharts(30, 7);
  PackOptions options;
  options.resolution = 512;
  options.texelsPerUnit = 20;
  const Packing packing = packOrFail(charts, options);
  EXPECT_EQ(packing.texelsPerUnit, 20);
  expectInsideTheBorder(packing, charts, options.padding);
  options.texelsPerUnit = 400;
  const auto refused = packCharts(charts, options);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::TooLarge);
  EXPECT_NE(refused.error().message.find("do not fit"), std::string::npos) << refused.error().message;
}

TEST(AtlasPackScale, ManyChartsFillMostOfTheAtlas) {
  // 0.708 since the scale is refined on the grid twice as fine (0.69 on the atlas's grid alone).
  const Packing packing = packOrFail(mixedCharts(300, 8), PackOptions{});
  EXPECT_GE(packing.utilization, 0.70);
}

/// The charts makeCharts cuts a mesh into, as packCharts takes them.
std::vector<ChartShape> chartsOfMesh(const TriMesh& mesh) {
  const ChartSet set = makeCharts(mesh, ChartOptions{}).value();
  std::vector<ChartShape> shapes;
  for (const FlatChart& chart : set.charts) shapes.push_back(ChartShape{chart.cornerUv});
  return shapes;
}

TEST(AtlasPackScale, RealChartSetsFillTheAtlas) {
  // Organic outlines, not the synthetic polygons: the charts of the torus sample and of a genus-2 slab, packed
  // at the default padding, and their exact distances checked as for any packing.
  // The floors are a little under what the packer reaches on these few, long charts (0.659 and 0.750; the
  // torus's are rings cut open: they fit only along the diagonal, which the right angles of their minimum
  // rectangles alone left at 0.29).
  const TriMesh torus = makeSample("torus").value(), slab = testing::genusSlab(2);
  const std::pair<const TriMesh*, double> cases[] = {{&torus, 0.64}, {&slab, 0.72}};
  for (const auto& [mesh, floor] : cases) {
    const auto charts = chartsOfMesh(*mesh);
    const Packing packing = packOrFail(charts, PackOptions{});
    EXPECT_GE(packing.utilization, floor) << charts.size() << " charts";
    EXPECT_GE(closestChartsDistance(packing, charts, 3), 2 - 1e-7);
  }
}

TEST(AtlasPackErrors, BadOptionsAreInvalidArguments) {
  const std::vector<ChartShape> charts = mixedCharts(3, 9);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  std::vector<PackOptions> bad(11);
  bad[0].resolution = 0;
  bad[1].resolution = -4;
  bad[2].resolution = kMaxAtlasSide + 1;
  bad[3].width = 100;  // height 0
  bad[4].width = -1, bad[4].height = 10;
  bad[5].padding = -1;
  bad[6].padding = nan;
  bad[7].texelsPerUnit = nan;
  bad[8].texelsPerUnit = -2;
  bad[9].texelsPerUnit = inf;
  bad[10].padding = 2000;  // a border of 1000 texels on each side of 1024
  for (size_t i = 0; i < bad.size(); ++i) {
    const auto result = packCharts(charts, bad[i]);
    ASSERT_FALSE(result.ok()) << "options " << i;
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument) << "options " << i << ": " << result.error().message;
  }
}

TEST(AtlasPackErrors, BadChartsAreInvalidArguments) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::vector<ChartShape>> bad = {
      {ChartShape{}},
      {ChartShape{{{0, 0}, {1, 0}, {0, 1}, {1, 1}}}},
      {ChartShape{{{0, 0}, {1, nan}, {0, 1}}}},
      {ChartShape{{{0, 0}, {1e300, 0}, {0, 1}}}},
  };
  for (size_t i = 0; i < bad.size(); ++i) {
    const auto result = packCharts(bad[i], PackOptions{});
    ASSERT_FALSE(result.ok()) << "charts " << i;
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument) << result.error().message;
  }
}

TEST(AtlasPackErrors, NoChartsIsAnEmptyPacking) {
  const auto packing = packCharts({}, PackOptions{});
  ASSERT_TRUE(packing.ok());
  EXPECT_TRUE(packing.value().placements.empty());
  EXPECT_EQ(packing.value().width, 1024);
}

TEST(AtlasPackProgress, ReportsPackAndCancels) {
  const auto charts = mixedCharts(100, 10);
  int calls = 0;
  bool otherStage = false;
  auto cancelled = packCharts(charts, PackOptions{}, [&](const char* stage, double) {
    otherStage = otherStage || std::string(stage) != "pack";
    return ++calls < 3;
  });
  ASSERT_FALSE(cancelled.ok());
  EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
  EXPECT_FALSE(otherStage);
  double last = -1;
  bool monotone = true;
  auto finished = packCharts(charts, PackOptions{}, [&](const char*, double fraction) {
    monotone = monotone && fraction >= last;
    last = fraction;
    return true;
  });
  ASSERT_TRUE(finished.ok());
  EXPECT_TRUE(monotone);
  EXPECT_EQ(last, 1);
}

}  // namespace
}  // namespace straightest
