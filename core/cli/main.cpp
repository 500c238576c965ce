// straightest — the native command-line tool. Thin: parse arguments, call core, print one JSON object
// (each result through its field list, result_fields.hpp). Exit codes: 0 success, 2 bad input or
// usage (message on stderr, or {"error", "category"} on stdout with --json-errors; a usage error is
// category invalid_argument, as in JS), 1 internal failure. Never a signal for bad input.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "huge_pages.hpp"
#include "json_writer.hpp"
#include "memory_warmup.hpp"
#include "straightest/api/distance_query.hpp"
#include "straightest/api/obj_with_uv.hpp"
#include "straightest/api/result_fields.hpp"
#include "straightest/base/names.hpp"
#include "straightest/base/threads.hpp"
#include "straightest/geodesics/exact_geodesic.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/geodesics/geodesic_shoot.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/paths/straightest_path.hpp"

using namespace straightest;
using straightest::cli::json;

namespace {

/// "a|b|c" for the usage text.
std::string alternatives(const std::vector<std::string>& names) { return choiceList(names, "|", "|"); }

std::string otherCommandsUsage();

std::string usage() {
  return "usage: straightest COMMAND MESH [options]\n"
         "\n"
         "commands:\n"
         "  info MESH        summary of the mesh as JSON (vertices, faces, boundary loops, Euler\n"
         "                   characteristic, components, degenerate and reoriented faces, bbox, problems)\n"
         "  paths MESH       straightest paths by cutting planes from a source to destinations\n"
         "      --source auto|N        source vertex (default auto: the interior vertex farthest from the boundary;\n"
         "                             with every vertex on it, the middle of the largest face)\n"
         "      --to boundary|all-boundaries|N,N,...\n"
         "                             destinations (default boundary: every vertex of the longest boundary loop;\n"
         "                             all-boundaries: every loop's, longest first; either may be one item of the\n"
         "                             list; a closed mesh needs vertices: both ways round the section are walked\n"
         "                             and the shorter arc returned, with direction and other_arc_length)\n"
         "      --points               include each path's points (and other_points, the other arc, where there is "
         "one)\n"
         "  param MESH       flatten a manifold mesh: boundary map + convex-combination interior, with texture\n"
         "                   stretch. A disk is mapped as it is; otherwise the largest component is made a disk\n"
         "                   first (cut: fill = holes filled virtually, the longest loop outside; path = a\n"
         "                   closed genus-0 surface cut between two far-apart vertices; cut-graph = genus >= 1\n"
         "                   cut by tree-cotree), reported with seam_edges, seam_length, genus, filled_loops\n"
         "      --source auto|N        center for the measured boundary (default auto)\n"
         "      --boundary " +
         alternatives(namesOf(kBoundaryKindNames, kAutoName)) +
         "   (default measured; free refines the measured (or circle) map, letting the\n"
         "                             boundary move, without folding; auto keeps the preferred map)\n"
         "      --weights " +
         alternatives(namesOf(kWeightKindNames)) +
         "   (default shape-preserving)\n"
         "      --solver " +
         alternatives(namesOf(kLinearSolverNames)) +
         "   sparse solver (default multigrid)\n"
         "      --max-iterations N     free boundary: refinement iterations at most (default " +
         std::to_string(FreeBoundaryOptions{}.maxIterations) +
         ")\n"
         "      --time-budget-ms T     free boundary: stop refining after T ms (default " +
         std::to_string(static_cast<long long>(FreeBoundaryOptions{}.timeBudgetMs)) +
         "), converged false\n"
         "      -o OUT.obj             write the mesh with its UVs (vt) in the input's vertex order; a cut or\n"
         "                             filled mesh gets a vt per distinct corner uv (f v/vt: the seam splits)\n" +
         otherCommandsUsage();
}

/// The usage text after param: shoot, atlas, distances, what MESH may be, the common options.
std::string otherCommandsUsage() {
  return "  shoot MESH       a straightest geodesic from a source and a direction (Polthier–Schmies)\n"
         "      --source auto|N        source vertex (default auto)\n"
         "      --direction ANGLE      radians in the source's tangent frame (0: its first edge, counter-clockwise)\n"
         "      --toward D             or: toward vertex D, as the cutting plane would start (reports miss_distance)\n"
         "      --length L             how far (required with --direction; default with --toward: the cutting\n"
         "                             plane's straightest distance to D)\n"
         "      --points               include the path's points\n"
         "  atlas MESH       a texture atlas of any manifold mesh: charts flattened with the free boundary (never\n"
         "                   folded, never mirrored) and packed into one texture without overlap\n"
         "      --max-stretch S        split charts whose L2 stretch exceeds S (default " +
         std::to_string(ChartOptions{}.maxStretch).substr(0, 4) +
         ")\n"
         "      --min-hull-fill F      split charts filling less than F of their convex hull (default " +
         std::to_string(ChartOptions{}.minHullFill).substr(0, 4) +
         ")\n"
         "      --max-charts N         at most N charts where the surface allows: merged whatever their\n"
         "                             stretch (default 0: no cap)\n"
         "      --resolution R         atlas side in texels (default " +
         std::to_string(PackOptions{}.resolution) +
         ")\n"
         "      --padding P            texels between charts (default " +
         std::to_string(static_cast<int>(PackOptions{}.padding)) +
         ")\n"
         "      --width W --height H   a W x H atlas instead of the square (both given)\n"
         "      --texels-per-unit T    this texel density (default: the largest at which the charts fit)\n"
         "      --no-rotate            keep each chart's orientation (default: turned to pack tighter)\n"
         "      -o OUT.obj             write the mesh with a vt per distinct corner uv (f v/vt)\n"
         "  distances MESH   geodesic distances from a source to vertices\n"
         "      --source auto|N        source vertex (default auto)\n"
         "      --method " +
         alternatives(namesOf(kDistanceMethodNames)) +
         "   (default exact: window propagation)\n"
         "      --to N,N,...           target vertices (default: every vertex)\n"
         "      --points               exact only: each target's shortest path (polyline)\n"
         "\n"
         "MESH is an .obj, .off, .ply or .stl file (PLY and STL ascii or binary; STL corners are welded),\n"
         "sample:NAME for a built-in sample (" +
         choiceList(sampleNames(), ", ", ", ") +
         "), or\n"
         "heightfield:N for the mountain relief on an N × N grid (heightfield:1000 has 1M vertices).\n"
         "\n"
         "options:\n"
         "  --pretty         indent the JSON output\n"
         "  --json-errors    report errors as {\"error\": ..., \"category\": ...} on stdout\n"
         "  --max-vertices N, --max-faces N   refuse larger meshes (defaults 50M / 100M)\n"
         "  --progress       progress lines on stderr: STAGE PERCENT, each stage from 0 to 100 (param, paths, atlas)\n"
         "  --threads N      threads to use (default: every core; 1 = the single-threaded path)\n"
         "  -h, --help       this text\n"
         "  --version        print the version (package.json's) and exit\n"
         "\n"
         "exit codes: 0 success, 2 bad input or usage, 1 internal error\n";
}

struct Options {
  std::string command, mesh;
  bool pretty = false, jsonErrors = false, points = false, progress = false;
  std::string source = "auto", to = "boundary";
  std::string boundary = "measured", weights = "shape-preserving", solver = "multigrid", output;
  BuildLimits limits;
  FreeBoundaryOptions free;
  bool toGiven = false;  // shoot / distances:
  std::string method = "exact", direction, toward;
  std::optional<double> length;
  int threads = 0;  // 0: every hardware thread
  AtlasOptions atlas;
};

struct UsageError {
  std::string message;
};

/// Reports an error; the exit code: 1 for an internal error, 2 for bad input or usage.
int fail(const Options& o, const Error& error) {
  if (o.jsonErrors) {
    std::cout << cli::toJson(error).dump(o.pretty ? 2 : -1) << "\n";
  } else {
    std::cerr << "straightest: " << error.message << "\n";
  }
  return error.code == ErrorCode::Internal ? 1 : 2;
}

/// The whole of `value` as a number of type T in decimal (no hex, no blanks, no '+'), or nothing.
template <typename T>
std::optional<T> decimal(const char* value) {
  T v{};
  const char* last = value + std::strlen(value);
  const auto [end, error] = std::from_chars(value, last, v);
  if (error != std::errc{} || end != last) return std::nullopt;
  return v;
}

int64_t parseCount(const std::string& flag, const char* value) {
  const auto v = decimal<int64_t>(value);
  if (!v || *v <= 0) throw UsageError{flag + " expects a positive integer, got '" + value + "'"};
  return *v;
}

double parsePositive(const std::string& flag, const char* value) {
  const auto v = decimal<double>(value);
  if (!v || !(*v > 0) || !std::isfinite(*v)) throw UsageError{flag + " expects a positive number, got '" + value + "'"};
  return *v;
}

double parseFraction(const std::string& flag, const char* value) {
  const auto v = decimal<double>(value);
  if (!v || !(*v >= 0 && *v <= 1)) throw UsageError{flag + " expects a number in [0, 1], got '" + value + "'"};
  return *v;
}

double parseNonNegative(const std::string& flag, const char* value) {
  const auto v = decimal<double>(value);
  if (!v || !(*v >= 0) || !std::isfinite(*v)) throw UsageError{flag + " expects a number >= 0, got '" + value + "'"};
  return *v;
}

int32_t parseCount32(const std::string& flag, const char* value) {
  return static_cast<int32_t>(std::min<int64_t>(parseCount(flag, value), std::numeric_limits<int32_t>::max()));
}

/// A count where 0 means "none" (no cap).
int32_t parseCountOrZero32(const std::string& flag, const char* value) {
  const auto v = decimal<int64_t>(value);
  if (!v || *v < 0) throw UsageError{flag + " expects an integer >= 0, got '" + value + "'"};
  return static_cast<int32_t>(std::min<int64_t>(*v, std::numeric_limits<int32_t>::max()));
}

/// -o's file: the CLI writes OBJ only, so another extension (a .glb, say) would get OBJ text under a wrong name.
std::string parseObjPath(const std::string& flag, const char* value) {
  std::string path = value;
  std::string extension = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".obj")
    throw UsageError{flag + " writes an OBJ file: give a name ending in .obj, got '" + path + "'"};
  return path;
}

