#include "straightest/boundary_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "straightest/geodesic_distance.hpp"
#include "straightest/straightest_path.hpp"

namespace straightest {
namespace {

/// A point of the measured polygon lies on a hull edge (and at a hull corner) when it is within this
/// fraction of the edge's length of it: the radial projection puts it there up to rounding.
constexpr double kOnHullRel = 1e-9;

/// Cumulative 3D edge length along the loop, normalized to [0, 1) (first vertex at 0).
std::vector<double> arcLengthParameter(const TriMesh& mesh, const std::vector<int32_t>& loop) {
  std::vector<double> s(loop.size(), 0.0);
  double total = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    s[i] = total;
    total += norm(mesh.position(loop[(i + 1) % loop.size()]) - mesh.position(loop[i]));
  }
  if (total > 0)
    for (double& x : s) x /= total;
  return s;
}

/// Indices of the convex hull of pts, counter-clockwise, without collinear points (monotone chain).
/// A turn whose sine is below kHullCollinear counts as straight: such a vertex (a rounding-made
/// corner) would split a hull edge in two, hide a chord lying along it from the bulge and allow no
/// lift there (a fuzzing finding); the points it drops are within 1e-9 of the edge's length outside
/// the hull and convexify() projects them onto it.
constexpr double kHullCollinear = 1e-9;
std::vector<size_t> convexHull(const std::vector<Vec2>& pts) {
  std::vector<size_t> order(pts.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return pts[a].x < pts[b].x || (pts[a].x == pts[b].x && pts[a].y < pts[b].y); });
  std::vector<size_t> hull(2 * pts.size() + 1);
  size_t k = 0;
  auto turn = [&](size_t o, size_t a, size_t b) {
    const Vec2 u = pts[a] - pts[o], v = pts[b] - pts[o];
    const double c = cross(u, v);
    return c > kHullCollinear * norm(u) * norm(v) ? c : 0.0;
  };
  for (size_t i : order) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], i) <= 0) --k;
    hull[k++] = i;
  }
  for (size_t t = k + 1, j = order.size(); j-- > 0;) {
    const size_t i = order[j];
    while (k >= t && turn(hull[k - 2], hull[k - 1], i) <= 0) --k;
    hull[k++] = i;
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

}  // namespace

std::vector<std::array<int32_t, 2>> boundaryChords(const TriMesh& mesh, const std::vector<int32_t>& loop) {
  std::vector<int32_t> position(mesh.numVertices(), -1);
  for (size_t i = 0; i < loop.size(); ++i) position[loop[i]] = static_cast<int32_t>(i);
  std::vector<std::array<int32_t, 2>> out;
  for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h) {
    const int32_t t = mesh.twin(h);
    if (t < 0 || t < h) continue;  // boundary edges run along the loop; each interior edge once
    const int32_t a = position[mesh.tail(h)], b = position[mesh.head(h)];
    if (a >= 0 && b >= 0) out.push_back({a, b});
  }
  return out;
}

