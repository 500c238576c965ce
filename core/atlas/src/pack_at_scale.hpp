// pack_at_scale.hpp — one greedy packing at a fixed texel density: charts in a given order, each at the
// rotation and first-fit position that keep the packed extent lowest.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "straightest/atlas/chart_packing.hpp"

namespace straightest::atlas_detail {

struct AtlasFrame {
  int32_t width = 0, height = 0, border = 0;
  double padding = 0;
};

/// Per chart, the rotations worth trying (the minimum-area rectangle's and its right angles, or 0 alone).
using ChartAngles = std::vector<std::vector<double>>;

enum class PackOutcome { Packed, DoesNotFit, Cancelled };

/// Places every chart of `charts`, in `order`, at `texelsPerUnit`; `placements` (one per chart, input order)
/// is complete only when the outcome is Packed. `keepGoing(fraction)` is asked as the charts go; false cancels.
PackOutcome packAtScale(const std::vector<ChartShape>& charts, const ChartAngles& angles,
                        const std::vector<int32_t>& order, double texelsPerUnit, const AtlasFrame& frame,
                        const std::function<bool(double)>& keepGoing, std::vector<Placement>& placements);

}  // namespace straightest::atlas_detail
