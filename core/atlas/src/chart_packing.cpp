// chart_packing.cpp — packCharts: the input's checks, the grid the charts are packed on (the atlas's, a finer
// one to refine the scale found, or a coarser one for a huge atlas), and the placement formula.
#include "straightest/atlas/chart_packing.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "chart_measures.hpp"
#include "chart_raster.hpp"
#include "pack_input.hpp"
#include "scale_search.hpp"

namespace straightest {
namespace {

using atlas_detail::AtlasFrame;
using atlas_detail::ChartMeasures;
using atlas_detail::PackOutcome;

constexpr const char* kStage = "pack";
// A packing's time and memory grow with the atlas's texels (its bitmaps, every chart's masks at every turn).
// Past this side the charts are packed on a grid k times coarser and placed k times larger: the same
// charts, with gaps and borders at least as wide (a coarse texel is k × k fine ones), for a few hundredths
// of utilization.
constexpr int32_t kFinestPackingSide = 4096;
// The first scale tried fills this fraction of the atlas with chart area; greedy packings of real chart sets
// reach about this, so the search brackets the answer within a step or two, climbing 4 % a step.
constexpr double kExpectedFill = 0.7, kClimb = 1 / 0.96;
// The scale found is searched again on a grid this many times finer, where it climbs 1 % a step, when that
// grid is at most kFinestRefinedSide wide (the refinement multiplies the packing's texels by 4).
constexpr int32_t kRefinement = 2, kFinestRefinedSide = 2048;
constexpr double kRefinedClimb = 1.01;

/// The search again on a grid kRefinement times finer, from the scale found (its placements, scaled, fit
/// there): a mask on the finer grid wastes half as much around its chart's outline and the padding is kept
/// to half a texel, so the charts fit larger (docs/BENCHMARKS.md). `placements` stay in atlas texels.
Expected<double> refinedOnFinerGrid(const std::vector<ChartShape>& charts, const PackOptions& options,
                                    const AtlasFrame& frame, double scale, const Progress& progress,
                                    std::vector<Placement>& placements) {
  PackOptions fineOptions = options;
  fineOptions.width = kRefinement * frame.width;
  fineOptions.height = kRefinement * frame.height;
  fineOptions.padding = kRefinement * options.padding;
  AtlasFrame fine = atlas_detail::atlasFrame(fineOptions);
  fine.border = kRefinement * frame.border;  // the atlas's border, not half a padding of fine texels
  const ChartMeasures measures = atlas_detail::measureCharts(charts, options.rotate, fine);
  for (Placement& placement : placements) placement.offset = placement.offset * static_cast<double>(kRefinement);
  const double fits = kRefinement * scale;
  // Each packing there costs four times as much: only the first order and rotation set climbs.
  const atlas_detail::ScaleSearchStart start{fits * kRefinedClimb, fits, kRefinedClimb, false};
  auto found = atlas_detail::largestFittingScale(charts, measures, fine, start, progress, placements);
  for (Placement& placement : placements) placement.offset = placement.offset / static_cast<double>(kRefinement);
  if (!found) return found.error();
  return found.value() / kRefinement;
}

/// The largest scale at which the charts fit the atlas, refined on the finer grid when it is small enough.
Expected<double> largestScale(const std::vector<ChartShape>& charts, const PackOptions& options,
                              const AtlasFrame& frame, const ChartMeasures& measures, const Progress& progress,
                              std::vector<Placement>& placements) {
  const bool refine = kRefinement * std::max(frame.width, frame.height) <= kFinestRefinedSide;
  const double start = measures.fillScale * std::sqrt(kExpectedFill);
  auto found = atlas_detail::largestFittingScale(charts, measures, frame, {start, 0, kClimb, true},
                                                 refine ? progress.range(0, 0.5) : progress, placements);
  if (!found || !refine) return found;
  return refinedOnFinerGrid(charts, options, frame, found.value(), progress.range(0.5, 1), placements);
}

Packing finishedPacking(const AtlasFrame& frame, double scale, std::vector<Placement> placements, double area) {
  Packing packing;
  packing.width = frame.width;
  packing.height = frame.height;
  packing.texelsPerUnit = scale;
  packing.placements = std::move(placements);
  packing.utilization = area * scale * scale / (static_cast<double>(frame.width) * frame.height);
  return packing;
}

Expected<Packing> packChecked(const std::vector<ChartShape>& charts, const PackOptions& options,
                              const Progress& progress) {
  const AtlasFrame frame = atlas_detail::atlasFrame(options);
  const ChartMeasures measures = atlas_detail::measureCharts(charts, options.rotate, frame);
  std::vector<Placement> placements;
  double scale = options.texelsPerUnit;
  if (charts.empty()) {
    // Nothing to place: the density asked for, or none.
  } else if (scale > 0) {
    const PackOutcome outcome = atlas_detail::packAtScale(charts, measures, frame, scale, progress, placements);
    if (outcome == PackOutcome::Cancelled) return cancelledError("packing");
    if (outcome == PackOutcome::DoesNotFit)
      return Error{ErrorCode::TooLarge, "pack: the charts do not fit in " + std::to_string(frame.width) + " x " +
                                            std::to_string(frame.height) + " texels at " + numberText(scale) +
                                            " texels per unit (texelsPerUnit 0 finds the largest that fits)"};
  } else {
    auto found = largestScale(charts, options, frame, measures, progress, placements);
    if (!found) return found.error();
    scale = found.value();
  }
  if (!progress(kStage, 1)) return cancelledError("packing");
  return finishedPacking(frame, scale, std::move(placements), measures.totalArea);
}

/// packChecked, on a coarser grid when the atlas is wider than kFinestPackingSide.
Expected<Packing> packOnFinestGrid(const std::vector<ChartShape>& charts, const PackOptions& options,
                                   const Progress& progress) {
  const AtlasFrame frame = atlas_detail::atlasFrame(options);
  int32_t k = (std::max(frame.width, frame.height) + kFinestPackingSide - 1) / kFinestPackingSide;
  // A thin atlas's short side must still hold a row of texels inside the coarse border.
  while (k > 1 && std::min(frame.width, frame.height) / k < 2 * ((frame.border + k - 1) / k) + 1) --k;
  if (k <= 1) return packChecked(charts, options, progress);
  PackOptions coarse = options;
  coarse.width = std::max(frame.width / k, 1);
  coarse.height = std::max(frame.height / k, 1);
  coarse.padding = options.padding / k;
  coarse.texelsPerUnit = options.texelsPerUnit / k;
  Expected<Packing> packed = packChecked(charts, coarse, progress);
  if (!packed) {
    if (packed.error().code != ErrorCode::TooLarge || options.texelsPerUnit <= 0) return packed;
    return Error{ErrorCode::TooLarge, "pack: the charts do not fit in " + std::to_string(frame.width) + " x " +
                                          std::to_string(frame.height) + " texels at " +
                                          numberText(options.texelsPerUnit) + " texels per unit"};
  }
  Packing packing = std::move(packed.value());
  const double coarseTexels = static_cast<double>(packing.width) * packing.height;
  packing.width = frame.width;
  packing.height = frame.height;
  packing.texelsPerUnit *= k;
  for (Placement& placement : packing.placements) placement.offset = placement.offset * static_cast<double>(k);
  packing.utilization *= coarseTexels * k * k / (static_cast<double>(frame.width) * frame.height);
  return packing;
}

}  // namespace

Expected<Packing> packCharts(const std::vector<ChartShape>& charts, const PackOptions& options,
                             const Progress& progress) {
  if (auto error = atlas_detail::checkPackInput(charts, options)) return *error;
  return guarded([&] { return packOnFinestGrid(charts, options, progress); });
}

Vec2 placeInTexels(const Packing& packing, int32_t chart, Vec2 uv) {
  const Placement& placement = packing.placements.at(chart);
  return atlas_detail::rotatedAndScaled(uv, packing.texelsPerUnit, placement.angle) + placement.offset;
}

Vec2 placeInAtlas(const Packing& packing, int32_t chart, Vec2 uv) {
  const Vec2 texels = placeInTexels(packing, chart, uv);
  return {texels.x / packing.width, texels.y / packing.height};
}

}  // namespace straightest