/// --progress: a line on stderr when a stage starts and at every further tenth of it.
Progress progressLines(bool enabled) {
  if (!enabled) return {};
  auto last = std::make_shared<std::pair<std::string, int>>("", -1);
  return Progress([last](const char* stage, double fraction) {
    const int tenth = static_cast<int>(fraction * 10);
    if (last->first != stage || tenth > last->second) {
      *last = {stage, tenth};
      std::cerr << stage << " " << 10 * tenth << "%\n";
    }
    return true;
  });
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
    else if (a == "--to") {
      o.to = value();
      o.toGiven = true;
    } else if (a == "--method") o.method = value();
    else if (a == "--direction") o.direction = value();
    else if (a == "--toward") o.toward = value();
    else if (a == "--length") o.length = parsePositive(a, value());
    else if (a == "--points") o.points = true;
    else if (a == "--boundary") o.boundary = value();
    else if (a == "--weights") o.weights = value();
    else if (a == "--solver") o.solver = value();
    else if (a == "--max-iterations")
      o.free.maxIterations = static_cast<int32_t>(
          std::min<int64_t>(parseCount(a, value()), std::numeric_limits<int32_t>::max()));
    else if (a == "--time-budget-ms") o.free.timeBudgetMs = parsePositive(a, value());
    else if (a == "--progress") o.progress = true;
    else if (a == "--max-stretch") o.atlas.charts.maxStretch = parsePositive(a, value());
    else if (a == "--min-hull-fill") o.atlas.charts.minHullFill = parseFraction(a, value());
    else if (a == "--max-charts") o.atlas.charts.maxCharts = parseCountOrZero32(a, value());
    else if (a == "--resolution") o.atlas.pack.resolution = parseCount32(a, value());
    else if (a == "--padding") o.atlas.pack.padding = parseNonNegative(a, value());
    else if (a == "--width") o.atlas.pack.width = parseCount32(a, value());
    else if (a == "--height") o.atlas.pack.height = parseCount32(a, value());
    else if (a == "--texels-per-unit") o.atlas.pack.texelsPerUnit = parsePositive(a, value());
    else if (a == "--no-rotate") o.atlas.pack.rotate = false;
    else if (a == "--threads")
      o.threads = static_cast<int>(std::min<int64_t>(parseCount(a, value()), std::numeric_limits<int>::max()));
    else if (a == "-o" || a == "--output") o.output = parseObjPath(a, value());
    else if (a == "-h" || a == "--help") o.command = "help";
    else if (a == "--version") o.command = "version";
    else if (a.size() > 1 && a[0] == '-') throw UsageError{"unknown option '" + a + "'"};
    else positional.push_back(a);
  }
  if (o.command == "help" || o.command == "version") return o;
  if (positional.empty()) throw UsageError{"missing COMMAND"};
  o.command = positional[0];
  if (o.command != "info" && o.command != "paths" && o.command != "param" && o.command != "shoot" &&
      o.command != "distances" && o.command != "atlas")
    throw UsageError{"unknown command '" + o.command + "'"};
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
    const auto size = decimal<int32_t>(n.c_str());
    if (!size || *size < 2 || *size > 10000)
      return Error{ErrorCode::InvalidArgument, "heightfield:N needs 2 <= N <= 10000 (N × N vertices), got '" + n + "'"};
    return makeHeightField(*size);
  }
  return loadMeshFile(o.mesh, o.limits);
}

