// chart_measures.hpp — what the scale search needs to know of the charts before packing: each chart's
// rotations and area, the order (largest first), and the scale above which they certainly cannot fit.
#pragma once
#include <cstdint>
#include <vector>

#include "pack_at_scale.hpp"

namespace straightest::atlas_detail {

struct ChartMeasures {
  ChartAngles angles;              // per chart: the rotations the packer tries
  bool beyondRightAngles = false;  // some chart has more rotations than the right angles
  // Charts by decreasing minimum-rectangle area, longest side and area: the hardest to place first, each
  // order a different greedy packing (one that fits is enough).
  std::vector<std::vector<int32_t>> orders;
  double totalArea = 0;        // Σ |uv triangle area|, in square units
  double largestExtent = 0;    // the longest side of any chart's minimum rectangle, in units
  double fillScale = 0;        // texels per unit at which the chart area equals the usable area (inf: no area)
  double scaleUpperBound = 0;  // texels per unit above which the charts cannot fit (infinite for points)
};

ChartMeasures measureCharts(const std::vector<ChartShape>& charts, bool rotate, const AtlasFrame& frame);

}  // namespace straightest::atlas_detail
