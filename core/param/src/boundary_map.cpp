// boundary_map.cpp — the boundary polygons (measured, circle, square), their convexification and the ear lift.
#include "straightest/param/boundary_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/paths/straightest_path.hpp"

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

namespace {

/// Where each vertex lies on the loop (its index there), −1 off the loop.
std::vector<int32_t> loopPositions(const TriMesh& mesh, const std::vector<int32_t>& loop) {
  std::vector<int32_t> position(mesh.numVertices(), -1);
  for (size_t i = 0; i < loop.size(); ++i) position[loop[i]] = static_cast<int32_t>(i);
  return position;
}

/// What ring(v) lists around the loop's vertices v and keep(item) accepts, ascending, each once: what a
/// scan of the whole mesh finds of the items that touch the loop, from the loop's rings alone (every vertex
/// is one fan, so its ring holds all its halfedges and faces). A scan of every halfedge and face would
/// cost more than the rest of the measured boundary outside the traces.
template <class Ring, class Keep>
std::vector<int32_t> aroundLoop(const std::vector<int32_t>& loop, const Ring& ring, const Keep& keep) {
  std::vector<int32_t> items;
  for (int32_t v : loop)
    for (int32_t item : ring(v))
      if (keep(item)) items.push_back(item);
  std::sort(items.begin(), items.end());
  items.erase(std::unique(items.begin(), items.end()), items.end());
  return items;
}

/// The interior edges with both ends on the loop, each as its halfedge of lower index, ascending.
std::vector<int32_t> chordHalfedges(const TriMesh& mesh, const std::vector<int32_t>& loop,
                                    const std::vector<int32_t>& position) {
  return aroundLoop(
      loop, [&](int32_t v) { return mesh.outgoingHalfedges(v); },
      [&](int32_t h) {
        const int32_t t = mesh.twin(h);  // boundary edges run along the loop; each interior edge once
        return t >= 0 && t > h && position[mesh.head(h)] >= 0;
      });
}

/// The faces with three corners on the loop, ascending.
std::vector<int32_t> earFaces(const TriMesh& mesh, const std::vector<int32_t>& loop,
                              const std::vector<int32_t>& position) {
  return aroundLoop(
      loop, [&](int32_t v) { return mesh.vertexFaces(v); },
      [&](int32_t f) {
        const Triangle& t = mesh.triangle(f);
        return position[t[0]] >= 0 && position[t[1]] >= 0 && position[t[2]] >= 0;
      });
}

}  // namespace

std::vector<std::array<int32_t, 2>> boundaryChords(const TriMesh& mesh, const std::vector<int32_t>& loop) {
  const std::vector<int32_t> position = loopPositions(mesh, loop);
  std::vector<std::array<int32_t, 2>> out;
  for (int32_t h : chordHalfedges(mesh, loop, position))
    out.push_back({position[mesh.tail(h)], position[mesh.head(h)]});
  return out;
}

namespace {

/// The convex hull of the points, and where each point lies on it after the radial projection.
struct HullProjection {
  std::vector<Vec2> hull;         // counter-clockwise, starting at the smallest polar angle
  std::vector<int64_t> edgeOf;    // hull edge j (from hull[j] to hull[j + 1]) strictly inside which a point lies
  std::vector<int64_t> cornerOf;  // hull vertex a point lies on
  std::vector<double> along;      // parameter along its hull edge
};

/// Moves every point radially (from the origin) exactly onto the convex hull of the points: the least
/// convex polygon, with the same polar angles, that contains them. False when the origin is not strictly
/// inside the hull. `moved` counts the points that were strictly inside.
bool projectOntoHull(std::vector<Vec2>& points, HullProjection& out, int64_t& moved) {
  const size_t n = points.size();
  const std::vector<size_t> hullIdx = convexHull(points);
  const size_t h = hullIdx.size();
  if (h < 3) return false;
  std::vector<Vec2>& hull = out.hull;
  hull.assign(h, Vec2{});
  for (size_t j = 0; j < h; ++j) hull[j] = points[hullIdx[j]];
  for (size_t j = 0; j < h; ++j) {  // the origin must be strictly inside (left of every CCW edge)
    const Vec2 e = hull[(j + 1) % h] - hull[j];
    if (!(cross(e, Vec2{} - hull[j]) > 1e-14 * norm(e) * norm(e))) return false;
  }
  // Hull vertices in angular order around the origin, starting at the smallest angle.
  std::vector<double> angle(h);
  for (size_t j = 0; j < h; ++j) angle[j] = std::atan2(hull[j].y, hull[j].x);
  const auto first = std::min_element(angle.begin(), angle.end()) - angle.begin();
  std::rotate(hull.begin(), hull.begin() + first, hull.end());
  std::rotate(angle.begin(), angle.begin() + first, angle.end());

  moved = 0;
  out.edgeOf.assign(n, -1);
  out.cornerOf.assign(n, -1);
  out.along.assign(n, 0.0);
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
      out.edgeOf[i] = static_cast<int64_t>(j);
      out.along[i] = t;
    } else if (t <= kOnHullRel && t > -kOnHullRel) {
      out.cornerOf[i] = static_cast<int64_t>(j);
    } else if (t >= 1 - kOnHullRel && t < 1 + kOnHullRel) {
      out.cornerOf[i] = static_cast<int64_t>((j + 1) % h);
    }
  }
  return true;
}

