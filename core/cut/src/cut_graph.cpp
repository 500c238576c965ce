// The seams a closed surface is cut along (see cut_graph.hpp): a double-sweep shortest path for genus 0,
// a pruned tree–cotree cut graph for genus ≥ 1.
#include "cut_graph.hpp"

#include "straightest/base/disjoint_sets.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <queue>
#include <utility>

namespace straightest::detail {
namespace {

struct ShortestPaths {
  std::vector<double> distance;
  std::vector<int32_t> parentHalfedge;  // the halfedge from the parent into the vertex; −1 at the root
};

/// Dijkstra on the edge graph from `source`, leaving vertices ≥ expandBelow reached but never expanded
/// (so no shortest path runs through them). False from `keepGoing` cancels (an empty result).
std::optional<ShortestPaths> dijkstra(const TriMesh& mesh, int32_t source, int32_t expandBelow,
                                      const std::function<bool(double)>& keepGoing) {
  const int32_t n = mesh.numVertices();
  ShortestPaths sp{std::vector<double>(n, std::numeric_limits<double>::infinity()), std::vector<int32_t>(n, -1)};
  std::vector<uint8_t> done(n, 0);
  using Item = std::pair<double, int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  sp.distance[source] = 0;
  queue.push({0.0, source});
  int64_t settled = 0;
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (done[v]) continue;
    done[v] = 1;
    if ((++settled & 1023) == 0 && !keepGoing(double(settled) / n)) return std::nullopt;
    if (v >= expandBelow) continue;
    for (int32_t h : mesh.outgoingHalfedges(v)) {
      const int32_t w = mesh.head(h);
      const double dw = d + norm(mesh.position(w) - mesh.position(v));
      if (dw < sp.distance[w]) {
        sp.distance[w] = dw;
        sp.parentHalfedge[w] = h;
        queue.push({dw, w});
      }
    }
  }
  return sp;
}

int32_t farthest(const std::vector<double>& distance) {
  int32_t best = 0;
  for (int32_t v = 1; v < int32_t(distance.size()); ++v)
    if (distance[v] > distance[best]) best = v;
  return best;
}

/// One key per undirected edge of a closed mesh: the smaller of its two halfedges.
int32_t edgeKey(const TriMesh& mesh, int32_t h) { return std::min(h, mesh.twin(h)); }

}  // namespace

Expected<Seam> pathSeam(const TriMesh& closed, const Progress& progress, const char* stage) {
  ThrottledProgress tick(progress, stage);
  if (!tick(0)) return cancelledError("cutting to a disk");
  const int32_t n = closed.numVertices();
  auto first = dijkstra(closed, 0, n, [&](double f) { return tick(0.5 * f); });
  if (!first) return cancelledError("cutting to a disk");
  const int32_t a = farthest(first->distance);
  auto second = dijkstra(closed, a, n, [&](double f) { return tick(0.5 + 0.5 * f); });
  if (!second) return cancelledError("cutting to a disk");
  int32_t b = farthest(second->distance);
  Seam seam;
  std::vector<int32_t> path{b};  // b back to a
  for (int32_t v = b; v != a; v = closed.tail(second->parentHalfedge[v]))
    path.push_back(closed.tail(second->parentHalfedge[v]));
  if (path.size() == 2) {
    // Neighbours (a tetrahedron): a one-edge seam cannot open a simplicial surface; go on to a third vertex.
    for (int32_t w : closed.vertexNeighbours(b))
      if (w != a) {
        path.insert(path.begin(), w);
        break;
      }
  }
  for (size_t i = 0; i + 1 < path.size(); ++i) seam.edges.push_back({path[i + 1], path[i]});
  std::reverse(seam.edges.begin(), seam.edges.end());
  seam.ends = {a, path.front()};
  return seam;
}

Expected<Seam> treeCotreeSeam(const TriMesh& closed, int32_t firstVirtual, const Progress& progress,
                              const char* stage) {
  ThrottledProgress tick(progress, stage);
  if (!tick(0)) return cancelledError("cutting to a disk");
  const int32_t n = closed.numVertices(), halfedges = 3 * closed.numFaces();
  auto tree = dijkstra(closed, 0, firstVirtual, [&](double f) { return tick(0.6 * f); });
  if (!tree) return cancelledError("cutting to a disk");

  std::vector<uint8_t> inTree(halfedges, 0);  // by edge key
  for (int32_t v = 0; v < n; ++v)
    if (tree->parentHalfedge[v] >= 0) inTree[edgeKey(closed, tree->parentHalfedge[v])] = 1;

  // The cotree: a maximum spanning tree of the dual over the edges not in T, weighted by the length of
  // the loop through T each edge would close; a hole's fan edges come first so that none is left over.
  struct Candidate {
    double loopLength;
    int32_t key;
  };
  std::vector<Candidate> candidates;
  for (int32_t h = 0; h < halfedges; ++h) {
    if (closed.twin(h) < h || inTree[h]) continue;
    const int32_t u = closed.tail(h), w = closed.head(h);
    const bool fan = u >= firstVirtual || w >= firstVirtual;
    const double length = fan ? std::numeric_limits<double>::infinity()
                              : tree->distance[u] + tree->distance[w] + norm(closed.position(u) - closed.position(w));
    candidates.push_back({length, h});
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    return x.loopLength != y.loopLength ? x.loopLength > y.loopLength : x.key < y.key;
  });
  if (!tick(0.7)) return cancelledError("cutting to a disk");
  DisjointSets faces(closed.numFaces());
  std::vector<int32_t> cutEdges;  // keys: T's edges and the leftover ones
  for (const Candidate& c : candidates)
    if (!faces.unite(TriMesh::face(c.key), TriMesh::face(closed.twin(c.key)))) cutEdges.push_back(c.key);
  for (int32_t key = 0; key < halfedges; ++key)
    if (inTree[key]) cutEdges.push_back(key);
  if (!tick(0.8)) return cancelledError("cutting to a disk");

  // Prune the dangling branches of T: remove degree-1 vertices until none is left.
  std::vector<std::vector<int32_t>> incident(n);
  for (size_t i = 0; i < cutEdges.size(); ++i) {
    incident[closed.tail(cutEdges[i])].push_back(int32_t(i));
    incident[closed.head(cutEdges[i])].push_back(int32_t(i));
  }
  std::vector<int32_t> degree(n);
  for (int32_t v = 0; v < n; ++v) degree[v] = int32_t(incident[v].size());
  std::vector<uint8_t> removed(cutEdges.size(), 0);
  std::vector<int32_t> leaves;
  for (int32_t v = 0; v < n; ++v)
    if (degree[v] == 1) leaves.push_back(v);
  while (!leaves.empty()) {
    const int32_t v = leaves.back();
    leaves.pop_back();
    if (degree[v] != 1) continue;
    for (int32_t i : incident[v]) {
      if (removed[i]) continue;
      removed[i] = 1;
      const int32_t other = closed.tail(cutEdges[i]) == v ? closed.head(cutEdges[i]) : closed.tail(cutEdges[i]);
      --degree[v];
      if (--degree[other] == 1) leaves.push_back(other);
      break;
    }
  }
  Seam seam;
  for (size_t i = 0; i < cutEdges.size(); ++i)
    if (!removed[i]) seam.edges.push_back({closed.tail(cutEdges[i]), closed.head(cutEdges[i])});
  if (!tick(1)) return cancelledError("cutting to a disk");
  return seam;
}

}  // namespace straightest::detail
