// Benchmark: straightest paths from the default source to every boundary vertex on generated height
// fields (the mountain relief at 10k, 100k and 1M vertices). Prints a table; never pass/fail.
// The same source builds natively and to WASM (run under Node), so the two columns are comparable.
//   bench_paths [TARGET] [REPEATS] [--threads N,N,...]   one row per thread count (default: every core),
//   the counts measured in turn within each repeat so that the machine's load weighs on them alike.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "../core/cli/huge_pages.hpp"
#include "straightest/base/threads.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/paths/straightest_path.hpp"
#include "thread_counts.hpp"

using namespace straightest;
using Clock = std::chrono::steady_clock;

static double ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

int main(int argc, char** argv) {
  straightest::cli::reexecWithHugePages(argv);  // as the CLI runs
  std::vector<const char*> positional;
  std::vector<int> counts = {0};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--threads" && i + 1 < argc) counts = threadCounts(argv[++i]);
    else positional.push_back(argv[i]);
  }
  const char* target = positional.size() > 0 ? positional[0] : "native";
  const int repeats = positional.size() > 1 ? std::max(1, std::atoi(positional[1])) : 5;
  std::printf(
      "| target | threads | vertices | boundary paths | reached | faces crossed | build ms | source ms | trace ms "
      "(median of %d) | M faces/s |\n",
      repeats);
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int n : {100, 317, 1000}) {
    const auto t0 = Clock::now();
    const TriMesh mesh = makeHeightField(n);
    const auto t1 = Clock::now();
    const int32_t source = defaultSource(mesh).value();
    const auto t2 = Clock::now();
    const auto targets = boundaryTargets(mesh);
    std::vector<std::vector<double>> traceMs(counts.size());
    int64_t crossed = 0, reached = 0;
    for (int r = 0; r < repeats; ++r) {
      for (size_t c = 0; c < counts.size(); ++c) {
        setThreadCount(counts[c]);
        Timings timings;
        const PathBatch batch = traceStraightestPaths(mesh, SurfacePoint::vertex(source), targets,
                                                      TraceOptions{false, 0, &timings})
                                    .value();
        traceMs[c].push_back(timings["trace"]);
        crossed = 0;
        for (int64_t f : batch.facesCrossed) crossed += f;
        reached = summarize(batch).reached;
      }
    }
    for (size_t c = 0; c < counts.size(); ++c) {
      std::sort(traceMs[c].begin(), traceMs[c].end());
      const double median = traceMs[c][traceMs[c].size() / 2];
      setThreadCount(counts[c]);
      std::printf("| %s | %d | %d | %zu | %lld | %lld | %.0f | %.0f | %.2f | %.1f |\n", target, threadCount(),
                  mesh.numVertices(), targets.size(), static_cast<long long>(reached), static_cast<long long>(crossed),
                  ms(t0, t1), ms(t1, t2), median, crossed / median / 1000.0);
    }
  }
  return 0;
}
