// Embind bindings: registers the JS-facing functions, each a call into the core between two
// adapters (js_values.hpp): arguments in, the result's field list (result_fields.hpp) out. Every
// entry point returns either a result or {error, category}; the ESM wrapper (index.js) turns the
// latter into a JS Error. No C++ exception crosses into JS (Embind would deliver a bare number).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <malloc.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "js_values.hpp"
#include "straightest/api/distance_query.hpp"
#include "straightest/api/obj_with_uv.hpp"
#include "straightest/api/warm_up.hpp"
#include "straightest/atlas/atlas.hpp"
#include "straightest/base/names.hpp"
#include "straightest/base/threads.hpp"
#include "straightest/geodesics/exact_geodesic.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/geodesics/geodesic_shoot.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/boundary_polygons.hpp"
#include "straightest/param/compare_parameterizations.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/paths/straightest_path.hpp"

using emscripten::val;
using namespace straightest;
using namespace straightest::js;

static_assert(sizeof(Vec3) == 3 * sizeof(double), "positions are handed to JS as one block of doubles");
static_assert(sizeof(Triangle) == 3 * sizeof(int32_t), "indices are handed to JS as one block of int32");

namespace {

/// The JS-facing mesh: owns an immutable TriMesh and its distance queries (heat factorization cache).
class MeshHandle {
 public:
  explicit MeshHandle(TriMesh mesh)
      : mesh_(std::make_shared<const TriMesh>(std::move(mesh))),
        distances_(std::make_shared<GeodesicDistances>(*mesh_)) {}

  val info() const { return toJs(mesh_->summary()); }

  val defaultSourceVertex() const {
    return respond([&]() -> Expected<val> {
      auto v = defaultSource(*mesh_);
      if (!v) return v.error();
      val o = val::object();
      o.set("vertex", v.value());
      return o;
    });
  }

  val boundaryLoops() const {
    val loops = val::array();
    for (const std::vector<int32_t>& loop : mesh_->boundaryLoops())
      loops.call<void>("push", val::global("Int32Array").new_(emscripten::typed_memory_view(loop.size(), loop.data())));
    return loops;
  }

  val vertexNormals() const {
    return respond([&]() -> Expected<val> {
      const std::vector<Vec3> normals = straightest::vertexNormals(*mesh_);
      JsWriter w;
      w.bulk("normals", packed(normals), 3 * normals.size(), Bulk::Float32);
      return w.result();
    });
  }

  val basePlaneAt(const val& sourceJs) const {
    return respond([&]() -> Expected<val> {
      auto source = resolvedSource(sourceJs);
      if (!source) return source.error();
      val o = toJs(basePlane(*mesh_, source.value()));
      o.set("source", pointToJs(source.value()));
      return o;
    });
  }

  val straightestPaths(const val& sourceJs, const val& targetsJs, bool keepPoints, const val& progress) const {
    return respond([&]() -> Expected<val> {
      auto source = resolvedSource(sourceJs);
      if (!source) return source.error();
      auto specs = targetsFrom(targetsJs);
      if (!specs) return specs.error();
      auto targets = resolveTargets(*mesh_, specs.value());
      if (!targets) return targets.error();
      Timings timings;
      auto batch = traceStraightestPaths(*mesh_, source.value(), std::move(targets).value(),
                                         TraceOptions{keepPoints, 0, &timings}, progressFrom(progress));
      if (!batch) return batch.error();
      JsWriter w;
      visitFields(batch.value(), w);
      w.bulk("targetPositions", packed(batch.value().targetPositions), 3 * batch.value().targetPositions.size(),
             Bulk::Float64);
      const PathSummary summary = summarize(batch.value());
      w.count("count", summary.paths);
      w.count("reached", summary.reached);
      w.object("summary", [&](auto& o) { visitFields(summary, o); });
      w.object("timings", [&](auto& o) { visitFields(timings, o); });
      return w.result();
    });
  }

  val geodesicDistances(const val& sourceJs, const std::string& methodName) const {
    return respond([&]() -> Expected<val> {
      auto source = resolvedSource(sourceJs);
      if (!source) return source.error();
      auto method = parseDistanceMethod(methodName);
      if (!method) return method.error();
      const std::vector<double> d = distances_->from(source.value(), method.value());
      JsWriter w;
      w.bulk("distances", d.data(), d.size(), Bulk::Float64);
      return w.result();
    });
  }

