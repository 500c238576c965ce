// Benchmark: straightest paths from the default source to every boundary vertex on generated height
// fields (the mountain relief at 10k, 100k and 1M vertices). Prints a table; never pass/fail.
// The same source builds natively and to WASM (run under Node), so the two columns are comparable.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "straightest/geodesic_distance.hpp"
#include "straightest/samples.hpp"
#include "straightest/straightest_path.hpp"

using namespace straightest;
using Clock = std::chrono::steady_clock;

static double ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

int main(int argc, char** argv) {
  const char* target = argc > 1 ? argv[1] : "native";
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  std::printf(
      "| target | vertices | boundary paths | reached | faces crossed | build ms | source ms | trace ms (median of %d) "
      "| M faces/s |\n",
      repeats);
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int n : {100, 317, 1000}) {
    const auto t0 = Clock::now();
    const TriMesh mesh = makeHeightField(n);
    const auto t1 = Clock::now();
    const int32_t source = defaultSource(mesh).value();
    const auto t2 = Clock::now();
    const auto targets = boundaryTargets(mesh);
    std::vector<double> traceMs;
    int64_t crossed = 0, reached = 0;
    for (int r = 0; r < repeats; ++r) {
      Timings timings;
      const PathBatch batch =
          traceStraightestPaths(mesh, SurfacePoint::vertex(source), targets, TraceOptions{false, 0, &timings}).value();
      traceMs.push_back(timings["trace"]);
      crossed = 0;
      for (int64_t c : batch.facesCrossed) crossed += c;
      reached = summarize(batch).reached;
    }
    std::sort(traceMs.begin(), traceMs.end());
    const double median = traceMs[traceMs.size() / 2];
    std::printf("| %s | %d | %zu | %lld | %lld | %.0f | %.0f | %.2f | %.1f |\n", target, mesh.numVertices(),
                targets.size(), static_cast<long long>(reached), static_cast<long long>(crossed), ms(t0, t1),
                ms(t1, t2), median, crossed / median / 1000.0);
  }
  return 0;
}
