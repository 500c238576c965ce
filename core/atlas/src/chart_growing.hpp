// chart_growing.hpp — charts grown from seeds through one priority queue: a face joins the chart that
// reaches it at the lowest cost (normal deviation + distance from the seed + boundary lengthening).
#pragma once
#include <cstdint>
#include <functional>
#include <queue>
#include <vector>

#include "straightest/mesh/trimesh.hpp"

namespace straightest::atlas {

struct GrowthCost {
  double normalWeight = 2;      // × (1 − n_face · n_chart): charts stay nearly flat
  double distanceWeight = 0.3;  // × distance from the seed / distanceScale: charts stay round
  double boundaryWeight = 1;    // × the share of the face's perimeter that would become chart boundary
  double distanceScale = 1;     // the expected radius of a chart
  double minNormalCosine = -2;  // a face joins only while n_face · n_chart >= this (-2: any face joins)
  int32_t maxFaces = 0;         // a chart stops growing at this many faces (0: no cap)
};

class ChartGrower {
 public:
  ChartGrower(const TriMesh& mesh, const std::vector<Vec3>& centroids, const GrowthCost& cost);

  /// Starts a new chart (numbered from 0 in order) at an unassigned face.
  void addSeed(int32_t face);
  /// Grows every chart until no face can join any; `keepGoing(fraction of faces assigned)` is asked now
  /// and then, and false stops the growth (returns false).
  bool grow(const std::function<bool(double)>& keepGoing);

  /// Per face its chart, or -1 while no chart has taken it.
  const std::vector<int32_t>& labels() const { return label_; }
  int32_t chartCount() const { return static_cast<int32_t>(normalSum_.size()); }
  int32_t assignedCount() const { return assigned_; }

 private:
  struct Candidate {
    double cost;
    int32_t face, chart;
    double distance;  // from the chart's seed, along the dual graph
    bool operator>(const Candidate& o) const {
      if (cost != o.cost) return cost > o.cost;
      if (face != o.face) return face > o.face;
      return chart > o.chart;
    }
  };
  double costOf(int32_t face, int32_t chart, double distance) const;
  bool fitsCone(int32_t face, int32_t chart) const;
  bool isFull(int32_t chart) const { return cost_.maxFaces > 0 && size_[chart] >= cost_.maxFaces; }
  void assign(int32_t face, int32_t chart, double distance);

  const TriMesh& mesh_;
  const std::vector<Vec3>& centroids_;
  GrowthCost cost_;
  std::vector<int32_t> label_;
  std::vector<double> distance_;
  std::vector<Vec3> normalSum_;  // per chart, Σ area × normal
  std::vector<int32_t> size_;    // per chart, its face count
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue_;
  int32_t assigned_ = 0;
};

}  // namespace straightest::atlas
