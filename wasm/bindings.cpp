// Embind bindings: marshal arrays and plain objects between JS and core, nothing else.
// Every entry point returns either a result or {error, category}; the ESM wrapper (index.js) turns
// the latter into a JS Error. No C++ exception crosses into JS (Embind would deliver a bare number).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <malloc.h>

#include <memory>
#include <new>
#include <string>

#include "straightest/geodesic_distance.hpp"
#include "straightest/mesh_io.hpp"
#include "straightest/parameterize.hpp"
#include "straightest/samples.hpp"
#include "straightest/straightest_path.hpp"

using emscripten::val;
using namespace straightest;

static_assert(sizeof(Vec3) == 3 * sizeof(double), "positions are handed to JS as one block of doubles");
static_assert(sizeof(Triangle) == 3 * sizeof(int32_t), "indices are handed to JS as one block of int32");

namespace {

val errorObject(const std::string& category, const std::string& message) {
  val o = val::object();
  o.set("error", message);
  o.set("category", category);
  return o;
}

val errorObject(const Error& e) { return errorObject(errorCodeName(e.code), e.message); }

/// Runs fn, turning allocation failure and unexpected exceptions into error objects.
template <class Fn>
val guarded(Fn&& fn) {
  try {
    return fn();
  } catch (const std::bad_alloc&) {
    return errorObject("too_large", "the mesh is too large for the available memory (WebAssembly allocation failed)");
  } catch (const std::exception& e) {
    return errorObject("internal", std::string("internal error: ") + e.what());
  }
}

val vec3(const Vec3& v) {
  val a = val::array();
  a.call<void>("push", v.x, v.y, v.z);
  return a;
}

BuildLimits limitsFrom(const val& options) {
  BuildLimits limits;
  if (options.isUndefined() || options.isNull()) return limits;
  const val mv = options["maxVertices"], mf = options["maxFaces"];
  if (!mv.isUndefined()) limits.maxVertices = static_cast<int64_t>(mv.as<double>());
  if (!mf.isUndefined()) limits.maxFaces = static_cast<int64_t>(mf.as<double>());
  return limits;
}

/// Copies a contiguous array into a new JS typed array of the given type (one copy).
template <class T>
val copyToJs(const char* type, const T* data, size_t n) {
  return val::global(type).new_(emscripten::typed_memory_view(n, data));
}

/// A surface point marshalled as 5 numbers: [kind, index, a, b, c]; kind 0 vertex, 1 edge (halfedge
/// index, t = a), 2 face (face index, barycentric a b c). Kind -1 means "auto" (the default source).
Expected<SurfacePoint> pointFrom(const TriMesh& mesh, const double* s) {
  const int kind = static_cast<int>(s[0]);
  const double index = s[1];
  if (!(index >= 0 && index <= 2147483647.0 && index == static_cast<int32_t>(index)))
    return Error{ErrorCode::InvalidArgument, "surface point index " + std::to_string(index) + " is not valid"};
  const auto i = static_cast<int32_t>(index);
  switch (kind) {
    case -1: {
      auto v = defaultSource(mesh);
      if (!v) return v.error();
      return SurfacePoint::vertex(v.value());
    }
    case 0: return validateSurfacePoint(mesh, SurfacePoint::vertex(i));
    case 1: return validateSurfacePoint(mesh, SurfacePoint::edge(i, s[2]));
    case 2: return validateSurfacePoint(mesh, SurfacePoint::face(i, {s[2], s[3], s[4]}));
    default: return Error{ErrorCode::InvalidArgument, "unknown surface point kind"};
  }
}

/// A JS progress function (stage, fraction) → false to cancel; undefined or null means none.
Progress progressFrom(const val& fn) {
  if (fn.isUndefined() || fn.isNull()) return {};
  return [fn](const char* stage, double fraction) { return !fn(std::string(stage), fraction).isFalse(); };
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
      o.set("face", p.index);
      val b = val::array();
      b.call<void>("push", p.bary[0], p.bary[1], p.bary[2]);
      o.set("bary", b);
      break;
    }
  }
  return o;
}

/// The JS-facing mesh: owns an immutable TriMesh.
class MeshHandle {
 public:
  explicit MeshHandle(TriMesh mesh) : mesh_(std::make_shared<const TriMesh>(std::move(mesh))) {}

