// libFuzzer harness: buildAtlas on random meshes (height-field grids, caps, closed bumpy spheres and
// open tubes; sometimes two of them as one mesh, as one atlas of several meshes is made), with random
// options (stretch target, resolution, padding, chart cap).
// Invariants: a result, or an error of a known category (InvalidArgument, TooLarge: the charts do not fit
// in a tiny atlas) with a message; a result has one finite uv per face corner in [0, 1]², a chart per
// face, and, where its uv is representable on the measurement's grid, the independent measurement of
// its uv (measureAtlas) finds as many charts, every one a disk, none flipped, mirrored or overlapping,
// and the padding kept.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "fuzz_meshes.hpp"
#include "straightest/atlas/atlas.hpp"

using namespace straightest;

namespace {

TriMesh randomMesh(FuzzedDataProvider& in) {
  const int kind = in.ConsumeIntegralInRange(0, 2);
  fuzz::RandomMesh gen = kind == 0 ? fuzz::heightGrid(in, 8) : kind == 1 ? fuzz::cap(in, true) : fuzz::sphereOrTube(in);
  return fuzz::transformAndBuild(in, gen);
}

AtlasOptions randomOptions(FuzzedDataProvider& in) {
  AtlasOptions options;
  options.charts.maxStretch = 1 + in.ConsumeFloatingPointInRange(0.005, 0.5);
  options.charts.maxCharts = in.ConsumeIntegralInRange(0, 3) == 0 ? in.ConsumeIntegralInRange(1, 8) : 0;
  options.charts.minHullFill = in.ConsumeFloatingPointInRange(0.0, 1.0);
  options.charts.free.maxIterations = in.ConsumeIntegralInRange(1, 8);
  options.charts.free.timeBudgetMs = 2000;
  options.pack.resolution = in.ConsumeIntegralInRange(16, 256);
  options.pack.padding = in.ConsumeIntegralInRange(0, 4);
  return options;
}

double shortestUvEdge(const std::vector<Vec2>& cornerUv) {
  double shortest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < cornerUv.size(); ++i)
    shortest = std::min(shortest, norm(cornerUv[i] - cornerUv[i - i % 3 + (i % 3 + 1) % 3]));
  return shortest;
}

void checkAtlas(const TriMesh& mesh, const AtlasOptions& options, const Atlas& a) {
  FUZZ_CHECK(a.cornerUv.size() == 3 * static_cast<size_t>(mesh.numFaces()), "cornerUv size");
  FUZZ_CHECK(a.chartOfFace.size() == static_cast<size_t>(mesh.numFaces()), "chartOfFace size");
  for (const Vec2& q : a.cornerUv)
    FUZZ_CHECK(std::isfinite(q.x) && std::isfinite(q.y) && q.x >= 0 && q.x <= 1 && q.y >= 0 && q.y <= 1,
               "uv (%g, %g) outside [0, 1]²", q.x, q.y);
  for (int32_t c : a.chartOfFace) FUZZ_CHECK(c >= 0 && c < a.charts, "chart %d of %d", c, a.charts);
  // The measurement's predicates are exact on the 2^-24 grid (atlas_quality.hpp); a uv edge shorter than a
  // few grid steps cannot be represented there (nor in float32), as with the slivers at a pole of a huge
  // sphere, or one of two meshes a million times apart in size sharing one texel density: the measurement
  // then says nothing about the map.
  if (shortestUvEdge(a.cornerUv) < 16 * std::ldexp(1.0, -24)) return;
  const AtlasQuality q = measureAtlas(mesh, a.cornerUv, {a.width, a.height, options.pack.padding});
  if (std::getenv("FUZZ_DUMP")) {  // the case as text, to study a failure outside the fuzzer
    std::FILE* out = std::fopen(std::getenv("FUZZ_DUMP"), "w");
    std::fprintf(out, "%d %d %d %g\n", mesh.numVertices(), mesh.numFaces(), a.width, options.pack.padding);
    for (const Vec3& p : mesh.positions()) std::fprintf(out, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    for (int32_t f = 0; f < mesh.numFaces(); ++f)
      std::fprintf(out, "%d %d %d %d %.17g %.17g %.17g %.17g %.17g %.17g\n", mesh.triangle(f)[0], mesh.triangle(f)[1],
                   mesh.triangle(f)[2], a.chartOfFace[f], a.cornerUv[3 * f].x, a.cornerUv[3 * f].y,
                   a.cornerUv[3 * f + 1].x, a.cornerUv[3 * f + 1].y, a.cornerUv[3 * f + 2].x, a.cornerUv[3 * f + 2].y);
    std::fclose(out);
  }
  FUZZ_CHECK(q.charts == a.charts, "measured %d charts, atlas says %d", q.charts, a.charts);
  FUZZ_CHECK(q.nonDiskCharts == 0, "%d charts are not disks", q.nonDiskCharts);
  FUZZ_CHECK(q.flipped == 0 && q.mirroredCharts == 0, "%lld flipped faces, %lld mirrored charts", (long long)q.flipped,
             (long long)q.mirroredCharts);
  FUZZ_CHECK(q.overlaps == 0 && q.paddingViolations == 0, "%lld overlaps, %lld padding violations (gap %g)",
             (long long)q.overlaps, (long long)q.paddingViolations, q.minGapTexels);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  TriMesh mesh = randomMesh(in);
  if (in.ConsumeBool()) {
    const TriMesh other = randomMesh(in);
    Expected<TriMesh> both = combineMeshes({&mesh, &other});
    FUZZ_CHECK(both.ok(), "combineMeshes: %s", both.ok() ? "" : both.error().message.c_str());
    mesh = std::move(both.value());
  }
  const AtlasOptions options = randomOptions(in);
  Expected<Atlas> atlas = buildAtlas(mesh, options);
  if (!atlas.ok()) {
    const ErrorCode code = atlas.error().code;
    FUZZ_CHECK(code == ErrorCode::InvalidArgument || code == ErrorCode::TooLarge, "unexpected %s: %s",
               errorCodeName(code), atlas.error().message.c_str());
    FUZZ_CHECK(!atlas.error().message.empty(), "error without a message");
    return 0;
  }
  checkAtlas(mesh, options, atlas.value());
  return 0;
}
