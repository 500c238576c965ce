// atlas.cpp — the atlas pipeline: charts, packing, one uv per face corner, and the independent check.
#include "straightest/atlas/atlas.hpp"

#include <algorithm>
#include <cmath>

#include "grid_windings.hpp"

namespace straightest {
namespace {

std::vector<ChartShape> chartShapes(const ChartSet& set) {
  std::vector<ChartShape> shapes(set.charts.size());
  for (size_t c = 0; c < set.charts.size(); ++c) shapes[c].triangles = set.charts[c].cornerUv;
  return shapes;
}

std::vector<Vec2> placedCornerUv(const TriMesh& mesh, const ChartSet& set, const Packing& packing) {
  std::vector<Vec2> cornerUv(3 * static_cast<size_t>(mesh.numFaces()));
  for (size_t c = 0; c < set.charts.size(); ++c) {
    const FlatChart& chart = set.charts[c];
    for (size_t i = 0; i < chart.faces.size(); ++i)
      for (int k = 0; k < 3; ++k)
        cornerUv[3 * static_cast<size_t>(chart.faces[i]) + k] = placeInAtlas(packing, static_cast<int32_t>(c),
                                                                             chart.cornerUv[3 * i + k]);
  }
  return cornerUv;
}

bool sameUv(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }

/// Interior mesh edges whose endpoints have different uv on the two sides (each edge once).
void collectSeam(const TriMesh& mesh, Atlas& atlas) {
  for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h) {
    const int32_t t = mesh.twin(h);
    if (t < 0 || t < h) continue;
    const Vec2 tailHere = atlas.cornerUv[h], headHere = atlas.cornerUv[TriMesh::next(h)];
    const Vec2 tailThere = atlas.cornerUv[TriMesh::next(t)], headThere = atlas.cornerUv[t];
    if (sameUv(tailHere, tailThere) && sameUv(headHere, headThere)) continue;
    atlas.seam.push_back({mesh.tail(h), mesh.head(h)});
    atlas.seamLength += norm(mesh.position(mesh.head(h)) - mesh.position(mesh.tail(h)));
  }
}

void record(Timings* timings, const char* stage, double ms) {
  if (timings) timings->add(stage, ms);
}

// A chart whose outline comes closer to itself than the uv's precision may cross itself once turned, scaled
// and placed (the independent check sees it on its 2^-24 grid): such charts are split and all packed again.
// A round or two clears them; the bound only keeps a pathological mesh from looping.
constexpr int kRepairRounds = 4;

/// The atlas of the charts as packed, measured by the independent check.
Atlas assemble(const TriMesh& mesh, const ChartSet& set, const Packing& packing, double padding) {
  Atlas atlas;
  atlas.cornerUv = placedCornerUv(mesh, set, packing);
  atlas_detail::mendGridWindings(mesh, set.chartOfFace, atlas.cornerUv);
  atlas.chartOfFace = set.chartOfFace;
  atlas.charts = static_cast<int32_t>(set.charts.size());
  atlas.width = packing.width;
  atlas.height = packing.height;
  atlas.texelsPerUnit = packing.texelsPerUnit;
  atlas.utilization = packing.utilization;
  atlas.splits = set.splits;
  atlas.merges = set.merges;
  atlas.capped = set.capped;
  collectSeam(mesh, atlas);
  atlas.quality = measureAtlas(mesh, atlas.cornerUv, {atlas.width, atlas.height, padding});
  return atlas;
}

/// The set's charts that the check found overlapping.
std::vector<int32_t> overlappingCharts(const ChartSet& set, const AtlasQuality& quality) {
  std::vector<int32_t> charts;
  for (const int32_t f : quality.overlappingFaces) charts.push_back(set.chartOfFace[f]);
  std::sort(charts.begin(), charts.end());
  charts.erase(std::unique(charts.begin(), charts.end()), charts.end());
  return charts;
}

}  // namespace

Expected<Atlas> buildAtlas(const TriMesh& mesh, const AtlasOptions& options, const Progress& progress) {
  Stopwatch total, lap;
  // Each stage reports its own 0..1 (progress.hpp). A re-split after packing finds overlaps (rare) is flatten
  // work after flatten finished (reported at its end), and packs again: the pack stage then runs once more.
  Expected<ChartSet> set = makeCharts(mesh, options.charts, progress);
  if (!set) return set.error();
  record(options.timings, "charts", lap.lap());
  Atlas atlas;
  for (int round = 0;; ++round) {
    Expected<Packing> packing = packCharts(chartShapes(set.value()), options.pack, progress);
    if (!packing) return packing.error();
    record(options.timings, "pack", lap.lap());
    if (!progress("measure", 0)) return cancelledError("atlas");
    atlas = assemble(mesh, set.value(), packing.value(), options.pack.padding);
    record(options.timings, "measure", lap.lap());
    if (atlas.quality.overlaps == 0 || round == kRepairRounds) break;
    Expected<void> split = splitCharts(mesh, set.value(), overlappingCharts(set.value(), atlas.quality), options.charts,
                                       progress.range(1, 1));
    if (!split) return split.error();
    record(options.timings, "charts", lap.lap());
  }
  record(options.timings, "total", total.ms());
  if (!progress("measure", 1)) return cancelledError("atlas");
  return atlas;
}

Expected<TriMesh> combineMeshes(const std::vector<const TriMesh*>& meshes) {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  for (const TriMesh* mesh : meshes) {
    const int32_t offset = static_cast<int32_t>(positions.size());
    positions.insert(positions.end(), mesh->positions().begin(), mesh->positions().end());
    for (Triangle t : mesh->triangles()) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  if (meshes.empty()) return Error{ErrorCode::Empty, "no mesh to combine"};
  return TriMesh::build(std::move(positions), std::move(triangles));
}

}  // namespace straightest
