// scale_search.cpp — the scale search: a bracket [fits, fails] found and halved with the first order and
// rotation set alone, then the other orders and sets tried where it failed and up from there while one fits.
#include "scale_search.hpp"

#include <algorithm>
#include <cmath>

namespace straightest::atlas_detail {
namespace {

constexpr const char* kStage = "pack";
// The search expects about this many scales (progress is reported against it).
constexpr double kExpectedTrials = 8;
// Below this the search gives up: the charts need more padded texels than the atlas has.
constexpr int kMaxShrinks = 80;
// Steps down before a scale fits: fine near the start, coarse when the charts are far from fitting (more
// charts than padded texels).
constexpr double kFineShrink = 0.96, kCoarseShrink = 0.8;

/// The packings a search makes: the charts, the atlas they go in and how far the search has got.
struct Search {
  const std::vector<ChartShape>& charts;
  const ChartMeasures& measures;
  const AtlasFrame& frame;
  const Progress& progress;
  PackingSpace space{frame};
  int trials = 0;
};

/// A range [first, end) of the order × rotation-set combinations a scale can be packed with (k: order k / sets,
/// the right angles alone when k is odd and there are two sets).
/// Neither rotation set packs better on every chart set: the extra rotations let long charts lie along the
/// diagonal and odd shapes nest, the right angles alone keep compact charts in rows.
struct Combos {
  size_t first = 0, end = 0;
};

size_t comboCount(const ChartMeasures& measures) {
  return measures.orders.size() * (measures.beyondRightAngles ? 2 : 1);
}

/// The part of the progress range that trial `done` covers, [from, to) of its work.
Progress trialPart(const Search& search, double done, double from, double to) {
  auto at = [&](double part) { return std::min(0.99, (done + part) / kExpectedTrials); };
  return search.progress.range(at(from), at(to));
}

/// The charts packed at `scale`: rasterized once, then packed with each combination of `combos` until one fits.
PackOutcome tryScale(Search& search, double scale, Combos combos, std::vector<Placement>& placements) {
  const double done = search.trials++;
  const auto masks = rasterizeAll(search.charts, search.measures.angles, scale, search.frame,
                                  trialPart(search, done, 0, 0.5));
  if (!masks) return PackOutcome::Cancelled;
  const size_t sets = search.measures.beyondRightAngles ? 2 : 1;
  const size_t count = combos.end - combos.first;
  for (size_t k = combos.first; k < combos.end; ++k) {
    const double from = 0.5 + 0.5 * (k - combos.first) / count;
    const Progress part = trialPart(search, done, from, from + 0.5 / count);  // outlives `throttled`, which keeps it
    ThrottledProgress throttled(part, kStage);
    const Rotations rotations = k % sets == 0 ? Rotations::All : Rotations::RightAngles;
    const PackOutcome outcome = packMasks(*masks, search.measures.orders[k / sets], rotations, search.space, throttled,
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
double nextScale(double scale, double fits, double fails, double upper, int shrinks, double climb) {
  if (fits == 0) return scale * (shrinks <= 3 ? kFineShrink : kCoarseShrink);
  if (fails > upper) return std::min(upper, fits * climb);
  return std::sqrt(fits * fails);
}

/// From a closed bracket: the scale where the first combination failed, packed with the others, and up from
/// there in steps of the tolerance with all of them while one fits. The largest fitting scale.
Expected<double> climbWithEveryCombo(Search& search, double fits, double fails, double upper,
                                     std::vector<Placement>& best) {
  std::vector<Placement> placements;
  Combos combos{1, comboCount(search.measures)};
  for (double scale = fails; scale <= upper && combos.first < combos.end; combos.first = 0) {
    const PackOutcome outcome = tryScale(search, scale, combos, placements);
    if (outcome == PackOutcome::Cancelled) return cancelledError("packing");
    if (outcome == PackOutcome::DoesNotFit) break;
    fits = scale;
    best.swap(placements);
    scale *= 1 + searchTolerance(search.measures, fits);
  }
  return fits;
}

}  // namespace

Expected<double> largestFittingScale(const std::vector<ChartShape>& charts, const ChartMeasures& measures,
                                     const AtlasFrame& frame, const ScaleSearchStart& start, const Progress& progress,
                                     std::vector<Placement>& best) {
  Search search{charts, measures, frame, progress};
  double upper = measures.scaleUpperBound;
  // All charts points: any scale packs them the same; 1 texel per unit is as good as any.
  if (!std::isfinite(upper)) upper = 1;
  const double unknown = 2 * upper;  // no scale has failed yet (every scale above the bound would)
  double fits = std::min(start.fits, upper), fails = unknown;
  double scale = std::min(upper, start.scale);
  std::vector<Placement> placements;
  for (int shrinks = 0;;) {
    const PackOutcome outcome = tryScale(search, scale, Combos{0, 1}, placements);
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
    if (fits > 0 && fails != unknown && (fits == fails || fails / fits <= 1 + searchTolerance(measures, fits)))
      return start.everyCombo ? climbWithEveryCombo(search, fits, fails, upper, best) : fits;
    scale = nextScale(scale, fits, fails, upper, shrinks, start.climb);
  }
}

PackOutcome packAtScale(const std::vector<ChartShape>& charts, const ChartMeasures& measures, const AtlasFrame& frame,
                        double scale, const Progress& progress, std::vector<Placement>& placements) {
  Search search{charts, measures, frame, progress};
  return tryScale(search, scale, Combos{0, comboCount(measures)}, placements);
}

}  // namespace straightest::atlas_detail
