// bench_cgal — compares straightest against CGAL 5.5 on the same meshes and the same source:
//  - distances from the source to every vertex of the (longest) boundary loop: our straightest paths
//    (traceStraightestPaths) vs CGAL's exact geodesics (Surface_mesh_shortest_path), with the
//    per-vertex ratio straightest / exact over the reached paths;
//  - disk parameterization: CGAL's Mean_value_coordinates_parameterizer_3 with
//    Circular_border_arc_length_parameterizer_3 vs our circle + mean-value and our measured +
//    shape-preserving; every UV set is judged by OUR textureStretch (one metric for all);
//  - free borders: CGAL's ARAP and LSCM vs our free boundary (free_border.hpp).
// Bench-only (bench/cgal/CMakeLists.txt); never a dependency of the library.
//
// usage: bench_cgal [--repeats N] [--sp-budget-s S] [--sp-max-vertices N] [--no-lengths] [--skip-paths]
//                   [--no-free-border] [--free-max-vertices N] [--free-once-above-s S] MESH...
//   MESH: an .obj/.off path or heightfield:N (makeHeightField(N), N² vertices).
//   --skip-paths: parameterizations only. Free-border runs longer than --free-once-above-s (2 s) are not
//   repeated; CGAL's free-border methods skip meshes above --free-max-vertices (30000).
// Output: one JSON object per mesh per line on stdout (flushed as soon as the mesh is done), then the
// markdown tables. Progress goes to stderr.
//
// Kernel: CGAL::Exact_predicates_inexact_constructions_kernel (double coordinates; exact predicates,
// which Surface_mesh_shortest_path's examples use). Both meshes have the same vertices in the same
// order and the same (consistently oriented) faces: the CGAL Surface_mesh is built from our TriMesh.
// Times: median of --repeats runs (default 3), std::chrono::steady_clock, loading excluded. A CGAL
// shortest-path run longer than the budget is not repeated, and meshes larger than one whose run
// exceeded the budget (or than --sp-max-vertices) skip the CGAL shortest paths, saying so.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <malloc.h>

#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/param/texture_stretch.hpp"
#include "straightest/paths/straightest_path.hpp"

#include "bench_support.hpp"
#include "free_border.hpp"

using namespace straightest;
using namespace bench_cgal;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;
using ShortestPathTraits = CGAL::Surface_mesh_shortest_path_traits<Kernel, SM>;
using ShortestPath = CGAL::Surface_mesh_shortest_path<ShortestPathTraits>;
using CgalBorder = SMP::Circular_border_arc_length_parameterizer_3<SM>;
using CgalMvc = SMP::Mean_value_coordinates_parameterizer_3<SM, CgalBorder>;

namespace {

struct Row {  // one line of the final table
  std::string name;
  int64_t vertices = 0, boundary = 0, reached = 0;
  double oursPathsMs = kInf, cgalSpMs = kInf;
  std::string cgalSpNote;
  double ratioMin = kInf, ratioMed = kInf, ratioMax = kInf;
  double cgalParamMs = kInf, cgalL2 = kInf, oursCircleMs = kInf, oursCircleL2 = kInf, oursMeasMs = kInf,
         oursMeasL2 = kInf;
  std::string error;
};

struct Settings {
  int repeats = 3;
  double spBudgetS = 60;       // a CGAL shortest-path run longer than this: larger meshes skip it
  int64_t spMaxVertices = -1;  // explicit cap (-1: none)
  bool lengths = true;         // per-boundary-vertex lengths in the JSON
  bool paths = true;           // --skip-paths: parameterizations only (the real-patch set)
  bool freeBorder = true;      // --no-free-border: skip CGAL's ARAP and LSCM and our free boundary
  FreeBorderSettings freeBorderSettings;
};

const char* solverName(LinearSolver s) {
  switch (s) {
    case LinearSolver::Multigrid: return "multigrid (BiCGSTAB + smoothed-aggregation multigrid)";
    case LinearSolver::SparseLU: return "SparseLU";
    case LinearSolver::BiCGSTAB: return "BiCGSTAB + ILUT";
  }
  return "?";
}

Expected<TriMesh> loadAny(const std::string& spec) {
  if (spec.rfind("heightfield:", 0) == 0) {
    const int n = std::atoi(spec.c_str() + 12);
    if (n < 2 || n > 5000) return Error{ErrorCode::InvalidArgument, "heightfield:N needs 2 <= N <= 5000"};
    return makeHeightField(n);
  }
  return loadMeshFile(spec);
}

std::string baseName(const std::string& spec) {
  const size_t slash = spec.find_last_of('/');
  return slash == std::string::npos ? spec : spec.substr(slash + 1);
}

}  // namespace