/// A vertex given on the command line: a non-negative integer that names a vertex used by a face.
Expected<int32_t> parseVertex(const TriMesh& mesh, const std::string& text, const std::string& what) {
  const auto index = decimal<int64_t>(text.c_str());
  if (!index || *index < 0)
    return Error{ErrorCode::InvalidArgument, what + " must be a vertex index, got '" + text + "'"};
  const int64_t v = *index;
  if (v >= mesh.numVertices())
    return Error{ErrorCode::InvalidArgument, what + " " + text + " is out of range (the mesh has " +
                                                 std::to_string(mesh.numVertices()) + " vertices)"};
  auto p = validateSurfacePoint(mesh, SurfacePoint::vertex(static_cast<int32_t>(v)));
  if (!p) return Error{ErrorCode::InvalidArgument, what + ": " + p.error().message};
  return static_cast<int32_t>(v);
}

/// --source: "auto" (nullopt, the core's default source) or a vertex.
Expected<std::optional<SurfacePoint>> sourceArgument(const TriMesh& mesh, const std::string& spec) {
  if (spec == kAutoName) return std::optional<SurfacePoint>();
  auto v = parseVertex(mesh, spec, "--source");
  if (!v) return v.error();
  return std::optional<SurfacePoint>(SurfacePoint::vertex(v.value()));
}

