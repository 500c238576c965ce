// Graph distances along mesh edges: the bucketed Dijkstra behind defaultSource gives the distances of a
// textbook binary-heap Dijkstra bit for bit.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "straightest/geodesic_distance.hpp"
#include "straightest/samples.hpp"

namespace straightest {
namespace {

/// The textbook version: binary heap of (distance, vertex), rotating around each vertex on the mesh.
std::vector<double> referenceDijkstra(const TriMesh& mesh, const std::vector<int32_t>& sources) {
  std::vector<double> dist(mesh.numVertices(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int32_t s : sources) {
    dist[s] = 0;
    queue.push({0.0, s});
  }
  auto relax = [&](double d, int32_t v, int32_t w) {
    const double nd = d + norm(mesh.position(w) - mesh.position(v));
    if (nd < dist[w]) {
      dist[w] = nd;
      queue.push({nd, w});
    }
  };
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    const int32_t first = mesh.vertexHalfedge(v);
    for (int32_t h = first; h >= 0;) {
      relax(d, v, mesh.head(h));
      const int32_t p = TriMesh::prev(h);
      if (mesh.twin(p) < 0) relax(d, v, mesh.tail(p));
      h = mesh.twin(p);
      if (h == first) break;
    }
  }
  return dist;
}

TEST(DijkstraDistances, BucketedGivesTheBinaryHeapDistancesExactly) {
  for (const TriMesh& mesh : {makeHeightField(50), makeSample("face").value(), makeSample("cap").value()}) {
    std::vector<int32_t> boundary;
    for (const auto& loop : mesh.boundaryLoops()) boundary.insert(boundary.end(), loop.begin(), loop.end());
    if (boundary.empty()) boundary.push_back(0);
    const std::vector<double> fast = dijkstraDistances(mesh, boundary);
    const std::vector<double> slow = referenceDijkstra(mesh, boundary);
    ASSERT_EQ(fast.size(), slow.size());
    for (size_t v = 0; v < fast.size(); ++v) ASSERT_EQ(fast[v], slow[v]) << v;
  }
}

}  // namespace
}  // namespace straightest
