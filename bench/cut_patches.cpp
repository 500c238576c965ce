// cut_patches — geodesic-ball disks cut from closed meshes: the "real patches" the parameterization is
// judged on (scripts/patches.sh rebuilds the set). A fixed-boundary benchmark on synthetic disks says
// little about scans and models with jagged boundaries and protrusions; balls cut from real closed
// meshes have both, and cutting them ourselves makes the set reproducible from public data.
//
// For each input mesh (closed, one component): seeds alternate between farthest-point samples over
// edge-graph distances (the first is vertex 0's farthest vertex; they land on extremities) and
// pseudo-random vertices (a fixed hash; they land where the area is). For each seed and each radius (a
// fraction of the bounding-box diagonal) the ball is every face whose three corners are within the
// radius by the heat method's geodesic distance, and the patch is the ball's face-connected component
// holding the seed. A patch is kept only when it is a manifold disk (one component, one boundary loop,
// Euler characteristic 1, by TriMesh::summary) with a vertex count in the requested range. Of the disks
// around one seed the smallest and the largest are kept (two scales of one neighbourhood), seed after
// seed, at most --per-mesh per mesh. Everything is deterministic: the same inputs and options give the
// same files.
//
// Writes DIR/MESH-seedK-rR.off (R = radius in percent of the diagonal) and one line per patch on stdout:
// name, vertices, faces, boundary vertices, degenerate faces. Progress and rejections go to stderr.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/trimesh.hpp"

using namespace straightest;

namespace {

struct Options {
  std::string outDir = "build/data/patches";
  std::vector<double> radii = {0.1, 0.2, 0.3};
  int seeds = 5;
  int perMesh = 4;
  int minVertices = 1000, maxVertices = 30000;
  std::vector<std::string> meshes;
};

std::vector<double> parseList(const std::string& text) {
  std::vector<double> values;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!item.empty()) values.push_back(std::atof(item.c_str()));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

bool parseArgs(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--out" && hasValue) o.outDir = argv[++i];
    else if (arg == "--radii" && hasValue) o.radii = parseList(argv[++i]);
    else if (arg == "--seeds" && hasValue) o.seeds = std::atoi(argv[++i]);
    else if (arg == "--per-mesh" && hasValue) o.perMesh = std::atoi(argv[++i]);
    else if (arg == "--min-vertices" && hasValue) o.minVertices = std::atoi(argv[++i]);
    else if (arg == "--max-vertices" && hasValue) o.maxVertices = std::atoi(argv[++i]);
    else if (!arg.empty() && arg[0] == '-') return false;
    else o.meshes.push_back(arg);
  }
  return !o.meshes.empty() && !o.radii.empty() && o.seeds > 0;
}

/// Seeds of two characters, alternating: farthest-point samples over edge-graph distances (spread out,
/// extremities first: balls around them are protrusions, limbs and tips) and pseudo-random vertices (a
/// fixed hash of the rank, so mostly where the area is: bodies, flanks, faces).
std::vector<int32_t> patchSeeds(const TriMesh& mesh, int count) {
  auto farthest = [](const std::vector<double>& d) {
    int32_t best = 0;
    for (int32_t v = 0; v < static_cast<int32_t>(d.size()); ++v)
      if (std::isfinite(d[v]) && d[v] > d[best]) best = v;
    return best;
  };
  auto hashed = [&](uint64_t k) {  // splitmix64: the same vertex on every platform
    uint64_t z = (k + 1) * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<int32_t>((z ^ (z >> 31)) % static_cast<uint64_t>(mesh.numVertices()));
  };
  std::vector<int32_t> extremities = {farthest(dijkstraDistances(mesh, std::vector<int32_t>{0}))};
  std::vector<int32_t> seeds;
  for (int k = 0; static_cast<int>(seeds.size()) < count; ++k) {
    if (k % 2 == 0) {
      if (k > 0) extremities.push_back(farthest(dijkstraDistances(mesh, extremities)));
      seeds.push_back(extremities.back());
    } else {
      seeds.push_back(hashed(static_cast<uint64_t>(k)));
    }
  }
  return seeds;
}

/// The faces within `radius` (all three corners) that are face-connected to a face around `seed`.
std::vector<int32_t> ballComponent(const TriMesh& mesh, const std::vector<double>& distance, double radius,
                                   int32_t seed) {
  auto inside = [&](int32_t f) {
    const Triangle& t = mesh.triangle(f);
    return distance[t[0]] <= radius && distance[t[1]] <= radius && distance[t[2]] <= radius;
  };
  std::vector<uint8_t> visited(mesh.numFaces(), 0);
  std::vector<int32_t> faces, stack;
  for (int32_t f : mesh.vertexFaces(seed))
    if (inside(f) && !visited[f]) visited[f] = 1, stack.push_back(f);
  while (!stack.empty()) {
    const int32_t f = stack.back();
    stack.pop_back();
    faces.push_back(f);
    for (int k = 0; k < 3; ++k) {
      const int32_t t = mesh.twin(3 * f + k);
      if (t >= 0 && !visited[TriMesh::face(t)] && inside(TriMesh::face(t))) {
        visited[TriMesh::face(t)] = 1;
        stack.push_back(TriMesh::face(t));
      }
    }
  }
  std::sort(faces.begin(), faces.end());  // the file's face order, whatever the walk's
  return faces;
}

