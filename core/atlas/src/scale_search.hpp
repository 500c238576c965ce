// scale_search.hpp — the largest texel density at which the greedy packing fits, found with one order and
// rotation set and then tried with the others at its top; or the one packing at a density asked for.
#pragma once
#include <vector>

#include "chart_measures.hpp"
#include "straightest/base/error.hpp"

namespace straightest::atlas_detail {

/// Where a search starts: the first scale tried, a scale known to fit (0: none; else its placements are the
/// search's `best` on entry), the factor each step up multiplies the scale by until a scale fails, and whether
/// the other orders and rotation sets are tried at the top of the bracket (or only the first one is).
struct ScaleSearchStart {
  double scale = 0;
  double fits = 0;
  double climb = 1;
  bool everyCombo = true;
};

/// The charts at the largest scale (within half a percent) at which a greedy packing fits, their placements
/// in `best`. TooLarge when they fit at no scale; Cancelled when `progress` says so.
Expected<double> largestFittingScale(const std::vector<ChartShape>& charts, const ChartMeasures& measures,
                                     const AtlasFrame& frame, const ScaleSearchStart& start, const Progress& progress,
                                     std::vector<Placement>& best);

/// The charts packed at `scale`, each order and rotation set in turn until one fits.
PackOutcome packAtScale(const std::vector<ChartShape>& charts, const ChartMeasures& measures, const AtlasFrame& frame,
                        double scale, const Progress& progress, std::vector<Placement>& placements);

}  // namespace straightest::atlas_detail
