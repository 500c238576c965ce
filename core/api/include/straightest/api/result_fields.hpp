// result_fields.hpp — the one field list of every result the CLI prints and the npm package returns.
// visitFields(result, visitor) names each field once, in camelCase, with its kind; the CLI's JSON
// writer (snake_case, nlohmann) and the bindings' JS writer (emscripten::val, typed arrays) are two
// small visitors. A visitor provides:
//   number(name, double), count(name, int64_t), flag(name, bool), text(name, std::string),
//   point(name, SurfacePoint), vec3(name, Vec3), nothing(name)            — scalars (nothing: null)
//   counts(name, std::vector<int64_t>), texts(name, std::vector<std::string>) — small lists
//   object(name, fill)  — a nested object: fill(childVisitor)
//   list(name, std::vector<T>) — a list of results, each written with visitFields
//   bulk(name, const T* data, size_t n, Bulk kind) — a large array of n numbers (typed array in JS;
//                                                    the CLI leaves it out)
//   points(name, std::vector<SurfacePoint>), textColumn(name, std::vector<std::string>) — one entry per
//                                       path (the CLI leaves these out and writes one row per path)
#pragma once
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "straightest/atlas/atlas.hpp"
#include "straightest/base/names.hpp"
#include "straightest/base/timings.hpp"
#include "straightest/geodesics/exact_geodesic.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/geodesics/geodesic_shoot.hpp"
#include "straightest/param/boundary_polygons.hpp"
#include "straightest/param/compare_parameterizations.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/paths/base_plane.hpp"
#include "straightest/paths/straightest_path.hpp"