  /// A straightest geodesic shot from a source (the initial value problem): by a 3D direction, an
  /// angle in the source's tangent frame, or toward a destination (then with its miss distance).
  val shootGeodesic(const val& sourceJs, const val& aimJs, bool keepPoints, const val& progress) const {
    return respond([&]() -> Expected<val> {
      auto source = resolvedSource(sourceJs);
      if (!source) return source.error();
      auto aim = shotAimFrom(aimJs);
      if (!aim) return aim.error();
      const ShotAim& a = aim.value();
      const double length = a.length.value_or(0);  // given unless toward (shotAimFrom)
      Timings timings;
      const Stopwatch clock;
      auto shot = a.toward
                      ? shootGeodesicToward(*mesh_, source.value(), *a.toward, a.length, {}, progressFrom(progress))
                  : a.direction
                      ? straightest::shootGeodesic(*mesh_, source.value(), *a.direction, length, {},
                                                   progressFrom(progress))
                      : shootGeodesicAtAngle(*mesh_, source.value(), *a.angle, length, {}, progressFrom(progress));
      if (!shot) return shot.error();
      timings.add("shoot", clock.ms());
      JsWriter w;
      visitFields(shot.value(), w);
      if (!keepPoints) w.bulk("points", static_cast<const double*>(nullptr), 0, Bulk::Float64);
      w.object("timings", [&](auto& o) { visitFields(timings, o); });
      return w.result();
    });
  }

  /// Exact shortest paths (window propagation) from a source to vertex targets: the table of the
  /// CLI's `distances --method exact` (source, method, targets, distances), the propagation's cost
  /// and, unless !keepPoints, each target's polyline packed like straightestPaths' points (an
  /// unreachable target: an empty polyline and an infinite distance).
  val exactShortestPaths(const val& sourceJs, const val& targetsJs, bool keepPoints, const val& progress) const {
    return respond([&]() -> Expected<val> {
      auto source = resolvedSource(sourceJs);
      if (!source) return source.error();
      auto specs = targetsFrom(targetsJs);
      if (!specs) return specs.error();
      auto targets = resolveTargets(*mesh_, specs.value());
      if (!targets) return targets.error();
      DistanceTable table{source.value(), DistanceMethod::Exact, {}, {}};
      for (size_t i = 0; i < targets.value().size(); ++i) {
        const SurfacePoint& t = targets.value()[i];
        if (t.kind != SurfacePoint::Kind::Vertex)
          return Error{ErrorCode::InvalidArgument,
                       "targets[" + std::to_string(i) + "]: exact shortest paths end at vertices (give a vertex)"};
        table.targets.push_back(t.index);
      }
      Timings timings;
      auto query = queryDistances(*mesh_, table.source, DistanceMethod::Exact, table.targets, keepPoints,
                                  progressFrom(progress), &timings);
      if (!query) return query.error();
      table = query.value().table;
      std::vector<float> points;
      std::vector<uint32_t> offsets{0};
      for (const std::vector<Vec3>& path : query.value().paths) {
        for (const Vec3& x : path) points.insert(points.end(), {float(x.x), float(x.y), float(x.z)});
        offsets.push_back(static_cast<uint32_t>(points.size() / 3));
      }
      if (!keepPoints) offsets.clear();
      JsWriter w;
      visitFields(table, w);
      w.count("count", static_cast<int64_t>(table.targets.size()));
      w.bulk("points", points.data(), points.size(), Bulk::Float32);
      w.bulk("offsets", offsets.data(), offsets.size(), Bulk::Uint32);
      w.object("exact", [&](auto& o) { visitFields(query.value().exact, o); });
      w.object("timings", [&](auto& o) { visitFields(timings, o); });
      return w.result();
    });
  }

