// chart_flattening.cpp — the three ways a chart is flattened (a lone face, a plane, the free boundary)
// and the checks every result passes through: finite, counter-clockwise (a chart that came out as a
// mirror image is mirrored back: the texture's tangent frame must agree with the face's), isometric scale.
#include "chart_flattening.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "chart_mesh.hpp"
#include "chart_shape.hpp"
#include "corner_stretch.hpp"
#include "straightest/param/boundary_overlaps.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/param/texture_stretch.hpp"

namespace straightest::atlas {

namespace {
const double kInfinity = std::numeric_limits<double>::infinity();

/// Face f alone, isometric, its longest edge on the u axis; a zero-area face gets a thin positive height.
void layOutLoneFace(const TriMesh& mesh, int32_t f, Vec2* uv) {
  const Triangle& t = mesh.triangle(f);
  int k = 0;
  for (int j = 1; j < 3; ++j)
    if (norm(mesh.position(t[(j + 1) % 3]) - mesh.position(t[j])) >
        norm(mesh.position(t[(k + 1) % 3]) - mesh.position(t[k])))
      k = j;
  const Vec3 base = mesh.position(t[(k + 1) % 3]) - mesh.position(t[k]);
  const Vec3 side = mesh.position(t[(k + 2) % 3]) - mesh.position(t[k]);
  double length = norm(base);
  if (!(length > 0)) length = mesh.meanEdgeLength();
  const double along = norm(base) > 0 ? dot(side, base) / norm(base) : 0.5 * length;
  const double height = mesh.isDegenerateFace(f) ? 1e-3 * length : 2 * mesh.faceArea(f) / length;
  uv[k] = {0, 0};
  uv[(k + 1) % 3] = {length, 0};
  uv[(k + 2) % 3] = {std::clamp(along, 0.0, length), height};
}

/// Every face of a chart laid out on its own (finite and counter-clockwise, but overlapping).
std::vector<Vec2> loneFaces(const TriMesh& mesh, const std::vector<int32_t>& faces) {
  std::vector<Vec2> uv(3 * faces.size());
  for (size_t i = 0; i < faces.size(); ++i) layOutLoneFace(mesh, faces[i], &uv[3 * i]);
  return uv;
}

/// Two unit axes of the plane normal to `normal` (unit), with e1 × e2 = normal: a face facing along the
/// normal projects counter-clockwise.
std::array<Vec3, 2> planeAxes(const Vec3& normal) {
  const Vec3 helper = std::fabs(normal.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  Vec3 e1 = cross(helper, normal);
  e1 = e1 / norm(e1);
  return {e1, cross(normal, e1)};
}

/// The chart projected onto its plane when every face lies in it (exactly isometric), else empty.
std::vector<Vec2> projectPlanar(const TriMesh& mesh, const std::vector<int32_t>& faces) {
  Vec3 normal{0, 0, 0};
  for (int32_t f : faces) normal += mesh.faceNormal(f) * mesh.faceArea(f);
  if (!(norm(normal) > 0)) return {};
  normal = normal / norm(normal);
  for (int32_t f : faces)
    if (!mesh.isDegenerateFace(f) && dot(mesh.faceNormal(f), normal) < 1 - 1e-12) return {};
  const auto [e1, e2] = planeAxes(normal);
  std::vector<Vec2> uv(3 * faces.size());
  for (size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.position(mesh.triangle(faces[i])[k]);
      uv[3 * i + k] = {dot(p, e1), dot(p, e2)};
    }
  return uv;
}

/// Whether a chart is a topological disk (one boundary loop, Euler characteristic 1) with a simple outline:
/// every chart of the atlas is one, so a texture painter sees each as one piece with one outline. A closed
/// chart, one with a handle or a hole, or one whose faces touch at a lone corner (buildChartMesh split that
/// vertex: the outline would pass through it twice) would need a cut inside the chart, which is what
/// splitting does better.
bool isDisk(const TriMesh& mesh, const std::vector<int32_t>& faces, const TriMesh& chart) {
  const MeshSummary& summary = chart.summary();
  if (summary.boundaryLoopSizes.size() != 1 || summary.eulerCharacteristic != 1) return false;
  std::vector<int32_t> corners;
  corners.reserve(3 * faces.size());
  for (int32_t f : faces) corners.insert(corners.end(), mesh.triangle(f).begin(), mesh.triangle(f).end());
  std::sort(corners.begin(), corners.end());
  return std::unique(corners.begin(), corners.end()) - corners.begin() == chart.numVertices();
}

/// The chart mesh's vertices projected onto the plane of its mean normal, when that is a bijective start
/// for the free boundary (every face counter-clockwise and not flat, no boundary crossing); else empty.
/// Much closer to isometric than the circle's map, so the refinement needs few iterations.
std::vector<Vec2> projectedStart(const TriMesh& chart) {
  Vec3 normal{0, 0, 0};
  for (int32_t f = 0; f < chart.numFaces(); ++f) normal += chart.faceNormal(f) * chart.faceArea(f);
  if (!(norm(normal) > 0)) return {};
  const auto [e1, e2] = planeAxes(normal / norm(normal));
  std::vector<Vec2> uv(chart.numVertices());
  for (int32_t v = 0; v < chart.numVertices(); ++v) uv[v] = {dot(chart.position(v), e1), dot(chart.position(v), e2)};
  std::vector<double> twiceArea(chart.numFaces());
  double sum = 0;
  for (int32_t f = 0; f < chart.numFaces(); ++f) {
    const Triangle& t = chart.triangle(f);
    twiceArea[f] = cross(uv[t[1]] - uv[t[0]], uv[t[2]] - uv[t[0]]);
    sum += std::fabs(twiceArea[f]);
  }
  for (double a : twiceArea)
    if (!(a > kDegenerateUV * sum / chart.numFaces())) return {};
  if (boundaryOverlaps(chart, uv) > 0) return {};
  return uv;
}

/// The free boundary refined from `start` (one uv per chart vertex), per corner; empty on failure.
std::vector<Vec2> refinedFrom(const TriMesh& chart, const std::vector<Vec2>& start, const FreeBoundaryOptions& free) {
  Expected<FreeBoundaryResult> refined = refineFreeBoundary(chart, start, free);
  if (!refined) return {};
  std::vector<Vec2> uv(3 * static_cast<size_t>(chart.numFaces()));
  for (int32_t f = 0; f < chart.numFaces(); ++f)
    for (int k = 0; k < 3; ++k) uv[3 * f + k] = refined.value().uv[chart.triangle(f)[k]];
  return uv;
}

/// The free-boundary map per corner from the circle's map (Tutte: bijective on a convex polygon), for a
/// chart whose projection folds; refined only when that start is bijective (floating point can collapse
/// Tutte's triangles), so no time goes into untangling. Empty on failure.
std::vector<Vec2> refinedFromCircle(const TriMesh& chart, const FreeBoundaryOptions& free) {
  ParamOptions options;
  options.boundary = BoundaryKind::Circle;
  Expected<Parameterization> start = parameterize(chart, options);
  if (!start || !start.value().metrics.bijective) return {};
  Expected<Parameterization> map = refineParameterization(chart, start.value(), free);
  if (!map || !map.value().metrics.bijective) return {};
  return std::move(map.value().cornerUv);
}

/// The free-boundary map of the chart (a disk, `chartMesh` its own mesh) per corner, counter-clockwise and
/// at its 3D scale; empty on failure. Every start is bijective, so the refinement keeps it bijective
/// whatever its iteration count.
std::vector<Vec2> freeBoundaryMap(const TriMesh& mesh, const std::vector<int32_t>& faces, const TriMesh& chartMesh,
                                  const FreeBoundaryOptions& free) {
  const std::vector<Vec2> start = projectedStart(chartMesh);
  std::vector<Vec2> uv = start.empty() ? refinedFromCircle(chartMesh, free) : refinedFrom(chartMesh, start, free);
  if (uv.empty()) return {};
  double twiceArea = 0, area3 = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
    twiceArea += twiceUvArea(uv, i);
    area3 += mesh.faceArea(faces[i]);
  }
  if (!std::all_of(uv.begin(), uv.end(), [](const Vec2& q) { return isFinite(q); }) || !(twiceArea != 0)) return {};
  const double scale = std::sqrt(2 * area3 / std::fabs(twiceArea));
  for (Vec2& q : uv) q = Vec2{twiceArea < 0 ? -q.x : q.x, q.y} * scale;
  return uv;
}

/// Whether the chart's outline under `uv` (per corner, face i of the chart mesh at 3i) crosses itself: every
/// triangle counter-clockwise is not enough for a chart to lie flat without covering itself (a planar chart
/// that winds round, a map whose boundary met itself), and the texture would be sampled twice there.
bool outlineCrossesItself(const TriMesh& chart, const std::vector<Vec2>& uv) {
  std::vector<Vec2> perVertex(chart.numVertices());
  for (int32_t f = 0; f < chart.numFaces(); ++f)
    for (int k = 0; k < 3; ++k) perVertex[chart.triangle(f)[k]] = uv[3 * static_cast<size_t>(f) + k];
  return boundaryOverlaps(chart, perVertex) > 0;
}

/// A chart of several faces mapped by projection when it is planar, else by the free boundary; empty when
/// it is not a disk or no map lies flat without folding or covering itself. The chart's mesh is built once
/// for the disk test, the maps and the outline check.
std::vector<Vec2> mapOfDisk(const TriMesh& mesh, const std::vector<int32_t>& faces, const FreeBoundaryOptions& free) {
  Expected<TriMesh> chartMesh = buildChartMesh(mesh, faces);
  if (!chartMesh || !isDisk(mesh, faces, chartMesh.value())) return {};
  std::vector<Vec2> uv = projectPlanar(mesh, faces);
  if (!uv.empty() && cornerStretch(mesh, faces, uv).flipped == 0 && !outlineCrossesItself(chartMesh.value(), uv))
    return uv;
  uv = freeBoundaryMap(mesh, faces, chartMesh.value(), free);
  if (uv.empty() || outlineCrossesItself(chartMesh.value(), uv)) return {};
  return uv;
}
/// Whether the chart fills enough of its convex hull: the gaps in a concave chart's hull are gaps no packer
/// fills well, and its convex halves pack tighter.
bool packsWell(const std::vector<Vec2>& cornerUv, const ChartLimits& limits) {
  return limits.minHullFill <= 0 || hullFill(cornerUv) >= limits.minHullFill;
}
}  // namespace

ChartFlattening flattenChart(const TriMesh& mesh, std::vector<int32_t> faces, const ChartLimits& limits,
                             const FreeBoundaryOptions& free) {
  ChartFlattening out;
  out.chart.faces = std::move(faces);
  const std::vector<int32_t>& chartFaces = out.chart.faces;
  std::vector<Vec2> uv;
  if (chartFaces.size() > 1) uv = mapOfDisk(mesh, chartFaces, free);
  const bool mapped = !uv.empty() || chartFaces.size() == 1;
  if (uv.empty()) uv = loneFaces(mesh, chartFaces);
  const CornerStretch stretch = cornerStretch(mesh, chartFaces, uv);
  out.chart.cornerUv = std::move(uv);
  out.chart.l2 = mapped ? stretch.l2 : kInfinity;  // faces laid out apart overlap: no map
  out.chart.linf = mapped ? stretch.linf : kInfinity;
  out.acceptable = chartFaces.size() == 1 || (mapped && stretch.flipped == 0 && stretch.l2 <= limits.maxStretch &&
                                              packsWell(out.chart.cornerUv, limits));
  return out;
}

}  // namespace straightest::atlas