double polygonArea(const std::vector<Vec2>& polygon) {
  double twice = 0;
  for (size_t i = 0; i < polygon.size(); ++i) twice += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return twice / 2;
}

/// An ear's corners as (a, m, b) in loop order along the shortest stretch of the loop that holds all three:
/// on a convex polygon the ear degenerates only when that stretch is straight, and m is the corner to lift.
std::array<int32_t, 3> earApexOrder(const std::array<int32_t, 3>& corners, int32_t n) {
  std::array<int32_t, 3> c = corners;
  std::sort(c.begin(), c.end());
  const int32_t span[3] = {c[2] - c[0], n - c[1] + c[0], n - c[2] + c[1]};
  const int best = static_cast<int>(std::min_element(span, span + 3) - span);
  return {c[best], c[(best + 1) % 3], c[(best + 2) % 3]};
}

/// Twice the least 2D area an ear may have: kEarAreaFraction of its 3D area at the polygon's scale.
double earRequirement(double area3D, double scale) { return kEarAreaFraction * area3D * scale; }

/// Where the radial projection puts point q once m's hull neighbours are `left` and P (q in the cone between them)
/// or P and `right`: on that new hull edge; elsewhere q stays.
Vec2 projectedNeighbour(const Vec2& q, const Vec2& left, const Vec2& P, const Vec2& right) {
  const double r = norm(q);
  if (!(r > 0)) return q;
  const Vec2 d = q / r;
  for (const auto& [from, to] : {std::pair<Vec2, Vec2>{left, P}, std::pair<Vec2, Vec2>{P, right}}) {
    if (!(cross(from, d) > 0) || !(cross(d, to) > 0)) continue;
    const Vec2 E = to - from;
    const double onEdge = cross(from, E) / cross(d, E);
    return onEdge > r ? d * onEdge : q;
  }
  return q;
}

/// One round of ear lifting. An ear (a, m, b) below its least area moves its apex m radially outward until the
/// ear has kEarLiftTarget times that area with a and b where the next projection puts them (on the new hull edges
/// from m to m's hull neighbours). Lifting m only until the triangle (a, m, b) as it stands holds would not do: the
/// projection then moves a and b out onto nearly the same line and undoes most of the lift. True if any moved.
bool liftEars(std::vector<Vec2>& points, const std::vector<BoundaryEar>& ears, double scale,
              const HullProjection& projection) {
  const int32_t n = static_cast<int32_t>(points.size());
  const std::vector<Vec2>& hull = projection.hull;
  const int64_t h = static_cast<int64_t>(hull.size());
  bool lifted = false;
  for (const BoundaryEar& ear : ears) {
    const auto [a, m, b] = earApexOrder(ear.corners, n);
    const Vec2 A = points[a], M = points[m], B = points[b];
    const double need = earRequirement(ear.area3D, scale);
    if (cross(M - A, B - A) / 2 >= need) continue;
    Vec2 left, right;  // m's neighbours on the hull
    if (projection.edgeOf[m] >= 0) {
      left = hull[projection.edgeOf[m]];
      right = hull[(projection.edgeOf[m] + 1) % h];
    } else if (projection.cornerOf[m] >= 0) {
      left = hull[(projection.cornerOf[m] + h - 1) % h];
      right = hull[(projection.cornerOf[m] + 1) % h];
    } else {
      continue;
    }
    const double r0 = norm(M);
    if (!(r0 > 0)) continue;
    const Vec2 d = M / r0;
    auto area = [&](double r) {
      const Vec2 P = d * r;
      const Vec2 A1 = projectedNeighbour(A, left, P, right), B1 = projectedNeighbour(B, left, P, right);
      return cross(P - A1, B1 - A1) / 2;
    };
    const double wanted = kEarLiftTarget * need;
    if (area(r0) >= wanted) continue;
    // Never more than kMaxEarLift times the apex's radius: an ear that needs more (its stretch of the loop
    // spans half a turn or more, so lifting cannot open it) is left as it is rather than blowing the polygon up.
    double lo = r0, hi = kMaxEarLift * r0;
    if (area(hi) < wanted) continue;
    for (int k = 0; k < 60; ++k) {
      const double mid = (lo + hi) / 2;
      (area(mid) < wanted ? lo : hi) = mid;
    }
    points[m] = d * hi;
    lifted = true;
  }
  return lifted;
}

}  // namespace

