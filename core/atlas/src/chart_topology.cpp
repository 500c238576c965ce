// chart_topology.cpp — χ = V − E + F and boundary loops of each chart, with corners welded where they
// share both mesh vertex and snapped uv (so a chart touching itself at one vertex is not a disk).
#include "chart_topology.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace straightest::atlas_detail {

namespace {

/// Welds corners of finite faces by (chart, mesh vertex, snapped uv), sorting them by that key.
void weldCorners(const TriMesh& mesh, const UvCharts& charts, WeldedCharts& w) {
  const auto& tris = mesh.triangles();
  auto key = [&](int32_t c) {
    const GridPoint& p = charts.corner[c];
    return std::make_tuple(charts.chartOfFace[c / 3], tris[c / 3][c % 3], p.x, p.y);
  };
  std::vector<int32_t> order;
  for (int32_t c = 0; c < 3 * mesh.numFaces(); ++c)
    if (charts.finiteFace[c / 3]) order.push_back(c);
  std::sort(order.begin(), order.end(), [&](int32_t a, int32_t b) { return key(a) < key(b); });
  w.vertexOfCorner.assign(3 * static_cast<size_t>(mesh.numFaces()), -1);
  for (size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || key(order[i]) != key(order[i - 1])) w.cornerOfVertex.push_back(order[i]);
    w.vertexOfCorner[order[i]] = static_cast<int32_t>(w.cornerOfVertex.size()) - 1;
  }
}

/// Union–find over welded vertices.
int32_t findRoot(std::vector<int32_t>& parent, int32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

WeldedCharts weldCharts(const TriMesh& mesh, const UvCharts& charts) {
  WeldedCharts w;
  weldCorners(mesh, charts, w);
  const int32_t nv = static_cast<int32_t>(w.cornerOfVertex.size());
  std::vector<int64_t> chi(charts.charts, 0), loops(charts.charts, 0);
  std::vector<int32_t> boundaryOut(nv, 0), parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  // Twice χ, so that an interior edge's two halfedges subtract one each: 2V − 2E + 2F.
  for (int32_t v = 0; v < nv; ++v) chi[charts.chartOfFace[w.cornerOfVertex[v] / 3]] += 2;
  for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h) {
    const int32_t chart = charts.chartOfFace[TriMesh::face(h)];
    if (chart < 0) continue;
    if (h % 3 == 0) chi[chart] += 2;
    const bool boundary = isChartBoundary(charts, h);
    // − 2E: an interior edge is two joined halfedges, a boundary edge one halfedge.
    if (boundary) {
      chi[chart] -= 2;
      const int32_t a = w.vertexOfCorner[h], b = w.vertexOfCorner[TriMesh::next(h)];
      ++boundaryOut[a];
      parent[findRoot(parent, a)] = findRoot(parent, b);
    } else {
      chi[chart] -= 1;
    }
  }
  std::vector<uint8_t> pinched(charts.charts, 0);
  for (int32_t v = 0; v < nv; ++v) {
    const int32_t chart = charts.chartOfFace[w.cornerOfVertex[v] / 3];
    if (boundaryOut[v] > 1) pinched[chart] = 1;
    if (boundaryOut[v] > 0 && findRoot(parent, v) == v) ++loops[chart];
  }
  w.isDisk.assign(charts.charts, 0);
  for (int32_t c = 0; c < charts.charts; ++c) w.isDisk[c] = chi[c] == 2 && loops[c] == 1 && !pinched[c];
  return w;
}

}  // namespace straightest::atlas_detail
