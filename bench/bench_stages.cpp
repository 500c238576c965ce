// Benchmark of every stage on one mesh, as one JSON line: load, source, base plane, all-boundary
// traces, then the measured-boundary parameterization's boundary, weights, solve and metrics, then the
// free boundary's refinement of that map ("refine", and its metrics in "refine_metrics"); the median
// of `repeats` runs per stage and the process's peak memory. Built natively and to WASM from this one
// source so scripts/bench.mjs can put the two side by side (the refinement runs the same iterations
// in both: compare per run, or per iteration with free_iterations). Never pass/fail.
//   bench_stages TARGET MESH [REPEATS] [MAX_ITERATIONS] [--threads N,N,...]
//   MESH: a file, heightfield:N or sample:NAME. --threads: one JSON line per thread count (default: one,
//   every core; 1 = the single-threaded path), the counts run in turn within each repeat so that the
//   machine's load weighs on them alike.
// Before anything else the process loads the mesh once and parameterizes it once (with the first thread
// count): that first call's stages are "cold_stages_ms" (a fresh process natively, a freshly
// instantiated module in WASM: what a one-shot CLI run or a page's single call meets), with its minor
// page faults and CPU time natively.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "../core/cli/huge_pages.hpp"
#include "straightest/base/threads.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/paths/straightest_path.hpp"
#include "thread_counts.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten/heap.h>
static double peakMemoryMB() { return emscripten_get_heap_size() / 1048576.0; }  // memory only grows
static long minorFaults() { return 0; }
static double cpuMs() { return 0; }
#else
#include <sys/resource.h>
static double peakMemoryMB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // KiB on Linux
}
static long minorFaults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}
// User + system time of the process (every thread), which a loaded machine's waiting does not count.
static double cpuMs() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return (u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-3;
}
#endif

using namespace straightest;
using Clock = std::chrono::steady_clock;

static double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

static Expected<TriMesh> open(const std::string& spec) {
  if (spec.rfind("heightfield:", 0) == 0) return makeHeightField(std::atoi(spec.c_str() + 12));
  if (spec.rfind("sample:", 0) == 0) return makeSample(spec.substr(7));
  return loadMeshFile(spec);
}

/// What one thread count measured: each stage's times and the results they gave.
struct Measured {
  double freeL2 = 0, l2 = 0;
  int32_t freeIterations = 0;
  bool freeBijective = false, bijective = false;
  std::map<std::string, std::vector<double>> stage;
  int64_t vertices = 0, faces = 0, paths = 0, reached = 0, crossed = 0;
  long warmFaults = 0;  // the last measured run's parameterize
  double warmCpu = 0;
};

