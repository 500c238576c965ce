// real_patches — the parameterization of each real patch (scripts/patches.sh) under every boundary,
// with the numbers that say why a boundary fails there: one JSON object per patch per line, which
// scripts/results.mjs turns into the "real patches" table of docs/RESULTS.md.
//
// Per patch: its size, and for each boundary (circle, measured, square, free) with shape-preserving
// weights and the default source: L2 / L∞ stretch, flipped, degenerate and overlapping counts,
// bijectivity, failed traces and outliers (the measured boundary's), time, and the worst ear; for free
// also its start (init), iterations, convergence and the refinement's own time, and the same refinement
// forced to start from the circle's map ("free_from_circle", through refineParameterization), so that
// RESULTS.md can say what the measured start buys. An ear is a triangle whose three corners are all
// boundary vertices: the measured boundary's convexification can put all three on one straight hull
// edge and collapse it. Its area ratio is (2D area / 3D area) of the ear divided by (total 2D area /
// total 3D area), the map's mean scale: 1 for an ear mapped like the map as a whole, near 0 for a
// collapsed one, negative for a flipped one.
//
// usage: real_patches MESH.off... (any disk meshes: scripts/results.mjs also runs it on CGAL's sample disks)
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "straightest/base/timings.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/param/parameterize.hpp"

using namespace straightest;

namespace {

std::string num(double x, int digits = 6) {
  if (!std::isfinite(x)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
  }
  return out + "\"";
}

/// The smallest ear area ratio (see the file comment) and how many ears there are; +inf without ears.
std::pair<double, int64_t> worstEar(const TriMesh& mesh, const std::vector<Vec2>& uv) {
  double area2 = 0, area3 = 0;
  std::vector<double> signedArea(mesh.numFaces());
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const Triangle& t = mesh.triangle(f);
    const Vec2 &a = uv[t[0]], &b = uv[t[1]], &c = uv[t[2]];
    signedArea[f] = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    area2 += std::fabs(signedArea[f]);
    area3 += mesh.faceArea(f);
  }
  const double meanRatio = area2 / area3;
  double worst = std::numeric_limits<double>::infinity();
  int64_t ears = 0;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const Triangle& t = mesh.triangle(f);
    if (!mesh.isBoundaryVertex(t[0]) || !mesh.isBoundaryVertex(t[1]) || !mesh.isBoundaryVertex(t[2])) continue;
    if (mesh.faceArea(f) <= 0) continue;  // a zero-area 3D face has no ratio
    ++ears;
    worst = std::fmin(worst, signedArea[f] / mesh.faceArea(f) / meanRatio);
  }
  return {worst, ears};
}

std::string patchName(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

/// The boundaries to run: the three fixed ones, and free when parseBoundaryChoice knows it.
std::vector<std::pair<std::string, BoundaryKind>> boundaries() {
  std::vector<std::pair<std::string, BoundaryKind>> kinds;
  for (const char* name : {"circle", "measured", "square", "free"}) {
    const auto kind = parseBoundaryChoice(name);
    if (kind && kind.value()) kinds.emplace_back(name, *kind.value());
  }
  return kinds;
}

/// One map's JSON object: its stretch and counts, and for a free map its refinement's numbers.
std::string describe(const TriMesh& mesh, const Parameterization& p, double ms, const Timings& timings) {
  const StretchMetrics& m = p.metrics;
  const auto [ear, ears] = worstEar(mesh, p.uv);
  std::string json = "{\"l2\":" + num(m.l2) + ",\"linf\":" + num(m.linf) + ",\"flipped\":" + std::to_string(m.flipped) +
                     ",\"degenerate\":" + std::to_string(m.degenerate) + ",\"overlaps\":" + std::to_string(m.overlaps) +
                     ",\"bijective\":" + (m.bijective ? "true" : "false") +
                     ",\"fallbacks\":" + std::to_string(p.fallbacks) + ",\"outliers\":" + std::to_string(p.outliers) +
                     ",\"worst_ear\":" + num(ear) + ",\"ears\":" + std::to_string(ears) + ",\"ms\":" + num(ms, 4);
  if (p.init)
    json += ",\"init\":" + jsonString(boundaryKindName(*p.init)) + ",\"iterations\":" + std::to_string(p.iterations) +
            ",\"converged\":" + (p.converged ? "true" : "false") +
            ",\"untangled\":" + (p.untangled ? "true" : "false") + ",\"energy_initial\":" + num(p.energyInitial) +
            ",\"energy_final\":" + num(p.energyFinal) + ",\"refine_ms\":" + num(timings["refine"], 4);
  return json + "}";
}

std::string errorJson(const Error& error) { return "{\"error\":" + jsonString(error.message) + "}"; }

std::string runBoundary(const TriMesh& mesh, BoundaryKind kind) {
  Timings timings;
  ParamOptions options;
  options.boundary = kind;
  options.weights = WeightKind::ShapePreserving;
  options.timings = &timings;
  const Stopwatch clock;
  const auto result = parameterize(mesh, options);
  if (!result) return errorJson(result.error());
  return describe(mesh, result.value(), clock.ms(), timings);
}

/// The free boundary refined from the circle's map whatever the measured map is (parameterize's free
/// starts from the measured map when it is bijective); ms counts the circle's solve and the refinement.
std::string runFreeFromCircle(const TriMesh& mesh) {
  ParamOptions options;
  options.boundary = BoundaryKind::Circle;
  options.weights = WeightKind::ShapePreserving;
  const Stopwatch clock;
  const auto start = parameterize(mesh, options);
  if (!start) return errorJson(start.error());
  Timings timings;
  const auto result = refineParameterization(mesh, start.value(), options.free, {}, &timings);
  if (!result) return errorJson(result.error());
  return describe(mesh, result.value(), clock.ms(), timings);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: real_patches MESH.off...\n");
    return 2;
  }
  const auto kinds = boundaries();
  int status = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string name = patchName(argv[i]);
    const auto mesh = loadMeshFile(argv[i]);
    if (!mesh) {
      std::fprintf(stderr, "real_patches: %s: %s\n", argv[i], mesh.error().message.c_str());
      status = 1;
      continue;
    }
    std::fprintf(stderr, "real_patches: %s\n", name.c_str());
    const MeshSummary& s = mesh.value().summary();
    std::string line = "{\"patch\":" + jsonString(name) + ",\"vertices\":" + std::to_string(s.vertices) +
                       ",\"faces\":" + std::to_string(s.faces) + ",\"boundary_vertices\":" +
                       std::to_string(s.boundaryLoopSizes.empty() ? 0 : s.boundaryLoopSizes[0]);
    for (const auto& [kindName, kind] : kinds) line += ",\"" + kindName + "\":" + runBoundary(mesh.value(), kind);
    line += ",\"free_from_circle\":" + runFreeFromCircle(mesh.value());
    std::printf("%s}\n", line.c_str());
    std::fflush(stdout);
  }
  return status;
}
