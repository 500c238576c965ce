// grid_windings.cpp — the charts are flattened and placed in double precision, but the atlas is read as
// float32 and checked on a grid of that precision, where a needle face thinner than a grid step can come out
// turned over once its chart is rotated and placed. Moving one corner by a step or two (far below a texel)
// turns it back; the packing's padding and the check's slack are both far wider than that.
#include "grid_windings.hpp"

#include <algorithm>
#include <cmath>

#include "snapped_uv.hpp"

namespace straightest::atlas_detail {
namespace {

// Moves tried for a corner, in grid steps from its own grid point: none, the eight neighbours, then the ring
// two steps out.
constexpr int kSteps[][2] = {{0, 0},  {1, 0},  {-1, 0},  {0, 1},  {0, -1}, {1, 1},  {1, -1}, {-1, 1},  {-1, -1},
                             {2, 0},  {-2, 0}, {0, 2},   {0, -2}, {2, 1},  {2, -1}, {-2, 1}, {-2, -1}, {1, 2},
                             {1, -2}, {-1, 2}, {-1, -2}, {2, 2},  {2, -2}, {-2, 2}, {-2, -2}};

// Rounding a corner to the grid moves it under a step (float32, in [0, 1], under half a step): a face at least
// this many steps high keeps its winding in every view.
constexpr double kThinSteps = 2;

bool finite(Vec2 uv) { return std::isfinite(uv.x) && std::isfinite(uv.y); }

/// The atlas's uv stay in [0, 1]²: a corner on its border is never moved out of it.
bool inUnitSquare(Vec2 uv) { return uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1; }

Vec2 gridPoint(Vec2 uv, const int step[2]) {
  const GridPoint p = snap(uv);
  return {static_cast<double>(p.x + step[0]) / kGridUnitsPerUv, static_cast<double>(p.y + step[1]) / kGridUnitsPerUv};
}

/// The uv as a float32 reader gets it.
Vec2 asFloat(Vec2 uv) { return {static_cast<float>(uv.x), static_cast<float>(uv.y)}; }

/// The face's height over its longest side is under kThinSteps grid steps.
bool thinFace(Vec2 a, Vec2 b, Vec2 c) {
  const double longest = std::max({norm(b - a), norm(c - b), norm(a - c)});
  return std::abs(cross(b - a, c - a)) < kThinSteps / kGridUnitsPerUv * longest;
}

/// Per chart the sign of its uv area: the winding its faces should have.
std::vector<int> chartWindings(const TriMesh& mesh, const std::vector<int32_t>& chartOfFace,
                               const std::vector<Vec2>& uv) {
  std::vector<double> area;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const int32_t c = chartOfFace[f];
    if (c < 0) continue;
    if (c >= static_cast<int32_t>(area.size())) area.resize(c + 1, 0);
    const size_t k = 3 * static_cast<size_t>(f);
    area[c] += cross(uv[k + 1] - uv[k], uv[k + 2] - uv[k]);
  }
  std::vector<int> winding(area.size());
  for (size_t c = 0; c < area.size(); ++c) winding[c] = area[c] < 0 ? -1 : 1;
  return winding;
}

class Mender {
 public:
  Mender(const TriMesh& mesh, const std::vector<int32_t>& chartOfFace, std::vector<Vec2>& uv)
      : mesh_(mesh), chartOfFace_(chartOfFace), uv_(uv), winding_(chartWindings(mesh, chartOfFace, uv)) {}

  /// Wound as its chart on the grid, and either thick enough that no rounding (to the grid or to float32)
  /// moves a corner across the opposite side, or certainly wound right in double precision and in float32
  /// too; or flat in 3D and flat on the grid.
  bool woundRight(int32_t f) const {
    const size_t c = 3 * static_cast<size_t>(f);
    const Vec2 &a = uv_[c], &b = uv_[c + 1], &d = uv_[c + 2];
    const int grid = orientation(snap(a), snap(b), snap(d));
    if (grid == 0 && mesh_.faceArea(f) == 0) return true;
    const int expected = winding_[chartOfFace_[f]];
    if (grid != expected) return false;
    return !thinFace(a, b, d) ||
           (certainSign(a, b, d) == expected && certainSign(asFloat(a), asFloat(b), asFloat(d)) == expected);
  }

  /// Puts f's corners on their grid points (the grid sees no change; the face's double-precision and float32
  /// winding become the grid's), then tries each corner with the moves in turn and keeps the first that
  /// leaves all faces at the moved corners wound right.
  void mend(int32_t f) {
    for (int k = 0; k < 3; ++k) {
      const Vec2 onGrid = gridPoint(uv_[3 * f + k], kSteps[0]);
      for (const int32_t c : cornersLike(3 * f + k)) uv_[c] = onGrid;
    }
    for (int k = 0; k < 3; ++k) {
      const std::vector<int32_t> corners = cornersLike(3 * f + k);
      const Vec2 home = uv_[3 * f + k];
      for (const auto& step : kSteps) {
        const Vec2 moved = gridPoint(home, step);
        if (!inUnitSquare(moved)) continue;
        for (const int32_t c : corners) uv_[c] = moved;
        if (std::all_of(corners.begin(), corners.end(), [&](int32_t c) { return woundRight(c / 3); })) return;
      }
      for (const int32_t c : corners) uv_[c] = home;
    }
  }

 private:
  /// The corners of the same chart at the same vertex and uv as `corner` (itself included): they move together,
  /// so the chart stays in one piece.
  std::vector<int32_t> cornersLike(int32_t corner) {
    if (cornersOfVertex_.empty()) {
      cornersOfVertex_.resize(mesh_.numVertices());
      for (int32_t h = 0; h < 3 * mesh_.numFaces(); ++h) cornersOfVertex_[mesh_.tail(h)].push_back(h);
    }
    std::vector<int32_t> like;
    const int32_t chart = chartOfFace_[corner / 3];
    for (const int32_t c : cornersOfVertex_[mesh_.tail(corner)])
      if (chartOfFace_[c / 3] == chart && uv_[c].x == uv_[corner].x && uv_[c].y == uv_[corner].y) like.push_back(c);
    return like;
  }

  const TriMesh& mesh_;
  const std::vector<int32_t>& chartOfFace_;
  std::vector<Vec2>& uv_;
  std::vector<int> winding_;
  std::vector<std::vector<int32_t>> cornersOfVertex_;  // built on the first mend: most atlases need none
};

}  // namespace

void mendGridWindings(const TriMesh& mesh, const std::vector<int32_t>& chartOfFace, std::vector<Vec2>& cornerUv) {
  Mender mender(mesh, chartOfFace, cornerUv);
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const size_t c = 3 * static_cast<size_t>(f);
    if (chartOfFace[f] >= 0 && finite(cornerUv[c]) && finite(cornerUv[c + 1]) && finite(cornerUv[c + 2]) &&
        !mender.woundRight(f))
      mender.mend(f);
  }
}

}  // namespace straightest::atlas_detail