/// --to: comma-separated vertices, "boundary" and "all-boundaries" items.
Expected<std::vector<TargetSpec>> targetArguments(const TriMesh& mesh, const std::string& spec) {
  std::vector<TargetSpec> targets;
  std::stringstream list(spec);
  std::string item;
  while (std::getline(list, item, ',')) {
    if (item == "boundary") {
      targets.emplace_back(BoundaryVertices{});
      continue;
    }
    if (item == "all-boundaries") {
      targets.emplace_back(AllBoundaryVertices{});
      continue;
    }
    auto v = parseVertex(mesh, item, "--to");
    if (!v) return v.error();
    targets.emplace_back(SurfacePoint::vertex(v.value()));
  }
  if (targets.empty())
    return Error{ErrorCode::InvalidArgument, "--to needs 'boundary', 'all-boundaries' or a list of vertices"};
  return targets;
}

int runPaths(const Options& o, const TriMesh& mesh, double loadMs) {
  auto given = sourceArgument(mesh, o.source);
  if (!given) return fail(o, given.error());
  auto source = resolveSource(mesh, given.value());
  if (!source) return fail(o, source.error());
  auto specs = targetArguments(mesh, o.to);
  if (!specs) return fail(o, specs.error());
  auto targets = resolveTargets(mesh, specs.value());
  if (!targets) return fail(o, targets.error());
  Timings timings;
  timings.add("load", loadMs);
  auto traced = traceStraightestPaths(mesh, source.value(), std::move(targets).value(),
                                      TraceOptions{o.points, 0, &timings}, progressLines(o.progress));
  if (!traced) return fail(o, traced.error());
  const PathBatch& batch = traced.value();
  json out = cli::toJson(batch);
  json paths = json::array();
  for (size_t i = 0; i < batch.status.size(); ++i) {
    json p{{"target", cli::pointJson(batch.targets[i])},
           {"status", traceStatusName(batch.status[i])},
           {"length", batch.length[i]},
           {"faces_crossed", batch.facesCrossed[i]},
           {"direction", batch.reversed[i] ? "backward" : "forward"},
           {"other_arc_length", batch.otherArcLength[i]}};  // NaN (no other arc) is written as null
    if (o.points) {
      auto polyline = [&](const std::vector<Vec3>& points, int64_t begin, int64_t end) {
        json pts = json::array();
        for (int64_t k = begin; k < end; ++k) pts.push_back(cli::vec3Json(points[k]));
        return pts;
      };
      p["points"] = polyline(batch.points, batch.offsets[i], batch.offsets[i + 1]);
      if (batch.otherOffsets[i + 1] > batch.otherOffsets[i])
        p["other_points"] = polyline(batch.otherPoints, batch.otherOffsets[i], batch.otherOffsets[i + 1]);
    }
    paths.push_back(std::move(p));
  }
  out["paths"] = std::move(paths);
  out["summary"] = cli::toJson(summarize(batch));
  out["timings_ms"] = cli::toJson(timings);
  std::cout << out.dump(o.pretty ? 2 : -1) << "\n";
  return 0;
}

