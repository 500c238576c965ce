// chart_smoothing.cpp — region growing on faces leaves borders with single-face teeth (a face reached first by
// the chart it sticks out of): they lengthen the seams and make outlines that waste texels when packed.
#include "chart_smoothing.hpp"

#include <algorithm>

#include "face_graph.hpp"

namespace straightest::atlas {
namespace {

// The first sweep takes off the teeth, the second the teeth that uncovered; more sweeps would go on to eat
// strips one face wide, which the splits after flattening judge better.
constexpr int kSweeps = 2;

/// The chart other than `own` that meets face f along at least two edges, or -1.
int32_t chartAcrossTwoEdges(const TriMesh& mesh, const std::vector<int32_t>& labels, int32_t f, int32_t own) {
  int32_t across[3];
  for (int k = 0; k < 3; ++k) {
    const int32_t g = faceAcross(mesh, f, k);
    across[k] = g < 0 ? -1 : labels[g];
  }
  for (int k = 0; k < 3; ++k) {
    const int32_t chart = across[k];
    if (chart < 0 || chart == own) continue;
    if (chart == across[(k + 1) % 3] || chart == across[(k + 2) % 3]) return chart;
  }
  return -1;
}

}  // namespace

void smoothChartBorders(const TriMesh& mesh, std::vector<int32_t>& labels, int32_t maxFaces) {
  if (labels.empty()) return;
  std::vector<int32_t> size(*std::max_element(labels.begin(), labels.end()) + 1, 0);
  for (const int32_t label : labels) ++size[label];
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    bool moved = false;
    for (int32_t f = 0; f < mesh.numFaces(); ++f) {
      const int32_t own = labels[f];
      if (size[own] == 1) continue;
      const int32_t other = chartAcrossTwoEdges(mesh, labels, f, own);
      if (other < 0 || (maxFaces > 0 && size[other] >= maxFaces)) continue;
      labels[f] = other;
      --size[own];
      ++size[other];
      moved = true;
    }
    if (!moved) return;
  }
}

}  // namespace straightest::atlas