/// The faces as a mesh of their own (vertices renumbered in first-use order of the sorted faces).
Expected<TriMesh> subMesh(const TriMesh& mesh, const std::vector<int32_t>& faces) {
  std::vector<int32_t> newIndex(mesh.numVertices(), -1);
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  for (int32_t f : faces) {
    Triangle t = mesh.triangle(f);
    for (int32_t& v : t) {
      if (newIndex[v] < 0) {
        newIndex[v] = static_cast<int32_t>(positions.size());
        positions.push_back(mesh.position(v));
      }
      v = newIndex[v];
    }
    triangles.push_back(t);
  }
  return TriMesh::build(std::move(positions), std::move(triangles));
}

struct Candidate {
  std::string name;
  Expected<TriMesh> patch;
};

bool writeOff(const TriMesh& mesh, const std::string& path) {
  FILE* file = std::fopen(path.c_str(), "w");
  if (!file) return false;
  std::fprintf(file, "OFF\n%d %d 0\n", mesh.numVertices(), mesh.numFaces());
  for (const Vec3& p : mesh.positions()) std::fprintf(file, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
  for (const Triangle& t : mesh.triangles()) std::fprintf(file, "3 %d %d %d\n", t[0], t[1], t[2]);
  return std::fclose(file) == 0;
}

std::string stem(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

/// Cuts the patches of one mesh; returns how many were written.
int cutMesh(const std::string& path, const Options& o) {
  const auto loaded = loadMeshFile(path);
  if (!loaded) {
    std::fprintf(stderr, "cut_patches: %s: %s\n", path.c_str(), loaded.error().message.c_str());
    return 0;
  }
  const TriMesh& mesh = loaded.value();
  const MeshSummary& s = mesh.summary();
  if (!s.boundaryLoopSizes.empty() || s.components != 1) {
    std::fprintf(stderr, "cut_patches: %s: not a closed connected mesh, skipped\n", path.c_str());
    return 0;
  }
  const double diagonal = s.bbox.diagonal();
  HeatMethod heat(mesh);
  int written = 0;
  const std::vector<int32_t> seeds = patchSeeds(mesh, o.seeds);
  for (size_t k = 0; k < seeds.size() && written < o.perMesh; ++k) {
    const std::vector<double> distance = heat.distances(SurfacePoint::vertex(seeds[k]));
    std::vector<Candidate> disks;
    for (double fraction : o.radii) {
      const int percent = static_cast<int>(std::lround(fraction * 100));
      Candidate c{stem(path) + "-seed" + std::to_string(k) + "-r" + std::to_string(percent),
                  subMesh(mesh, ballComponent(mesh, distance, fraction * diagonal, seeds[k]))};
      if (!c.patch) {
        std::fprintf(stderr, "cut_patches: %s: %s\n", c.name.c_str(), c.patch.error().message.c_str());
        continue;
      }
      const MeshSummary& ps = c.patch.value().summary();
      const bool disk = ps.components == 1 && ps.boundaryLoopSizes.size() == 1 && ps.eulerCharacteristic == 1;
      if (!disk || ps.vertices < o.minVertices || ps.vertices > o.maxVertices) {
        std::fprintf(stderr, "cut_patches: %s rejected: %lld vertices, %zu boundary loops, Euler %lld\n",
                     c.name.c_str(), static_cast<long long>(ps.vertices), ps.boundaryLoopSizes.size(),
                     static_cast<long long>(ps.eulerCharacteristic));
        continue;
      }
      disks.push_back(std::move(c));
    }
    // The smallest and the largest disk around this seed: two scales of the same neighbourhood.
    if (disks.size() > 2) disks.erase(disks.begin() + 1, disks.end() - 1);
    for (const Candidate& c : disks) {
      if (written >= o.perMesh) break;
      const MeshSummary& ps = c.patch.value().summary();
      if (!writeOff(c.patch.value(), o.outDir + "/" + c.name + ".off")) {
        std::fprintf(stderr, "cut_patches: cannot write %s/%s.off\n", o.outDir.c_str(), c.name.c_str());
        return written;
      }
      std::printf("%s %lld %lld %lld %lld\n", c.name.c_str(), static_cast<long long>(ps.vertices),
                  static_cast<long long>(ps.faces), static_cast<long long>(ps.boundaryLoopSizes[0]),
                  static_cast<long long>(ps.degenerateFaces));
      std::fflush(stdout);
      ++written;
    }
  }
  return written;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parseArgs(argc, argv, o)) {
    std::fprintf(stderr,
                 "usage: cut_patches [--out DIR] [--radii 0.1,0.2,0.3] [--seeds 5] [--per-mesh 4]\n"
                 "                   [--min-vertices 1000] [--max-vertices 30000] closed.off...\n");
    return 2;
  }
  int total = 0;
  for (const std::string& path : o.meshes) total += cutMesh(path, o);
  std::fprintf(stderr, "cut_patches: %d patches in %s\n", total, o.outDir.c_str());
  return total > 0 ? 0 : 1;
}
