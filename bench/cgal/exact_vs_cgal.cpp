// Bench-only: our exact geodesic distances (window propagation, exact_geodesic.hpp) against CGAL's
// Surface_mesh_shortest_path, from the default source to every vertex of each mesh named on the command
// line (same vertices, same faces): the largest relative difference and both times (wall and processor). Prints a
// markdown table; never pass/fail. CGAL runs are skipped above --cgal-max-vertices (default 20000: CGAL's time and
// memory grow fast; see scripts/bench-cgal.sh).
//   exact_vs_cgal [--cgal-max-vertices N] MESH.off ...
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "free_border.hpp"
#include "straightest/geodesics/exact_geodesic.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/io/mesh_io.hpp"

using namespace straightest;
using namespace bench_cgal;
using ShortestPathTraits = CGAL::Surface_mesh_shortest_path_traits<Kernel, SM>;
using ShortestPath = CGAL::Surface_mesh_shortest_path<ShortestPathTraits>;

/// Processor time since c0 in ms: on a shared, loaded machine the wall clock also counts waiting.
static double cpuMsSince(std::clock_t c0) { return 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC; }

int main(int argc, char** argv) {
  int64_t cgalMax = 20000;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--cgal-max-vertices" && i + 1 < argc) cgalMax = std::atoll(argv[++i]);
    else files.push_back(a);
  }
  std::printf(
      "| mesh | vertices | ours ms | ours CPU ms | windows | queue peak | CGAL ms | CGAL CPU ms | CGAL ÷ ours | "
      "CGAL ÷ ours (CPU) | max relative difference | vertex "
      "|\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
      "\n");
  for (const std::string& file : files) {
    const std::string name = file.substr(file.find_last_of('/') + 1);
    auto loaded = loadMeshFile(file);
    if (!loaded) {
      std::printf("| %s | error: %s |\n", name.c_str(), loaded.error().message.c_str());
      continue;
    }
    const TriMesh& mesh = loaded.value();
    auto source = defaultSource(mesh);
    if (!source) {
      std::printf("| %s | %d | %s |\n", name.c_str(), mesh.numVertices(), source.error().message.c_str());
      continue;
    }
    const auto t0 = Clock::now();
    const std::clock_t c0 = std::clock();
    auto field = exactGeodesics(mesh, SurfacePoint::vertex(source.value()));
    const double oursCpu = cpuMsSince(c0);
    const double oursMs = msSince(t0);
    if (!field) {
      std::printf("| %s | %d | error: %s |\n", name.c_str(), mesh.numVertices(), field.error().message.c_str());
      continue;
    }
    const ExactGeodesics& f = field.value();
    std::string cgalMs = "skipped", cgalCpu = "", ratio = "", cpuRatio = "", diff = "", where = "";
    if (mesh.numVertices() <= cgalMax) {
      SM sm;
      for (const Vec3& p : mesh.positions()) sm.add_vertex(Point3(p.x, p.y, p.z));
      for (const Triangle& t : mesh.triangles()) sm.add_face(VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2]));
      std::vector<double> exact(mesh.numVertices(), kInf);
      const auto t1 = Clock::now();
      const std::clock_t c1 = std::clock();
      ShortestPath paths(sm);
      paths.add_source_point(VertexIndex(source.value()));
      paths.build_sequence_tree();
      for (int32_t v = 0; v < mesh.numVertices(); ++v) {
        const double d = paths.shortest_distance_to_source_points(VertexIndex(v)).first;
        exact[v] = d >= 0 ? d : kInf;
      }
      const double cpu = cpuMsSince(c1);
      const double ms = msSince(t1);
      double worst = 0;
      int32_t worstVertex = -1;
      for (int32_t v = 0; v < mesh.numVertices(); ++v) {
        if (!std::isfinite(exact[v]) && !std::isfinite(f.distances[v])) continue;
        const double rel = std::fabs(f.distances[v] - exact[v]) / std::max(exact[v], 1e-300);
        if (v != source.value() && !(rel <= worst)) {
          worst = rel;
          worstVertex = v;
        }
      }
      cgalMs = fmt(ms, "%.1f");
      ratio = fmt(ms / oursMs, "%.1f");
      cgalCpu = fmt(cpu, "%.1f");
      cpuRatio = fmt(cpu / oursCpu, "%.1f");
      diff = fmt(worst, "%.2e");
      where = std::to_string(worstVertex);
    }
    std::printf("| %s | %d | %.1f | %.1f | %lld | %lld | %s | %s | %s | %s | %s | %s |\n", name.c_str(),
                mesh.numVertices(), oursMs, oursCpu, static_cast<long long>(f.stats.windows),
                static_cast<long long>(f.stats.maxQueue), cgalMs.c_str(), cgalCpu.c_str(), ratio.c_str(),
                cpuRatio.c_str(), diff.c_str(), where.c_str());
    std::fflush(stdout);
  }
  return 0;
}
