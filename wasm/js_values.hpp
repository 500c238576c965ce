// js_values.hpp — the bindings' adapters between JS values and core types, and nothing else:
// surface points ('auto' → nullopt), targets ('boundary' → BoundaryVertices), name lists, progress
// functions, build limits, the free boundary's options, a geodesic shot's aim, and JsWriter, the visitor of
// result_fields.hpp that writes each result as a plain JS object with typed arrays for its large arrays. No policy:
// every decision is the core's.
#pragma once
#include <emscripten/val.h>

#include <optional>
#include <string>
#include <vector>

#include "straightest/api/result_fields.hpp"
#include "straightest/base/progress.hpp"

namespace straightest::js {

using emscripten::val;

/// A source as JS gives it: 'auto' (nullopt), a vertex number, {vertex}, {face, bary: [a, b, c]} or
/// {halfedge, t}. Only the shape is checked here (validateSurfacePoint checks the rest).
Expected<std::optional<SurfacePoint>> sourceFrom(const val& p, const std::string& what = "source");

/// Targets: 'boundary', or an array of surface points and 'boundary' entries.
Expected<std::vector<TargetSpec>> targetsFrom(const val& targets);

/// An array of names through a core name table ("unknown <what> 'x' (use …)"); undefined means every
/// name of the table, so the default lists live in the core only.
template <class E, size_t N>
Expected<std::vector<E>> namesFrom(const val& names, const EnumName<E> (&table)[N], const char* what) {
  std::vector<E> out;
  if (names.isUndefined()) {
    for (const EnumName<E>& e : table) out.push_back(e.value);
    return out;
  }
  if (!names.isArray()) return Error{ErrorCode::InvalidArgument, std::string(what) + " must be an array of names"};
  const auto n = names["length"].as<unsigned>();
  for (unsigned i = 0; i < n; ++i) {
    auto e = parseName(table, names[i].isString() ? names[i].as<std::string>() : std::string("?"), what);
    if (!e) return e.error();
    out.push_back(e.value());
  }
  return out;
}

/// A JS function (stage, fraction) → false to cancel; undefined or null means none.
Progress progressFrom(const val& fn);

/// { maxVertices, maxFaces } (either may be missing: the core's default); InvalidArgument unless a
/// positive integer.
Expected<BuildLimits> limitsFrom(const val& options);

/// The free boundary's { maxIterations, timeBudgetMs } (either may be missing: the core's default);
/// InvalidArgument unless a positive integer / a positive number.
Expected<FreeBoundaryOptions> freeOptionsFrom(const val& options);

/// The atlas's { maxStretch, maxCharts, resolution, width, height, padding, texelsPerUnit, rotate } (any may be
/// missing: the core's default). Only types are checked here (numbers, integers for the counts and sizes, a
/// boolean); their ranges are buildAtlas's to refuse.
Expected<AtlasOptions> atlasOptionsFrom(const val& options);

/// How shootGeodesic is aimed: exactly one of a 3D direction, an angle in the source's tangent frame
/// or a destination, and the length (required unless toward). Only shapes are checked here: a zero or
/// NaN direction, a NaN angle and a length ≤ 0 reach the core, which refuses them.
struct ShotAim {
  std::optional<Vec3> direction;
  std::optional<double> angle;
  std::optional<SurfacePoint> toward;
  std::optional<double> length;
};
Expected<ShotAim> shotAimFrom(const val& options);

/// A name list as a JS array of strings.
val stringArray(const std::vector<std::string>& names);

val pointToJs(const SurfacePoint& p);

class JsWriter {
 public:
  JsWriter() : out_(val::object()) {}
  void number(const char* name, double x) { out_.set(name, x); }
  void count(const char* name, int64_t x) { out_.set(name, static_cast<double>(x)); }
  void flag(const char* name, bool b) { out_.set(name, b); }
  void text(const char* name, const std::string& s) { out_.set(name, s); }
  void point(const char* name, const SurfacePoint& p) { out_.set(name, pointToJs(p)); }
  void vec3(const char* name, const Vec3& v);
  void nothing(const char* name) { out_.set(name, val::null()); }
  void counts(const char* name, const std::vector<int64_t>& xs);
  void texts(const char* name, const std::vector<std::string>& xs) { out_.set(name, stringArray(xs)); }
  void textColumn(const char* name, const std::vector<std::string>& xs);  // one text per item (few distinct)
  void points(const char* name, const std::vector<SurfacePoint>& ps);
  template <class Fill>
  void object(const char* name, Fill&& fill) {
    JsWriter child;
    fill(child);
    out_.set(name, child.out_);
  }
  /// An array of n objects, object i written by fill(i, writer).
  template <class Fill>
  void objects(const char* name, size_t n, Fill&& fill) {
    val array = val::array();
    for (size_t i = 0; i < n; ++i) {
      JsWriter child;
      fill(i, child);
      array.call<void>("push", child.out_);
    }
    out_.set(name, array);
  }
  template <class T>
  void list(const char* name, const std::vector<T>& items) {
    val array = val::array();
    for (const T& item : items) {
      JsWriter child;
      visitFields(item, child);
      array.call<void>("push", child.out_);
    }
    out_.set(name, array);
  }
  /// A typed array of the given kind, converted element by element (one copy out of WASM memory).
  template <class T>
  void bulk(const char* name, const T* data, size_t n, Bulk kind) {
    switch (kind) {
      case Bulk::Float32: out_.set(name, typedArray<float>("Float32Array", data, n)); break;
      case Bulk::Float64: out_.set(name, typedArray<double>("Float64Array", data, n)); break;
      case Bulk::Int32: out_.set(name, typedArray<int32_t>("Int32Array", data, n)); break;
      case Bulk::Uint32: out_.set(name, typedArray<uint32_t>("Uint32Array", data, n)); break;
      case Bulk::Uint8: out_.set(name, typedArray<uint8_t>("Uint8Array", data, n)); break;
    }
  }
  const val& result() const { return out_; }

 private:
  template <class Out, class T>
  static val typedArray(const char* type, const T* data, size_t n) {
    std::vector<Out> converted(data, data + n);
    return val::global(type).new_(emscripten::typed_memory_view(converted.size(), converted.data()));
  }
  val out_;
};

/// A result's fields as a JS object.
template <class T>
val toJs(const T& result) {
  JsWriter writer;
  visitFields(result, writer);
  return writer.result();
}

/// Either the value written by `write`, or {error, category}: what every binding returns (index.js
/// turns the latter into a StraightestError). Exceptions become errors through the core's mapping.
template <class Fn>
val respond(Fn&& fn) {
  Expected<val> r = guarded([&]() -> Expected<val> { return fn(); });
  return r ? r.value() : toJs(r.error());
}

}  // namespace straightest::js
