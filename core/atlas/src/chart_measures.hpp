// chart_measures.hpp — what the scale search needs to know of the charts before packing: each chart's
// rotations and area, the order (largest first), and the scale above which they certainly cannot fit.
#pragma once
#include <cstdint>
#include <vector>

#include "pack_at_scale.hpp"

namespace straightest::atlas_detail {

struct ChartMeasures {
  ChartAngles angles;          // per chart: the rotations the packer tries
  std::vector<int32_t> order;  // charts by decreasing minimum-rectangle area (the hardest to place first)
  double totalArea = 0;        // Σ |uv triangle area|, in square units
  double largestExtent = 0;    // the longest side of any chart's minimum rectangle, in units
  double scaleUpperBound = 0;  // texels per unit above which the charts cannot fit (infinite for points)
};

ChartMeasures measureCharts(const std::vector<ChartShape>& charts, bool rotate, const AtlasFrame& frame);

}  // namespace straightest::atlas_detail
