// initial_charts.hpp — the first segmentation of a whole mesh: farthest-point seeds in every component,
// charts grown within a normal cone, and what no chart could take reseeded until every face has a chart.
#pragma once
#include <cstdint>
#include <vector>

#include "chart_growing.hpp"
#include "straightest/base/error.hpp"
#include "straightest/base/progress.hpp"

namespace straightest::atlas {

/// Per face its chart (0 .. count − 1). `cost.distanceScale` is set here from the mesh. Progress stage
/// "segment"; Cancelled when it says stop.
Expected<std::vector<int32_t>> initialCharts(const TriMesh& mesh, const std::vector<Vec3>& centroids, GrowthCost cost,
                                             const Progress& progress);

}  // namespace straightest::atlas
