// cut_meshes — cutToDisk on every mesh given (e.g. CGAL's sample meshes): one table row per mesh with
// its size, boundary loops, genus, the method, the seam (also relative to the bounding box's diagonal)
// and the cut's time (wall clock and CPU: the machine may be shared), after checking that the
// result is a disk with faithful maps back to the mesh. Exits 1 if any check fails (a mesh that does not
// load is listed and skipped).
//   usage: cut_meshes MESH.off...
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "straightest/cut/disk_cut.hpp"
#include "straightest/io/mesh_io.hpp"

using namespace straightest;
using Clock = std::chrono::steady_clock;

namespace {

/// What is wrong with the cut, or an empty string: the disk's topology, the face and vertex maps, the
/// seam on the boundary (each seam edge twice), the seam's length and the genus.
std::string problems(const TriMesh& mesh, const DiskCut& cut) {
  const MeshSummary& s = cut.disk.summary();
  if (s.boundaryLoopSizes.size() != 1) return std::to_string(s.boundaryLoopSizes.size()) + " boundary loops";
  if (s.eulerCharacteristic != 1) return "Euler characteristic " + std::to_string(s.eulerCharacteristic);
  if (s.components != 1) return std::to_string(s.components) + " components";
  if (s.reorientedFaces != 0) return std::to_string(s.reorientedFaces) + " reoriented faces";
  if (cut.vertexOrigin.size() != size_t(cut.disk.numVertices()) || cut.faceOrigin.size() != size_t(cut.disk.numFaces()))
    return "map sizes";
  std::vector<int> hits(mesh.numFaces(), 0);
  int64_t real = 0;
  for (int32_t f = 0; f < cut.disk.numFaces(); ++f) {
    const int32_t origin = cut.faceOrigin[f];
    if (origin < 0) continue;
    if (origin >= mesh.numFaces() || hits[origin]++) return "faceOrigin not one-to-one";
    ++real;
    for (int k = 0; k < 3; ++k)
      if (cut.vertexOrigin[cut.disk.triangle(f)[k]] != mesh.triangle(origin)[k]) return "corners differ";
  }
  if (real != cut.faces) return "faceOrigin misses faces of the component";
  using Edge = std::pair<int32_t, int32_t>;
  auto edge = [](int32_t a, int32_t b) { return Edge{std::min(a, b), std::max(a, b)}; };
  std::map<Edge, int> boundary;
  const std::vector<int32_t>& loop = cut.disk.boundaryLoops()[0];
  for (size_t i = 0; i < loop.size(); ++i) {
    const int32_t a = cut.vertexOrigin[loop[i]], b = cut.vertexOrigin[loop[(i + 1) % loop.size()]];
    if (a < 0 || b < 0) return "a virtual vertex on the boundary";
    ++boundary[edge(a, b)];
  }
  double length = 0;
  for (const auto& e : cut.seam) {
    if (boundary[edge(e[0], e[1])] != 2) return "a seam edge not twice on the boundary";
    length += norm(mesh.position(e[0]) - mesh.position(e[1]));
  }
  if (std::abs(length - cut.seamLength) > 1e-9 * (1 + length)) return "seam length";
  if (cut.method == CutMethod::CutGraph) {
    std::vector<int32_t> vertices;
    for (const auto& e : cut.seam) vertices.insert(vertices.end(), {e[0], e[1]});
    std::sort(vertices.begin(), vertices.end());
    const int64_t seamEuler = int64_t(std::unique(vertices.begin(), vertices.end()) - vertices.begin()) -
                              int64_t(cut.seam.size());
    if (seamEuler != 1 - 2 * cut.genus) return "seam graph has Euler characteristic " + std::to_string(seamEuler);
  }
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: cut_meshes MESH.off...\n");
    return 2;
  }
  int failures = 0;
  std::printf("%-28s %8s %8s %5s %5s %5s %-9s %10s %12s %9s %9s %9s  %s\n", "mesh", "V", "F", "comps", "loops", "genus",
              "method", "seam_edges", "seam_length", "seam/diag", "cut_ms", "cpu_ms", "check");
  for (int i = 1; i < argc; ++i) {
    const std::string name = std::filesystem::path(argv[i]).stem().string();
    auto mesh = loadMeshFile(argv[i]);
    if (!mesh) {
      std::printf("%-28s not loaded: %s\n", name.c_str(), mesh.error().message.c_str());
      continue;
    }
    const TriMesh& m = mesh.value();
    const Clock::time_point start = Clock::now();
    const std::clock_t cpuStart = std::clock();
    auto cut = cutToDisk(m);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    const double cpuMs = 1000.0 * double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    if (!cut) {
      ++failures;
      std::printf("%-28s %8d %8d  FAILED: %s\n", name.c_str(), m.numVertices(), m.numFaces(),
                  cut.error().message.c_str());
      continue;
    }
    const DiskCut& c = cut.value();
    const std::string wrong = problems(m, c);
    if (!wrong.empty()) ++failures;
    // The cut component's loops: the filled ones, and the one Disk and Fill leave open.
    const int loops = int(c.filledLoops.size()) + (c.method == CutMethod::Disk || c.method == CutMethod::Fill ? 1 : 0);
    std::printf("%-28s %8d %8d %5d %5d %5d %-9s %10zu %12.4g %9.2f %9.1f %9.1f  %s\n", name.c_str(), m.numVertices(),
                m.numFaces(), c.components, loops, c.genus, cutMethodName(c.method), c.seam.size(), c.seamLength,
                c.seamLength / m.summary().bbox.diagonal(), ms, cpuMs, wrong.empty() ? "ok" : wrong.c_str());
  }
  std::printf("%d failed\n", failures);
  return failures == 0 ? 0 : 1;
}