namespace {

/// The faces on one side of the interior edge h (h's own face's side), reached without crossing h; empty when
/// there are more than kPocketFaces of them.
std::vector<int32_t> facesBeside(const TriMesh& mesh, int32_t h) {
  std::vector<int32_t> faces{TriMesh::face(h)};
  for (size_t q = 0; q < faces.size(); ++q) {
    const int32_t f = faces[q];
    for (int32_t e = 3 * f; e < 3 * f + 3; ++e) {
      const int32_t t = mesh.twin(e);
      if (t < 0 || e == h) continue;
      const int32_t g = TriMesh::face(t);
      if (std::find(faces.begin(), faces.end(), g) != faces.end()) continue;
      if (static_cast<int64_t>(faces.size()) == kPocketFaces) return {};
      faces.push_back(g);
    }
  }
  return faces;
}

}  // namespace

std::vector<BoundaryEar> boundaryEars(const TriMesh& mesh, const std::vector<int32_t>& loop) {
  const int32_t n = static_cast<int32_t>(loop.size());
  const std::vector<int32_t> position = loopPositions(mesh, loop);
  std::vector<BoundaryEar> out;
  for (int32_t f : earFaces(mesh, loop, position)) {
    const Triangle& t = mesh.triangle(f);
    out.push_back({{position[t[0]], position[t[1]], position[t[2]]}, mesh.faceArea(f)});
  }
  // Pockets: a chord cuts the disk in two; a side of at most kPocketFaces faces (the smaller, when both are) is
  // bounded by the chord and the stretch of the loop between its ends, and collapses with that stretch.
  for (int32_t h : chordHalfedges(mesh, loop, position)) {
    const int32_t tw = mesh.twin(h);
    const int32_t i = position[mesh.tail(h)], k = position[mesh.head(h)];
    const std::vector<int32_t> left = facesBeside(mesh, h), right = facesBeside(mesh, tw);
    if (left.empty() && right.empty()) continue;
    const bool leftIsPocket = !left.empty() && (right.empty() || left.size() <= right.size());
    const std::vector<int32_t>& pocket = leftIsPocket ? left : right;
    // The loop keeps the surface on its left, so the side left of h (from loop[i] to loop[k]) is bounded by the
    // stretch from k forward to i.
    const int32_t start = leftIsPocket ? k : i, end = leftIsPocket ? i : k;
    const int32_t length = (end - start + n) % n;
    if (length < 2) continue;
    double area = 0;
    for (int32_t f : pocket) area += mesh.faceArea(f);
    out.push_back({{start, (start + length / 2) % n, end}, area});
  }
  return out;
}

double worstEarRatio(const std::vector<Vec2>& polygon, const std::vector<BoundaryEar>& ears, double surfaceArea) {
  const double scale = polygonArea(polygon) / surfaceArea;
  double worst = std::numeric_limits<double>::infinity();
  for (const BoundaryEar& ear : ears) {
    if (!(ear.area3D > 0)) continue;
    const Vec2 A = polygon[ear.corners[0]], B = polygon[ear.corners[1]], C = polygon[ear.corners[2]];
    worst = std::min(worst, std::abs(cross(B - A, C - A)) / 2 / (ear.area3D * scale));
  }
  return worst;
}