int main(int argc, char** argv) {
  Settings st;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "bench_cgal: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--repeats") st.repeats = std::max(1, std::atoi(next()));
    else if (a == "--sp-budget-s") st.spBudgetS = std::atof(next());
    else if (a == "--sp-max-vertices") st.spMaxVertices = std::atoll(next());
    else if (a == "--no-lengths") st.lengths = false;
    else if (a == "--skip-paths") st.paths = false;
    else if (a == "--no-free-border") st.freeBorder = false;
    else if (a == "--free-max-vertices") st.freeBorderSettings.cgalMaxVertices = std::atoll(next());
    else if (a == "--free-once-above-s") st.freeBorderSettings.onceAboveMs = 1000 * std::atof(next());
    else if (a == "-h" || a == "--help") {
      std::printf(
          "usage: bench_cgal [--repeats N] [--sp-budget-s S] [--sp-max-vertices N] [--no-lengths] [--skip-paths]\n"
          "                  [--no-free-border] [--free-max-vertices N] [--free-once-above-s S] MESH...\n"
          "  MESH: an .obj/.off file or heightfield:N\n");
      return 0;
    } else meshes.push_back(a);
  }
  if (meshes.empty()) {
    std::fprintf(stderr, "bench_cgal: no mesh given (try --help)\n");
    return 2;
  }
  const double onceAboveMs = 30'000;  // do not repeat a run that took longer than 30 s
  int64_t spSkipAbove = st.spMaxVertices >= 0 ? st.spMaxVertices : std::numeric_limits<int64_t>::max();
  std::string spSkipReason = st.spMaxVertices >= 0
                                 ? "more than --sp-max-vertices " + std::to_string(st.spMaxVertices) + " vertices"
                                 : "";
  int64_t spLargestV = 0;  // the largest mesh whose CGAL shortest paths ran, and their peak (MB)
  double spLargestMb = 0;
  st.freeBorderSettings.repeats = st.repeats;
  std::vector<Row> rows;
  std::vector<FreeBorderRow> freeRows;

  for (const std::string& spec : meshes) {
    Row row;
    row.name = spec.rfind("heightfield:", 0) == 0 ? spec : baseName(spec);
    Obj out;
    out.addStr("mesh", row.name)
        .addStr("cgal", CGAL_VERSION_STR)
        .addStr("kernel", "Exact_predicates_inexact_constructions_kernel");
    std::fprintf(stderr, "bench_cgal: %s: loading\n", row.name.c_str());
    auto loaded = loadAny(spec);
    if (!loaded) {
      row.error = loaded.error().message;
      out.addStr("error", row.error);
      std::printf("%s\n", out.done().c_str());
      std::fflush(stdout);
      rows.push_back(row);
      continue;
    }
    const TriMesh& mesh = loaded.value();
    const auto disk = requireDisk(mesh);
    const auto src = defaultSource(mesh);
    if (!disk || !src) {
      row.error = !disk ? disk.error().message : src.error().message;
      out.add("vertices", static_cast<int64_t>(mesh.numVertices())).addStr("error", row.error);
      std::printf("%s\n", out.done().c_str());
      std::fflush(stdout);
      rows.push_back(row);
      continue;
    }
    const int32_t source = src.value();
    const std::vector<SurfacePoint> targets = boundaryTargets(mesh);
    row.vertices = mesh.numVertices();
    row.boundary = static_cast<int64_t>(targets.size());
    out.add("vertices", row.vertices)
        .add("faces", static_cast<int64_t>(mesh.numFaces()))
        .add("boundary_vertices", row.boundary)
        .add("source", static_cast<int64_t>(source));

    // The same mesh for CGAL: same vertex order, the same (oriented) faces.
    SM sm;
    sm.reserve(mesh.numVertices(), mesh.numFaces() * 3 / 2 + mesh.numVertices(), mesh.numFaces());
    for (const Vec3& p : mesh.positions()) sm.add_vertex(Point3(p.x, p.y, p.z));
    bool smOk = true;
    for (const Triangle& t : mesh.triangles())
      if (sm.add_face(VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2])) == SM::null_face()) smOk = false;
    if (!smOk) {
      row.error = "CGAL Surface_mesh rejected a face";
      out.addStr("error", row.error);
      std::printf("%s\n", out.done().c_str());
      std::fflush(stdout);
      rows.push_back(row);
      continue;
    }

    // ---------------------------------------------------------------- ours: straightest paths
    PathBatch batch;
    std::vector<double> exact(targets.size(), kInf);
    if (st.paths) {
      std::fprintf(stderr, "bench_cgal: %s: straightest paths\n", row.name.c_str());
      Timings pathTimings;
      const double oursPathsBase = resetPeakRss();
      const Timed oursPaths = timeIt(st.repeats, onceAboveMs, [&] {
        pathTimings = Timings();
        batch = traceStraightestPaths(mesh, SurfacePoint::vertex(source), targets,
                                      TraceOptions{/*keepPoints=*/false, 0, &pathTimings})
                    .value();
      });
      const double oursPathsRss = peakRssMb();
      row.oursPathsMs = oursPaths.ms;
      row.reached = summarize(batch).reached;
      out.add("ours_paths", Obj()
                                .add("ms", oursPaths.ms, 4)
                                .add("runs", oursPaths.runs)
                                .add("prepare_ms", pathTimings["prepare"], 4)
                                .add("trace_ms", pathTimings["trace"], 4)
                                .add("reached", row.reached)
                                .add("peak_rss_mb", oursPathsRss, 4)
                                .add("baseline_rss_mb", oursPathsBase, 4)
                                .done());

      // ---------------------------------------------------------------- CGAL: exact geodesic distances
      Obj sp;
      // Memory guard: the sequence tree's peak grew like V^1.55 from 10k to 100k vertices on the height
      // fields (274 MB → 9.6 GB); predict from the largest mesh run so far with exponent 1.5 and skip
      // when the prediction exceeds 80% of the memory available now.
      std::string memoryReason;
      if (spLargestV > 0 && row.vertices > spLargestV) {
        const double predicted = spLargestMb * std::pow(double(row.vertices) / spLargestV, 1.5);
        const double available = memAvailableMb();
        if (available > 0 && predicted > 0.8 * available) {
          char buf[200];
          std::snprintf(buf, sizeof buf,
                        "predicted peak %.0f GB (%.0f MB at %lld vertices × (V ratio)^1.5) > 80%% of "
                        "the %.0f GB available",
                        predicted / 1024, spLargestMb, static_cast<long long>(spLargestV), available / 1024);
          memoryReason = buf;
        }
      }
      if (row.vertices > spSkipAbove || !memoryReason.empty()) {
        const std::string reason = row.vertices > spSkipAbove ? spSkipReason : memoryReason;
        row.cgalSpNote = "skipped: " + reason;
        sp.add("skipped", true).addStr("reason", reason);
        std::fprintf(stderr, "bench_cgal: %s: CGAL shortest paths %s\n", row.name.c_str(), row.cgalSpNote.c_str());
      } else {
        std::fprintf(stderr, "bench_cgal: %s: CGAL shortest paths\n", row.name.c_str());
        const double base = resetPeakRss();
        const Timed t = timeIt(st.repeats, onceAboveMs, [&] {
          ShortestPath paths(sm);
          paths.add_source_point(VertexIndex(source));
          paths.build_sequence_tree();
          for (size_t i = 0; i < targets.size(); ++i) {
            const double d = paths.shortest_distance_to_source_points(VertexIndex(targets[i].index)).first;
            exact[i] = d >= 0 ? d : kInf;
          }
        });
        const double rss = peakRssMb();
        row.cgalSpMs = t.ms;
        int64_t unreachable = 0;
        for (double d : exact) unreachable += std::isinf(d);
        sp.add("skipped", false)
            .add("ms", t.ms, 4)
            .add("runs", t.runs)
            .add("peak_rss_mb", rss, 4)
            .add("baseline_rss_mb", base, 4)
            .add("unreachable", unreachable);
        if (row.vertices > spLargestV && rss > base) {
          spLargestV = row.vertices;
          spLargestMb = rss - base;
        }
        if (t.ms > st.spBudgetS * 1000 && row.vertices < spSkipAbove) {
          spSkipAbove = row.vertices;
          char buf[160];
          std::snprintf(buf, sizeof buf, "%s (%lld vertices) took %.0f s > the %.0f s budget", row.name.c_str(),
                        static_cast<long long>(row.vertices), t.ms / 1000, st.spBudgetS);
          spSkipReason = buf;
        }
      }
      out.add("cgal_shortest_path", sp.done());

      // ratio straightest / exact over the reached paths
      std::vector<double> ratios;
      int64_t belowOne = 0;
      for (size_t i = 0; i < targets.size(); ++i) {
        if (batch.status[i] != TraceStatus::Reached || !std::isfinite(exact[i]) || exact[i] <= 0) continue;
        const double r = batch.length[i] / exact[i];
        ratios.push_back(r);
        belowOne += r < 1 - 1e-9;
      }
      Obj ratio;
      ratio.add("count", static_cast<int64_t>(ratios.size()));
      if (!ratios.empty()) {
        row.ratioMin = *std::min_element(ratios.begin(), ratios.end());
        row.ratioMax = *std::max_element(ratios.begin(), ratios.end());
        row.ratioMed = median(ratios);
        double mean = 0;
        for (double r : ratios) mean += r;
        ratio.add("min", row.ratioMin, 9)
            .add("median", row.ratioMed, 9)
            .add("max", row.ratioMax, 9)
            .add("mean", mean / ratios.size(), 9)
            .add("below_one", belowOne);
      }
      out.add("ratio_straightest_over_exact", ratio.done());
    } else {
      row.reached = -1;
      out.add("paths", std::string("\"skipped\""));
    }

    // ---------------------------------------------------------------- CGAL: circle + mean value
    std::fprintf(stderr, "bench_cgal: %s: CGAL parameterization\n", row.name.c_str());
    {
      auto uvMap = sm.add_property_map<VertexIndex, Point2>("v:uv", Point2(0, 0)).first;
      const auto border = PMP::longest_border(sm).first;
      SMP::Error_code status = SMP::OK;
      const double base = resetPeakRss();
      const Timed t = timeIt(st.repeats, onceAboveMs, [&] {
        for (VertexIndex v : sm.vertices()) uvMap[v] = Point2(0, 0);
        status = SMP::parameterize(sm, CgalMvc(), border, uvMap);
      });
      const double rss = peakRssMb();
      Obj o;
      o.addStr("method",
               "Mean_value_coordinates_parameterizer_3 + Circular_border_arc_length_parameterizer_3 "
               "(default solver: Eigen BiCGSTAB + IncompleteLUT)");
      o.add("status", str(SMP::get_error_message(status)))
          .add("ms", t.ms, 4)
          .add("runs", t.runs)
          .add("peak_rss_mb", rss, 4)
          .add("baseline_rss_mb", base, 4);
      if (status == SMP::OK) {
        std::vector<Vec2> uv(mesh.numVertices());
        for (int32_t v = 0; v < mesh.numVertices(); ++v) {
          const Point2& p = uvMap[VertexIndex(v)];
          uv[v] = {p.x(), p.y()};
        }
        const Stretch s = stretchOf(mesh, uv);
        stretchFields(o, s);
        o.add("mirrored", s.mirrored);
        row.cgalParamMs = t.ms;
        row.cgalL2 = s.m.l2;
      }
      out.add("cgal_circle_mean_value", o.done());
    }

    // ---------------------------------------------------------------- ours: two parameterizations
    // The source is passed explicitly (it is the one CGAL's shortest paths used), so the "source" timing
    // does not contain the default-source search; total includes our stretch computation (metrics).
    struct Variant {
      const char* key;
      BoundaryKind boundary;
      WeightKind weights;
    };
    for (const Variant& var :
         {Variant{"ours_circle_mean_value", BoundaryKind::Circle, WeightKind::MeanValue},
          Variant{"ours_measured_shape_preserving", BoundaryKind::Measured, WeightKind::ShapePreserving}}) {
      std::fprintf(stderr, "bench_cgal: %s: %s\n", row.name.c_str(), var.key);
      ParamOptions po;
      po.source = SurfacePoint::vertex(source);
      po.boundary = var.boundary;
      po.weights = var.weights;
      std::vector<double> totals;
      Expected<Parameterization> last = Error{ErrorCode::InvalidArgument, "not run"};
      const double base = resetPeakRss();
      Timings tm;
      for (int i = 0; i < st.repeats; ++i) {
        tm = Timings();
        po.timings = &tm;
        last = parameterize(mesh, po);
        if (!last) break;
        totals.push_back(tm["total"]);
        if (i == 0 && totals[0] > onceAboveMs) break;
      }
      const double rss = peakRssMb();
      Obj o;
      if (!last) {
        o.addStr("error", last.error().message);
      } else {
        const Parameterization& p = last.value();
        const Stretch s = stretchOf(mesh, p.uv);  // the same function as CGAL's UVs go through
        const double ms = median(totals);
        o.addStr("solver", solverName(po.solver));
        o.add("ms", ms, 4)
            .add("runs", static_cast<int>(totals.size()))
            .add("peak_rss_mb", rss, 4)
            .add("baseline_rss_mb", base, 4)
            .add("timings_ms", Obj()
                                   .add("source", tm["source"], 4)
                                   .add("trace", tm["trace"], 4)
                                   .add("boundary", tm["boundary"], 4)
                                   .add("weights", tm["weights"], 4)
                                   .add("solve", tm["solve"], 4)
                                   .add("metrics", tm["metrics"], 4)
                                   .add("total", tm["total"], 4)
                                   .done());
        stretchFields(o, s);
        o.add("l2_reported", p.metrics.l2, 9)
            .add("residual", p.residual, 3)
            .add("fallbacks", p.fallbacks)
            .add("weight_fallbacks", p.weightFallbacks);
        if (var.boundary == BoundaryKind::Circle) {
          row.oursCircleMs = ms;
          row.oursCircleL2 = s.m.l2;
        } else {
          row.oursMeasMs = ms;
          row.oursMeasL2 = s.m.l2;
        }
      }
      out.add(var.key, o.done());
    }
    if (st.freeBorder) {
      FreeBorderRow freeRow;
      freeRow.name = row.name;
      out.add("free_border", compareFreeBorders(mesh, sm, source, st.freeBorderSettings, freeRow));
      freeRows.push_back(freeRow);
    }
    if (std::isfinite(row.cgalL2) && std::isfinite(row.oursCircleL2))
      out.add("l2_relative_difference_cgal_vs_ours_circle_mean_value",
              std::fabs(row.cgalL2 - row.oursCircleL2) / row.oursCircleL2, 3);

    if (st.lengths && st.paths) {
      std::vector<double> straight(targets.size());
      for (size_t i = 0; i < targets.size(); ++i)
        straight[i] = batch.status[i] == TraceStatus::Reached ? batch.length[i] : kInf;
      std::vector<double> ids(targets.size());
      for (size_t i = 0; i < targets.size(); ++i) ids[i] = targets[i].index;
      out.add("boundary_vertex_ids", array(ids, 12))
          .add("straightest_lengths", array(straight))
          .add("exact_lengths", array(exact));
    }
    std::printf("%s\n", out.done().c_str());
    std::fflush(stdout);
    rows.push_back(row);
  }

  // ---------------------------------------------------------------- the tables
  std::printf(
      "\n### Paths and fixed borders\n\n| mesh | vertices | boundary | reached | ours paths ms | CGAL exact ms | "
      "straightest/exact min / median / max "
      "| CGAL circle+MVC ms | CGAL L2 | ours circle+MV ms | ours circle+MV L2 | ours measured+SP ms "
      "| ours measured+SP L2 | CGAL ÷ ours: circle+MV / measured+SP | L2 CGAL vs ours circle+MV |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---|---:|\n");
  for (const Row& r : rows) {
    if (!r.error.empty()) {
      std::printf("| %s | error: %s |||||||||||||\n", r.name.c_str(), r.error.c_str());
      continue;
    }
    const std::string cgalSp = r.cgalSpNote.empty() ? fmtMs(r.cgalSpMs) : "skipped¹";
    const std::string ratio = std::isfinite(r.ratioMin) ? fmt(r.ratioMin, "%.4f") + " / " + fmt(r.ratioMed, "%.4f") +
                                                              " / " + fmt(r.ratioMax, "%.4f")
                                                        : "—";
    // Speedups: CGAL's parameterize call over our total (the same job: circle + mean value; and our
    // measured boundary with shape-preserving weights, which also traces every boundary path).
    const std::string speedup = fmt(r.cgalParamMs / r.oursCircleMs, "%.1f×") + " / " +
                                fmt(r.cgalParamMs / r.oursMeasMs, "%.1f×");
    const std::string l2diff = fmt(std::fabs(r.cgalL2 - r.oursCircleL2) / r.oursCircleL2, "%.1e");
    const std::string reached = r.reached < 0 ? "—" : std::to_string(r.reached);
    std::printf("| %s | %lld | %lld | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.name.c_str(),
                static_cast<long long>(r.vertices), static_cast<long long>(r.boundary), reached.c_str(),
                fmtMs(r.oursPathsMs).c_str(), cgalSp.c_str(), ratio.c_str(), fmtMs(r.cgalParamMs).c_str(),
                fmt(r.cgalL2, "%.6f").c_str(), fmtMs(r.oursCircleMs).c_str(), fmt(r.oursCircleL2, "%.6f").c_str(),
                fmtMs(r.oursMeasMs).c_str(), fmt(r.oursMeasL2, "%.6f").c_str(), speedup.c_str(), l2diff.c_str());
  }
  std::printf(
      "\nTimes in ms, median of %d run(s) (a run over 30 s is not repeated), loading excluded; CGAL kernel: "
      "Exact_predicates_inexact_constructions_kernel. Paths: ours = traceStraightestPaths to every boundary "
      "vertex (setup included); CGAL = Surface_mesh_shortest_path construction + add_source_point + "
      "build_sequence_tree + shortest_distance_to_source_points per boundary vertex. Ratio over the reached "
      "paths. Parameterizations: CGAL = the SMP::parameterize call (its default solver, Eigen BiCGSTAB + "
      "IncompleteLUT); ours = the \"total\" timing (source given, the library's default solver: %s; "
      "stretch metrics included). L2 = our textureStretch for every UV set.\n",
      st.repeats, solverName(ParamOptions{}.solver));
  for (const Row& r : rows)
    if (!r.cgalSpNote.empty()) std::printf("¹ %s: CGAL shortest paths %s\n", r.name.c_str(), r.cgalSpNote.c_str());
  if (st.freeBorder) printFreeBorderTable(freeRows, st.freeBorderSettings);
  return 0;
}
