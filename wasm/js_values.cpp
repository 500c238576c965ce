// js_values.cpp — the adapters of js_values.hpp.
#include "js_values.hpp"

#include <emscripten/em_js.h>
#include <emscripten/em_macros.h>

#include <cmath>
#include <map>

// A column of many small JS values is built in one call into JavaScript from packed arrays in WASM
// memory: value by value through Embind (a call for each object, each field and each push) the targets
// and statuses of many paths cost a noticeable share of the traces themselves. Pointers are unsigned (the memory may
// exceed 2 GB), hence `>>> 2`.

// The bodies are JavaScript: clang-format would break them (`===` into `== =`).
// clang-format off
/// [{vertex} | {halfedge, t} | {face, bary}] from kinds (0, 1, 2), indices and three parameters a point.
EM_JS(emscripten::EM_VAL, straightest_surface_points, (const int32_t* kinds, const int32_t* indices, const double* params, int count), {
  const points = new Array(count);
  for (let i = 0; i < count; ++i) {
    const index = HEAP32[(indices >>> 2) + i];
    const at = (params >>> 3) + 3 * i;
    const kind = HEAP32[(kinds >>> 2) + i];
    if (kind === 0) points[i] = { vertex: index };
    else if (kind === 1) points[i] = { halfedge: index, t: HEAPF64[at] };
    else points[i] = { face: index, bary: [HEAPF64[at], HEAPF64[at + 1], HEAPF64[at + 2]] };
  }
  return Emval.toHandle(points);
});

/// [names[codes[0]], names[codes[1]], ...].
EM_JS(emscripten::EM_VAL, straightest_text_column, (emscripten::EM_VAL names, const int32_t* codes, int count), {
  const table = Emval.toValue(names);
  const column = new Array(count);
  for (let i = 0; i < count; ++i) column[i] = table[HEAP32[(codes >>> 2) + i]];
  return Emval.toHandle(column);
});
// clang-format on