int64_t convexify(std::vector<Vec2>& points, const std::vector<std::array<int32_t, 2>>& chords,
                  const std::vector<BoundaryEar>& ears, double surfaceArea) {
  const size_t n = points.size();
  if (n < 3) return -1;
  const std::vector<Vec2> input = points;
  HullProjection projection;
  int64_t moved = 0;
  if (!projectOntoHull(points, projection, moved)) return -1;
  // 1. Ears: lift the apex of every ear below its least area, then project onto the new hull (which moves the
  //    neighbours a lift has left inside); repeat until every ear holds. Points only ever move outward, so this
  //    settles on the least such polygon; a lift aims at kEarLiftTarget times the bound so that the neighbours'
  //    later moves (which shrink an ear) rarely undo it.
  if (!ears.empty() && surfaceArea > 0) {
    for (int round = 0; round < kMaxEarRounds; ++round) {
      if (!liftEars(points, ears, polygonArea(points) / surfaceArea, projection)) break;
      int64_t ignored = 0;
      if (!projectOntoHull(points, projection, ignored)) return -1;
    }
    moved = 0;
    for (size_t i = 0; i < n; ++i)
      if (norm(points[i]) > norm(input[i]) * (1 + 1e-12)) ++moved;
  }
  const std::vector<Vec2>& hull = projection.hull;
  const std::vector<int64_t>& edgeOf = projection.edgeOf;
  const std::vector<int64_t>& cornerOf = projection.cornerOf;
  const std::vector<double>& along = projection.along;
  const size_t h = hull.size();
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

std::vector<double> fallbackRadii(const TriMesh& mesh, const SurfacePoint& source) {
  std::vector<double> radius = dijkstraDistances(mesh, source);
  // The heat distances only tighten the graph's upper bound. Where their factorization fails (near-zero
  // cotangent weights on a degenerate mesh: found by fuzz_param) the graph distances stand alone.
  std::vector<double> heat;
  try {
    heat = HeatMethod(mesh).distances(source);
  } catch (const std::runtime_error&) {
    return radius;
  }
  const Vec3 S = position(mesh, source);
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    const double straight = norm(mesh.position(v) - S);  // no path is shorter than the straight line
    if (std::isfinite(heat[v])) radius[v] = std::min(radius[v], std::max(heat[v], straight));
  }
  return radius;
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
  // Radii: the straightest distance; a failed trace, or a reached one longer than kOutlierFactor times the
  // edge-graph distance (an upper bound of the geodesic distance, so no straightest path that long is plausible),
  // takes fallbackRadii instead. The graph distance is computed only when some trace is longer than
  // kOutlierFactor times the straight line (the graph distance is never shorter, so no other can be an outlier).
  std::vector<double> graph, estimate;  // computed when first needed
  auto outlying = [&](int32_t v, double length) {
    if (!(length > kOutlierFactor * norm(mesh.position(v) - S))) return false;
    if (graph.empty()) graph = dijkstraDistances(mesh, source);
    return length > kOutlierFactor * graph[v];
  };
  map.polygon.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const int32_t v = map.loop[i];
    double r = batch.length[i];
    const bool failed = batch.status[i] != TraceStatus::Reached;
    if (failed || outlying(v, r)) {
      if (estimate.empty()) estimate = fallbackRadii(mesh, source);
      r = estimate[v];
      ++(failed ? map.fallbacks : map.outliers);
    }
    const double theta = kTwoPi * cumulative[i] / total;
    map.polygon[i] = {r * std::cos(theta), r * std::sin(theta)};
  }
  double surfaceArea = 0;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) surfaceArea += mesh.faceArea(f);
  map.movedToHull = convexify(map.polygon, boundaryChords(mesh, map.loop), boundaryEars(mesh, map.loop), surfaceArea);
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

const char* boundaryKindName(BoundaryKind k) { return nameOf(kBoundaryKindNames, k); }

Expected<std::optional<BoundaryKind>> parseBoundaryChoice(const std::string& name) {
  if (name == kAutoName) return std::optional<BoundaryKind>();
  if (auto kind = valueOf(kBoundaryKindNames, name)) return std::optional<BoundaryKind>(*kind);
  return Error{ErrorCode::InvalidArgument,
               "unknown boundary '" + name + "' (use " + choiceList(namesOf(kBoundaryKindNames, kAutoName)) + ")"};
}

}  // namespace straightest
