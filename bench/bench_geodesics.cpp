// Benchmark: the paper's two comparison methods. (1) Exact geodesic distances (window propagation) from the
// default source to every vertex, on height fields and on the meshes named on the command line: time,
// windows, the queue's peak, and the exact distances' agreement with Dijkstra's upper bound. (2) Geodesic
// shooting (Polthier–Schmies) toward every boundary vertex, in the direction and for the length the
// cutting plane gives, against the cutting-plane tracer: faces per second (processor time, both without
// polylines; the shots with them too), and how far the shot passes from the target (the miss, relative to
// the length). Prints tables; never pass/fail.
//   bench_geodesics TARGET [--heightfields 100,250,1000] [--budget-s 60] [MESH.off ...]
// A height field is skipped once a smaller one took longer than the budget (its time would be ~4× that).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../core/cli/huge_pages.hpp"
#include "straightest/geodesics/exact_geodesic.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/geodesics/geodesic_shoot.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/paths/base_plane.hpp"
#include "straightest/paths/straightest_path.hpp"

using namespace straightest;
using Clock = std::chrono::steady_clock;

namespace {

double msSince(Clock::time_point a) { return std::chrono::duration<double, std::milli>(Clock::now() - a).count(); }
/// Processor time of the process in ms: on a shared, loaded machine the wall clock also counts waiting.
double cpuMs() { return 1000.0 * static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Mesh {
  std::string name;
  TriMesh mesh;
};

void exactRow(const char* target, const Mesh& m, double& lastMs) {
  const auto chosen = defaultSource(m.mesh);
  if (!chosen) {  // e.g. a height field too small to have an interior vertex
    std::printf("| %s | %s | %d | no default source: %s |\n", target, m.name.c_str(), m.mesh.numVertices(),
                chosen.error().message.c_str());
    return;
  }
  const int32_t source = chosen.value();
  const auto t0 = Clock::now();
  const double c0 = cpuMs();
  auto field = exactGeodesics(m.mesh, SurfacePoint::vertex(source));
  const double cpu = cpuMs() - c0;
  const double ms = msSince(t0);
  lastMs = ms;
  if (!field) {
    std::printf("| %s | %s | %d | error: %s |\n", target, m.name.c_str(), m.mesh.numVertices(),
                field.error().message.c_str());
    return;
  }
  const ExactGeodesics& f = field.value();
  const std::vector<double> graph = dijkstraDistances(m.mesh, SurfacePoint::vertex(source));
  double worstRatio = 0, sumRatio = 0;
  int64_t counted = 0, above = 0;
  for (int32_t v = 0; v < m.mesh.numVertices(); ++v) {
    if (!(graph[v] > 0) || !std::isfinite(graph[v])) continue;
    const double r = f.distances[v] / graph[v];
    worstRatio = std::max(worstRatio, r);
    sumRatio += r;
    above += r > 1 + 1e-12;
    ++counted;
  }
  std::printf("| %s | %s | %d | %.1f | %.1f | %.2f | %lld | %.1f | %lld | %lld | %.4f | %lld |\n", target,
              m.name.c_str(), m.mesh.numVertices(), ms, cpu, m.mesh.numVertices() / cpu,
              static_cast<long long>(f.stats.windows), static_cast<double>(f.stats.windows) / m.mesh.numVertices(),
              static_cast<long long>(f.stats.maxQueue), static_cast<long long>(f.stats.pseudoSources),
              counted ? sumRatio / counted : 0.0, static_cast<long long>(above));
}

void shootRow(const char* target, const Mesh& m) {
  const auto chosen = defaultSource(m.mesh);
  if (!chosen) return;  // said in the exact distances' table
  const int32_t source = chosen.value();
  const SurfacePoint s = SurfacePoint::vertex(source);
  const std::vector<SurfacePoint> targets = boundaryTargets(m.mesh);
  if (targets.empty()) return;
  // Processor times, the least of three runs (both are a few ms on the smaller meshes).
  constexpr int kRuns = 3;
  double traceMs = 1e300;
  PathBatch batch;
  for (int run = 0; run < kRuns; ++run) {
    const double t0 = cpuMs();
    batch = traceStraightestPaths(m.mesh, s, targets, TraceOptions{false, 0, nullptr}).value();
    traceMs = std::min(traceMs, cpuMs() - t0);
  }
  int64_t traceFaces = 0;
  for (int64_t c : batch.facesCrossed) traceFaces += c;
  const BasePlane base = basePlane(m.mesh, s);
  std::vector<std::pair<Vec3, size_t>> shots;  // direction, target
  for (size_t i = 0; i < targets.size(); ++i) {
    if (batch.status[i] != TraceStatus::Reached) continue;
    const std::optional<Vec3> dir = inPlaneDirection(base, position(m.mesh, targets[i]));
    if (dir) shots.push_back({*dir, i});
  }
  ShootOptions options;
  options.tangentNormal = base.normal;  // as shootGeodesicToward, with the base plane computed once
  // Timed like the tracer's batch: lengths, ends and statuses, no polylines. One shooter per mesh: its
  // table of flat faces is made once (timed apart: the first allocation of its memory dominates).
  options.keepPoints = false;
  const double t0 = cpuMs();
  const GeodesicShooter shooter = GeodesicShooter::make(m.mesh).value();
  const double tableMs = cpuMs() - t0;
  int64_t shotFaces = 0;
  double shootMs = 1e300;
  for (int run = 0; run < kRuns; ++run) {
    shotFaces = 0;
    const double c0 = cpuMs();
    for (const auto& [dir, i] : shots) {
      auto shot = shooter.shoot(s, dir, batch.length[i], options);
      if (shot) shotFaces += shot.value().facesCrossed;
    }
    shootMs = std::min(shootMs, cpuMs() - c0);
  }
  // Again with polylines, one shot at a time (the functions, no table): their cost, and the closest
  // approach to each target over the segments.
  options.keepPoints = true;
  std::vector<double> miss;
  const double c1 = cpuMs();
  for (const auto& [dir, i] : shots) {
    auto shot = shootGeodesic(m.mesh, s, dir, batch.length[i], options);
    if (!shot) continue;
    const Vec3 d = position(m.mesh, targets[i]);
    const std::vector<Vec3>& p = shot.value().positions;
    double closest = norm(d - p.front());
    for (size_t k = 1; k < p.size(); ++k) {
      const Vec3 e = p[k] - p[k - 1];
      const double ee = dot(e, e);
      const double t = ee > 0 ? std::clamp(dot(d - p[k - 1], e) / ee, 0.0, 1.0) : 0.0;
      closest = std::min(closest, norm(d - (p[k - 1] + e * t)));
    }
    miss.push_back(closest / batch.length[i]);
  }
  const double polylineMs = cpuMs() - c1;
  std::sort(miss.begin(), miss.end());
  const double median = miss.empty() ? 0 : miss[miss.size() / 2], worst = miss.empty() ? 0 : miss.back();
  int64_t hits = 0;
  for (double x : miss) hits += x < 1e-6;
  std::printf("| %s | %s | %d | %zu | %.2f | %.1f | %zu | %.2f | %.2f | %.1f | %.2f | %.1f | %.4f | %.4f | %lld |\n",
              target, m.name.c_str(), m.mesh.numVertices(), targets.size(), traceMs, traceFaces / traceMs / 1000.0,
              shots.size(), tableMs, shootMs, shotFaces / shootMs / 1000.0,
              (static_cast<double>(shotFaces) / shootMs) / (static_cast<double>(traceFaces) / traceMs),
              shotFaces / polylineMs / 1000.0, median, worst, static_cast<long long>(hits));
}

}  // namespace

int main(int argc, char** argv) {
  straightest::cli::reexecWithHugePages(argv);  // as the CLI runs
  const char* target = argc > 1 ? argv[1] : "native";
  std::vector<int> heightfields{100, 250, 1000};
  double budgetS = 60;
  std::vector<std::string> files;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--heightfields" && i + 1 < argc) {
      heightfields.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while (std::getline(list, item, ',')) heightfields.push_back(std::atoi(item.c_str()));
    } else if (a == "--budget-s" && i + 1 < argc) {
      budgetS = std::atof(argv[++i]);
    } else {
      files.push_back(a);
    }
  }
  std::printf(
      "Exact distances from the default source to every vertex (windows: created after the filter; mean and "
      "count of exact ÷ Dijkstra above 1 are a sanity check)\n\n");
  std::printf(
      "| target | mesh | vertices | ms | CPU ms | k vertices/CPU s | windows | windows/vertex | queue peak | "
      "pseudo-sources | mean exact/graph | exact > graph "
      "|\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::vector<Mesh> meshes;
  for (const std::string& f : files) {
    auto m = loadMeshFile(f);
    if (!m) {
      std::fprintf(stderr, "bench_geodesics: %s: %s\n", f.c_str(), m.error().message.c_str());
      continue;
    }
    meshes.push_back({f.substr(f.find_last_of('/') + 1), std::move(m).value()});
  }
  double lastMs = 0;
  for (const Mesh& m : meshes) exactRow(target, m, lastMs);
  lastMs = 0;
  for (int n : heightfields) {
    Mesh m{"heightfield " + std::to_string(n), makeHeightField(n)};
    if (lastMs > budgetS * 1000) {
      std::printf("| %s | %s | %d | skipped: the previous size took %.0f s > %.0f s |\n", target, m.name.c_str(),
                  m.mesh.numVertices(), lastMs / 1000, budgetS);
      continue;
    }
    exactRow(target, m, lastMs);
    meshes.push_back(std::move(m));
  }
  std::printf(
      "\nShooting toward every boundary vertex (direction and length from the cutting plane) vs the tracer "
      "(miss: closest approach ÷ length; hits: miss < 1e-6)\n\n");
  std::printf(
      "| target | mesh | vertices | targets | trace CPU ms | tracer M faces/s | shots | flat faces CPU ms | shoot "
      "CPU ms | shooting M faces/s | shooting ÷ tracer | with polylines M faces/s | median miss | worst miss | hits "
      "|\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Mesh& m : meshes) shootRow(target, m);
  return 0;
}
