// chart_packing.cpp — packCharts: the input's checks, then the search for the largest texel density at which
// the greedy packing fits (or the one packing at the density asked for), and the placement formula.
#include "straightest/atlas/chart_packing.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "chart_measures.hpp"
#include "chart_raster.hpp"
#include "pack_input.hpp"

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
// The scale search expects about this many packings (progress is reported against it).
constexpr double kExpectedTrials = 12;
// Below this the search gives up: the charts need more padded texels than the atlas has.
constexpr int kMaxShrinks = 80;
// The first scale tried fills this fraction of the atlas with chart area; greedy packings of real chart sets
// reach about this, so the search brackets the answer within a step or two.
constexpr double kExpectedFill = 0.7;
// Steps of the search before it has a bracket: fine near the estimate, coarse when the charts are far from
// fitting (more charts than padded texels).
constexpr double kFineStep = 0.96, kCoarseShrink = 0.8;

struct Search {
  const std::vector<ChartShape>& charts;
  const ChartMeasures& measures;
  const AtlasFrame& frame;
  const Progress& progress;
  atlas_detail::PackingSpace space{frame};
  int trials = 0;
};

/// The part of the progress range that trial `done` covers, [from, to) of its work.
Progress trialPart(const Search& search, double done, double from, double to) {
  auto at = [&](double part) { return std::min(0.99, (done + part) / kExpectedTrials); };
  return search.progress.range(at(from), at(to));
}

/// The charts packed at `scale`: rasterized once, then packed in each order, at every rotation and then at
/// the right angles alone, until one packing fits. Neither rotation set packs better on every chart set: the
/// extra rotations let long charts lie along the diagonal and odd shapes nest, the right angles alone keep
/// compact charts in rows.
PackOutcome tryScale(Search& search, double scale, std::vector<Placement>& placements) {
  using atlas_detail::Rotations;
  const double done = search.trials++;
  const auto masks = atlas_detail::rasterizeAll(search.charts, search.measures.angles, scale, search.frame,
                                                trialPart(search, done, 0, 0.5));
  if (!masks) return PackOutcome::Cancelled;
  std::vector<Rotations> rotationSets{Rotations::All};
  if (search.measures.beyondRightAngles) rotationSets.push_back(Rotations::RightAngles);
  const auto& orders = search.measures.orders;
  const size_t packings = orders.size() * rotationSets.size();
  for (size_t k = 0; k < packings; ++k) {
    const Progress part = trialPart(search, done, 0.5 + 0.5 * k / packings, 0.5 + 0.5 * (k + 1) / packings);
    ThrottledProgress throttled(part, kStage);
    const PackOutcome outcome = atlas_detail::packMasks(*masks, orders[k / rotationSets.size()],
                                                        rotationSets[k % rotationSets.size()], search.space, throttled,
                                                        placements);
    if (outcome != PackOutcome::DoesNotFit) return outcome;
  }
  return PackOutcome::DoesNotFit;
}

/// The search stops when the bracket [fits, fails] is within 0.5 % (1 % of utilization at most: below that the
/// greedy packing's luck at one scale or the next outweighs the step), or within half a texel on the largest
/// chart when that is wider (a small atlas, where a finer scale moves no texel).
double searchTolerance(const ChartMeasures& measures, double fittingScale) {
  const double halfTexel = 0.5 / std::max(fittingScale * measures.largestExtent, 1e-300);
  return std::max(0.005, halfTexel);
}

/// The next scale to try: down in growing steps until one fits, then up in steps until one fails (never past
/// the bound), then the geometric middle of the bracket.
double nextScale(double scale, double fits, double fails, double upper, int shrinks) {
  if (fits == 0) return scale * (shrinks <= 3 ? kFineStep : kCoarseShrink);
  if (fails > upper) return std::min(upper, fits / kFineStep);
  return std::sqrt(fits * fails);
}

/// The largest scale (within the tolerance) at which the greedy packing fits; its placements in `best`. The
/// search starts where the charts would fill kExpectedFill of the atlas, so that a few packings bracket it.
Expected<double> largestFittingScale(Search& search, std::vector<Placement>& best) {
  double upper = search.measures.scaleUpperBound;
  // All charts points: any scale packs them the same; 1 texel per unit is as good as any.
  if (!std::isfinite(upper)) upper = 1;
  const double unknown = 2 * upper;  // no scale has failed yet (every scale above the bound would)
  double fits = 0, fails = unknown;
  double scale = std::min(upper, search.measures.fillScale * std::sqrt(kExpectedFill));
  std::vector<Placement> placements;
  for (int shrinks = 0;;) {
    const PackOutcome outcome = tryScale(search, scale, placements);
    if (outcome == PackOutcome::Cancelled) return cancelledError("packing");
    if (outcome == PackOutcome::Packed) {
      fits = scale;
      best.swap(placements);
    } else {
      fails = scale;
    }
    if (fits == 0 && ++shrinks > kMaxShrinks)
      return Error{ErrorCode::TooLarge, "pack: the charts do not fit at any scale"};
    if (fits == upper) return fits;
    if (fits > 0 && fails != unknown && (fits == fails || fails / fits <= 1 + searchTolerance(search.measures, fits)))
      return fits;
    scale = nextScale(scale, fits, fails, upper, shrinks);
  }
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
  Search search{charts, measures, frame, progress};
  std::vector<Placement> placements;
  double scale = options.texelsPerUnit;
  if (charts.empty()) {
    // Nothing to place: the density asked for, or none.
  } else if (scale > 0) {
    const PackOutcome outcome = tryScale(search, scale, placements);
    if (outcome == PackOutcome::Cancelled) return cancelledError("packing");
    if (outcome == PackOutcome::DoesNotFit)
      return Error{ErrorCode::TooLarge, "pack: the charts do not fit in " + std::to_string(frame.width) + " x " +
                                            std::to_string(frame.height) + " texels at " + numberText(scale) +
                                            " texels per unit (texelsPerUnit 0 finds the largest that fits)"};
  } else {
    auto found = largestFittingScale(search, placements);
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
  const int32_t k = (std::max(frame.width, frame.height) + kFinestPackingSide - 1) / kFinestPackingSide;
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