namespace straightest::js {
namespace {

std::string describe(const val& v) {
  if (v.isUndefined()) return "undefined";
  // JSON would write NaN and the infinities as null.
  if (v.typeOf().as<std::string>() == "number") return val::global("String")(v).as<std::string>();
  const val text = val::global("JSON").call<val>("stringify", v);
  return text.isString() ? text.as<std::string>() : "undefined";
}

/// A point index: a whole number in [0, 2^31).
Expected<int32_t> indexFrom(const val& v) {
  const double index = v.as<double>();
  if (!(index >= 0 && index <= 2147483647.0 && index == static_cast<double>(static_cast<int32_t>(index))))
    return Error{ErrorCode::InvalidArgument, "surface point index " + describe(v) + " is not valid"};
  return static_cast<int32_t>(index);
}

bool isNumber(const val& v) { return v.typeOf().as<std::string>() == "number"; }

/// A surface point, or nullopt when `p` has none of the four shapes.
std::optional<Expected<SurfacePoint>> pointFrom(const val& p) {
  auto make = [](const val& index, auto build) -> Expected<SurfacePoint> {
    auto i = indexFrom(index);
    if (!i) return i.error();
    return build(i.value());
  };
  if (isNumber(p)) return make(p, [](int32_t v) { return SurfacePoint::vertex(v); });
  if (p.isNull() || p.isUndefined() || p.typeOf().as<std::string>() != "object") return std::nullopt;
  if (isNumber(p["vertex"])) return make(p["vertex"], [](int32_t v) { return SurfacePoint::vertex(v); });
  const val bary = p["bary"];
  if (isNumber(p["face"]) && !bary.isUndefined() && !bary.isNull() && bary["length"].as<double>() == 3)
    return make(p["face"], [&](int32_t f) {
      return SurfacePoint::face(f, {bary[0].as<double>(), bary[1].as<double>(), bary[2].as<double>()});
    });
  if (isNumber(p["halfedge"]) && isNumber(p["t"]))
    return make(p["halfedge"], [&](int32_t h) { return SurfacePoint::edge(h, p["t"].as<double>()); });
  return std::nullopt;
}

Error shapeError(const std::string& what, bool allowAuto, const val& p) {
  return Error{ErrorCode::InvalidArgument,
               what + " must be " + (allowAuto ? "'auto', " : "") +
                   "a vertex index, {vertex}, {face, bary: [a, b, c]} or {halfedge, t}; got " + describe(p)};
}

}  // namespace

Expected<std::optional<SurfacePoint>> sourceFrom(const val& p, const std::string& what) {
  if (p.isString() && p.as<std::string>() == kAutoName) return std::optional<SurfacePoint>();
  auto point = pointFrom(p);
  if (!point) return shapeError(what, true, p);
  if (!*point) return point->error();
  return std::optional<SurfacePoint>(point->value());
}

Expected<std::vector<TargetSpec>> targetsFrom(const val& targets) {
  // 'boundary' (the longest loop's vertices) or 'all-boundaries' (every loop's), else nullopt.
  const auto named = [](const val& v) -> std::optional<TargetSpec> {
    if (!v.isString()) return std::nullopt;
    const std::string name = v.as<std::string>();
    if (name == "boundary") return TargetSpec{BoundaryVertices{}};
    if (name == "all-boundaries") return TargetSpec{AllBoundaryVertices{}};
    return std::nullopt;
  };
  if (auto spec = named(targets)) return std::vector<TargetSpec>{*spec};
  if (!targets.isArray())
    return Error{ErrorCode::InvalidArgument,
                 "targets must be 'boundary', 'all-boundaries' or an array of surface points (and such entries)"};
  std::vector<TargetSpec> specs;
  const auto n = targets["length"].as<unsigned>();
  specs.reserve(n);
  for (unsigned i = 0; i < n; ++i) {
    const val t = targets[i];
    if (auto spec = named(t)) {
      specs.push_back(*spec);
      continue;
    }
    auto point = pointFrom(t);
    if (!point) return shapeError("targets[" + std::to_string(i) + "]", false, t);
    if (!*point) return point->error();
    specs.emplace_back(point->value());
  }
  return specs;
}

Progress progressFrom(const val& fn) {
  if (fn.isUndefined() || fn.isNull()) return {};
  return [fn](const char* stage, double fraction) { return !fn(std::string(stage), fraction).isFalse(); };
}

Expected<BuildLimits> limitsFrom(const val& options) {
  BuildLimits limits;
  if (options.isUndefined() || options.isNull()) return limits;
  for (auto [name, cap] : {std::pair{"maxVertices", &limits.maxVertices}, std::pair{"maxFaces", &limits.maxFaces}}) {
    const val given = options[name];
    if (given.isUndefined() || given.isNull()) continue;
    const double n = given.isNumber() ? given.as<double>() : -1;
    if (!(n >= 1 && n <= 9007199254740992.0 && n == std::floor(n)))  // up to 2^53: exact as a double
      return Error{ErrorCode::InvalidArgument, std::string(name) + " must be a positive integer"};
    *cap = static_cast<int64_t>(n);
  }
  return limits;
}

Expected<FreeBoundaryOptions> freeOptionsFrom(const val& options) {
  FreeBoundaryOptions free;
  if (options.isUndefined() || options.isNull()) return free;
  const val iterations = options["maxIterations"], budget = options["timeBudgetMs"];
  if (!iterations.isUndefined() && !iterations.isNull()) {
    const double n = iterations.isNumber() ? iterations.as<double>() : -1;
    if (!(n >= 1 && n <= 2147483647.0 && n == std::floor(n)))
      return Error{ErrorCode::InvalidArgument, "maxIterations must be a positive integer"};
    free.maxIterations = static_cast<int32_t>(n);
  }
  if (!budget.isUndefined() && !budget.isNull()) {
    const double ms = budget.isNumber() ? budget.as<double>() : -1;
    if (!(ms > 0) || !std::isfinite(ms))
      return Error{ErrorCode::InvalidArgument, "timeBudgetMs must be a positive number of milliseconds"};
    free.timeBudgetMs = ms;
  }
  return free;
}

Expected<AtlasOptions> atlasOptionsFrom(const val& options) {
  AtlasOptions atlas;
  if (options.isUndefined() || options.isNull()) return atlas;
  const auto given = [&](const char* name) { return !options[name].isUndefined() && !options[name].isNull(); };
  for (auto [name, x] :
       {std::pair{"maxStretch", &atlas.charts.maxStretch}, std::pair{"minHullFill", &atlas.charts.minHullFill},
        std::pair{"padding", &atlas.pack.padding}, std::pair{"texelsPerUnit", &atlas.pack.texelsPerUnit}}) {
    if (!given(name)) continue;
    if (!isNumber(options[name])) return Error{ErrorCode::InvalidArgument, std::string(name) + " must be a number"};
    *x = options[name].as<double>();
  }
  for (auto [name, n] :
       {std::pair{"maxCharts", &atlas.charts.maxCharts}, std::pair{"resolution", &atlas.pack.resolution},
        std::pair{"width", &atlas.pack.width}, std::pair{"height", &atlas.pack.height}}) {
    if (!given(name)) continue;
    const double x = isNumber(options[name]) ? options[name].as<double>() : NAN;
    // An int32 exactly: the core refuses the values out of its range, but it cannot see a fraction or an overflow.
    if (!(std::abs(x) <= 2147483647.0 && x == std::floor(x)))
      return Error{ErrorCode::InvalidArgument,
                   std::string(name) + " must be an integer, got " + describe(options[name])};
    *n = static_cast<int32_t>(x);
  }
  if (given("rotate")) {
    if (!options["rotate"].isTrue() && !options["rotate"].isFalse())
      return Error{ErrorCode::InvalidArgument, "rotate must be true or false"};
    atlas.pack.rotate = options["rotate"].isTrue();
  }
  return atlas;
}

Expected<ShotAim> shotAimFrom(const val& options) {
  ShotAim aim;
  const auto given = [&](const char* name) { return !options[name].isUndefined() && !options[name].isNull(); };
  const auto number = [&](const char* name) -> Expected<double> {
    if (!isNumber(options[name])) return Error{ErrorCode::InvalidArgument, std::string(name) + " must be a number"};
    return options[name].as<double>();
  };
  if (options.isUndefined() || options.isNull() || options.typeOf().as<std::string>() != "object")
    return Error{ErrorCode::InvalidArgument, "shootGeodesic needs an options object"};
  if (given("direction") + given("angle") + given("toward") != 1)
    return Error{ErrorCode::InvalidArgument, "shootGeodesic needs one of direction, angle or toward (exactly one)"};
  if (given("direction")) {
    const val d = options["direction"];
    const bool shaped = !d.isString() && d.typeOf().as<std::string>() == "object" && isNumber(d["length"]) &&
                        d["length"].as<double>() == 3 && isNumber(d[0]) && isNumber(d[1]) && isNumber(d[2]);
    if (!shaped)
      return Error{ErrorCode::InvalidArgument, "direction must be [x, y, z] (3 numbers); got " + describe(d)};
    aim.direction = Vec3{d[0].as<double>(), d[1].as<double>(), d[2].as<double>()};
  }
  if (given("angle")) {
    auto a = number("angle");
    if (!a) return a.error();
    aim.angle = a.value();
  }
  if (given("toward")) {
    auto point = pointFrom(options["toward"]);
    if (!point) return shapeError("toward", false, options["toward"]);
    if (!*point) return point->error();
    aim.toward = point->value();
  }
  if (given("length")) {
    auto l = number("length");
    if (!l) return l.error();
    aim.length = l.value();
  }
  if (!aim.toward && !aim.length)
    return Error{ErrorCode::InvalidArgument, "shootGeodesic needs a length with direction or angle"};
  return aim;
}

val stringArray(const std::vector<std::string>& names) {
  val a = val::array();
  for (const std::string& n : names) a.call<void>("push", n);
  return a;
}

val pointToJs(const SurfacePoint& p) {
  val o = val::object();
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: o.set("vertex", p.index); break;
    case SurfacePoint::Kind::Edge:
      o.set("halfedge", p.index);
      o.set("t", p.t);
      break;
    case SurfacePoint::Kind::Face: {
      val b = val::array();
      b.call<void>("push", p.bary[0], p.bary[1], p.bary[2]);
      o.set("face", p.index);
      o.set("bary", b);
      break;
    }
  }
  return o;
}

