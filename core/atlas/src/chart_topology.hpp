// chart_topology.hpp — which charts are topological disks, on each chart welded by (vertex, snapped uv).
#pragma once
#include <cstdint>
#include <vector>

#include "uv_charts.hpp"

namespace straightest::atlas_detail {

struct WeldedCharts {
  std::vector<int32_t> vertexOfCorner;  // welded vertex per corner (−1 on non-finite faces)
  std::vector<int32_t> cornerOfVertex;  // one corner of each welded vertex
  std::vector<uint8_t> isDisk;          // per chart: χ = 1, one boundary loop, no pinched boundary vertex
};

WeldedCharts weldCharts(const TriMesh& mesh, const UvCharts& charts);

}  // namespace straightest::atlas_detail
