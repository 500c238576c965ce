// The atlas as a whole (buildAtlas): what it promises about the uv it returns, checked by the
// independent measurement (measureAtlas: charts found from the uv alone, exact overlap predicates) and
// by the test's own winding and round-trip checks, never by the packer's bookkeeping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "geodesic_surfaces.hpp"
#include "straightest/atlas/atlas.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/samples.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

Atlas atlasOf(const TriMesh& mesh, const AtlasOptions& options = {}) {
  Expected<Atlas> atlas = buildAtlas(mesh, options);
  EXPECT_TRUE(atlas.ok()) << (atlas.ok() ? "" : atlas.error().message);
  return atlas.ok() ? std::move(atlas.value()) : Atlas{};
}

/// What every atlas must be, on any mesh: one uv per corner inside the square, every triangle
/// counter-clockwise like its face (counted here, from the uv), every chart a disk, nothing flipped,
/// mirrored or overlapping, and the padding kept between every pair of charts.
void expectSound(const TriMesh& mesh, const Atlas& atlas, double padding) {
  ASSERT_EQ(atlas.cornerUv.size(), 3 * static_cast<size_t>(mesh.numFaces()));
  int64_t clockwise = 0;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const Vec2 &a = atlas.cornerUv[3 * f], &b = atlas.cornerUv[3 * f + 1], &c = atlas.cornerUv[3 * f + 2];
    for (const Vec2& q : {a, b, c}) ASSERT_TRUE(q.x >= 0 && q.x <= 1 && q.y >= 0 && q.y <= 1) << "face " << f;
    if (!mesh.isDegenerateFace(f) && !(cross(b - a, c - a) > 0)) ++clockwise;
  }
  EXPECT_EQ(clockwise, 0);
  const AtlasQuality q = measureAtlas(mesh, atlas.cornerUv, {atlas.width, atlas.height, padding});
  EXPECT_EQ(q.charts, atlas.charts);
  EXPECT_EQ(q.nonDiskCharts, 0);
  EXPECT_EQ(q.flipped, 0);
  EXPECT_EQ(q.mirroredCharts, 0);
  EXPECT_EQ(q.overlaps, 0);
  EXPECT_EQ(q.paddingViolations, 0);
  EXPECT_GE(q.minGapTexels, padding);
  EXPECT_EQ(q.outside + q.nonFinite, 0);
  EXPECT_TRUE(std::isfinite(q.l2));
  EXPECT_GT(atlas.utilization, 0);
  EXPECT_LE(atlas.utilization, 1);
}

TEST(AtlasPipeline, DevelopableSurfacesFlattenIsometrically) {
  const TriMesh cube = testing::voxelSurface({{0, 0, 0}});
  const TriMesh cylinder = testing::prism(24, 12, 1.0, 0.25).mesh;
  const TriMesh sheet = testing::flatGrid(12, testing::GridPattern::Regular);
  for (const TriMesh* mesh : {&cube, &cylinder, &sheet}) {
    const Atlas atlas = atlasOf(*mesh);
    expectSound(*mesh, atlas, PackOptions{}.padding);
    EXPECT_NEAR(atlas.quality.l2, 1, 1e-6);
    for (double l2 : atlas.quality.chartL2) EXPECT_NEAR(l2, 1, 1e-6);
  }
}

TEST(AtlasPipeline, NonSquareAtlasMeasuresStretchOnSquareTexels) {
  // Charts are packed at one density in texels, so a developable surface stays isometric on the texels of a
  // wide or tall atlas, while its [0,1]² uv is squeezed by the aspect: the measure must see the texels.
  const TriMesh cylinder = testing::prism(24, 12, 1.0, 0.25).mesh;
  const TriMesh sheet = testing::flatGrid(12, testing::GridPattern::Regular);
  const std::pair<int32_t, int32_t> sizes[] = {{1024, 256}, {200, 900}, {512, 512}};
  for (const TriMesh* mesh : {&cylinder, &sheet})
    for (const auto& [width, height] : sizes) {
      SCOPED_TRACE(std::to_string(width) + " x " + std::to_string(height));
      AtlasOptions options;
      options.pack.width = width;
      options.pack.height = height;
      const Atlas atlas = atlasOf(*mesh, options);
      expectSound(*mesh, atlas, options.pack.padding);
      EXPECT_NEAR(atlas.quality.l2, 1, 1e-6);
      EXPECT_NEAR(atlas.quality.linf, 1, 1e-6);
      for (double l2 : atlas.quality.chartL2) EXPECT_NEAR(l2, 1, 1e-6);
      EXPECT_NEAR(atlas.quality.utilization, atlas.utilization, 1e-9);
    }
}

