// chart_smoothing.hpp — chart borders without teeth: a face that another chart meets along two of its edges
// joins that chart, so borders follow the surface instead of zigzagging around single faces.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/mesh/trimesh.hpp"

namespace straightest::atlas {

/// Moves every face that one other chart meets along two or three of its edges into that chart, sweeping the
/// faces in order twice (or until a sweep moves none). A chart is never emptied, so the labels keep their
/// numbers; a face leaves a chart it meets along one edge at most, so no chart comes apart; a chart of
/// `maxFaces` faces takes no more (0: no cap).
void smoothChartBorders(const TriMesh& mesh, std::vector<int32_t>& labels, int32_t maxFaces = 0);

}  // namespace straightest::atlas
