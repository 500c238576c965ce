// chart_splitting.hpp — a chart that flattened badly, cut in two: two far-apart seeds regrown inside it.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/mesh/trimesh.hpp"

namespace straightest::atlas {

/// The chart's faces (ascending, edge-connected, at least 2) as two edge-connected parts, each ascending:
/// seeds at the two ends of a farthest-point pass over the chart's dual graph, every face grown into one
/// of them. When the chart has no mesh of its own (every face of it has zero area) each face is a part.
std::vector<std::vector<int32_t>> splitChart(const TriMesh& mesh, const std::vector<int32_t>& faces);

}  // namespace straightest::atlas