int main(int argc, char** argv) {
  straightest::cli::reexecWithHugePages(argv);  // as the CLI runs
  std::vector<std::string> args;
  std::vector<int> counts = {0};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--threads" && i + 1 < argc) counts = threadCounts(argv[++i]);
    else args.push_back(argv[i]);
  }
  if (args.size() < 2) {
    std::fprintf(stderr, "usage: bench_stages TARGET MESH [REPEATS] [MAX_ITERATIONS] [--threads N,N,...]\n");
    return 2;
  }
  const std::string target = args[0], spec = args[1];
  const int repeats = args.size() > 2 ? std::max(1, std::atoi(args[2].c_str())) : 3;
  FreeBoundaryOptions free;
  if (args.size() > 3) free.maxIterations = std::max(1, std::atoi(args[3].c_str()));
  std::vector<Measured> measured(counts.size());
  // The cold call: the first parameterize of this process (or module instance).
  Timings cold;
  long coldFaults = 0;
  double coldCpu = 0;
  {
    setThreadCount(counts[0]);
    auto loaded = open(spec);
    if (!loaded) {
      std::printf("{\"target\":\"%s\",\"mesh\":\"%s\",\"error\":\"%s\"}\n", target.c_str(), spec.c_str(),
                  loaded.error().message.c_str());
      return 2;
    }
    ParamOptions options;
    options.timings = &cold;
    const long faults = minorFaults();
    const double cpu = cpuMs();
    const auto p = parameterize(loaded.value(), options);
    coldFaults = minorFaults() - faults;
    coldCpu = cpuMs() - cpu;
    if (!p) {
      std::printf("{\"target\":\"%s\",\"mesh\":\"%s\",\"error\":\"%s\"}\n", target.c_str(), spec.c_str(),
                  p.error().message.c_str());
      return 2;
    }
  }
  // Warm-up runs first, not counted: for at least 1.5 s (at least one run). They warm caches and, in
  // WASM, let the engine tier every hot function up from its baseline compiler to the optimizing one
  // (V8 does that in the background, by call counts: one short warm-up run left small meshes measured
  // partly in baseline code, 2-3x slow and different from run to run).
  int warmups = 0;
  const auto warmStart = Clock::now();
  for (int r = -1; r < repeats; ++r) {
    for (size_t c = 0; c < counts.size(); ++c) {
      setThreadCount(counts[c]);
      Measured& m = measured[c];
      std::map<std::string, std::vector<double>>& stage = m.stage;
      auto t = Clock::now();
      auto loaded = open(spec);
      if (!loaded) {
        std::printf("{\"target\":\"%s\",\"mesh\":\"%s\",\"error\":\"%s\"}\n", target.c_str(), spec.c_str(),
                    loaded.error().message.c_str());
        return 2;
      }
      const TriMesh mesh = std::move(loaded).value();
      const double loadMs = msSince(t);
      if (r >= 0) stage["load"].push_back(loadMs);
      m.vertices = mesh.numVertices();
      m.faces = mesh.numFaces();
      t = Clock::now();
      const int32_t source = defaultSource(mesh).value();
      const double sourceMs = msSince(t);
      t = Clock::now();
      const BasePlane base = basePlane(mesh, SurfacePoint::vertex(source));
      const double baseMs = msSince(t);
      (void)base;
      Timings traceTimings;
      const PathBatch batch = traceStraightestPaths(mesh, SurfacePoint::vertex(source), boundaryTargets(mesh),
                                                    TraceOptions{false, 0, &traceTimings})
                                  .value();
      if (r >= 0) {
        stage["source"].push_back(sourceMs);
        stage["base_plane"].push_back(baseMs);
        stage["traces"].push_back(traceTimings["prepare"] + traceTimings["trace"]);
      }
      m.paths = static_cast<int64_t>(batch.status.size());
      m.reached = summarize(batch).reached;
      m.crossed = 0;
      for (int64_t f : batch.facesCrossed) m.crossed += f;
      ParamOptions options;
      options.source = SurfacePoint::vertex(source);
      Timings pt;
      options.timings = &pt;
      const long faults = minorFaults();
      const double cpu = cpuMs();
      const auto p = parameterize(mesh, options);
      if (r >= 0) {  // the last run's
        m.warmFaults = minorFaults() - faults;
        m.warmCpu = cpuMs() - cpu;
      }
      if (!p) {
        std::printf("{\"target\":\"%s\",\"mesh\":\"%s\",\"error\":\"%s\"}\n", target.c_str(), spec.c_str(),
                    p.error().message.c_str());
        return 2;
      }
      m.l2 = p.value().metrics.l2;
      m.bijective = p.value().metrics.bijective;
      // The free boundary from this map (parameterize with boundary free does the same when it is bijective).
      Timings ft;
      const auto refined = refineParameterization(mesh, p.value(), free, {}, &ft);
      if (!refined) {
        std::printf("{\"target\":\"%s\",\"mesh\":\"%s\",\"error\":\"%s\"}\n", target.c_str(), spec.c_str(),
                    refined.error().message.c_str());
        return 2;
      }
      m.freeL2 = refined.value().metrics.l2;
      m.freeIterations = refined.value().iterations;
      m.freeBijective = refined.value().metrics.bijective;
      if (r < 0) continue;
      stage["boundary"].push_back(pt["boundary"]);
      stage["weights"].push_back(pt["weights"]);
      stage["solve"].push_back(pt["solve"]);
      stage["metrics"].push_back(pt["metrics"]);
      stage["param_total"].push_back(pt["total"]);
      stage["refine"].push_back(ft["refine"]);
      stage["refine_metrics"].push_back(ft["metrics"]);
    }
    if (r < 0 && ++warmups < 200 && msSince(warmStart) < 1500) --r;  // stay in the warm-up
  }
  for (size_t c = 0; c < counts.size(); ++c) {
    Measured& m = measured[c];
    setThreadCount(counts[c]);
    std::printf(
        "{\"target\":\"%s\",\"mesh\":\"%s\",\"threads\":%d,\"vertices\":%lld,\"faces\":%lld,\"repeats\":%d,"
        "\"paths\":%lld,\"reached\":%lld,\"faces_crossed\":%lld,\"l2\":%.6f,\"bijective\":%s,\"free_l2\":%.6f,"
        "\"free_bijective\":%s,\"free_iterations\":%d,\"peak_memory_mb\":%.1f,\"cold_minor_faults\":%ld,"
        "\"warm_minor_faults\":%ld,\"cold_cpu_ms\":%.1f,\"warm_cpu_ms\":%.1f,\"cold_stages_ms\":{",
        target.c_str(), spec.c_str(), threadCount(), static_cast<long long>(m.vertices),
        static_cast<long long>(m.faces), repeats, static_cast<long long>(m.paths), static_cast<long long>(m.reached),
        static_cast<long long>(m.crossed), m.l2, m.bijective ? "true" : "false", m.freeL2,
        m.freeBijective ? "true" : "false", m.freeIterations, peakMemoryMB(), coldFaults, m.warmFaults, coldCpu,
        m.warmCpu);
    bool first = true;
    // The cold call ran once, with the first thread count: every line repeats it.
    for (const char* name : {"source", "trace", "boundary", "weights", "solve", "metrics", "total"}) {
      std::printf("%s\"%s\":%.3f", first ? "" : ",", name, cold[name]);
      first = false;
    }
    std::printf("},\"stages_ms\":{");
    first = true;
    for (const char* name : {"load", "source", "base_plane", "traces", "boundary", "weights", "solve", "metrics",
                             "param_total", "refine", "refine_metrics"}) {
      std::vector<double>& v = m.stage[name];
      std::sort(v.begin(), v.end());
      std::printf("%s\"%s\":%.3f", first ? "" : ",", name, v[v.size() / 2]);
      first = false;
    }
    std::printf("}}\n");
  }
  return 0;
}