TEST(AtlasPipeline, AnyGenusHolesAndComponentsGiveSoundCharts) {
  const TriMesh torus = makeSample("torus").value();
  const TriMesh sphere = makeSample("sphere").value();
  const TriMesh holes = makeSample("holes").value();
  const TriMesh genus2 = testing::genusSlab(2), genus3 = testing::genusSlab(3);
  const TriMesh two = combineMeshes({&sphere, &holes}).value();
  const char* names[] = {"sphere", "torus", "genus 2", "genus 3", "holes", "two components"};
  int i = 0;
  for (const TriMesh* mesh : {&sphere, &torus, &genus2, &genus3, &holes, &two}) {
    SCOPED_TRACE(names[i++]);
    const Atlas atlas = atlasOf(*mesh);
    expectSound(*mesh, atlas, PackOptions{}.padding);
    EXPECT_LE(atlas.quality.l2, ChartOptions{}.maxStretch);
  }
}

TEST(AtlasPipeline, PaddingIsKeptAtAnyWidth) {
  const TriMesh torus = makeSample("torus").value();
  for (double padding : {0.0, 1.0, 4.0}) {
    AtlasOptions options;
    options.pack.padding = padding;
    options.pack.resolution = 512;
    expectSound(torus, atlasOf(torus, options), padding);
  }
}

TEST(AtlasPipeline, ChartsOfACombinedMeshStayInTheirMesh) {
  const TriMesh sphere = makeSample("sphere").value(), torus = makeSample("torus").value();
  const TriMesh both = combineMeshes({&sphere, &torus}).value();
  ASSERT_EQ(both.numFaces(), sphere.numFaces() + torus.numFaces());
  const Atlas atlas = atlasOf(both);
  expectSound(both, atlas, PackOptions{}.padding);
  std::vector<int> meshOfChart(atlas.charts, -1);
  for (int32_t f = 0; f < both.numFaces(); ++f) {
    const int owner = f < sphere.numFaces() ? 0 : 1;
    int& seen = meshOfChart[atlas.chartOfFace[f]];
    EXPECT_TRUE(seen == -1 || seen == owner) << "chart " << atlas.chartOfFace[f] << " spans both meshes";
    seen = owner;
  }
}

TEST(AtlasPipeline, CornerUvRoundTripsThroughObj) {
  const TriMesh torus = makeSample("torus").value();
  const Atlas atlas = atlasOf(torus);
  Expected<std::vector<Vec2>> read = readObjCornerUv(writeObjWithCornerUv(torus, atlas.cornerUv));
  ASSERT_TRUE(read.ok()) << read.error().message;
  ASSERT_EQ(read.value().size(), atlas.cornerUv.size());
  for (size_t i = 0; i < atlas.cornerUv.size(); ++i) {
    EXPECT_EQ(read.value()[i].x, atlas.cornerUv[i].x);
    EXPECT_EQ(read.value()[i].y, atlas.cornerUv[i].y);
  }
}

TEST(AtlasPipeline, SeamIsWhereTheTwoSidesDiffer) {
  const TriMesh sphere = makeSample("sphere").value();
  const Atlas atlas = atlasOf(sphere);
  EXPECT_EQ(static_cast<int64_t>(atlas.seam.size()), atlas.quality.seamEdges);
  EXPECT_NEAR(atlas.seamLength, atlas.quality.seamLength, 1e-9 * atlas.seamLength);
  EXPECT_GT(atlas.seam.size(), 0u);  // a sphere cannot be one flat piece
}

TEST(AtlasPipeline, ZeroAreaFacesGetFiniteCounterClockwiseUv) {
  // A grid whose middle row is squashed flat: its faces have zero area.
  TriMesh grid = testing::flatGrid(6, testing::GridPattern::Regular);
  std::vector<Vec3> p = grid.positions();
  for (Vec3& q : p)
    if (q.y > 1.5 && q.y < 3.5) q.y = 2;
  const TriMesh squashed = testing::buildOrFail(p, grid.triangles());
  ASSERT_GT(squashed.summary().degenerateFaces, 0);
  const Atlas atlas = atlasOf(squashed);
  for (const Vec2& q : atlas.cornerUv) ASSERT_TRUE(isFinite(q));
  EXPECT_EQ(atlas.quality.overlaps, 0);
  EXPECT_EQ(atlas.quality.flipped, 0);
}

