// chart_merging.cpp — which neighbours to try (adjacent, normals within 90°, not known to fail), and
// rounds of disjoint trials. A pair whose average normals are more than 90° apart would need a fold-like
// bend to lie flat within the stretch target, so it is not worth a trial.
#include "chart_merging.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

#include "face_graph.hpp"
#include "parallel_flattening.hpp"

namespace straightest::atlas {

namespace {
// The faces all merge trials may flatten together, per mesh face: late rounds try few, large unions, so
// an unbounded search costs tens of flattenings of the whole mesh for a few charts less. Counted in
// faces, not time, so the result does not depend on the machine.
constexpr int64_t kTrialFacesPerFace = 4;

struct MergeTrial {
  int32_t a, b;  // indices into charts, a < b
  size_t smaller;
  double shared;
};

Vec3 averageNormal(const TriMesh& mesh, const FlatChart& chart) {
  Vec3 n{0, 0, 0};
  for (int32_t f : chart.faces) n += mesh.faceNormal(f) * mesh.faceArea(f);
  const double length = norm(n);
  return length > 0 ? n / length : n;
}

/// What a merge must keep: the union's limits, its size, and whether charts facing apart are tried.
struct MergeRule {
  ChartLimits limits;
  int32_t maxFaces = 0;      // 0: any size
  bool facingApart = false;  // try pairs whose average normals are more than 90° apart too
  size_t fewestCharts = 0;   // stop merging at this many charts
  // The faces all trials may flatten together, per mesh face (0: no bound, the merges go on while any is
  // acceptable: a cap the caller asked for is worth the time).
  int64_t trialFacesPerFace = kTrialFacesPerFace;
};

/// Adjacent pairs worth a trial, best first, each chart in at most one; none whose union exceeds the rule's
/// size.
std::vector<MergeTrial> chooseTrials(const TriMesh& mesh, const std::vector<FlatChart>& charts,
                                     const ChartPairs& knownBad, const MergeRule& rule) {
  std::vector<int32_t> label(mesh.numFaces());
  std::vector<Vec3> normal(charts.size());
  for (size_t c = 0; c < charts.size(); ++c) {
    for (int32_t f : charts[c].faces) label[f] = static_cast<int32_t>(c);
    normal[c] = averageNormal(mesh, charts[c]);
  }
  std::map<std::pair<int32_t, int32_t>, double> shared;
  for (int32_t f = 0; f < mesh.numFaces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int32_t g = faceAcross(mesh, f, k);
      if (g >= 0 && label[f] < label[g]) shared[{label[f], label[g]}] += edgeLength(mesh, f, k);
    }
  std::vector<MergeTrial> candidates;
  for (const auto& [pair, length] : shared) {
    const auto& [a, b] = pair;
    if (!rule.facingApart && dot(normal[a], normal[b]) < 0) continue;
    if (rule.maxFaces > 0 && charts[a].faces.size() + charts[b].faces.size() > static_cast<size_t>(rule.maxFaces))
      continue;
    if (knownBad.count(chartPair(chartKey(charts[a].faces), chartKey(charts[b].faces)))) continue;
    candidates.push_back({a, b, std::min(charts[a].faces.size(), charts[b].faces.size()), length});
  }
  std::sort(candidates.begin(), candidates.end(), [](const MergeTrial& x, const MergeTrial& y) {
    if (x.smaller != y.smaller) return x.smaller < y.smaller;
    if (x.shared != y.shared) return x.shared > y.shared;
    return std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
  });
  std::vector<uint8_t> taken(charts.size(), 0);
  std::vector<MergeTrial> trials;
  for (const MergeTrial& t : candidates)
    if (!taken[t.a] && !taken[t.b]) {
      taken[t.a] = taken[t.b] = 1;
      trials.push_back(t);
    }
  return trials;
}

std::vector<int32_t> unionOf(const std::vector<int32_t>& a, const std::vector<int32_t>& b) {
  std::vector<int32_t> faces(a.size() + b.size());
  std::merge(a.begin(), a.end(), b.begin(), b.end(), faces.begin());
  return faces;
}

/// Rounds of disjoint merge trials under `rule`, until none is left, the budget is spent or the rule's
/// fewest charts is reached.
Expected<int32_t> mergeRounds(const TriMesh& mesh, std::vector<FlatChart>& charts, ChartPairs& knownBad,
                              const MergeRule& rule, const FreeBoundaryOptions& free, const Progress& progress) {
  int32_t merges = 0;
  const bool bounded = rule.trialFacesPerFace > 0;
  // Unbounded, progress is counted against the bound the caps-free merges have; it stops short of 1.
  const int64_t fullBudget = (bounded ? rule.trialFacesPerFace : kTrialFacesPerFace) *
                             static_cast<int64_t>(std::max(mesh.numFaces(), 1));
  int64_t budget = fullBudget;
  // Progress is the budget spent, so it only grows from round to round.
  auto spent = [&] {
    return std::min(0.99, static_cast<double>(fullBudget - budget) / static_cast<double>(fullBudget));
  };
  while ((budget > 0 || !bounded) && charts.size() > rule.fewestCharts) {
    std::vector<MergeTrial> trials = chooseTrials(mesh, charts, knownBad, rule);
    // Each merge takes one chart away: no more trials than charts above the fewest.
    if (rule.fewestCharts > 0) trials.resize(std::min(trials.size(), charts.size() - rule.fewestCharts));
    std::vector<std::vector<int32_t>> unions;
    const double roundBegins = spent();
    for (const MergeTrial& t : trials) {
      if (bounded && budget <= 0) break;  // the trials are best first: the ones left out matter least
      unions.push_back(unionOf(charts[t.a].faces, charts[t.b].faces));
      budget -= static_cast<int64_t>(unions.back().size());
    }
    if (unions.empty()) break;
    trials.resize(unions.size());
    auto flattened = flattenCharts(mesh, std::move(unions), rule.limits, free, progress.range(roundBegins, spent()));
    if (!flattened) return flattened.error();
    std::vector<uint8_t> gone(charts.size(), 0);
    int32_t merged = 0;
    for (size_t i = 0; i < trials.size(); ++i) {
      const MergeTrial& t = trials[i];
      if (!flattened.value()[i].acceptable) {
        knownBad.insert(chartPair(chartKey(charts[t.a].faces), chartKey(charts[t.b].faces)));
        continue;
      }
      charts[t.a] = std::move(flattened.value()[i].chart);
      gone[t.b] = 1;
      ++merged;
    }
    size_t kept = 0;
    for (size_t c = 0; c < charts.size(); ++c) {
      if (gone[c]) continue;
      if (kept != c) charts[kept] = std::move(charts[c]);  // never onto itself: that would empty it
      ++kept;
    }
    charts.resize(kept);
    merges += merged;
  }
  return merges;
}

}  // namespace

Expected<int32_t> mergeCharts(const TriMesh& mesh, std::vector<FlatChart>& charts, ChartPairs& knownBad,
                              const ChartOptions& options, const ChartLimits& limits, const Progress& progress) {
  return mergeRounds(mesh, charts, knownBad, MergeRule{limits, options.maxChartFaces}, options.free, progress);
}

Expected<int32_t> mergeDownTo(const TriMesh& mesh, std::vector<FlatChart>& charts, size_t count,
                              const FreeBoundaryOptions& free, const Progress& progress) {
  ChartPairs knownBad;  // pairs that failed the stricter limits may pass these
  const MergeRule anyBijective{ChartLimits{std::numeric_limits<double>::infinity(), 0}, 0, true, count, 0};
  return mergeRounds(mesh, charts, knownBad, anyBijective, free, progress);
}

}  // namespace straightest::atlas
