// parallel_flattening.cpp — a chart per task; the few large ones alone, so their solves use every thread.
#include "parallel_flattening.hpp"

#include "straightest/base/parallel_for.hpp"

namespace straightest::atlas {

namespace {
constexpr size_t kLargeChart = 20000;  // faces: a solve this large keeps the threads busy on its own
}

Expected<std::vector<ChartFlattening>> flattenCharts(const TriMesh& mesh, std::vector<std::vector<int32_t>> charts,
                                                     const ChartLimits& limits, const FreeBoundaryOptions& free,
                                                     const Progress& progress) {
  std::vector<ChartFlattening> out(charts.size());
  if (charts.empty()) return out;
  std::vector<size_t> small;
  double total = 0, done = 0;
  for (const auto& faces : charts) total += static_cast<double>(faces.size());
  for (size_t i = 0; i < charts.size(); ++i) {
    if (charts[i].size() < kLargeChart) {
      small.push_back(i);
      continue;
    }
    if (!progress("flatten", done / total)) return cancelledError("atlas flattening");
    done += static_cast<double>(charts[i].size());
    out[i] = flattenChart(mesh, std::move(charts[i]), limits, free);
  }
  if (!progress("flatten", done / total)) return cancelledError("atlas flattening");
  auto body = [&](size_t, size_t begin, size_t end) {
    for (size_t j = begin; j < end; ++j) out[small[j]] = flattenChart(mesh, std::move(charts[small[j]]), limits, free);
  };
  if (!detail::parallelFor(small.size(), 1, body, progress.range(total > 0 ? done / total : 0, 1), "flatten"))
    return cancelledError("atlas flattening");
  return out;
}

}  // namespace straightest::atlas