int64_t convexify(std::vector<Vec2>& points, const std::vector<std::array<int32_t, 2>>& chords) {
  const size_t n = points.size();
  if (n < 3) return -1;
  const std::vector<size_t> hullIdx = convexHull(points);
  const size_t h = hullIdx.size();
  if (h < 3) return -1;
  std::vector<Vec2> hull(h);
  for (size_t j = 0; j < h; ++j) hull[j] = points[hullIdx[j]];
  for (size_t j = 0; j < h; ++j) {  // the origin must be strictly inside (left of every CCW edge)
    const Vec2 e = hull[(j + 1) % h] - hull[j];
    if (!(cross(e, Vec2{} - hull[j]) > 1e-14 * norm(e) * norm(e))) return -1;
  }
  // Hull vertices in angular order around the origin, starting at the smallest angle.
  std::vector<double> angle(h);
  for (size_t j = 0; j < h; ++j) angle[j] = std::atan2(hull[j].y, hull[j].x);
  const auto first = std::min_element(angle.begin(), angle.end()) - angle.begin();
  std::rotate(hull.begin(), hull.begin() + first, hull.end());
  std::rotate(angle.begin(), angle.begin() + first, angle.end());

  // 1. Radial projection onto the hull; remember each point's hull edge and parameter along it.
  int64_t moved = 0;
  std::vector<int64_t> edgeOf(n, -1), cornerOf(n, -1);  // hull edge (inside it) or hull vertex of each point
  std::vector<double> along(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    Vec2& p = points[i];
    const double r = norm(p);
    if (!(r > 0)) continue;
    const double a = std::atan2(p.y, p.x);
    size_t j = static_cast<size_t>(std::upper_bound(angle.begin(), angle.end(), a) - angle.begin());
    j = (j + h - 1) % h;
    const Vec2& A = hull[j];
    const Vec2 E = hull[(j + 1) % h] - A;
    const Vec2 d = p / r;
    const double rHull = cross(A, E) / cross(d, E);  // distance along the ray to the edge's line
    // Every point goes exactly onto the hull: those inside move out (counted), and those the
    // collinearity tolerance left a hair outside move in.
    if (r < rHull * (1 - 1e-12)) ++moved;
    p = d * rHull;
    const double L2 = squaredNorm(E);
    const double t = dot(p - A, E) / L2;
    const double off = std::abs(cross(E, p - A)) / std::sqrt(L2);
    if (off > kOnHullRel * std::sqrt(L2)) continue;
    if (t > kOnHullRel && t < 1 - kOnHullRel) {
      edgeOf[i] = static_cast<int64_t>(j);
      along[i] = t;
    } else if (t <= kOnHullRel && t > -kOnHullRel) {
      cornerOf[i] = static_cast<int64_t>(j);
    } else if (t >= 1 - kOnHullRel && t < 1 + kOnHullRel) {
      cornerOf[i] = static_cast<int64_t>((j + 1) % h);
    }
  }
  // 2. Hull edges along which an interior edge of the mesh joining two boundary vertices (a chord)
  //    would lie: its triangles would collapse. A point at a hull vertex lies on both adjacent edges.
  //    (Both ends may be hull corners, with the chord's third triangle corner inside the edge.)
  std::vector<uint8_t> bulgeEdge(h, 0);
  auto onEdge = [&](int32_t i, int64_t j) {
    return edgeOf[i] == j || cornerOf[i] == j || cornerOf[i] == (j + 1) % static_cast<int64_t>(h);
  };
  const int64_t hullSize = static_cast<int64_t>(h);
  for (const auto& c : chords) {
    const int64_t corner = cornerOf[c[0]];
    const int64_t candidates[3] = {edgeOf[c[0]], corner, corner >= 0 ? (corner + hullSize - 1) % hullSize : -1};
    for (int64_t j : candidates)
      if (j >= 0 && onEdge(c[0], j) && onEdge(c[1], j)) bulgeEdge[j] = 1;
  }
  // 3. Lift the points of those edges onto a parabola; its end slopes stay below a third of the
  //    hull's turning angle at each end, so the polygon stays convex.
  auto turnAngle = [&](size_t j) {
    const Vec2 a = hull[j] - hull[(j + h - 1) % h], b = hull[(j + 1) % h] - hull[j];
    return std::atan2(cross(a, b), dot(a, b));
  };
  for (size_t i = 0; i < n; ++i) {
    const int64_t j = edgeOf[i];
    if (j < 0 || !bulgeEdge[j]) continue;
    const double slope = std::min({kBulge, std::tan(turnAngle(j) / 3), std::tan(turnAngle((j + 1) % h) / 3)});
    const Vec2 E = hull[(j + 1) % h] - hull[j];
    const double L = norm(E), t = along[i];
    const double lift = slope * L * t * (1 - t);
    points[i] += Vec2{E.y, -E.x} / L * lift;  // outward: the hull runs counter-clockwise
  }
  return moved;
}