  val parameterizeMesh(const val& sourceJs, const std::string& boundary, const std::string& weights,
                       const std::string& solver, const val& freeJs, const val& progress) const {
    return respond([&]() -> Expected<val> {
      ParamOptions options;
      auto source = sourceFrom(sourceJs);
      if (!source) return source.error();
      auto b = parseBoundaryChoice(boundary);
      if (!b) return b.error();
      auto w = parseWeightKind(weights);
      if (!w) return w.error();
      auto linear = parseLinearSolver(solver);
      if (!linear) return linear.error();
      auto free = freeOptionsFrom(freeJs);
      if (!free) return free.error();
      options.free = free.value();
      options.source = source.value();
      options.boundary = b.value();
      options.weights = w.value();
      options.solver = linear.value();
      Timings timings;
      options.timings = &timings;
      auto result = parameterize(*mesh_, options, progressFrom(progress));
      if (!result) return result.error();
      JsWriter out;
      visitFields(result.value(), out);
      out.object("timings", [&](auto& o) { visitFields(timings, o); });
      return out.result();
    });
  }

  val boundaryPolygonsOf(const val& sourceJs, const val& kindsJs, const val& progress) const {
    return respond([&]() -> Expected<val> {
      auto source = sourceFrom(sourceJs);
      if (!source) return source.error();
      // Undefined: every kind with a polygon (not free, which has none without its refinement).
      auto kinds = kindsJs.isUndefined() ? Expected<std::vector<BoundaryKind>>(polygonBoundaryKinds())
                                         : namesFrom(kindsJs, kBoundaryKindNames, "boundary");
      if (!kinds) return kinds.error();
      auto polygons = boundaryPolygons(*mesh_, source.value(), kinds.value(), progressFrom(progress));
      if (!polygons) return polygons.error();
      JsWriter w;
      w.list("polygons", polygons.value());
      return w.result();
    });
  }

  val compare(const val& sourceJs, const val& boundariesJs, const val& weightsJs, const std::string& solver,
              const val& freeJs, const val& progress) const {
    return respond([&]() -> Expected<val> {
      auto source = sourceFrom(sourceJs);
      if (!source) return source.error();
      auto boundaries = namesFrom(boundariesJs, kBoundaryKindNames, "boundary");
      if (!boundaries) return boundaries.error();
      auto weights = namesFrom(weightsJs, kWeightKindNames, "weights");
      if (!weights) return weights.error();
      auto linear = parseLinearSolver(solver);
      if (!linear) return linear.error();
      auto free = freeOptionsFrom(freeJs);
      if (!free) return free.error();
      auto comparison = compareParameterizations(*mesh_, source.value(), boundaries.value(), weights.value(),
                                                 linear.value(), progressFrom(progress), free.value());
      if (!comparison) return comparison.error();
      return toJs(comparison.value());
    });
  }

  /// A texture atlas of the mesh: the Atlas's fields and the stages' timings.
  val atlas(const val& optionsJs, const val& progress) const {
    return respond([&]() -> Expected<val> {
      auto options = atlasOptionsFrom(optionsJs);
      if (!options) return options.error();
      Timings timings;
      options.value().timings = &timings;
      auto result = buildAtlas(*mesh_, options.value(), progressFrom(progress));
      if (!result) return result.error();
      JsWriter w;
      visitFields(result.value(), w);
      w.object("timings", [&](auto& o) { visitFields(timings, o); });
      return w.result();
    });
  }

  const TriMesh& mesh() const { return *mesh_; }

