// free_border.hpp — bench_cgal's free-border comparison: CGAL's ARAP_parameterizer_3 and
// LSCM_parameterizer_3 (each with its default border parameterizer, Two_vertices_parameterizer_3: the
// border is free) next to our `free` boundary (when the core has it), every UV set judged by OUR
// textureStretch, which makes a map with a flipped or degenerate triangle or a self-overlapping boundary
// non-bijective (infinite stretch). A fixed-border table cannot show what a free border buys, nor that the
// free-border tools that exist fold on real meshes; this one shows both.
#pragma once
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <string>
#include <vector>

#include "bench_support.hpp"

namespace bench_cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Point2 = Kernel::Point_2;
using SM = CGAL::Surface_mesh<Point3>;
using VertexIndex = SM::Vertex_index;

struct FreeBorderSettings {
  int repeats = 3;
  double onceAboveMs = 2000;        // a run longer than this is not repeated (CGAL's ARAP can take minutes)
  int64_t cgalMaxVertices = 30000;  // larger meshes skip CGAL's free-border methods, saying so
};

/// One method on one mesh. `note` says why there are no numbers (skipped, n/a, CGAL's error) or is empty.
struct FreeBorderMethod {
  bool ran = false;
  std::string note;
  StretchMetrics metrics;
  int64_t iterations = -1;  // ours: the refinement's iterations, when the result reports them
  double ms = kInf;         // median of the runs
};

struct FreeBorderRow {
  std::string name;
  int64_t vertices = 0;
  FreeBorderMethod arap, lscm, ours;
};

/// Runs CGAL's ARAP and LSCM (free border) and our free boundary (from `source`, shape-preserving
/// weights) on one disk; `sm` is the same mesh as CGAL sees it. Fills `row` and returns the JSON object
/// of the three methods.
std::string compareFreeBorders(const TriMesh& mesh, SM& sm, int32_t source, const FreeBorderSettings& settings,
                               FreeBorderRow& row);

/// The markdown table of every row, and which meshes each method folds or fails on.
void printFreeBorderTable(const std::vector<FreeBorderRow>& rows, const FreeBorderSettings& settings);

}  // namespace bench_cgal
