// uv_charts.cpp — charts as connected components of uv-joined faces (union–find), and the seam edges.
#include "uv_charts.hpp"

#include "straightest/base/disjoint_sets.hpp"

#include <cmath>
#include <numeric>

namespace straightest::atlas_detail {

namespace {

void snapCorners(const std::vector<Vec2>& cornerUv, UvCharts& c) {
  const size_t faces = cornerUv.size() / 3;
  c.corner.resize(cornerUv.size());
  c.finiteFace.assign(faces, 1);
  for (size_t i = 0; i < cornerUv.size(); ++i) {
    if (std::isfinite(cornerUv[i].x) && std::isfinite(cornerUv[i].y)) {
      c.corner[i] = snap(cornerUv[i]);
    } else {
      ++c.nonFiniteCorners;
      c.finiteFace[i / 3] = 0;
    }
  }
}

/// Joins halfedges whose twin's endpoints snap to the same uv (twin t runs head(h) → tail(h)); counts the
/// interior edges that are not joined as seams.
void joinAcrossEdges(const TriMesh& mesh, UvCharts& c, DisjointSets& sets) {
  const int32_t halfedges = 3 * mesh.numFaces();
  c.joined.assign(halfedges, 0);
  for (int32_t h = 0; h < halfedges; ++h) {
    const int32_t t = mesh.twin(h);
    if (t < h) continue;  // boundary, or seen from its twin
    const int32_t f = TriMesh::face(h), g = TriMesh::face(t);
    const bool same = c.finiteFace[f] && c.finiteFace[g] && c.corner[h] == c.corner[TriMesh::next(t)] &&
                      c.corner[TriMesh::next(h)] == c.corner[t];
    if (same) {
      c.joined[h] = c.joined[t] = 1;
      sets.unite(f, g);
    } else {
      ++c.seamEdges;
      c.seamLength += norm(mesh.position(mesh.head(h)) - mesh.position(mesh.tail(h)));
    }
  }
}

}  // namespace

UvCharts findUvCharts(const TriMesh& mesh, const std::vector<Vec2>& cornerUv) {
  UvCharts c;
  const int32_t faces = mesh.numFaces();
  snapCorners(cornerUv, c);
  DisjointSets sets(faces);
  joinAcrossEdges(mesh, c, sets);
  c.chartOfFace.assign(faces, -1);
  std::vector<int32_t> chartOfRoot(faces, -1);
  for (int32_t f = 0; f < faces; ++f) {
    if (!c.finiteFace[f]) continue;
    int32_t& chart = chartOfRoot[sets.find(f)];
    if (chart < 0) chart = c.charts++;
    c.chartOfFace[f] = chart;
  }
  return c;
}

}  // namespace straightest::atlas_detail
