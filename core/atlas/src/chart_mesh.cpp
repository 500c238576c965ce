// chart_mesh.cpp — corners of the chart's faces joined across the chart's inner edges (union-find): each
// class is one vertex of the chart mesh.
#include "chart_mesh.hpp"

#include <algorithm>
#include <numeric>

namespace straightest::atlas {

int32_t localFace(const std::vector<int32_t>& faces, int32_t f) {
  const auto it = std::lower_bound(faces.begin(), faces.end(), f);
  return it != faces.end() && *it == f ? static_cast<int32_t>(it - faces.begin()) : -1;
}

namespace {
int32_t findRoot(std::vector<int32_t>& parent, int32_t c) {
  while (parent[c] != c) c = parent[c] = parent[parent[c]];
  return c;
}

void join(std::vector<int32_t>& parent, int32_t a, int32_t b) {
  a = findRoot(parent, a), b = findRoot(parent, b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

/// Corner classes: corner 3i + k joined with the twin face's corner at the same vertex across every
/// inner edge.
std::vector<int32_t> cornerClasses(const TriMesh& mesh, const std::vector<int32_t>& faces) {
  std::vector<int32_t> parent(3 * faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const int32_t h = mesh.adjacency(faces[i]).twins[k];
      if (h < 0) continue;
      const int32_t j = localFace(faces, TriMesh::face(h));
      if (j < 0) continue;
      const int32_t kt = h % 3;  // the twin runs from our corner k+1 to our corner k
      join(parent, static_cast<int32_t>(3 * i + (k + 1) % 3), 3 * j + kt);
      join(parent, static_cast<int32_t>(3 * i + k), 3 * j + (kt + 1) % 3);
    }
  for (size_t c = 0; c < parent.size(); ++c) parent[c] = findRoot(parent, static_cast<int32_t>(c));
  return parent;
}
}  // namespace

Expected<TriMesh> buildChartMesh(const TriMesh& mesh, const std::vector<int32_t>& faces) {
  const std::vector<int32_t> root = cornerClasses(mesh, faces);
  std::vector<int32_t> vertexOfRoot(root.size(), -1);
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles(faces.size());
  for (size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      int32_t& v = vertexOfRoot[root[3 * i + k]];
      if (v < 0) {
        v = static_cast<int32_t>(positions.size());
        positions.push_back(mesh.position(mesh.triangle(faces[i])[k]));
      }
      triangles[i][k] = v;
    }
  return TriMesh::build(std::move(positions), std::move(triangles));
}

}  // namespace straightest::atlas
