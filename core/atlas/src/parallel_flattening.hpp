// parallel_flattening.hpp — many charts flattened at once on the core's threads, deterministically.
#pragma once
#include <cstdint>
#include <vector>

#include "chart_flattening.hpp"
#include "straightest/base/error.hpp"
#include "straightest/base/progress.hpp"

namespace straightest::atlas {

/// flattenChart for every chart, results in the same order. Large charts go one after the other with
/// the threads inside their solver; the rest each on one thread. Either way a chart's map is the same
/// (the core's loops give bit-identical results for any thread count), so the result does not depend on
/// the thread count. Progress stage "flatten" (fraction of faces flattened); Cancelled when it says stop.
Expected<std::vector<ChartFlattening>> flattenCharts(const TriMesh& mesh, std::vector<std::vector<int32_t>> charts,
                                                     const ChartLimits& limits, const FreeBoundaryOptions& free,
                                                     const Progress& progress);

}  // namespace straightest::atlas