void JsWriter::vec3(const char* name, const Vec3& v) {
  val a = val::array();
  a.call<void>("push", v.x, v.y, v.z);
  out_.set(name, a);
}

void JsWriter::counts(const char* name, const std::vector<int64_t>& xs) {
  val a = val::array();
  for (int64_t x : xs) a.call<void>("push", static_cast<double>(x));
  out_.set(name, a);
}

void JsWriter::points(const char* name, const std::vector<SurfacePoint>& ps) {
  std::vector<int32_t> kinds(ps.size()), indices(ps.size());
  std::vector<double> params(3 * ps.size());
  for (size_t i = 0; i < ps.size(); ++i) {
    const SurfacePoint& p = ps[i];
    kinds[i] = p.kind == SurfacePoint::Kind::Vertex ? 0 : p.kind == SurfacePoint::Kind::Edge ? 1 : 2;
    indices[i] = p.index;
    if (p.kind == SurfacePoint::Kind::Edge) params[3 * i] = p.t;
    if (p.kind == SurfacePoint::Kind::Face)
      for (int k = 0; k < 3; ++k) params[3 * i + k] = p.bary[k];
  }
  out_.set(name, val::take_ownership(straightest_surface_points(kinds.data(), indices.data(), params.data(),
                                                                static_cast<int>(ps.size()))));
}

void JsWriter::textColumn(const char* name, const std::vector<std::string>& xs) {
  std::map<std::string, int32_t> codeOf;  // distinct texts (a column has a few: status names)
  std::vector<std::string> names;
  std::vector<int32_t> codes(xs.size());
  for (size_t i = 0; i < xs.size(); ++i) {
    const auto [at, added] = codeOf.emplace(xs[i], static_cast<int32_t>(names.size()));
    if (added) names.push_back(xs[i]);
    codes[i] = at->second;
  }
  const val table = stringArray(names);
  out_.set(name,
           val::take_ownership(straightest_text_column(table.as_handle(), codes.data(), static_cast<int>(xs.size()))));
}

}  // namespace straightest::js
