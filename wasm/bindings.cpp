// Embind bindings: marshal arrays and plain objects between JS and core, nothing else.
// Every entry point returns either a result or {error, category}; the ESM wrapper (index.js) turns
// the latter into a JS Error. No C++ exception crosses into JS (Embind would deliver a bare number).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <memory>
#include <new>
#include <string>

#include "straightest/mesh_io.hpp"
#include "straightest/samples.hpp"

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

}  // namespace

EMSCRIPTEN_BINDINGS(straightest) {
  emscripten::class_<MeshHandle>("MeshHandle")
      .function("info", &MeshHandle::info)
      .function("positionsView", &MeshHandle::positionsView)
      .function("indicesView", &MeshHandle::indicesView);
  emscripten::function("loadMeshBytes", &loadMeshBytes);
  emscripten::function("meshFromArrays", &meshFromArrays);
  emscripten::function("sample", &sample);
  emscripten::function("sampleNames", &sampleNameList);
}
