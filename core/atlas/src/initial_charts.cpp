// initial_charts.cpp — how many seeds, where, and reseeding the regions growth leaves over.
// The seed count follows the component's total absolute Gaussian curvature (angle deficits): that is
// what a flat chart cannot absorb, so a developable part, however large, asks for one seed. It is kept
// low on purpose (the cone test and the splits after flattening do the fine work) and capped by the
// face count, so a noisy scan does not start from thousands of charts.
#include "initial_charts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "chart_smoothing.hpp"
#include "face_graph.hpp"

namespace straightest::atlas {

namespace {
constexpr double kCurvaturePerSeed = kPi;  // a hemisphere's worth of Gaussian curvature per seed
constexpr int32_t kFacesPerSeed = 2000;    // the fewest faces per initial seed
const double kInfinity = std::numeric_limits<double>::infinity();

/// |angle deficit| of every interior vertex, summed per component.
std::vector<double> curvaturePerComponent(const TriMesh& mesh, const std::vector<int32_t>& component, int32_t count) {
  std::vector<double> angleSum(mesh.numVertices(), 0.0), curvature(count, 0.0);
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const Triangle& t = mesh.triangle(f);
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = mesh.position(t[(k + 1) % 3]) - mesh.position(t[k]);
      const Vec3 b = mesh.position(t[(k + 2) % 3]) - mesh.position(t[k]);
      angleSum[t[k]] += std::atan2(norm(cross(a, b)), dot(a, b));
    }
  }
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    const int32_t h = mesh.vertexHalfedge(v);
    if (h < 0 || mesh.isBoundaryVertex(v)) continue;
    curvature[component[TriMesh::face(h)]] += std::fabs(kTwoPi - angleSum[v]);
  }
  return curvature;
}

/// Seeds for `faces` faces when no chart may exceed `maxFaces`: grown charts are not equal, so a third more
/// than the even share, which leaves few regions over for reseeding.
int32_t cappedSeedCount(size_t faces, int32_t maxFaces) {
  return static_cast<int32_t>(std::ceil(4.0 / 3.0 * static_cast<double>(faces) / maxFaces));
}

/// `count` seeds spread by farthest-point sampling over one component's faces (`distance` is scratch).
std::vector<int32_t> farthestPointSeeds(const TriMesh& mesh, const std::vector<Vec3>& centroids,
                                        const std::vector<int32_t>& faces, int32_t count,
                                        std::vector<double>& distance) {
  const std::vector<uint8_t> everywhere;
  for (int32_t f : faces) distance[f] = kInfinity;
  lowerDualDistances(mesh, centroids, {faces.front()}, everywhere, distance);
  std::vector<int32_t> seeds{farthestFace(faces, distance)};
  for (int32_t f : faces) distance[f] = kInfinity;
  lowerDualDistances(mesh, centroids, seeds, everywhere, distance);
  while (static_cast<int32_t>(seeds.size()) < count) {
    const int32_t next = farthestFace(faces, distance);
    if (next < 0 || distance[next] <= 0) break;
    seeds.push_back(next);
    lowerDualDistances(mesh, centroids, {next}, everywhere, distance);
  }
  return seeds;
}

/// The seeds of every component, in component order: enough for its curvature and, with a cap on the
/// chart size, enough that the capped charts can cover it (else growth leaves regions for many reseeds).
std::vector<int32_t> initialSeeds(const TriMesh& mesh, const std::vector<Vec3>& centroids, int32_t maxFaces) {
  int32_t count = 0;
  const std::vector<int32_t> component = faceComponents(mesh, count);
  const std::vector<double> curvature = curvaturePerComponent(mesh, component, count);
  std::vector<std::vector<int32_t>> faces(count);
  for (int32_t f = 0; f < mesh.numFaces(); ++f) faces[component[f]].push_back(f);
  std::vector<double> distance(mesh.numFaces(), kInfinity);
  std::vector<int32_t> seeds;
  for (int32_t c = 0; c < count; ++c) {
    const int32_t byFaces = 1 + static_cast<int32_t>(faces[c].size()) / kFacesPerSeed;
    int32_t byCurvature = static_cast<int32_t>(std::ceil(curvature[c] / kCurvaturePerSeed));
    if (maxFaces > 0) byCurvature = std::max(byCurvature, cappedSeedCount(faces[c].size(), maxFaces));
    const int32_t wanted = std::clamp(byCurvature, 1, byFaces);
    for (int32_t s : farthestPointSeeds(mesh, centroids, faces[c], wanted, distance)) seeds.push_back(s);
  }
  return seeds;
}

/// One new seed in every region of faces no chart took: its face farthest from the charts around it.
std::vector<int32_t> reseedLeftovers(const TriMesh& mesh, const std::vector<Vec3>& centroids,
                                     const std::vector<int32_t>& labels) {
  std::vector<uint8_t> free(mesh.numFaces(), 0);
  std::vector<int32_t> frontier;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    if (labels[f] >= 0) continue;
    free[f] = 1;
    for (int k = 0; k < 3; ++k) {
      const int32_t g = faceAcross(mesh, f, k);
      if (g >= 0 && labels[g] >= 0) {
        frontier.push_back(f);
        break;
      }
    }
  }
  std::vector<double> distance(mesh.numFaces(), kInfinity);
  lowerDualDistances(mesh, centroids, frontier, free, distance);
  std::vector<int32_t> seeds, region(mesh.numFaces(), -1), stack;
  for (int32_t start = 0; start < mesh.numFaces(); ++start) {
    if (!free[start] || region[start] >= 0) continue;
    int32_t best = start;  // flood this region, keeping its farthest face
    region[start] = start;
    stack.push_back(start);
    while (!stack.empty()) {
      const int32_t f = stack.back();
      stack.pop_back();
      if (distance[f] > distance[best] || (distance[f] == distance[best] && f < best)) best = f;
      for (int k = 0; k < 3; ++k) {
        const int32_t g = faceAcross(mesh, f, k);
        if (g >= 0 && free[g] && region[g] < 0) region[g] = start, stack.push_back(g);
      }
    }
    seeds.push_back(best);
  }
  return seeds;
}

}  // namespace

Expected<std::vector<int32_t>> initialCharts(const TriMesh& mesh, const std::vector<Vec3>& centroids, GrowthCost cost,
                                             const Progress& progress) {
  ThrottledProgress throttled(progress, "segment");
  if (!throttled(0)) return cancelledError("atlas segmentation");
  const std::vector<int32_t> seeds = initialSeeds(mesh, centroids, cost.maxFaces);
  double area = 0;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) area += mesh.faceArea(f);
  cost.distanceScale = std::max(std::sqrt(area / (kPi * seeds.size())), 1e-300);
  ChartGrower grower(mesh, centroids, cost);
  for (int32_t s : seeds) grower.addSeed(s);
  auto keepGoing = [&](double fraction) { return throttled(fraction); };
  if (!grower.grow(keepGoing)) return cancelledError("atlas segmentation");
  while (grower.assignedCount() < mesh.numFaces()) {
    for (int32_t s : reseedLeftovers(mesh, centroids, grower.labels())) grower.addSeed(s);
    if (!grower.grow(keepGoing)) return cancelledError("atlas segmentation");
  }
  std::vector<int32_t> labels = grower.labels();
  smoothChartBorders(mesh, labels, cost.maxFaces);
  if (!progress("segment", 1)) return cancelledError("atlas segmentation");
  return labels;
}

}  // namespace straightest::atlas
