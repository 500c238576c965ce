// Cutting a surface open along a seam (see cut_open.hpp): one copy of a vertex per wedge of its fan.
#include "cut_open.hpp"

#include <algorithm>
#include <unordered_set>

namespace straightest::detail {

std::optional<CutOpen> cutOpen(const TriMesh& surface, const std::vector<std::array<int32_t, 2>>& seam,
                               const Progress& progress, const char* stage) {
  ThrottledProgress tick(progress, stage);
  const int32_t n = surface.numVertices();
  auto key = [n](int32_t a, int32_t b) { return int64_t(std::min(a, b)) * n + std::max(a, b); };
  std::unordered_set<int64_t> seamEdges;
  std::vector<int32_t> seamDegree(n, 0);
  for (const auto& e : seam) {
    seamEdges.insert(key(e[0], e[1]));
    ++seamDegree[e[0]];
    ++seamDegree[e[1]];
  }
  auto onSeam = [&](int32_t h) { return seamEdges.count(key(surface.tail(h), surface.head(h))) > 0; };

  CutOpen out;
  std::vector<int32_t> cornerCopy(3 * size_t(surface.numFaces()), -1);  // by outgoing halfedge = corner
  auto newCopy = [&](int32_t v) {
    out.positions.push_back(surface.position(v));
    out.copyOf.push_back(v);
    return int32_t(out.copyOf.size() - 1);
  };
  for (int32_t v = 0; v < n; ++v) {
    if ((v & 4095) == 0 && !tick(double(v) / n)) return std::nullopt;
    if (surface.vertexHalfedge(v) < 0) continue;
    if (seamDegree[v] < 2) {
      const int32_t copy = newCopy(v);
      for (int32_t h : surface.outgoingHalfedges(v)) cornerCopy[h] = copy;
      continue;
    }
    // Start the rotation at a seam edge (at the boundary edge for a boundary vertex: its fan starts there).
    int32_t start = surface.vertexHalfedge(v);
    if (!surface.isBoundaryVertex(v))
      for (int32_t h : surface.outgoingHalfedges(v))
        if (onSeam(h)) {
          start = h;
          break;
        }
    int32_t copy = newCopy(v);
    for (int32_t h = start;;) {
      cornerCopy[h] = copy;
      h = surface.nextOutgoing(h);
      if (h < 0 || h == start) break;
      if (onSeam(h)) copy = newCopy(v);
    }
  }
  out.triangles.reserve(surface.numFaces());
  for (int32_t f = 0; f < surface.numFaces(); ++f)
    out.triangles.push_back({cornerCopy[3 * f], cornerCopy[3 * f + 1], cornerCopy[3 * f + 2]});
  return out;
}

}  // namespace straightest::detail
