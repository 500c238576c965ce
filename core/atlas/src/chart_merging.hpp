// chart_merging.hpp — fewer charts: neighbours merged wherever their union still flattens acceptably.
#pragma once
#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "chart_flattening.hpp"
#include "straightest/atlas/chart_segmentation.hpp"

namespace straightest::atlas {

/// A chart's identity while merging: its first face and its face count (a merge changes the count).
using ChartKey = std::array<int64_t, 2>;
inline ChartKey chartKey(const std::vector<int32_t>& faces) { return {faces.front(), int64_t(faces.size())}; }
/// Two charts whose union is known not to flatten acceptably (the halves of a split, failed merges).
using ChartPairs = std::set<std::array<ChartKey, 2>>;
inline std::array<ChartKey, 2> chartPair(ChartKey a, ChartKey b) { return a < b ? std::array{a, b} : std::array{b, a}; }

/// Merges pairs of adjacent charts (smallest chart first, then the longest shared boundary) whose union is
/// acceptable (bijective, l2 <= maxStretch), in rounds of disjoint pairs flattened in parallel, until no pair is left
/// to try or the trials have flattened 4× the mesh's faces. `charts` is updated (merged charts replace the pair);
/// returns the merge count. Progress stage "flatten"; Cancelled when it says stop.
Expected<int32_t> mergeCharts(const TriMesh& mesh, std::vector<FlatChart>& charts, ChartPairs& knownBad,
                              const ChartOptions& options, const ChartLimits& limits, const Progress& progress);

/// Merges pairs of adjacent charts as mergeCharts does, whatever their stretch, shape, size or normals, as long
/// as the union is a disk that flattens bijectively, until at most `count` charts are left (ChartOptions::
/// maxCharts) or no pair merges. Returns the merge count. Progress stage "flatten"; Cancelled.
Expected<int32_t> mergeDownTo(const TriMesh& mesh, std::vector<FlatChart>& charts, size_t count,
                              const FreeBoundaryOptions& free, const Progress& progress);

}  // namespace straightest::atlas