Expected<BoundaryMap> measuredBoundary(const TriMesh& mesh, const SurfacePoint& source, const Progress& progress,
                                       Timings* timings) {
  BoundaryMap map;
  map.kind = BoundaryKind::Measured;
  map.loop = mesh.boundaryLoops().at(0);
  const size_t n = map.loop.size();
  const Vec3 S = position(mesh, source);
  std::vector<double> increment(n), cumulative(n, 0.0);
  double total = 0;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 a = mesh.position(map.loop[i]) - S, b = mesh.position(map.loop[(i + 1) % n]) - S;
    increment[i] = std::atan2(norm(cross(a, b)), dot(a, b));
    total += increment[i];
  }
  if (!(total > 0)) return Error{ErrorCode::Topology, "the boundary subtends no angle at the source"};
  // Every step of the polar angle is at least kMinAngleStep of the mean step: a boundary edge that
  // points at the source subtends no angle, and its two ends would land on one ray and then on one
  // point of the hull, collapsing their triangles (a fuzzing finding).
  const double minStep = kMinAngleStep * total / static_cast<double>(n);
  total = 0;
  for (size_t i = 0; i < n; ++i) {
    cumulative[i] = total;
    total += std::max(increment[i], minStep);
  }
  const Stopwatch traceTime;
  auto traced = traceStraightestPaths(mesh, source, boundaryTargets(mesh), TraceOptions{false}, progress);
  if (!traced) return traced.error();
  const PathBatch& batch = traced.value();
  record(timings, "trace", traceTime.ms());
  std::vector<double> fallback;
  map.polygon.resize(n);
  for (size_t i = 0; i < n; ++i) {
    double r = batch.length[i];
    if (batch.status[i] != TraceStatus::Reached) {
      if (fallback.empty()) fallback = dijkstraDistances(mesh, source);
      r = fallback[map.loop[i]];
      ++map.fallbacks;
    }
    const double theta = kTwoPi * cumulative[i] / total;
    map.polygon[i] = {r * std::cos(theta), r * std::sin(theta)};
  }
  map.movedToHull = convexify(map.polygon, boundaryChords(mesh, map.loop));
  if (map.movedToHull < 0)
    return Error{ErrorCode::Topology,
                 "the measured boundary does not surround the source (a boundary edge "
                 "subtends half of the total angle or more)"};
  return map;
}

BoundaryMap circleBoundary(const TriMesh& mesh) {
  BoundaryMap map;
  map.kind = BoundaryKind::Circle;
  map.loop = mesh.boundaryLoops().at(0);
  const std::vector<double> s = arcLengthParameter(mesh, map.loop);
  for (double x : s) map.polygon.push_back({std::cos(kTwoPi * x), std::sin(kTwoPi * x)});
  return map;
}

BoundaryMap squareBoundary(const TriMesh& mesh) {
  BoundaryMap map;
  map.kind = BoundaryKind::Square;
  map.loop = mesh.boundaryLoops().at(0);
  const std::vector<double> s = arcLengthParameter(mesh, map.loop);
  for (double x : s) {
    const double p = 4 * x;
    const int side = std::min(3, static_cast<int>(p));
    const double f = p - side;
    // Centred at the origin for convexify(); shifted back to [0, 1]² afterwards.
    const Vec2 q = side == 0 ? Vec2{f, 0} : side == 1 ? Vec2{1, f} : side == 2 ? Vec2{1 - f, 1} : Vec2{0, 1 - f};
    map.polygon.push_back(q - Vec2{0.5, 0.5});
  }
  convexify(map.polygon, boundaryChords(mesh, map.loop));  // lifts sides only where triangles collapse
  for (Vec2& q : map.polygon) q += Vec2{0.5, 0.5};
  return map;
}

UnitSquareFrame unitSquareFrame(const std::vector<Vec2>& polygon) {
  Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 hi = -lo;
  for (const Vec2& q : polygon)
    for (int c = 0; c < 2; ++c) {
      lo[c] = std::min(lo[c], q[c]);
      hi[c] = std::max(hi[c], q[c]);
    }
  const double scale = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(scale > 0)) return {};  // a point or nothing: leave it where it is
  return {lo, scale};
}

}  // namespace straightest
