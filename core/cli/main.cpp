// straightest — the native command-line tool. Thin: parse arguments, call core, print one JSON object.
// Exit codes: 0 success, 2 bad input or usage (message on stderr, or {"error": ...} on stdout with
// --json-errors), 1 internal failure. Never a signal for bad input.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <cmath>
#include <exception>
#include <fstream>
#include <map>
#include <sstream>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "straightest/geodesic_distance.hpp"
#include "straightest/mesh_io.hpp"
#include "straightest/parameterize.hpp"
#include "straightest/samples.hpp"
#include "straightest/straightest_path.hpp"

using json = nlohmann::ordered_json;
using namespace straightest;

namespace {

constexpr const char* kUsage =
    "usage: straightest COMMAND MESH [options]\n"
    "\n"
    "commands:\n"
    "  info MESH        summary of the mesh as JSON (vertices, faces, boundary loops, Euler\n"
    "                   characteristic, components, degenerate and reoriented faces, bbox, problems)\n"
    "  paths MESH       straightest paths by cutting planes from a source to destinations\n"
    "      --source auto|N        source vertex (default auto: the interior vertex farthest from the boundary)\n"
    "      --to boundary|N,N,...  destinations (default boundary: every vertex of the longest boundary loop)\n"
    "      --points               include each path's points\n"
    "  param MESH       flatten a disk: boundary map + convex-combination interior, with texture stretch\n"
    "      --source auto|N        center for the measured boundary (default auto)\n"
    "      --boundary measured|circle|square|auto   (default measured; auto keeps the least stretched)\n"
    "      --weights shape-preserving|mean-value|cotan|uniform   (default shape-preserving)\n"
    "      --solver multigrid|lu|bicgstab   sparse solver (default multigrid)\n"
    "      -o OUT.obj             write the mesh with its UVs (vt) in the input's vertex order\n"
    "\n"
    "MESH is an .obj or .off file, sample:NAME for a built-in sample (mountain, cap, saddle, face), or\n"
    "heightfield:N for the mountain relief on an N × N grid (heightfield:1000 has 1M vertices).\n"
    "\n"
    "options:\n"
    "  --pretty         indent the JSON output\n"
    "  --json-errors    report errors as {\"error\": ..., \"category\": ...} on stdout\n"
    "  --max-vertices N, --max-faces N   refuse larger meshes (defaults 50M / 100M)\n"
    "  -h, --help       this text\n"
    "\n"
    "exit codes: 0 success, 2 bad input or usage, 1 internal error\n";

struct Options {
  std::string command, mesh;
  bool pretty = false, jsonErrors = false, points = false;
  std::string source = "auto", to = "boundary";
  std::string boundary = "measured", weights = "shape-preserving", solver = "multigrid", output;
  BuildLimits limits;
};

struct UsageError {
  std::string message;
};

int fail(const Options& o, int code, const std::string& category, const std::string& message) {
  if (o.jsonErrors) {
    std::cout << json{{"error", message}, {"category", category}}.dump(o.pretty ? 2 : -1) << "\n";
  } else {
    std::cerr << "straightest: " << message << "\n";
  }
  return code;
}

int64_t parseCount(const std::string& flag, const char* value) {
  char* end = nullptr;
  const long long v = std::strtoll(value, &end, 10);
  if (!*value || *end || v <= 0) throw UsageError{flag + " expects a positive integer, got '" + value + "'"};
  return v;
}

Options parseArgs(int argc, char** argv) {
  Options o;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) throw UsageError{a + " needs a value"};
      return argv[++i];
    };
    if (a == "--pretty") o.pretty = true;
    else if (a == "--json-errors") o.jsonErrors = true;
    else if (a == "--max-vertices") o.limits.maxVertices = parseCount(a, value());
    else if (a == "--max-faces") o.limits.maxFaces = parseCount(a, value());
    else if (a == "--source") o.source = value();
    else if (a == "--to") o.to = value();
    else if (a == "--points") o.points = true;
    else if (a == "--boundary") o.boundary = value();
    else if (a == "--weights") o.weights = value();
    else if (a == "--solver") o.solver = value();
    else if (a == "-o" || a == "--output") o.output = value();
    else if (a == "-h" || a == "--help") o.command = "help";
    else if (a.size() > 1 && a[0] == '-') throw UsageError{"unknown option '" + a + "'"};
    else positional.push_back(a);
  }
  if (o.command == "help") return o;
  if (positional.empty()) throw UsageError{"missing COMMAND"};
  o.command = positional[0];
  if (o.command != "info" && o.command != "paths" && o.command != "param") throw UsageError{"unknown command '" + o.command + "'"};
  if (positional.size() < 2) throw UsageError{"missing MESH"};
  if (positional.size() > 2) throw UsageError{"unexpected argument '" + positional[2] + "'"};
  o.mesh = positional[1];
  return o;
}

