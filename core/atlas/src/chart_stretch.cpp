// chart_stretch.cpp — Sander et al.'s stretch (texture_stretch.hpp's formulas) per corner uv, per chart and
// for the whole atlas, after deciding each face's winding exactly against its chart's majority. The uv is
// measured in texels (u times the width, v times the height): a texel is square whatever the atlas's aspect,
// so a chart mapped without distortion onto texels has stretch 1 in a 1024 x 256 atlas too.
#include "chart_stretch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace straightest::atlas_detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Sums of one chart (or of the atlas): |uv area|, 3D area, Σ L2² A3, max L∞, and whether any face is bad.
struct StretchSums {
  double uvArea = 0, area = 0, l2Squared = 0, maxLinf = 0;
  bool bad = false;

  void add(const StretchSums& o) {
    uvArea += o.uvArea, area += o.area, l2Squared += o.l2Squared;
    maxLinf = std::max(maxLinf, o.maxLinf);
    bad = bad || o.bad;
  }
  /// L2 and L∞ with the uv scaled so that its area equals the 3D area.
  std::pair<double, double> stretch() const {
    if (bad) return {kInf, kInf};
    if (!(area > 0)) return {0, 0};
    const double scale = std::sqrt(uvArea / area);
    return {std::sqrt(l2Squared / area) * scale, maxLinf * scale};
  }
};

/// Adds face f's L2² A3 and L∞ (Sander: S_s, S_t the derivatives of the position by u and v).
void addFaceStretch(const TriMesh& mesh, int32_t f, const Vec2* q, double doubleArea, StretchSums& s) {
  const Triangle& t = mesh.triangle(f);
  const Vec3 &p1 = mesh.position(t[0]), &p2 = mesh.position(t[1]), &p3 = mesh.position(t[2]);
  const Vec3 Ss = (p1 * (q[1].y - q[2].y) + p2 * (q[2].y - q[0].y) + p3 * (q[0].y - q[1].y)) / doubleArea;
  const Vec3 St = (p1 * (q[2].x - q[1].x) + p2 * (q[0].x - q[2].x) + p3 * (q[1].x - q[0].x)) / doubleArea;
  const double a = dot(Ss, Ss), b = dot(Ss, St), c = dot(St, St);
  s.l2Squared += (a + c) / 2 * mesh.faceArea(f);
  s.maxLinf = std::max(s.maxLinf, std::sqrt(((a + c) + std::sqrt((a - c) * (a - c) + 4 * b * b)) / 2));
}

Vec2 inTexels(Vec2 uv, Vec2 texels) { return {uv.x * texels.x, uv.y * texels.y}; }

/// Each finite face's winding: exact on the snapped uv (+1, −1 or 0); where the snapped corners are collinear
/// but the face has a certain orientation in double precision (a sliver thinner than the grid, e.g. a mesh's
/// needle face at its true shape), that orientation: the face is mapped, only finer than the grid.
std::vector<int8_t> faceWindings(const UvCharts& charts, const std::vector<Vec2>& uv) {
  std::vector<int8_t> winding(charts.chartOfFace.size(), 0);
  for (size_t f = 0; f < winding.size(); ++f)
    if (charts.chartOfFace[f] >= 0) {
      winding[f] = static_cast<int8_t>(
          orientation(charts.corner[3 * f], charts.corner[3 * f + 1], charts.corner[3 * f + 2]));
      if (winding[f] == 0) winding[f] = certainSign(uv[3 * f], uv[3 * f + 1], uv[3 * f + 2]);
    }
  return winding;
}

/// Each chart's majority winding, weighted by 3D area (by uv area where the 3D areas tie, e.g. all zero).
std::vector<int8_t> majorityWindings(const TriMesh& mesh, const std::vector<Vec2>& uv, const UvCharts& charts,
                                     const std::vector<int8_t>& winding) {
  std::vector<double> byArea(charts.charts, 0), byUvArea(charts.charts, 0);
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const int32_t c = charts.chartOfFace[f];
    if (c < 0 || winding[f] == 0) continue;
    byArea[c] += winding[f] * mesh.faceArea(f);
    byUvArea[c] += winding[f] * std::abs(cross(uv[3 * f + 1] - uv[3 * f], uv[3 * f + 2] - uv[3 * f]));
  }
  std::vector<int8_t> majority(charts.charts);
  for (int32_t c = 0; c < charts.charts; ++c) majority[c] = (byArea[c] != 0 ? byArea[c] : byUvArea[c]) < 0 ? -1 : 1;
  return majority;
}

}  // namespace

ChartStretch measureChartStretch(const TriMesh& mesh, const std::vector<Vec2>& cornerUv, const UvCharts& charts,
                                 Vec2 texels) {
  ChartStretch r;
  const double atlasArea = texels.x * texels.y;
  const std::vector<int8_t> winding = faceWindings(charts, cornerUv);
  const std::vector<int8_t> majority = majorityWindings(mesh, cornerUv, charts, winding);
  std::vector<StretchSums> sums(charts.charts);
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const int32_t c = charts.chartOfFace[f];
    if (c < 0) continue;
    const Vec2* uv = &cornerUv[3 * static_cast<size_t>(f)];
    const Vec2 q[3] = {inTexels(uv[0], texels), inTexels(uv[1], texels), inTexels(uv[2], texels)};
    const double doubleArea = cross(q[1] - q[0], q[2] - q[0]);
    const double area = mesh.faceArea(f);
    StretchSums& s = sums[c];
    s.uvArea += std::abs(doubleArea) / 2;
    s.area += area;
    if (winding[f] == 0 && area > 0) ++r.degenerate, s.bad = true;
    if (winding[f] != 0 && winding[f] != majority[c]) ++r.flipped, s.bad = true;
    if (winding[f] == majority[c] && area > 0) addFaceStretch(mesh, f, q, doubleArea, s);
  }
  StretchSums atlas;
  atlas.bad = charts.nonFiniteCorners > 0;
  r.chartL2.resize(charts.charts), r.chartLinf.resize(charts.charts);
  for (int32_t c = 0; c < charts.charts; ++c) {
    std::tie(r.chartL2[c], r.chartLinf[c]) = sums[c].stretch();
    r.mirroredCharts += majority[c] < 0;
    atlas.add(sums[c]);
  }
  std::tie(r.l2, r.linf) = atlas.stretch();
  r.uvArea = atlas.uvArea / atlasArea;
  return r;
}

}  // namespace straightest::atlas_detail