/// A flat strip of `quads` unit-wide squares whose bottom edges each carry a needle face `height` high: a
/// vertex just above the edge's middle (offset along it a little differently in each square, so that the
/// needles meet the uv grid in different ways).
TriMesh needleStrip(int32_t quads, double height) {
  std::vector<Vec3> p;
  std::vector<Triangle> faces;
  auto bottom = [](int32_t i) { return 3 * i; };
  auto top = [](int32_t i) { return 3 * i + 1; };
  for (int32_t i = 0; i <= quads; ++i) {
    p.push_back({static_cast<double>(i), 0, 0});
    p.push_back({static_cast<double>(i), 1, 0});
    p.push_back({i + 0.5 + 0.0137 * i, height, 0});  // the needle's tip (unused after the last square)
  }
  for (int32_t i = 0; i < quads; ++i) {
    const int32_t tip = 3 * i + 2;
    faces.push_back({bottom(i), bottom(i + 1), tip});  // the needle
    faces.push_back({bottom(i), tip, top(i)});
    faces.push_back({tip, bottom(i + 1), top(i + 1)});
    faces.push_back({tip, top(i + 1), top(i)});
  }
  return testing::buildOrFail(p, faces);
}

TEST(AtlasPipeline, NeedleFacesWindAsTheirFaceOnTheGridAndInFloat32) {
  // Needles a thousand times thinner than the check's 2^-24 grid: placed as the chart is turned and moved, the
  // grid (and a float32 reader) would see some of them turned over. expectSound counts windings from the
  // double uv, the check on its grid; the test also reads each corner as float32.
  const TriMesh strip = needleStrip(24, 1e-9);
  for (const int32_t resolution : {256, 1000, 1024}) {
    AtlasOptions options;
    options.pack.width = options.pack.height = resolution;
    const Atlas atlas = atlasOf(strip, options);
    SCOPED_TRACE(resolution);
    expectSound(strip, atlas, options.pack.padding);
    EXPECT_EQ(atlas.quality.degenerate, 0);
    int32_t turnedInFloat32 = 0;
    for (int32_t f = 0; f < strip.numFaces(); ++f) {
      Vec2 q[3];
      for (int k = 0; k < 3; ++k)
        q[k] = {static_cast<float>(atlas.cornerUv[3 * f + k].x), static_cast<float>(atlas.cornerUv[3 * f + k].y)};
      turnedInFloat32 += cross(q[1] - q[0], q[2] - q[0]) < 0;
    }
    EXPECT_EQ(turnedInFloat32, 0);
  }
}

TEST(AtlasPipeline, CancelInEveryStageReturnsCancelledAndLeavesNothingBroken) {
  const TriMesh torus = makeSample("torus").value();
  for (const std::string stage : {"segment", "flatten", "pack", "measure"}) {
    Expected<Atlas> cancelled = buildAtlas(torus, {}, [&](const char* s, double) { return stage != s; });
    ASSERT_FALSE(cancelled.ok()) << stage;
    EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled) << stage;
  }
  expectSound(torus, atlasOf(torus), PackOptions{}.padding);
}

TEST(AtlasPipeline, EachStageReportsItsOwnRisingFractionFromZeroToOne) {
  // The stages in order, each from 0 to 1 and never back (a progress bar per stage never jumps back); a
  // torus whose segmentation is merged down to a cap runs every part of the flatten stage.
  const TriMesh torus = makeSample("torus").value();
  AtlasOptions options;
  options.charts.maxCharts = 5;
  std::vector<std::pair<std::string, std::vector<double>>> stages;
  const Expected<Atlas> atlas = buildAtlas(torus, options, [&](const char* stage, double fraction) {
    if (stages.empty() || stages.back().first != stage) stages.push_back({stage, {}});
    stages.back().second.push_back(fraction);
    return true;
  });
  ASSERT_TRUE(atlas.ok()) << atlas.error().message;
  ASSERT_EQ(stages.size(), 4u);
  const char* order[] = {"segment", "flatten", "pack", "measure"};
  for (size_t k = 0; k < stages.size(); ++k) {
    const auto& [name, fractions] = stages[k];
    EXPECT_EQ(name, order[k]);
    EXPECT_EQ(fractions.front(), 0) << name;
    EXPECT_EQ(fractions.back(), 1) << name;
    const auto falls = std::is_sorted_until(fractions.begin(), fractions.end());
    EXPECT_TRUE(falls == fractions.end()) << name << " falls back to " << *falls << " from " << *(falls - 1);
  }
}

TEST(AtlasPipeline, BadOptionsAreInvalidArguments) {
  const TriMesh sphere = makeSample("sphere").value();
  AtlasOptions negativePadding, noTexels, lowStretch;
  negativePadding.pack.padding = -1;
  noTexels.pack.resolution = 0;
  lowStretch.charts.maxStretch = 0.5;
  for (const AtlasOptions& options : {negativePadding, noTexels, lowStretch}) {
    Expected<Atlas> atlas = buildAtlas(sphere, options);
    ASSERT_FALSE(atlas.ok());
    EXPECT_EQ(atlas.error().code, ErrorCode::InvalidArgument) << atlas.error().message;
  }
}

}  // namespace
}  // namespace straightest
