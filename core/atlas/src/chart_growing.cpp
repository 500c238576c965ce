// chart_growing.cpp — region growing with lazily re-evaluated costs: a candidate's cost is recomputed when
// it leaves the queue (the chart's normal and boundary have moved since it was queued) and queued again
// when it rose, so faces join in the order of their current cost.
#include "chart_growing.hpp"

#include "face_graph.hpp"

namespace straightest::atlas {

ChartGrower::ChartGrower(const TriMesh& mesh, const std::vector<Vec3>& centroids, const GrowthCost& cost)
    : mesh_(mesh), centroids_(centroids), cost_(cost), label_(mesh.numFaces(), -1), distance_(mesh.numFaces(), 0) {}

void ChartGrower::addSeed(int32_t face) {
  normalSum_.push_back({0, 0, 0});
  size_.push_back(0);
  assign(face, chartCount() - 1, 0);
}

double ChartGrower::costOf(int32_t face, int32_t chart, double distance) const {
  double deviation = 0;
  const double sumNorm = norm(normalSum_[chart]);
  if (!mesh_.isDegenerateFace(face) && sumNorm > 0)
    deviation = 1 - dot(mesh_.faceNormal(face), normalSum_[chart]) / sumNorm;
  double inside = 0, perimeter = 0;
  for (int k = 0; k < 3; ++k) {
    const double length = edgeLength(mesh_, face, k);
    perimeter += length;
    const int32_t g = faceAcross(mesh_, face, k);
    if (g >= 0 && label_[g] == chart) inside += length;
  }
  const double lengthening = perimeter > 0 ? (perimeter - inside) / perimeter : 0;
  return cost_.normalWeight * deviation + cost_.distanceWeight * distance / cost_.distanceScale +
         cost_.boundaryWeight * lengthening;
}

bool ChartGrower::fitsCone(int32_t face, int32_t chart) const {
  const double sumNorm = norm(normalSum_[chart]);
  if (mesh_.isDegenerateFace(face) || sumNorm == 0) return true;
  return dot(mesh_.faceNormal(face), normalSum_[chart]) >= cost_.minNormalCosine * sumNorm;
}

void ChartGrower::assign(int32_t face, int32_t chart, double distance) {
  label_[face] = chart;
  distance_[face] = distance;
  normalSum_[chart] += mesh_.faceNormal(face) * mesh_.faceArea(face);
  ++size_[chart];
  ++assigned_;
  for (int k = 0; k < 3; ++k) {
    const int32_t g = faceAcross(mesh_, face, k);
    if (g < 0 || label_[g] >= 0 || isFull(chart)) continue;
    const double d = distance + norm(centroids_[g] - centroids_[face]);
    queue_.push({costOf(g, chart, d), g, chart, d});
  }
}

bool ChartGrower::grow(const std::function<bool(double)>& keepGoing) {
  int64_t pops = 0;
  while (!queue_.empty()) {
    if (++pops % 4096 == 0 && !keepGoing(double(assigned_) / mesh_.numFaces())) return false;
    const Candidate c = queue_.top();
    queue_.pop();
    if (label_[c.face] >= 0 || isFull(c.chart)) continue;
    const double now = costOf(c.face, c.chart, c.distance);
    if (now > c.cost) {  // the chart moved away since it was queued: wait for its turn at the new cost
      queue_.push({now, c.face, c.chart, c.distance});
      continue;
    }
    if (fitsCone(c.face, c.chart)) assign(c.face, c.chart, c.distance);
  }
  return keepGoing(double(assigned_) / mesh_.numFaces());
}

}  // namespace straightest::atlas
