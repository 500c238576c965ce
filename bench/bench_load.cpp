// Benchmark: loading meshes from files. Writes the mountain height field (1M vertices by default) as
// OBJ and as OFF, then times loadMeshFile (read, parse, build the TriMesh) and the reader alone
// (parsePolygonSoup on bytes already in memory); prints a table with MB/s. Never pass/fail. The same
// source builds natively and to WASM (run under Node with NODERAWFS).
//   bench_load [TARGET] [N] [REPEATS] [DIR]   N × N vertices (default 1000), median of REPEATS (default 3)
// With DIR the files are DIR/heightfield.obj and .off, written only if missing and kept (so that
// npm run bench times the same files natively, as WASM and with `wc -w`); without it they go to a
// temporary directory and are removed.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../core/cli/huge_pages.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/samples.hpp"

using namespace straightest;
using Clock = std::chrono::steady_clock;

static double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

static double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

static std::string offText(const TriMesh& mesh) {
  std::string out = "OFF\n" + std::to_string(mesh.numVertices()) + " " + std::to_string(mesh.numFaces()) + " 0\n";
  char line[128];
  for (const Vec3& p : mesh.positions()) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    out += line;
  }
  for (const Triangle& t : mesh.triangles()) {
    std::snprintf(line, sizeof line, "3 %d %d %d\n", t[0], t[1], t[2]);
    out += line;
  }
  return out;
}

int main(int argc, char** argv) {
  straightest::cli::reexecWithHugePages(argv);  // as the CLI runs
  const char* target = argc > 1 ? argv[1] : "native";
  const int n = argc > 2 ? std::max(2, std::atoi(argv[2])) : 1000;
  const int repeats = argc > 3 ? std::max(1, std::atoi(argv[3])) : 3;
  const bool keep = argc > 4;
  const TriMesh mesh = makeHeightField(n);
  const std::filesystem::path dir = keep ? std::filesystem::path(argv[4])
                                         : std::filesystem::temp_directory_path() / "straightest-bench-load";
  std::filesystem::create_directories(dir);
  std::printf("| target | format | vertices | MB | load file ms | MB/s | parse only ms | MB/s |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (const char* format : {"obj", "off"}) {
    const std::string path = (dir / (std::string("heightfield.") + format)).string();
    if (!keep || !std::filesystem::exists(path))
      std::ofstream(path, std::ios::binary) << (format == std::string("obj") ? writeObj(mesh) : offText(mesh));
    std::string text;  // the file's bytes, for the parse-only timing
    {
      std::ifstream in(path, std::ios::binary | std::ios::ate);
      text.resize(static_cast<size_t>(in.tellg()));
      in.seekg(0).read(text.data(), static_cast<std::streamsize>(text.size()));
    }
    std::vector<double> load, parse;
    for (int r = -1; r < repeats; ++r) {  // r = -1: warm-up, not counted
      auto t = Clock::now();
      auto loaded = loadMeshFile(path);
      const double loadMs = msSince(t);
      if (!loaded || loaded.value().numVertices() != mesh.numVertices()) {
        std::fprintf(stderr, "bench_load: %s did not load back: %s\n", path.c_str(),
                     loaded ? "vertex count differs" : loaded.error().message.c_str());
        return 1;
      }
      t = Clock::now();
      auto soup = parsePolygonSoup(text, meshFormatFromFileName(path));
      const double parseMs = msSince(t);
      if (r >= 0) {
        load.push_back(loadMs);
        parse.push_back(parseMs);
      }
    }
    const double mb = text.size() / 1e6;
    std::printf("| %s | %s | %d | %.1f | %.0f | %.0f | %.0f | %.0f |\n", target, format, mesh.numVertices(), mb,
                median(load), mb / median(load) * 1e3, median(parse), mb / median(parse) * 1e3);
    if (!keep) std::filesystem::remove(path);
  }
  if (!keep) std::filesystem::remove(dir);
  return 0;
}
