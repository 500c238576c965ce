// straightest — the native command-line tool. Thin: parse arguments, call core, print one JSON object.
// Exit codes: 0 success, 2 bad input or usage (message on stderr, or {"error": ...} on stdout with
// --json-errors), 1 internal failure. Never a signal for bad input.
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "straightest/mesh_io.hpp"
#include "straightest/samples.hpp"

using json = nlohmann::ordered_json;
using namespace straightest;

namespace {

constexpr const char* kUsage =
    "usage: straightest COMMAND MESH [options]\n"
    "\n"
    "commands:\n"
    "  info MESH        summary of the mesh as JSON (vertices, faces, boundary loops, Euler\n"
    "                   characteristic, components, degenerate and reoriented faces, bbox, problems)\n"
    "\n"
    "MESH is an .obj or .off file, or sample:NAME for a built-in sample (mountain, cap, saddle, face).\n"
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
  bool pretty = false, jsonErrors = false;
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
    else if (a == "-h" || a == "--help") o.command = "help";
    else if (a.size() > 1 && a[0] == '-') throw UsageError{"unknown option '" + a + "'"};
    else positional.push_back(a);
  }
  if (o.command == "help") return o;
  if (positional.empty()) throw UsageError{"missing COMMAND"};
  o.command = positional[0];
  if (o.command != "info") throw UsageError{"unknown command '" + o.command + "'"};
  if (positional.size() < 2) throw UsageError{"missing MESH"};
  if (positional.size() > 2) throw UsageError{"unexpected argument '" + positional[2] + "'"};
  o.mesh = positional[1];
  return o;
}

Expected<TriMesh> openMesh(const Options& o) {
  const std::string prefix = "sample:";
  if (o.mesh.compare(0, prefix.size(), prefix) == 0) return makeSample(o.mesh.substr(prefix.size()));
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
    auto mesh = openMesh(o);
    if (!mesh) return fail(o, 2, errorCodeName(mesh.error().code), mesh.error().message);
    std::cout << infoJson(mesh.value()).dump(o.pretty ? 2 : -1) << "\n";
    return 0;
  } catch (const std::bad_alloc&) {
    return fail(o, 2, "too_large", "out of memory: the mesh is too large for this machine");
  } catch (const std::exception& e) {
    return fail(o, 1, "internal", std::string("internal error: ") + e.what());
  }
}