  val info() const {
    const MeshSummary& s = mesh_->summary();
    val o = val::object();
    o.set("vertices", static_cast<double>(s.vertices));
    o.set("faces", static_cast<double>(s.faces));
    o.set("edges", static_cast<double>(s.edges));
    val loops = val::array();
    for (int64_t n : s.boundaryLoopSizes) loops.call<void>("push", static_cast<double>(n));
    o.set("boundaryLoops", loops);
    o.set("eulerCharacteristic", static_cast<double>(s.eulerCharacteristic));
    o.set("components", static_cast<double>(s.components));
    o.set("degenerateFaces", static_cast<double>(s.degenerateFaces));
    o.set("reorientedFaces", static_cast<double>(s.reorientedFaces));
    o.set("unreferencedVertices", static_cast<double>(s.unreferencedVertices));
    val bbox = val::object();
    bbox.set("min", vec3(s.bbox.min));
    bbox.set("max", vec3(s.bbox.max));
    o.set("bbox", bbox);
    val problems = val::array();
    for (const std::string& p : s.problems) problems.call<void>("push", p);
    o.set("problems", problems);
    return o;
  }

  val defaultSourceVertex() const {
    return guarded([&] {
      auto v = defaultSource(*mesh_);
      if (!v) return errorObject(v.error());
      val o = val::object();
      o.set("vertex", v.value());
      return o;
    });
  }

  val basePlaneAt(const val& sourceSpec) const {
    return guarded([&] {
      const auto spec = emscripten::convertJSArrayToNumberVector<double>(sourceSpec);
      auto source = pointFrom(*mesh_, spec.data());
      if (!source) return errorObject(source.error());
      const BasePlane base = basePlane(*mesh_, source.value());
      val o = val::object();
      o.set("source", pointToJs(source.value()));
      o.set("origin", vec3(base.origin));
      o.set("normal", vec3(base.normal));
      o.set("fallback", base.fallback);
      o.set("note", base.note);
      return o;
    });
  }

  /// targetSpecs: 5 numbers per target (see pointFrom); an empty array means the boundary.
  val straightestPaths(const val& sourceSpec, const val& targetSpecs, bool boundary, bool keepPoints,
                       const val& progress) const {
    return guarded([&] {
      const auto spec = emscripten::convertJSArrayToNumberVector<double>(sourceSpec);
      auto source = pointFrom(*mesh_, spec.data());
      if (!source) return errorObject(source.error());
      std::vector<SurfacePoint> targets;
      if (boundary) {
        targets = boundaryTargets(*mesh_);
        if (targets.empty()) return errorObject("topology", "targets 'boundary': the mesh is closed (no boundary loop)");
      } else {
        const auto flat = emscripten::convertJSArrayToNumberVector<double>(targetSpecs);
        for (size_t i = 0; i + 5 <= flat.size(); i += 5) {
          auto t = pointFrom(*mesh_, flat.data() + i);
          if (!t) return errorObject(errorCodeName(t.error().code), "target " + std::to_string(i / 5) + ": " + t.error().message);
          targets.push_back(t.value());
        }
      }
      const PathBatch batch =
          traceStraightestPaths(*mesh_, source.value(), std::move(targets), keepPoints, progressFrom(progress));
      if (batch.cancelled) return errorObject("cancelled", "straightest paths cancelled");
      const size_t n = batch.status.size();
      std::vector<uint8_t> status(n);
      std::vector<uint32_t> crossed(n), offsets(batch.offsets.size());
      for (size_t i = 0; i < n; ++i) {
        status[i] = static_cast<uint8_t>(batch.status[i]);
        crossed[i] = static_cast<uint32_t>(batch.facesCrossed[i]);
      }
      for (size_t i = 0; i < offsets.size(); ++i) offsets[i] = static_cast<uint32_t>(batch.offsets[i]);
      std::vector<float> points(3 * batch.points.size());
      for (size_t i = 0; i < batch.points.size(); ++i) {
        points[3 * i] = static_cast<float>(batch.points[i].x);
        points[3 * i + 1] = static_cast<float>(batch.points[i].y);
        points[3 * i + 2] = static_cast<float>(batch.points[i].z);
      }
      val targetsJs = val::array();
      std::vector<double> targetXyz;
      targetXyz.reserve(3 * n);
      for (const SurfacePoint& t : batch.targets) {
        targetsJs.call<void>("push", pointToJs(t));
        const Vec3 x = position(*mesh_, t);
        targetXyz.insert(targetXyz.end(), {x.x, x.y, x.z});
      }
      val o = val::object();
      o.set("source", pointToJs(batch.source));
      o.set("sourcePosition", vec3(batch.base.origin));
      o.set("targetPositions", copyToJs("Float64Array", targetXyz.data(), targetXyz.size()));
      o.set("normal", vec3(batch.base.normal));
      o.set("baseFallback", batch.base.fallback);
      o.set("baseNote", batch.base.note);
      o.set("targets", targetsJs);
      o.set("statusCodes", copyToJs("Uint8Array", status.data(), n));
      o.set("lengths", copyToJs("Float64Array", batch.length.data(), n));
      o.set("facesCrossed", copyToJs("Uint32Array", crossed.data(), n));
      o.set("points", copyToJs("Float32Array", points.data(), points.size()));
      o.set("offsets", copyToJs("Uint32Array", offsets.data(), offsets.size()));
      o.set("prepareMs", batch.prepareMs);
      o.set("traceMs", batch.traceMs);
      return o;
    });
  }

