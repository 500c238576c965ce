// chart_segmentation.cpp — makeCharts: segment, then flatten and split until every chart is acceptable,
// then merge neighbours; the charts in a fixed order and the atlas's stretch.
#include "straightest/atlas/chart_segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "chart_merging.hpp"
#include "chart_splitting.hpp"
#include "corner_stretch.hpp"
#include "face_graph.hpp"
#include "initial_charts.hpp"
#include "parallel_flattening.hpp"

namespace straightest {

namespace {
using namespace atlas;

// A face joins a chart only within 66° of its normal: wider cones wrap around bumps and are split again
// after an expensive flattening; narrower ones cut gently curved parts the free boundary flattens well.
constexpr double kConeCosine = 0.4;

std::vector<std::vector<int32_t>> facesPerChart(const std::vector<int32_t>& labels) {
  std::vector<std::vector<int32_t>> charts;
  for (int32_t f = 0; f < static_cast<int32_t>(labels.size()); ++f) {
    if (labels[f] >= static_cast<int32_t>(charts.size())) charts.resize(labels[f] + 1);
    charts[labels[f]].push_back(f);
  }
  return charts;
}

/// Flattens `pending`, splitting every unacceptable chart (unless maxCharts forbids) until none is left.
Expected<std::vector<FlatChart>> flattenAndSplit(const TriMesh& mesh, std::vector<std::vector<int32_t>> pending,
                                                 const ChartOptions& options, const ChartLimits& limits, ChartSet& set,
                                                 ChartPairs& knownBad, const Progress& progress) {
  std::vector<FlatChart> done;
  double flattenedFaces = 0;
  while (!pending.empty()) {
    const double begin = 0.8 * flattenedFaces / mesh.numFaces();
    auto flattened = flattenCharts(mesh, std::move(pending), limits, options.free, progress.range(begin, begin));
    if (!flattened) return flattened.error();
    pending.clear();
    size_t unread = flattened.value().size();  // this round's results not yet taken, this one included
    for (ChartFlattening& result : flattened.value()) {
      const size_t count = done.size() + pending.size() + unread--;
      const bool mayGrow = options.maxCharts == 0 || count < static_cast<size_t>(options.maxCharts);
      // The cap keeps a chart that is only too stretched; one that has no flat map (its faces would lie
      // apart and overlap) is split whatever the cap: the atlas never overlaps.
      if (result.acceptable || (!mayGrow && std::isfinite(result.chart.l2))) {
        if (!result.acceptable) set.capped = true, set.overStretch += result.chart.l2 > options.maxStretch;
        flattenedFaces += static_cast<double>(result.chart.faces.size());
        done.push_back(std::move(result.chart));
        continue;
      }
      std::vector<std::vector<int32_t>> parts = splitChart(mesh, result.chart.faces);
      ++set.splits;
      if (parts.size() == 2) knownBad.insert(chartPair(chartKey(parts[0]), chartKey(parts[1])));
      for (auto& part : parts) pending.push_back(std::move(part));
    }
  }
  return done;
}

/// The charts in order of their first face, chartOfFace and the whole atlas's stretch.
void finish(const TriMesh& mesh, std::vector<FlatChart> charts, ChartSet& set) {
  std::sort(charts.begin(), charts.end(),
            [](const FlatChart& a, const FlatChart& b) { return a.faces.front() < b.faces.front(); });
  set.chartOfFace.assign(mesh.numFaces(), -1);
  std::vector<int32_t> faces;
  std::vector<Vec2> cornerUv;
  for (size_t c = 0; c < charts.size(); ++c) {
    for (int32_t f : charts[c].faces) set.chartOfFace[f] = static_cast<int32_t>(c);
    faces.insert(faces.end(), charts[c].faces.begin(), charts[c].faces.end());
    cornerUv.insert(cornerUv.end(), charts[c].cornerUv.begin(), charts[c].cornerUv.end());
  }
  const CornerStretch stretch = cornerStretch(mesh, faces, cornerUv);
  set.l2 = stretch.l2;
  set.linf = stretch.linf;
  set.charts = std::move(charts);
}

Expected<ChartSet> charts(const TriMesh& mesh, const ChartOptions& options, const Progress& progress) {
  GrowthCost cost;
  cost.minNormalCosine = kConeCosine;
  cost.maxFaces = options.maxChartFaces;
  auto labels = initialCharts(mesh, faceCentroids(mesh), cost, progress);
  if (!labels) return labels.error();
  ChartSet set;
  ChartPairs knownBad;
  const ChartLimits limits{options.maxStretch, options.minHullFill};
  auto flat = flattenAndSplit(mesh, facesPerChart(labels.value()), options, limits, set, knownBad, progress);
  if (!flat) return flat.error();
  auto merges = mergeCharts(mesh, flat.value(), knownBad, options, limits, progress.range(0.8, 0.9));
  if (!merges) return merges.error();
  set.merges = merges.value();
  std::vector<FlatChart>& charts = flat.value();
  if (options.maxCharts > 0 && charts.size() > static_cast<size_t>(options.maxCharts)) {
    // The cap asks for fewer charts than the segmentation made: merge further, whatever the stretch.
    auto more = mergeDownTo(mesh, charts, options.maxCharts, options.free, progress.range(0.9, 1));
    if (!more) return more.error();
    set.merges += more.value();
    set.capped = true;
    set.overStretch = static_cast<int32_t>(
        std::count_if(charts.begin(), charts.end(), [&](const FlatChart& c) { return c.l2 > options.maxStretch; }));
  }
  finish(mesh, std::move(charts), set);
  if (!progress("flatten", 1)) return cancelledError("atlas flattening");
  return set;
}
Expected<void> resplit(const TriMesh& mesh, ChartSet& set, const std::vector<int32_t>& charts,
                       const ChartOptions& options, const Progress& progress) {
  std::vector<uint8_t> chosen(set.charts.size(), 0);
  for (const int32_t c : charts) chosen.at(c) = 1;
  std::vector<FlatChart> kept;
  std::vector<std::vector<int32_t>> pending;
  for (size_t c = 0; c < set.charts.size(); ++c) {
    if (!chosen[c] || set.charts[c].faces.size() < 2) {
      kept.push_back(std::move(set.charts[c]));
      continue;
    }
    for (auto& part : splitChart(mesh, set.charts[c].faces)) pending.push_back(std::move(part));
    ++set.splits;
  }
  ChartPairs knownBad;
  auto flat = flattenAndSplit(mesh, std::move(pending), options, ChartLimits{options.maxStretch, options.minHullFill},
                              set, knownBad, progress);
  if (!flat) return flat.error();
  for (FlatChart& chart : flat.value()) kept.push_back(std::move(chart));
  finish(mesh, std::move(kept), set);
  return {};
}
}  // namespace

Expected<void> splitCharts(const TriMesh& mesh, ChartSet& set, const std::vector<int32_t>& charts,
                           const ChartOptions& options, const Progress& progress) {
  return guarded([&] { return resplit(mesh, set, charts, options, progress); });
}

Expected<ChartSet> makeCharts(const TriMesh& mesh, const ChartOptions& options, const Progress& progress) {
  if (!std::isfinite(options.maxStretch) || options.maxStretch < 1)
    return Error{ErrorCode::InvalidArgument,
                 "maxStretch must be a finite number >= 1, not " + numberText(options.maxStretch)};
  if (!(options.minHullFill >= 0 && options.minHullFill <= 1))
    return Error{ErrorCode::InvalidArgument,
                 "minHullFill must be a number in [0, 1], not " + numberText(options.minHullFill)};
  if (options.maxCharts < 0)
    return Error{ErrorCode::InvalidArgument,
                 "maxCharts must be 0 (no cap) or positive, not " + std::to_string(options.maxCharts)};
  if (options.maxChartFaces < 0)
    return Error{ErrorCode::InvalidArgument,
                 "maxChartFaces must be 0 (no cap) or positive, not " + std::to_string(options.maxChartFaces)};
  return guarded([&] { return charts(mesh, options, progress); });
}

}  // namespace straightest
