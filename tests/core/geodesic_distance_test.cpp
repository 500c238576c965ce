// Distances on the surface: the heat method against the straightest distance, the edge graph and the
// plane's Euclidean distance; the bucketed Dijkstra behind defaultSource gives the distances of a
// textbook binary-heap Dijkstra bit for bit; the default source is the interior vertex farthest from
// the boundary.
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/paths/straightest_path.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

using testing::GridPattern;
using testing::kPi;

int32_t centerVertex(const TriMesh& mesh) { return defaultSource(mesh).value(); }

TEST(HeatMethod, NeverExceedsTheStraightestDistanceBeyondItsError) {
  const std::vector<std::pair<std::string, TriMesh>> meshes = [] {
    std::vector<std::pair<std::string, TriMesh>> m;
    m.emplace_back("plane", testing::flatGrid(31, GridPattern::Jittered));
    m.emplace_back("cap", makeSphericalCap(1.0, kPi / 3, 24));
    m.emplace_back("saddle", makeSample("saddle").value());
    m.emplace_back("face", makeSample("face").value());
    return m;
  }();
  for (const auto& [name, mesh] : meshes) {
    const int32_t source = centerVertex(mesh);
    const HeatMethod heat(mesh);
    const auto distances = heat.distances(SurfacePoint::vertex(source));
    const auto graph = dijkstraDistances(mesh, std::vector<int32_t>{source});
    StraightestPathTracer tracer(mesh, SurfacePoint::vertex(source));
    for (const auto& target : boundaryTargets(mesh)) {
      const StraightestPath& path = tracer.trace(target);
      if (path.status != TraceStatus::Reached) continue;
      // The heat method is an approximation: allow it 5% above the straightest (itself an upper
      // bound of the geodesic distance).
      EXPECT_LE(distances[target.index], path.length * 1.05) << name;
      EXPECT_GT(distances[target.index], 0) << name;
      // The edge graph never beats the heat method's approximation of the geodesic distance by much.
      EXPECT_GE(graph[target.index], distances[target.index] * 0.95) << name;
    }
  }
}

TEST(HeatMethod, GivesEuclideanDistanceOnAPlaneWithinAFewPercent) {
  const TriMesh mesh = testing::flatGrid(41, GridPattern::UnionJack);
  const HeatMethod heat(mesh);
  const int32_t source = 20 * 41 + 20;
  const auto d = heat.distances(SurfacePoint::vertex(source));
  EXPECT_NEAR(d[source], 0, 1e-12);
  for (int32_t v = 0; v < mesh.numVertices(); v += 37) {
    const double e = norm(mesh.position(v) - mesh.position(source));
    EXPECT_NEAR(d[v], e, 0.05 * e + 0.1) << "vertex " << v;
  }
}

TEST(DefaultSource, IsTheInteriorVertexFarthestFromTheBoundary) {
  const TriMesh mesh = testing::flatGrid(9, GridPattern::Regular);
  EXPECT_EQ(defaultSource(mesh).value(), 4 * 9 + 4);
  EXPECT_EQ(defaultSource(makeSphericalCap(1, 1, 6)).value(), 0);
  const TriMesh single = testing::buildOrFail({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  EXPECT_EQ(defaultSource(single).error().code, ErrorCode::Topology);
}

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
