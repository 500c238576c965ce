// bench_atlas_pack.cpp — utilization and time of packCharts on synthetic chart sets (convex polygons, L shapes,
// strips, and the three mixed) at several chart counts and resolutions; one line per set.
// Usage: bench_atlas_pack [padding]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>

#include "atlas_chart_shapes.hpp"
#include "straightest/atlas/chart_packing.hpp"

using namespace straightest;

namespace {

std::vector<ChartShape> chartsOfKind(const char* kind, int count, uint32_t seed) {
  if (std::string(kind) == "mixed") return testing::mixedCharts(count, seed);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<ChartShape> charts;
  for (int i = 0; i < count; ++i) {
    const double size = 0.5 + 1.5 * unit(random) * unit(random);
    if (std::string(kind) == "convex") charts.push_back(testing::randomConvexChart(random, size));
    else if (std::string(kind) == "L") charts.push_back(testing::lShapedChart(random, size));
    else charts.push_back(testing::stripChart(random, size));
  }
  return charts;
}

}  // namespace

int main(int argc, char** argv) {
  const double padding = argc > 1 ? std::atof(argv[1]) : 2;
  std::printf("%-7s %6s %6s %8s %11s %9s\n", "kind", "charts", "side", "padding", "utilization", "ms");
  for (const char* kind : {"mixed", "convex", "L", "strip"})
    for (const int count : {20, 200, 2000})
      for (const int side : {1024, 4096}) {
        const auto charts = chartsOfKind(kind, count, 42);
        PackOptions options;
        options.resolution = side;
        options.padding = padding;
        const auto start = std::chrono::steady_clock::now();
        const auto packing = packCharts(charts, options);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (!packing) {
          std::printf("%-7s %6d %6d: %s\n", kind, count, side, packing.error().message.c_str());
          continue;
        }
        std::printf("%-7s %6d %6d %8.1f %11.3f %9.1f\n", kind, count, side, padding, packing.value().utilization, ms);
        std::fflush(stdout);
      }
  return 0;
}