  val geodesicDistances(const val& sourceSpec, const std::string& method) const {
    return guarded([&] {
      const auto spec = emscripten::convertJSArrayToNumberVector<double>(sourceSpec);
      auto source = pointFrom(*mesh_, spec.data());
      if (!source) return errorObject(source.error());
      std::vector<double> d;
      if (method == "heat") {
        if (!heat_) heat_ = std::make_shared<HeatMethod>(*mesh_);  // factored once, reused per source
        d = heat_->distances(source.value());
      } else if (method == "dijkstra") {
        d = dijkstraDistances(*mesh_, source.value());
      } else {
        return errorObject("invalid_argument", "unknown distance method '" + method + "' (use heat or dijkstra)");
      }
      val o = val::object();
      o.set("distances", copyToJs("Float64Array", d.data(), d.size()));
      return o;
    });
  }

  val parameterizeMesh(const val& sourceSpec, const std::string& boundary, const std::string& weights,
                       const std::string& solver, const val& progress) const {
    return guarded([&] {
      ParamOptions options;
      auto b = parseBoundaryChoice(boundary);
      if (!b) return errorObject(b.error());
      auto w = parseWeightKind(weights);
      if (!w) return errorObject(w.error());
      auto linear = parseLinearSolver(solver);
      if (!linear) return errorObject(linear.error());
      options.boundary = b.value();
      options.weights = w.value();
      options.solver = linear.value();
      const auto spec = emscripten::convertJSArrayToNumberVector<double>(sourceSpec);
      if (spec.at(0) >= 0) {
        auto source = pointFrom(*mesh_, spec.data());
        if (!source) return errorObject(source.error());
        options.autoSource = false;
        options.source = source.value();
      }
      auto result = parameterize(*mesh_, options, progressFrom(progress));
      if (!result) return errorObject(result.error());
      const Parameterization& p = result.value();
      const StretchMetrics& m = p.metrics;
      auto flat = [](const std::vector<Vec2>& v) {
        std::vector<float> out(2 * v.size());
        for (size_t i = 0; i < v.size(); ++i) {
          out[2 * i] = static_cast<float>(v[i][0]);
          out[2 * i + 1] = static_cast<float>(v[i][1]);
        }
        return out;
      };
      const std::vector<float> uv = flat(p.uv), polygon = flat(p.boundaryPolygon);
      val o = val::object();
      o.set("source", pointToJs(p.source));
      o.set("boundary", std::string(boundaryKindName(p.boundary)));
      o.set("weights", std::string(weightKindName(p.weights)));
      o.set("uv", copyToJs("Float32Array", uv.data(), uv.size()));
      o.set("faceStretch", copyToJs("Float32Array", m.faceStretch.data(), m.faceStretch.size()));
      o.set("boundaryPolygon", copyToJs("Float32Array", polygon.data(), polygon.size()));
      o.set("boundaryLoop", copyToJs("Int32Array", p.boundaryLoop.data(), p.boundaryLoop.size()));
      val stretch = val::object();
      stretch.set("l2", m.l2);
      stretch.set("linf", m.linf);
      o.set("stretch", stretch);
      o.set("bijective", m.bijective);
      o.set("flipped", static_cast<double>(m.flipped));
      o.set("degenerate", static_cast<double>(m.degenerate));
      o.set("fallbacks", static_cast<double>(p.fallbacks));
      o.set("weightFallbacks", static_cast<double>(p.weightFallbacks));
      val angle = val::object();
      angle.set("mean", m.angleDistortionMean);
      angle.set("max", m.angleDistortionMax);
      o.set("angleDistortion", angle);
      val area = val::object();
      area.set("mean", m.areaDistortionMean);
      area.set("max", m.areaDistortionMax);
      o.set("areaDistortion", area);
      o.set("residual", p.residual);
      val candidates = val::array();
      for (const BoundaryCandidate& c : p.candidates) {
        val cand = val::object();
        cand.set("boundary", std::string(boundaryKindName(c.kind)));
        cand.set("l2", c.l2);
        cand.set("linf", c.linf);
        cand.set("flipped", static_cast<double>(c.flipped));
        cand.set("degenerate", static_cast<double>(c.degenerate));
        candidates.call<void>("push", cand);
      }
      o.set("candidates", candidates);
      const ParamTimings& t = p.timingsMs;
      val timings = val::object();
      timings.set("source", t.source);
      timings.set("trace", t.trace);
      timings.set("boundary", t.boundary);
      timings.set("weights", t.weights);
      timings.set("solve", t.solve);
      timings.set("metrics", t.metrics);
      timings.set("total", t.total);
      o.set("timings", timings);
      return o;
    });
  }

