// chart_splitting.cpp — the split works on the chart's own mesh, so its cost is the chart's size, not the
// mesh's, and its adjacency is exactly the chart's inner edges (each part stays edge-connected).
#include "chart_splitting.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "chart_growing.hpp"
#include "chart_mesh.hpp"
#include "chart_smoothing.hpp"
#include "face_graph.hpp"

namespace straightest::atlas {

namespace {
/// Two distinct faces of a connected mesh far apart along its dual graph.
std::array<int32_t, 2> farApartFaces(const TriMesh& chart, const std::vector<Vec3>& centroids) {
  std::vector<int32_t> all(chart.numFaces());
  for (int32_t f = 0; f < chart.numFaces(); ++f) all[f] = f;
  const std::vector<uint8_t> everywhere;
  std::vector<double> distance(chart.numFaces(), std::numeric_limits<double>::infinity());
  lowerDualDistances(chart, centroids, {0}, everywhere, distance);
  const int32_t a = farthestFace(all, distance);
  distance.assign(chart.numFaces(), std::numeric_limits<double>::infinity());
  lowerDualDistances(chart, centroids, {a}, everywhere, distance);
  int32_t b = farthestFace(all, distance);
  if (b == a) b = a == 0 ? 1 : 0;  // every centroid in one place (zero-area faces)
  return {a, b};
}
}  // namespace

std::vector<std::vector<int32_t>> splitChart(const TriMesh& mesh, const std::vector<int32_t>& faces) {
  Expected<TriMesh> built = buildChartMesh(mesh, faces);
  std::vector<std::vector<int32_t>> parts;
  if (!built) {
    for (int32_t f : faces) parts.push_back({f});
    return parts;
  }
  const TriMesh& chart = built.value();
  const std::vector<Vec3> centroids = faceCentroids(chart);
  double area = 0;
  for (int32_t f = 0; f < chart.numFaces(); ++f) area += chart.faceArea(f);
  GrowthCost cost;
  cost.distanceScale = std::max(std::sqrt(area / (2 * kPi)), 1e-300);
  ChartGrower grower(chart, centroids, cost);
  for (int32_t seed : farApartFaces(chart, centroids)) grower.addSeed(seed);
  grower.grow([](double) { return true; });
  std::vector<int32_t> labels = grower.labels();
  smoothChartBorders(chart, labels);
  parts.resize(2);
  for (int32_t f = 0; f < chart.numFaces(); ++f) parts[labels[f]].push_back(faces[f]);
  return parts;
}

}  // namespace straightest::atlas
