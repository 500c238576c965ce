// bench_atlas_pack.cpp — utilization and time of packCharts on synthetic chart sets (convex polygons, L shapes,
// strips, and the three mixed) at several chart counts and resolutions, and on the charts of real meshes
// (segmented once, then packed alone so that only the packer is timed); one line per set.
// Usage: bench_atlas_pack [padding] [resolution MESH...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>

#include "atlas_chart_shapes.hpp"
#include "straightest/atlas/chart_packing.hpp"
#include "straightest/atlas/chart_segmentation.hpp"
#include "straightest/io/mesh_io.hpp"

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

/// The packed charts as a grey image (PGM), each chart filled with its own shade, to look at a layout.
void writeLayout(const std::string& path, const Packing& packing, const std::vector<ChartShape>& charts) {
  std::vector<unsigned char> image(static_cast<size_t>(packing.width) * packing.height, 0);
  for (size_t c = 0; c < charts.size(); ++c) {
    const auto& points = charts[c].triangles;
    const unsigned char shade = static_cast<unsigned char>(80 + (c * 37) % 170);
    for (size_t t = 0; t + 2 < points.size(); t += 3) {
      Vec2 p[3];
      for (int k = 0; k < 3; ++k) p[k] = placeInTexels(packing, static_cast<int32_t>(c), points[t + k]);
      const int x0 = std::max(0, static_cast<int>(std::min({p[0].x, p[1].x, p[2].x})));
      const int x1 = std::min(packing.width - 1, static_cast<int>(std::max({p[0].x, p[1].x, p[2].x})));
      const int y0 = std::max(0, static_cast<int>(std::min({p[0].y, p[1].y, p[2].y})));
      const int y1 = std::min(packing.height - 1, static_cast<int>(std::max({p[0].y, p[1].y, p[2].y})));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const Vec2 q{x + 0.5, y + 0.5};
          const double a = cross(p[1] - p[0], q - p[0]), b = cross(p[2] - p[1], q - p[1]),
                       d = cross(p[0] - p[2], q - p[2]);
          if ((a >= 0 && b >= 0 && d >= 0) || (a <= 0 && b <= 0 && d <= 0))
            image[static_cast<size_t>(packing.height - 1 - y) * packing.width + x] = shade;
        }
    }
  }
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return;
  std::fprintf(file, "P5 %d %d 255\n", packing.width, packing.height);
  std::fwrite(image.data(), 1, image.size(), file);
  std::fclose(file);
}

void packAndReport(const std::string& name, const std::vector<ChartShape>& charts, int side, double padding) {
  PackOptions options;
  options.resolution = side;
  options.padding = padding;
  const auto start = std::chrono::steady_clock::now();
  const auto packing = packCharts(charts, options);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!packing) {
    std::printf("%-20s %6zu %6d: %s\n", name.c_str(), charts.size(), side, packing.error().message.c_str());
    return;
  }
  if (const char* folder = std::getenv("PACK_LAYOUT_DIR"))
    writeLayout(std::string(folder) + "/" + name + "-" + std::to_string(side) + ".pgm", packing.value(), charts);
  std::printf("%-20s %6zu %6d %8.1f %11.3f %9.1f\n", name.c_str(), charts.size(), side, padding,
              packing.value().utilization, ms);
  std::fflush(stdout);
}

/// The charts of a mesh file, as packCharts takes them; empty (with a message) when the mesh fails.
std::vector<ChartShape> meshCharts(const std::string& path) {
  auto mesh = loadMeshFile(path);
  if (!mesh) {
    std::printf("%s: %s\n", path.c_str(), mesh.error().message.c_str());
    return {};
  }
  auto set = makeCharts(mesh.value(), ChartOptions{});
  if (!set) {
    std::printf("%s: %s\n", path.c_str(), set.error().message.c_str());
    return {};
  }
  std::vector<ChartShape> shapes;
  for (const FlatChart& chart : set.value().charts) shapes.push_back(ChartShape{chart.cornerUv});
  return shapes;
}

std::string baseName(const std::string& path) {
  const std::string file = path.substr(path.find_last_of('/') + 1);
  return file.substr(0, file.find_last_of('.'));
}

}  // namespace

int main(int argc, char** argv) {
  const double padding = argc > 1 ? std::atof(argv[1]) : 2;
  std::printf("%-20s %6s %6s %8s %11s %9s\n", "set", "charts", "side", "padding", "utilization", "ms");
  if (argc > 3) {
    const int side = std::atoi(argv[2]);
    for (int i = 3; i < argc; ++i) packAndReport(baseName(argv[i]), meshCharts(argv[i]), side, padding);
    return 0;
  }
  for (const char* kind : {"mixed", "convex", "L", "strip"})
    for (const int count : {20, 200, 2000})
      for (const int side : {1024, 4096}) packAndReport(kind, chartsOfKind(kind, count, 42), side, padding);
  return 0;
}