  /// OBJ text of the mesh; with uv also vt lines and v/vt faces. uv is 2 numbers per vertex (a vt per
  /// vertex) or, when it has 6 per face instead (a cut mesh's cornerUv), one per face corner (a vt per
  /// distinct uv: seams split; NaN corners: the face without vt). Per vertex wins if both lengths fit.
  val toObj(const val& uv) const {
    return respond([&]() -> Expected<val> {
      val o = val::object();
      if (uv.isUndefined() || uv.isNull()) {
        o.set("text", writeObj(*mesh_));
        return o;
      }
      const auto flat = emscripten::convertJSArrayToNumberVector<double>(uv);
      if (flat.size() % 2 != 0)
        return Error{ErrorCode::InvalidArgument,
                     "uv has " + std::to_string(flat.size()) + " numbers, expected 2 per vertex (" +
                         std::to_string(2 * mesh_->numVertices()) + ") or 2 per face corner (" +
                         std::to_string(6 * mesh_->numFaces()) + ")"};
      std::vector<Vec2> coords(flat.size() / 2);
      for (size_t i = 0; i < coords.size(); ++i) coords[i] = {flat[2 * i], flat[2 * i + 1]};
      auto text = objWithUv(*mesh_, coords);
      if (!text) return text.error();
      o.set("text", text.value());
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
  Expected<SurfacePoint> resolvedSource(const val& sourceJs) const {
    auto given = sourceFrom(sourceJs);
    if (!given) return given.error();
    return resolveSource(*mesh_, given.value());
  }

  std::shared_ptr<const TriMesh> mesh_;
  std::shared_ptr<GeodesicDistances> distances_;
};

Expected<val> meshResult(Expected<TriMesh>&& mesh) {
  if (!mesh) return mesh.error();
  val o = val::object();
  o.set("mesh", val(MeshHandle(std::move(mesh).value())));
  return o;
}

/// `bytes` is a Uint8Array (index.js's toBytes). It is copied once, from the JS array straight into
/// the module's memory (a std::string parameter copies twice: into Embind's transfer buffer, then into
/// the string), and read in place from there. With `warmUp`, the parse and build run while another
/// thread warms up for the first call (warm_up.hpp; the threaded module only).
val loadMeshBytes(const val& bytes, const std::string& formatName, const val& options, bool warmUp) {
  return respond([&]() -> Expected<val> {
    auto format = parseMeshFormat(formatName);
    if (!format) return format.error();
    const size_t size = bytes["length"].as<size_t>();
    std::unique_ptr<char[]> content(new char[size]);
    // Nothing allocates between making the view and filling it, so the view stays valid (growing the
    // memory would detach it).
    val(emscripten::typed_memory_view(size, reinterpret_cast<unsigned char*>(content.get()))).call<void>("set", bytes);
    const std::string_view text(content.get(), size);
    const auto checked = limitsFrom(options);  // read from JS before the warm-up starts
    if (!checked) return checked.error();
    const BuildLimits limits = checked.value();
    WarmUp what;
    if (warmUp) what = WarmUp{0, text, format.value(), true, limits.maxVertices};
    std::optional<Expected<TriMesh>> mesh;
    loadWhileWarmingUp(what, [&] { mesh = loadMesh(text, format.value(), limits); });
    return meshResult(std::move(*mesh));
  });
}

val meshFromArrays(const val& positions, const val& indices, const val& options, bool warmUp) {
  return respond([&]() -> Expected<val> {
    // Converted before the warm-up starts: a JavaScript exception thrown here must not unwind through it.
    const auto xyz = emscripten::convertJSArrayToNumberVector<double>(positions);
    const auto idx = emscripten::convertJSArrayToNumberVector<double>(indices);
    const auto checked = limitsFrom(options);
    if (!checked) return checked.error();
    const BuildLimits limits = checked.value();
    WarmUp what;
    if (warmUp)
      what = WarmUp{parameterizationHeapBytes(std::min(static_cast<int64_t>(xyz.size() / 3), limits.maxVertices)),
                    {},
                    MeshFormat::Auto,
                    true,
                    limits.maxVertices};
    std::optional<Expected<TriMesh>> mesh;
    loadWhileWarmingUp(what, [&] { mesh = meshFromFlatArrays(xyz, idx, limits); });
    return meshResult(std::move(*mesh));
  });
}

/// One atlas shared by several meshes (an array of MeshHandles): the Atlas of their union (combineMeshes), and
/// `meshes`, each mesh's cornerUv and chartOfFace (its faces are a contiguous range of the union's, in order).
val atlasOfMeshes(const val& handles, const val& optionsJs, const val& progress) {
  return respond([&]() -> Expected<val> {
    auto options = atlasOptionsFrom(optionsJs);
    if (!options) return options.error();
    std::vector<const TriMesh*> meshes;
    const auto n = handles["length"].as<unsigned>();
    for (unsigned i = 0; i < n; ++i)
      meshes.push_back(&handles[i].as<MeshHandle*>(emscripten::allow_raw_pointers())->mesh());
    auto combined = combineMeshes(meshes);
    if (!combined) return combined.error();
    Timings timings;
    options.value().timings = &timings;
    auto result = buildAtlas(combined.value(), options.value(), progressFrom(progress));
    if (!result) return result.error();
    const Atlas& a = result.value();
    JsWriter w;
    visitFields(a, w);
    w.object("timings", [&](auto& o) { visitFields(timings, o); });
    size_t first = 0;  // the mesh's first face in the union
    w.objects("meshes", meshes.size(), [&](size_t i, JsWriter& o) {
      const size_t faces = static_cast<size_t>(meshes[i]->numFaces());
      o.bulk("cornerUv", packed(a.cornerUv) + 6 * first, 6 * faces, Bulk::Float32);
      o.bulk("chartOfFace", a.chartOfFace.data() + first, faces, Bulk::Int32);
      first += faces;
    });
    return w.result();
  });
}

val sample(const std::string& name) {
  return respond([&]() -> Expected<val> { return meshResult(makeSample(name)); });
}

val sampleNameList() { return stringArray(sampleNames()); }

/// Every name list of the core, for st.traceStatuses, st.boundaryKinds, ...
val nameLists() {
  val o = val::object();
  o.set("traceStatuses", stringArray(namesOf(kTraceStatusNames)));
  o.set("shootStatuses", stringArray(namesOf(kShootStatusNames)));
  o.set("boundaryKinds", stringArray(namesOf(kBoundaryKindNames)));
  o.set("boundaryChoices", stringArray(namesOf(kBoundaryKindNames, kAutoName)));
  std::vector<std::string> polygonKinds;
  for (BoundaryKind k : polygonBoundaryKinds()) polygonKinds.push_back(boundaryKindName(k));
  o.set("polygonBoundaryKinds", stringArray(polygonKinds));
  o.set("weightKinds", stringArray(namesOf(kWeightKindNames)));
  o.set("solvers", stringArray(namesOf(kLinearSolverNames)));
  o.set("distanceMethods", stringArray(namesOf(kDistanceMethodNames)));
  o.set("meshFormats", stringArray(namesOf(kMeshFormatNames)));
  o.set("errorCategories", stringArray(errorCodeNames()));
  return o;
}

std::string formatOfFileName(const std::string& name) { return nameOf(kMeshFormatNames, meshFormatFromFileName(name)); }

/// Bytes currently allocated by malloc in WASM memory (for leak checks).
double heapUsedBytes() { return static_cast<double>(mallinfo().uordblks); }

}  // namespace

EMSCRIPTEN_BINDINGS(straightest) {
  emscripten::class_<MeshHandle>("MeshHandle")
      .function("info", &MeshHandle::info)
      .function("defaultSource", &MeshHandle::defaultSourceVertex)
      .function("boundaryLoops", &MeshHandle::boundaryLoops)
      .function("vertexNormals", &MeshHandle::vertexNormals)
      .function("basePlane", &MeshHandle::basePlaneAt)
      .function("straightestPaths", &MeshHandle::straightestPaths)
      .function("geodesicDistances", &MeshHandle::geodesicDistances)
      .function("shootGeodesic", &MeshHandle::shootGeodesic)
      .function("exactShortestPaths", &MeshHandle::exactShortestPaths)
      .function("parameterize", &MeshHandle::parameterizeMesh)
      .function("boundaryPolygons", &MeshHandle::boundaryPolygonsOf)
      .function("compareParameterizations", &MeshHandle::compare)
      .function("atlas", &MeshHandle::atlas)
      .function("toObj", &MeshHandle::toObj)
      .function("positionsView", &MeshHandle::positionsView)
      .function("indicesView", &MeshHandle::indicesView);
  emscripten::function("loadMeshBytes", &loadMeshBytes);
  emscripten::function("meshFromArrays", &meshFromArrays);
  emscripten::function("atlas", &atlasOfMeshes);
  emscripten::function("sample", &sample);
  emscripten::function("sampleNames", &sampleNameList);
  emscripten::function("nameLists", &nameLists);
  emscripten::function("formatFromFileName", &formatOfFileName);
  emscripten::function("heapUsedBytes", &heapUsedBytes);
  // The process-wide thread count (threads.hpp); in the single-threaded module it stays 1.
  emscripten::function("setThreadCount", &setThreadCount);
  emscripten::function("threadCount", &threadCount);
}