int runParam(const Options& o, const TriMesh& mesh, double loadMs) {
  ParamOptions options;
  auto boundary = parseBoundaryChoice(o.boundary);
  if (!boundary) return fail(o, boundary.error());
  auto weights = parseWeightKind(o.weights);
  if (!weights) return fail(o, weights.error());
  auto solver = parseLinearSolver(o.solver);
  if (!solver) return fail(o, solver.error());
  auto source = sourceArgument(mesh, o.source);
  if (!source) return fail(o, source.error());
  options.boundary = boundary.value();
  options.weights = weights.value();
  options.solver = solver.value();
  options.source = source.value();
  options.free = o.free;
  Timings timings;
  timings.add("load", loadMs);
  options.timings = &timings;
  auto result = parameterize(mesh, options, progressLines(o.progress));
  if (!result) return fail(o, result.error());
  const Parameterization& p = result.value();
  if (!o.output.empty()) {
    std::ofstream out(o.output, std::ios::binary);
    out << objOfParameterization(mesh, p);
    if (!out) return fail(o, Error{ErrorCode::Io, "cannot write '" + o.output + "'"});
  }
  json out = cli::toJson(p);
  out["timings_ms"] = cli::toJson(timings);
  if (!o.output.empty()) out["output"] = o.output;
  std::cout << out.dump(o.pretty ? 2 : -1) << "\n";
  return 0;
}

int runAtlas(const Options& o, const TriMesh& mesh, double loadMs) {
  Timings timings;
  timings.add("load", loadMs);
  AtlasOptions options = o.atlas;
  options.timings = &timings;
  auto result = buildAtlas(mesh, options, progressLines(o.progress));
  if (!result) return fail(o, result.error());
  if (!o.output.empty()) {
    std::ofstream out(o.output, std::ios::binary);
    out << writeObjWithCornerUv(mesh, result.value().cornerUv);
    if (!out) return fail(o, Error{ErrorCode::Io, "cannot write '" + o.output + "'"});
  }
  json out = cli::toJson(result.value());
  out["timings_ms"] = cli::toJson(timings);
  if (!o.output.empty()) out["output"] = o.output;
  std::cout << out.dump(o.pretty ? 2 : -1) << "\n";
  return 0;
}

int runShoot(const Options& o, const TriMesh& mesh, double loadMs) {
  if (o.direction.empty() == o.toward.empty())
    return fail(o, Error{ErrorCode::InvalidArgument, "shoot needs --direction ANGLE or --toward D (one of them)"});
  auto given = sourceArgument(mesh, o.source);
  if (!given) return fail(o, given.error());
  auto source = resolveSource(mesh, given.value());
  if (!source) return fail(o, source.error());
  Timings timings;
  timings.add("load", loadMs);
  const Stopwatch clock;
  Expected<GeodesicShot> shot = Error{ErrorCode::Internal, ""};
  if (!o.toward.empty()) {
    auto d = parseVertex(mesh, o.toward, "--toward");
    if (!d) return fail(o, d.error());
    shot = shootGeodesicToward(mesh, source.value(), SurfacePoint::vertex(d.value()), o.length, {},
                               progressLines(o.progress));
  } else {
    const auto direction = decimal<double>(o.direction.c_str());
    if (!direction || !std::isfinite(*direction))
      return fail(o, Error{ErrorCode::InvalidArgument,
                           "--direction expects an angle in radians, got '" + o.direction + "'"});
    const double angle = *direction;
    if (!o.length) return fail(o, Error{ErrorCode::InvalidArgument, "--direction needs --length L"});
    shot = shootGeodesicAtAngle(mesh, source.value(), angle, *o.length, {}, progressLines(o.progress));
  }
  if (!shot) return fail(o, shot.error());
  timings.add("shoot", clock.ms());
  json out = cli::toJson(shot.value());
  if (o.points) {
    json pts = json::array();
    for (const Vec3& x : shot.value().positions) pts.push_back(cli::vec3Json(x));
    out["points"] = std::move(pts);
  }
  out["timings_ms"] = cli::toJson(timings);
  std::cout << out.dump(o.pretty ? 2 : -1) << "\n";
  return 0;
}