Expected<TriMesh> openMesh(const Options& o) {
  const std::string prefix = "sample:", field = "heightfield:";
  if (o.mesh.compare(0, prefix.size(), prefix) == 0) return makeSample(o.mesh.substr(prefix.size()));
  if (o.mesh.compare(0, field.size(), field) == 0) {
    const std::string n = o.mesh.substr(field.size());
    char* end = nullptr;
    const long size = std::strtol(n.c_str(), &end, 10);
    if (n.empty() || *end || size < 2 || size > 10000)
      return Error{ErrorCode::InvalidArgument, "heightfield:N needs 2 <= N <= 10000 (N × N vertices), got '" + n + "'"};
    return makeHeightField(static_cast<int>(size));
  }
  return loadMeshFile(o.mesh, o.limits);
}

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }

json infoJson(const TriMesh& mesh) {
  const MeshSummary& s = mesh.summary();
  return json{{"vertices", s.vertices},
              {"faces", s.faces},
              {"edges", s.edges},
              {"boundary_loops", s.boundaryLoopSizes},
              {"euler_characteristic", s.eulerCharacteristic},
              {"components", s.components},
              {"degenerate_faces", s.degenerateFaces},
              {"reoriented_faces", s.reorientedFaces},
              {"unreferenced_vertices", s.unreferencedVertices},
              {"bbox", {{"min", vec(s.bbox.min)}, {"max", vec(s.bbox.max)}}},
              {"problems", s.problems}};
}

/// A vertex given on the command line: a non-negative integer that names a vertex used by a face.
Expected<int32_t> parseVertex(const TriMesh& mesh, const std::string& text, const std::string& what) {
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end || v < 0)
    return Error{ErrorCode::InvalidArgument, what + " must be a vertex index, got '" + text + "'"};
  if (v >= mesh.numVertices())
    return Error{ErrorCode::InvalidArgument, what + " " + text + " is out of range (the mesh has " +
                                                 std::to_string(mesh.numVertices()) + " vertices)"};
  auto p = validateSurfacePoint(mesh, SurfacePoint::vertex(static_cast<int32_t>(v)));
  if (!p) return Error{ErrorCode::InvalidArgument, what + ": " + p.error().message};
  return static_cast<int32_t>(v);
}

Expected<int32_t> resolveSource(const TriMesh& mesh, const std::string& spec) {
  if (spec == "auto") return defaultSource(mesh);
  return parseVertex(mesh, spec, "--source");
}

Expected<std::vector<SurfacePoint>> resolveTargets(const TriMesh& mesh, const std::string& spec) {
  if (spec == "boundary") {
    auto targets = boundaryTargets(mesh);
    if (targets.empty()) return Error{ErrorCode::Topology, "--to boundary: the mesh is closed (no boundary loop)"};
    return targets;
  }
  std::vector<SurfacePoint> targets;
  std::stringstream list(spec);
  std::string item;
  while (std::getline(list, item, ',')) {
    auto v = parseVertex(mesh, item, "--to");
    if (!v) return v.error();
    targets.push_back(SurfacePoint::vertex(v.value()));
  }
  if (targets.empty()) return Error{ErrorCode::InvalidArgument, "--to needs 'boundary' or a list of vertices"};
  return targets;
}

int runPaths(const Options& o, const TriMesh& mesh, double loadMs) {
  auto source = resolveSource(mesh, o.source);
  if (!source) return fail(o, 2, errorCodeName(source.error().code), source.error().message);
  auto targets = resolveTargets(mesh, o.to);
  if (!targets) return fail(o, 2, errorCodeName(targets.error().code), targets.error().message);
  const PathBatch batch =
      traceStraightestPaths(mesh, SurfacePoint::vertex(source.value()), std::move(targets).value(), o.points);
  json paths = json::array();
  std::map<std::string, int64_t> failures;
  double sum = 0, maxLength = 0;
  for (size_t i = 0; i < batch.status.size(); ++i) {
    json p{{"target", batch.targets[i].index},
           {"status", traceStatusName(batch.status[i])},
           {"length", batch.length[i]},
           {"faces_crossed", batch.facesCrossed[i]}};
    if (batch.status[i] == TraceStatus::Reached) {
      sum += batch.length[i];
      maxLength = std::max(maxLength, batch.length[i]);
    } else {
      ++failures[traceStatusName(batch.status[i])];
    }
    if (o.points) {
      json pts = json::array();
      for (int64_t k = batch.offsets[i]; k < batch.offsets[i + 1]; ++k) pts.push_back(vec(batch.points[k]));
      p["points"] = std::move(pts);
    }
    paths.push_back(std::move(p));
  }
  const int64_t reached = batch.reached();
  int64_t crossed = 0;
  for (int64_t c : batch.facesCrossed) crossed += c;
  json out{{"source", source.value()},
           {"normal", vec(batch.base.normal)},
           {"base_fallback", batch.base.fallback},
           {"paths", std::move(paths)},
           {"summary", {{"paths", batch.status.size()},
                        {"reached", reached},
                        {"failures", failures},
                        {"mean_length", reached > 0 ? sum / reached : 0.0},
                        {"max_length", maxLength},
                        {"faces_crossed", crossed}}},
           {"timings_ms", {{"load", loadMs}, {"prepare", batch.prepareMs}, {"trace", batch.traceMs}}}};
  if (batch.base.fallback) out["base_note"] = batch.base.note;
  std::cout << out.dump(o.pretty ? 2 : -1) << "\n";
  return 0;
}

