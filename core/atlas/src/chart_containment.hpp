// chart_containment.hpp — chart pairs where a point of one (a welded vertex, a boundary edge's midpoint or a
// face centroid) lies strictly inside a triangle of the other: overlaps no boundary crossing shows (containment).
#pragma once
#include <cstdint>
#include <vector>

#include "chart_topology.hpp"
#include "uv_charts.hpp"

namespace straightest::atlas_detail {

/// Chart pair keys (chartPairKey), possibly repeated.
std::vector<uint64_t> containedPointPairs(const UvCharts& charts, const WeldedCharts& welded);

}  // namespace straightest::atlas_detail