namespace straightest {

/// The element type a bulk array is handed over as.
enum class Bulk { Float32, Float64, Int32, Uint32, Uint8 };

static_assert(sizeof(Vec2) == 2 * sizeof(double) && sizeof(Vec3) == 3 * sizeof(double),
              "bulk arrays read Vec2 and Vec3 as packed doubles");

/// Vec2 / Vec3 arrays as packed doubles (nullptr when empty, with n = 0).
inline const double* packed(const std::vector<Vec2>& v) { return reinterpret_cast<const double*>(v.data()); }
inline const double* packed(const std::vector<Vec3>& v) { return reinterpret_cast<const double*>(v.data()); }

template <class V>
void visitFields(const Error& e, V& v) {
  v.text("error", e.message);
  v.text("category", errorCodeName(e.code));
}

template <class V>
void visitFields(const Timings& t, V& v) {
  for (const auto& [stage, ms] : t.stages()) v.number(stage.c_str(), ms);
}

template <class V>
void visitFields(const MeshSummary& s, V& v) {
  v.count("vertices", s.vertices);
  v.count("faces", s.faces);
  v.count("edges", s.edges);
  v.counts("boundaryLoops", s.boundaryLoopSizes);
  v.count("eulerCharacteristic", s.eulerCharacteristic);
  v.count("components", s.components);
  v.count("degenerateFaces", s.degenerateFaces);
  v.count("reorientedFaces", s.reorientedFaces);
  v.count("unreferencedVertices", s.unreferencedVertices);
  v.object("bbox", [&](auto& box) {
    box.vec3("min", s.bbox.min);
    box.vec3("max", s.bbox.max);
  });
  v.texts("problems", s.problems);
}

/// The base plane of a source (source itself written by the caller, who knows which point it used).
template <class V>
void visitFields(const BasePlane& b, V& v) {
  v.vec3("origin", b.origin);
  v.vec3("normal", b.normal);
  v.flag("fallback", b.fallback);
  v.text("note", b.note);
}

template <class V>
void visitFields(const PathSummary& s, V& v) {
  v.count("paths", s.paths);
  v.count("reached", s.reached);
  v.object("failures", [&](auto& failures) {
    for (const EnumName<TraceStatus>& e : kTraceStatusNames)
      if (e.value != TraceStatus::Reached && s.byStatus[static_cast<size_t>(e.value)] > 0)
        failures.count(e.name, s.byStatus[static_cast<size_t>(e.value)]);
  });
  v.number("meanLength", s.meanLength);
  v.number("maxLength", s.maxLength);
  v.count("facesCrossed", s.facesCrossed);
  v.count("maxFacesCrossed", s.maxFacesCrossed);
  v.count("otherArcs", s.otherArcs);
}

/// A batch column by column (path i's points are points[offsets[i] .. offsets[i+1]), its other arc
/// otherPoints[otherOffsets[i] .. otherOffsets[i+1]); backward[i] = 1 when it leaves S away from D).
template <class V>
void visitFields(const PathBatch& b, V& v) {
  v.point("source", b.source);
  v.vec3("sourcePosition", b.base.origin);
  v.vec3("normal", b.base.normal);
  v.flag("baseFallback", b.base.fallback);
  v.text("baseNote", b.base.note);
  v.points("targets", b.targets);
  const size_t n = b.status.size();
  std::vector<std::string> statuses;
  statuses.reserve(n);
  for (TraceStatus s : b.status) statuses.push_back(traceStatusName(s));
  v.textColumn("statuses", statuses);
  v.bulk("lengths", b.length.data(), n, Bulk::Float64);
  v.bulk("facesCrossed", b.facesCrossed.data(), n, Bulk::Uint32);
  v.bulk("backward", b.reversed.data(), n, Bulk::Uint8);
  v.bulk("otherArcLengths", b.otherArcLength.data(), n, Bulk::Float64);
  v.bulk("directions", packed(b.directions), 3 * b.directions.size(), Bulk::Float64);
  v.bulk("points", packed(b.points), 3 * b.points.size(), Bulk::Float32);
  v.bulk("offsets", b.offsets.data(), b.offsets.size(), Bulk::Uint32);
  v.bulk("otherPoints", packed(b.otherPoints), 3 * b.otherPoints.size(), Bulk::Float32);
  v.bulk("otherOffsets", b.otherOffsets.data(), b.otherOffsets.size(), Bulk::Uint32);
}

template <class V>
void visitFields(const BoundaryCandidate& c, V& v) {
  v.text("boundary", boundaryKindName(c.kind));
  v.number("l2", c.l2);
  v.number("linf", c.linf);
  v.count("flipped", c.flipped);
  v.count("degenerate", c.degenerate);
  v.count("overlaps", c.overlaps);
}

/// The free-boundary refinement's fields: its start, iterations, energies and how it stopped; null
/// for a fixed boundary (no refinement ran).
template <class V>
void visitRefinement(const Parameterization& p, V& v) {
  if (!p.init) {
    for (const char* name : {"init", "iterations", "energyInitial", "energyFinal", "converged", "untangled"})
      v.nothing(name);
    return;
  }
  v.text("init", boundaryKindName(*p.init));
  v.count("iterations", p.iterations);
  v.number("energyInitial", p.energyInitial);
  v.number("energyFinal", p.energyFinal);
  v.flag("converged", p.converged);
  v.flag("untangled", p.untangled);
}

/// How the mesh was made a disk (disk_cut.hpp) and the map per face corner: cornerUv 6 numbers per
/// face (NaN outside the parameterized component), seam 2 vertex numbers per edge cut open.
template <class V>
void visitCut(const Parameterization& p, V& v) {
  static_assert(sizeof(std::array<int32_t, 2>) == 2 * sizeof(int32_t), "seam edges as packed int32 pairs");
  v.text("cut", cutMethodName(p.cut));
  v.bulk("cornerUv", packed(p.cornerUv), 2 * p.cornerUv.size(), Bulk::Float32);
  v.bulk("seam", reinterpret_cast<const int32_t*>(p.seam.data()), 2 * p.seam.size(), Bulk::Int32);
  v.count("seamEdges", static_cast<int64_t>(p.seam.size()));
  v.number("seamLength", p.seamLength);
  v.counts("filledLoops", std::vector<int64_t>(p.filledLoops.begin(), p.filledLoops.end()));
  v.count("genus", p.genus);
  v.count("component", p.component);
  v.count("components", p.components);
  v.count("virtualVertices", p.virtualVertices);
}

template <class V>
void visitFields(const Parameterization& p, V& v) {
  const StretchMetrics& m = p.metrics;
  v.point("source", p.source);
  v.text("boundary", boundaryKindName(p.boundary));
  v.text("weights", weightKindName(p.weights));
  v.bulk("uv", packed(p.uv), 2 * p.uv.size(), Bulk::Float32);
  v.bulk("faceStretch", m.faceStretch.data(), m.faceStretch.size(), Bulk::Float32);
  v.bulk("boundaryPolygon", packed(p.boundaryPolygon), 2 * p.boundaryPolygon.size(), Bulk::Float32);
  v.bulk("boundaryLoop", p.boundaryLoop.data(), p.boundaryLoop.size(), Bulk::Int32);
  v.object("stretch", [&](auto& o) {
    o.number("l2", m.l2);
    o.number("linf", m.linf);
  });
  v.flag("bijective", m.bijective);
  v.count("flipped", m.flipped);
  v.count("degenerate", m.degenerate);
  v.count("overlaps", m.overlaps);
  v.count("fallbacks", p.fallbacks);
  v.count("outliers", p.outliers);
  v.count("weightFallbacks", p.weightFallbacks);
  v.object("angleDistortion", [&](auto& o) {
    o.number("mean", m.angleDistortionMean);
    o.number("max", m.angleDistortionMax);
  });
  v.object("areaDistortion", [&](auto& o) {
    o.number("mean", m.areaDistortionMean);
    o.number("max", m.areaDistortionMax);
  });
  v.number("residual", p.residual);
  visitRefinement(p, v);
  v.list("candidates", p.candidates);
  visitCut(p, v);
}

/// A texture atlas: uv per face corner (6 numbers per face, in [0, 1]²), the chart of every face, the seam
/// (2 vertex numbers per edge), the packing, and the independent measurement of the uv (atlas_quality.hpp).
template <class V>
void visitFields(const Atlas& a, V& v) {
  const AtlasQuality& q = a.quality;
  v.bulk("cornerUv", packed(a.cornerUv), 2 * a.cornerUv.size(), Bulk::Float32);
  v.bulk("chartOfFace", a.chartOfFace.data(), a.chartOfFace.size(), Bulk::Int32);
  v.bulk("seam", reinterpret_cast<const int32_t*>(a.seam.data()), 2 * a.seam.size(), Bulk::Int32);
  v.bulk("chartStretch", q.chartL2.data(), q.chartL2.size(), Bulk::Float64);
  v.count("charts", a.charts);
  v.object("stretch", [&](auto& o) {
    o.number("l2", q.l2);
    o.number("linf", q.linf);
  });
  v.number("utilization", a.utilization);
  v.count("width", a.width);
  v.count("height", a.height);
  v.number("texelsPerUnit", a.texelsPerUnit);
  v.count("seamEdges", static_cast<int64_t>(a.seam.size()));
  v.number("seamLength", a.seamLength);
  v.count("flipped", q.flipped);
  v.count("mirrored", q.mirroredCharts);
  v.count("degenerate", q.degenerate);
  v.count("overlaps", q.overlaps);
  v.count("nonDiskCharts", q.nonDiskCharts);
  v.number("minGapTexels", q.minGapTexels);
  v.count("paddingViolations", q.paddingViolations);
  v.count("splits", a.splits);
  v.count("merges", a.merges);
  v.flag("capped", a.capped);
}

/// "error" and "category" of a part that may have failed: the error's, or null for both.
template <class V>
void visitOptionalError(const std::optional<Error>& error, V& v) {
  if (error) {
    visitFields(*error, v);
  } else {
    v.nothing("error");
    v.nothing("category");
  }
}

template <class V>
void visitFields(const BoundaryPolygon& b, V& v) {
  v.text("boundary", boundaryKindName(b.kind));
  if (b.error) v.nothing("polygon");
  else v.bulk("polygon", packed(b.polygon), 2 * b.polygon.size(), Bulk::Float32);
  v.bulk("loop", b.loop.data(), b.loop.size(), Bulk::Int32);
  visitOptionalError(b.error, v);
}

template <class V>
void visitFields(const ComparisonRow& r, V& v) {
  v.text("boundary", boundaryKindName(r.boundary));
  v.text("weights", weightKindName(r.weights));
  if (r.error) {
    for (const char* name : {"l2", "linf", "flipped", "degenerate", "overlaps", "bijective"}) v.nothing(name);
  } else {
    v.number("l2", r.l2);
    v.number("linf", r.linf);
    v.count("flipped", r.flipped);
    v.count("degenerate", r.degenerate);
    v.count("overlaps", r.overlaps);
    v.flag("bijective", r.bijective);
  }
  if (r.error || !r.init) {
    for (const char* name : {"init", "iterations", "converged"}) v.nothing(name);
  } else {
    v.text("init", boundaryKindName(*r.init));
    v.count("iterations", r.iterations);
    v.flag("converged", r.converged);
  }
  v.number("timeMs", r.timeMs);
  visitOptionalError(r.error, v);
}

template <class V>
void visitFields(const Comparison& c, V& v) {
  v.list("rows", c.rows);
  v.count("best", c.best);
}

/// A geodesic shot from a source (the initial value problem); target fields null unless shot toward one.
template <class V>
void visitFields(const GeodesicShot& s, V& v) {
  v.point("source", s.source);
  v.vec3("sourcePosition", s.positions.empty() ? Vec3{} : s.positions.front());
  v.vec3("normal", s.normal);
  v.vec3("direction", s.direction);
  v.text("status", shootStatusName(s.status));
  v.number("requestedLength", s.requestedLength);
  v.number("length", s.length);
  v.count("facesCrossed", s.facesCrossed);
  v.count("vertexPassings", s.vertexPassings);
  v.point("end", s.end);
  v.vec3("endPosition", s.endPosition);
  if (std::isnan(s.target.x)) {
    for (const char* name : {"target", "straightestDistance", "missDistance"}) v.nothing(name);
  } else {
    v.vec3("target", s.target);
    v.number("straightestDistance", s.straightestDistance);
    v.number("missDistance", s.missDistance);
  }
  v.bulk("points", packed(s.positions), 3 * s.positions.size(), Bulk::Float64);
}

template <class V>
void visitFields(const ExactGeodesicStats& s, V& v) {
  v.count("windows", s.windows);
  v.count("filtered", s.filtered);
  v.count("maxQueue", s.maxQueue);
  v.count("pseudoSources", s.pseudoSources);
}

/// Distances to chosen vertices (the CLI writes targets and distances as rows of its own).
template <class V>
void visitFields(const DistanceTable& t, V& v) {
  v.point("source", t.source);
  v.text("method", nameOf(kDistanceMethodNames, t.method));
  v.bulk("targets", t.targets.data(), t.targets.size(), Bulk::Int32);
  v.bulk("distances", t.distances.data(), t.distances.size(), Bulk::Float64);
}

}  // namespace straightest