json finiteOrNull(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

int runParam(const Options& o, const TriMesh& mesh, double loadMs) {
  ParamOptions options;
  auto boundary = parseBoundaryChoice(o.boundary);
  if (!boundary) return fail(o, 2, "usage", boundary.error().message);
  auto weights = parseWeightKind(o.weights);
  if (!weights) return fail(o, 2, "usage", weights.error().message);
  auto solver = parseLinearSolver(o.solver);
  if (!solver) return fail(o, 2, "usage", solver.error().message);
  options.boundary = boundary.value();
  options.weights = weights.value();
  options.solver = solver.value();
  if (o.source != "auto") {
    auto v = parseVertex(mesh, o.source, "--source");
    if (!v) return fail(o, 2, errorCodeName(v.error().code), v.error().message);
    options.source = SurfacePoint::vertex(v.value());
  }
  Timings t;
  options.timings = &t;
  auto result = parameterize(mesh, options);
  if (!result) return fail(o, 2, errorCodeName(result.error().code), result.error().message);
  const Parameterization& p = result.value();
  if (!o.output.empty()) {
    std::ofstream out(o.output, std::ios::binary);
    out << writeObj(mesh, &p.uv);
    if (!out) return fail(o, 2, "io", "cannot write '" + o.output + "'");
  }
  const StretchMetrics& m = p.metrics;
  json candidates = json::array();
  for (const BoundaryCandidate& c : p.candidates)
    candidates.push_back({{"boundary", boundaryKindName(c.kind)}, {"l2", finiteOrNull(c.l2)},
                          {"linf", finiteOrNull(c.linf)}, {"flipped", c.flipped}, {"degenerate", c.degenerate}});
  json out{{"source", p.source.index},
           {"boundary", boundaryKindName(p.boundary)},
           {"weights", weightKindName(p.weights)},
           {"stretch", {{"l2", finiteOrNull(m.l2)}, {"linf", finiteOrNull(m.linf)}}},
           {"bijective", m.bijective},
           {"flipped", m.flipped},
           {"degenerate", m.degenerate},
           {"fallbacks", p.fallbacks},
           {"weight_fallbacks", p.weightFallbacks},
           {"angle_distortion", {{"mean", finiteOrNull(m.angleDistortionMean)}, {"max", finiteOrNull(m.angleDistortionMax)}}},
           {"area_distortion", {{"mean", finiteOrNull(m.areaDistortionMean)}, {"max", finiteOrNull(m.areaDistortionMax)}}},
           {"residual", p.residual},
           {"candidates", candidates},
           {"timings_ms", {{"load", loadMs}, {"source", t["source"]}, {"trace", t["trace"]}, {"boundary", t["boundary"]},
                           {"weights", t["weights"]}, {"solve", t["solve"]}, {"metrics", t["metrics"]}, {"total", t["total"]}}}};
  if (!o.output.empty()) out["output"] = o.output;
  std::cout << out.dump(o.pretty ? 2 : -1) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  try {
    o = parseArgs(argc, argv);
  } catch (const UsageError& e) {
    std::cerr << kUsage << "\n";
    return fail(o, 2, "usage", e.message);
  }
  if (o.command == "help") {
    std::cout << kUsage;
    return 0;
  }
  try {
    const auto t0 = std::chrono::steady_clock::now();
    auto mesh = openMesh(o);
    const double loadMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!mesh) return fail(o, 2, errorCodeName(mesh.error().code), mesh.error().message);
    if (o.command == "paths") return runPaths(o, mesh.value(), loadMs);
    if (o.command == "param") return runParam(o, mesh.value(), loadMs);
    std::cout << infoJson(mesh.value()).dump(o.pretty ? 2 : -1) << "\n";
    return 0;
  } catch (const std::bad_alloc&) {
    return fail(o, 2, "too_large", "out of memory: the mesh is too large for this machine");
  } catch (const std::exception& e) {
    return fail(o, 1, "internal", std::string("internal error: ") + e.what());
  }
}