int runDistances(const Options& o, const TriMesh& mesh, double loadMs) {
  auto method = parseDistanceMethod(o.method);
  if (!method) return fail(o, method.error());
  auto given = sourceArgument(mesh, o.source);
  if (!given) return fail(o, given.error());
  auto source = resolveSource(mesh, given.value());
  if (!source) return fail(o, source.error());
  DistanceTable table{source.value(), method.value(), {}, {}};
  if (o.toGiven) {
    std::stringstream list(o.to);
    std::string item;
    while (std::getline(list, item, ',')) {
      auto v = parseVertex(mesh, item, "--to");
      if (!v) return fail(o, v.error());
      table.targets.push_back(v.value());
    }
    if (table.targets.empty()) return fail(o, Error{ErrorCode::InvalidArgument, "--to needs a list of vertices"});
  }
  if (o.points && table.method != DistanceMethod::Exact)
    return fail(o, Error{ErrorCode::InvalidArgument, "--points (shortest paths) needs --method exact"});
  Timings timings;
  timings.add("load", loadMs);
  auto query = queryDistances(mesh, table.source, table.method, table.targets, o.points, progressLines(o.progress),
                              &timings);
  if (!query) return fail(o, query.error());
  table = query.value().table;
  json paths = json::array();
  for (const std::vector<Vec3>& path : query.value().paths) {
    json pts = json::array();
    for (const Vec3& x : path) pts.push_back(cli::vec3Json(x));
    paths.push_back(std::move(pts));
  }
  json out = cli::toJson(table);
  out["targets"] = table.targets;
  json distances = json::array();
  for (double d : table.distances) distances.push_back(std::isfinite(d) ? json(d) : json(nullptr));
  out["distances"] = std::move(distances);
  if (o.points) out["paths"] = std::move(paths);
  if (table.method == DistanceMethod::Exact) out["exact"] = cli::toJson(query.value().exact);
  out["timings_ms"] = cli::toJson(timings);
  std::cout << out.dump(o.pretty ? 2 : -1) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  straightest::cli::reexecWithHugePages(argv);
  Options o;
  try {
    o = parseArgs(argc, argv);
  } catch (const UsageError& e) {
    // The output flags hold even when another argument is wrong.
    for (int i = 1; i < argc; ++i) {
      o.jsonErrors = o.jsonErrors || std::string(argv[i]) == "--json-errors";
      o.pretty = o.pretty || std::string(argv[i]) == "--pretty";
    }
    // With no command at all the whole usage helps; otherwise the one line that says what was wrong.
    if (!o.jsonErrors && argc < 2) std::cerr << usage() << "\n";
    const int code = fail(o, Error{ErrorCode::InvalidArgument, e.message});
    if (!o.jsonErrors && argc >= 2) std::cerr << "straightest --help lists the commands and their options\n";
    return code;
  }
  if (o.command == "help") {
    std::cout << usage();
    return 0;
  }
  if (o.command == "version") {
    std::cout << "straightest " << STRAIGHTEST_VERSION << "\n";  // package.json's version, through CMake
    return 0;
  }
  setThreadCount(o.threads);
  Expected<int> exitCode = guarded([&]() -> Expected<int> {
    const Stopwatch load;
    std::optional<cli::MemoryWarmup> warmup;
    if (o.command == "param") warmup.emplace(cli::parameterizationBytes(o.mesh));
    auto mesh = openMesh(o);
    warmup.reset();
    const double loadMs = load.ms();
    if (!mesh) return fail(o, mesh.error());
    if (o.command == "paths") return runPaths(o, mesh.value(), loadMs);
    if (o.command == "param") return runParam(o, mesh.value(), loadMs);
    if (o.command == "shoot") return runShoot(o, mesh.value(), loadMs);
    if (o.command == "distances") return runDistances(o, mesh.value(), loadMs);
    if (o.command == "atlas") return runAtlas(o, mesh.value(), loadMs);
    std::cout << cli::toJson(mesh.value().summary()).dump(o.pretty ? 2 : -1) << "\n";
    return 0;
  });
  return exitCode ? exitCode.value() : fail(o, exitCode.error());
}
