// face_graph.cpp — components and shortest distances on the face-adjacency graph.
#include "face_graph.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace straightest::atlas {

std::vector<Vec3> faceCentroids(const TriMesh& mesh) {
  std::vector<Vec3> centroids(mesh.numFaces());
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const Triangle& t = mesh.triangle(f);
    centroids[f] = (mesh.position(t[0]) + mesh.position(t[1]) + mesh.position(t[2])) / 3.0;
  }
  return centroids;
}

std::vector<int32_t> faceComponents(const TriMesh& mesh, int32_t& count) {
  std::vector<int32_t> component(mesh.numFaces(), -1), stack;
  count = 0;
  for (int32_t start = 0; start < mesh.numFaces(); ++start) {
    if (component[start] >= 0) continue;
    component[start] = count;
    stack.push_back(start);
    while (!stack.empty()) {
      const int32_t f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int32_t g = faceAcross(mesh, f, k);
        if (g >= 0 && component[g] < 0) {
          component[g] = count;
          stack.push_back(g);
        }
      }
    }
    ++count;
  }
  return component;
}

void lowerDualDistances(const TriMesh& mesh, const std::vector<Vec3>& centroids, const std::vector<int32_t>& sources,
                        const std::vector<uint8_t>& allowed, std::vector<double>& distance) {
  using Entry = std::pair<double, int32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int32_t s : sources) {
    distance[s] = 0;
    queue.push({0.0, s});
  }
  while (!queue.empty()) {
    const auto [d, f] = queue.top();
    queue.pop();
    if (d > distance[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const int32_t g = faceAcross(mesh, f, k);
      if (g < 0 || (!allowed.empty() && !allowed[g])) continue;
      const double dg = d + norm(centroids[g] - centroids[f]);
      if (dg < distance[g]) {
        distance[g] = dg;
        queue.push({dg, g});
      }
    }
  }
}

int32_t farthestFace(const std::vector<int32_t>& faces, const std::vector<double>& distance) {
  int32_t best = -1;
  double bestDistance = -1;
  for (int32_t f : faces)
    if (std::isfinite(distance[f]) && distance[f] > bestDistance) {
      bestDistance = distance[f];
      best = f;
    }
  return best;
}

}  // namespace straightest::atlas