  /// OBJ text of the mesh; with uv (2 floats per vertex) also vt lines and v/vt faces.
  val toObj(const val& uv) const {
    return guarded([&] {
      val o = val::object();
      if (uv.isUndefined() || uv.isNull()) {
        o.set("text", writeObj(*mesh_));
        return o;
      }
      const auto flat = emscripten::convertJSArrayToNumberVector<double>(uv);
      if (flat.size() != 2 * static_cast<size_t>(mesh_->numVertices()))
        return errorObject("invalid_argument", "uv has " + std::to_string(flat.size()) + " numbers, expected 2 per vertex (" +
                                                   std::to_string(2 * mesh_->numVertices()) + ")");
      std::vector<Vec2> coords(mesh_->numVertices());
      for (size_t i = 0; i < coords.size(); ++i) coords[i] = {flat[2 * i], flat[2 * i + 1]};
      o.set("text", writeObj(*mesh_, &coords));
      return o;
    });
  }

  /// Views into WASM memory; the JS wrapper copies them at once (.slice()).
  val positionsView() const {
    return val(emscripten::typed_memory_view(3 * mesh_->positions().size(),
                                             reinterpret_cast<const double*>(mesh_->positions().data())));
  }
  val indicesView() const {
    return val(emscripten::typed_memory_view(3 * mesh_->triangles().size(),
                                             reinterpret_cast<const uint32_t*>(mesh_->triangles().data())));
  }

 private:
  std::shared_ptr<const TriMesh> mesh_;
  mutable std::shared_ptr<HeatMethod> heat_;
};

val meshResult(Expected<TriMesh>&& mesh) {
  if (!mesh) return errorObject(mesh.error());
  val o = val::object();
  o.set("mesh", val(MeshHandle(std::move(mesh).value())));
  return o;
}

val loadMeshBytes(const std::string& bytes, const std::string& formatName, const val& options) {
  return guarded([&] {
    auto format = parseMeshFormat(formatName);
    if (!format) return errorObject(format.error());
    return meshResult(loadMesh(bytes, format.value(), limitsFrom(options)));
  });
}

val meshFromArrays(const val& positions, const val& indices, const val& options) {
  return guarded([&] {
    const auto xyz = emscripten::convertJSArrayToNumberVector<double>(positions);
    const auto idx = emscripten::convertJSArrayToNumberVector<double>(indices);
    return meshResult(meshFromFlatArrays(xyz, idx, limitsFrom(options)));
  });
}

val sample(const std::string& name) {
  return guarded([&] { return meshResult(makeSample(name)); });
}

val sampleNameList() {
  val a = val::array();
  for (const std::string& n : sampleNames()) a.call<void>("push", n);
  return a;
}

val traceStatusNameList() {
  val a = val::array();
  for (int i = 0; i < kTraceStatusCount; ++i) a.call<void>("push", std::string(traceStatusName(static_cast<TraceStatus>(i))));
  return a;
}

/// Bytes currently allocated by malloc in WASM memory (for leak checks).
double heapUsedBytes() { return static_cast<double>(mallinfo().uordblks); }

}  // namespace

EMSCRIPTEN_BINDINGS(straightest) {
  emscripten::class_<MeshHandle>("MeshHandle")
      .function("info", &MeshHandle::info)
      .function("defaultSource", &MeshHandle::defaultSourceVertex)
      .function("basePlane", &MeshHandle::basePlaneAt)
      .function("straightestPaths", &MeshHandle::straightestPaths)
      .function("geodesicDistances", &MeshHandle::geodesicDistances)
      .function("parameterize", &MeshHandle::parameterizeMesh)
      .function("toObj", &MeshHandle::toObj)
      .function("positionsView", &MeshHandle::positionsView)
      .function("indicesView", &MeshHandle::indicesView);
  emscripten::function("loadMeshBytes", &loadMeshBytes);
  emscripten::function("meshFromArrays", &meshFromArrays);
  emscripten::function("sample", &sample);
  emscripten::function("sampleNames", &sampleNameList);
  emscripten::function("traceStatusNames", &traceStatusNameList);
  emscripten::function("heapUsedBytes", &heapUsedBytes);
}
