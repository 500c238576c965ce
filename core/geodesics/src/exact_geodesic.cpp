// exact_geodesic.cpp — window propagation (ICH) for exact polyhedral geodesic distances; see
// exact_geodesic.hpp. The back-trace of shortest paths is in exact_geodesic_path.cpp.
#include "straightest/geodesics/exact_geodesic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "exact_geodesic_queue.hpp"
#include "exact_geodesic_reference.hpp"
#include "straightest/base/huge_page_allocator.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/mesh/unfolding.hpp"

namespace straightest {
namespace {

using unfolding::corner;
using unfolding::lineMeetsSegment;

constexpr double kInf = std::numeric_limits<double>::infinity();
/// A vertex whose total angle exceeds 2π by more than rounding is a saddle: shortest paths may bend there.
constexpr double kSaddleExcess = 1e-9;
/// Windows narrower than this fraction of their edge are dropped: the rays they carry are within rounding
/// of their neighbours' (the corners they touch get their distance directly), and keeping them would
/// let zero-width windows multiply along rays through vertices.
constexpr double kMinWindowRel = 1e-10;
/// A corner is seen by a window whose end it lies on within this fraction of the edge (see propagate).
constexpr double kSeenSlack = 1e-9;
/// The shadow cone is widened by this angle on each side so that rounding in the arriving direction cannot
/// lose a direction.
constexpr double kConeSlack = 1e-7;
/// The queue orders windows to this fraction of the mean edge length (see exact_geodesic_queue.hpp).
constexpr double kQueueResolution = 1.0 / 64;
/// The filter drops a window only when a corner is shorter by more than rounding (relative).
constexpr double kFilterMargin = 1e-12;

/// What the propagation reads of a halfedge h, in one record: a face's three take 240 bytes, where the
/// lengths, corners, vertices and twins in arrays of their own cost a cache miss each in the inner loop.
struct Halfedge {
  double len;       // |h|
  Vec2 corner;      // face(h)'s third corner c in h's frame (unfolding::oppositeCorner)
  Vec2 toCorner;    // the unit vector from tail(h) to c, and from c to head(h), in h's frame: the axes of
  Vec2 fromCorner;  // the children's frames (unfolding::toFrame's u, divided once here instead of per window)
  int32_t twin;     // −1 on the boundary
  int32_t tail;     // the vertex h leaves (face(h)'s third corner is tail(prev(h)))
  int32_t head;     // the vertex h enters, tail(next(h)) (here too: the padding had room, and a window's
                    // filters read both ends of its edge)
  int32_t edge;     // the edge's number, for its record of windows (−1: boundary)
  double angle;     // face(h)'s angle at tail(h), from the three edge lengths (for the saddles; here rather
                    // than in an array of its own: 8 bytes a halfedge more in memory the propagation
                    // touches anyway, where a separate array is mapped, and faulted in, on every call)
};

/// unfolding::toFrame(q, from, to) with its unit axis u = (to − from)/|to − from| given: the same bits.
Vec2 inFrame(const Vec2& q, const Vec2& from, const Vec2& u) {
  const Vec2 d = q - from;
  return {dot(d, u), cross(u, d)};
}

/// unfolding::toFrame's unit axis from `from` to `to`.
Vec2 unitAxis(const Vec2& from, const Vec2& to) {
  const Vec2 axis = to - from;
  return axis / unfolding::length(axis);
}

/// The angle between two sides a and b of a triangle whose third side is o.
double angleBetween(double a, double b, double o) {
  const double cosine = (a * a + b * b - o * o) / (2 * a * b);
  return std::acos(std::clamp(std::isfinite(cosine) ? cosine : 1.0, -1.0, 1.0));
}

/// The records, face by face from the three lengths (as unfolding::halfedgeLengths and oppositeCorner make
/// them: the same bits as the back-trace's frames), written once.
detail::HugeVector<Halfedge> halfedges(const TriMesh& mesh) {
  detail::HugeVector<Halfedge> half;
  half.reserve(3 * static_cast<size_t>(mesh.numFaces()));
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    double len[3];
    for (int k = 0; k < 3; ++k)
      len[k] = norm(mesh.position(mesh.head(3 * f + k)) - mesh.position(mesh.tail(3 * f + k)));
    for (int k = 0; k < 3; ++k) {
      const int32_t h = 3 * f + k;
      const double next = len[(k + 1) % 3], prev = len[(k + 2) % 3];
      const Vec2 c = corner(len[k], prev, next);
      half.push_back(Halfedge{len[k], c, unitAxis(Vec2{0, 0}, c), unitAxis(c, Vec2{len[k], 0}), mesh.twin(h),
                              mesh.tail(h), mesh.head(h), -1, angleBetween(len[k], prev, next)});
    }
  }
  return half;
}

double meanLength(const detail::HugeVector<Halfedge>& half) {
  double sum = 0;
  for (const Halfedge& h : half) sum += h.len;
  return half.empty() ? 0.0 : sum / static_cast<double>(half.size());
}

/// A window on `halfedge` (propagating into face(halfedge)), or when halfedge < 0 a pseudo-source event
/// for vertex −1 − halfedge.
struct Window {
  double b0, b1;  // the interval, as distances from the halfedge's tail
  Vec2 image;     // the origin unfolded into the halfedge's frame (y <= 0: behind the edge)
  double sigma;   // distance at the origin
  double f0, f1;  // distances at b0 and b1 (σ + |image − b|): kept for the filter when the window is popped
  int32_t halfedge;
  int32_t origin;  // pseudo-source vertex, −1: the source point

  /// The least distance over the interval, the queue's order: at the image's foot, or at the nearer end
  /// (the same bits as σ + |image − clamp(image.x)|, without a square root).
  double nearest() const { return image.x < b0 ? f0 : image.x > b1 ? f1 : sigma + std::fabs(image.y); }
};

class Propagation {
 public:
  /// prune = false: the reference (exact_geodesic_reference.hpp): no filter, no shadow cones; windows whose
  /// least distance exceeds `cap` (an upper bound of every vertex's distance) are dropped instead.
  Propagation(const TriMesh& mesh, ExactGeodesics& out, bool prune = true, double cap = kInf)
      : prune_(prune),
        cap_(cap),
        mesh_(mesh),
        out_(out),
        half_(halfedges(mesh)),
        pseudo_(mesh.numVertices(), 0),
        emitted_(mesh.numVertices(), kInf),
        queue_(meanLength(half_) * kQueueResolution) {
    out_.distances.assign(mesh.numVertices(), kInf);
    out_.parents.assign(mesh.numVertices(), GeodesicParent{});
    std::vector<double> angle(mesh.numVertices(), 0.0);
    for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h) angle[half_[h].tail] += half_[h].angle;
    for (int32_t v = 0; v < mesh.numVertices(); ++v)
      pseudo_[v] = mesh.isBoundaryVertex(v) || angle[v] > kTwoPi + kSaddleExcess;
    int32_t edges = 0;
    for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h) {
      const int32_t t = mesh.twin(h);
      if (t > h) half_[h].edge = half_[t].edge = edges++;
    }
    seen_.assign(edges, Seen{1, 0, 0, 0, 0});
    queueLimit_ = 100 * static_cast<int64_t>(mesh.numFaces()) + 1'000'000;
  }

  Expected<void> run(const SurfacePoint& source, const Progress& progress) {
    seed(source);
    int64_t referenced = 0;
    for (int32_t v = 0; v < mesh_.numVertices(); ++v) referenced += mesh_.vertexHalfedge(v) >= 0;
    ThrottledProgress report(progress, "distances");
    int64_t pops = 0;
    while (!queue_.empty()) {
      if ((++pops & 4095) == 0) {
        if (!report(referenced > 0 ? static_cast<double>(reached_) / referenced : 1.0))
          return cancelledError("exact geodesic distances");
        if (static_cast<int64_t>(queue_.size()) > queueLimit_)
          return Error{ErrorCode::TooLarge, "exact geodesic distances: more than " + std::to_string(queueLimit_) +
                                                " windows in the queue (100 per face); the mesh is too large "
                                                "or too degenerate for window propagation"};
      }
      const Window w = queue_.pop();
      if (w.halfedge < 0) emitFromVertex(-1 - w.halfedge, false);
      else propagate(w);
    }
    out_.stats.maxQueue = static_cast<int64_t>(queue_.peak());
    if (!progress("distances", 1.0)) return cancelledError("exact geodesic distances");
    return {};
  }

 private:
  void push(const Window& w) { queue_.push(w.nearest(), w); }

  void update(int32_t v, double d, const GeodesicParent& parent) {
    if (!(d < out_.distances[v])) return;
    if (out_.distances[v] == kInf) ++reached_;
    out_.distances[v] = d;
    out_.parents[v] = parent;
    if (pseudo_[v]) push(Window{0, 0, Vec2{}, d, d, d, -1 - v, v});
  }

  /// The source point's first windows: every edge of the faces around it that it sees across.
  void seed(const SurfacePoint& source) {
    const Vec3 s = position(mesh_, source);
    if (source.kind == SurfacePoint::Kind::Vertex) {
      const int32_t v = source.index;
      out_.distances[v] = 0;
      ++reached_;
      emitFromVertex(v, true);
      return;
    }
    std::vector<int32_t> faces;
    incidentFaces(mesh_, source, faces);
    for (int32_t f : faces)
      for (int k = 0; k < 3; ++k) {
        const int32_t h = 3 * f + k;
        const double toTail = norm(s - mesh_.position(mesh_.tail(h)));
        update(mesh_.tail(h), toTail, GeodesicParent{-1, -1, Vec2{}});
        if (source.kind == SurfacePoint::Kind::Edge && (h == source.index || h == mesh_.twin(source.index)))
          continue;  // the source lies on this edge: the other face's windows cover what is beyond it
        windowAcross(h, norm(s - mesh_.position(mesh_.head(h))), toTail, 0, -1);
      }
  }

  /// A window covering the whole edge of halfedge h (of a face that holds the origin), seen from an origin
  /// at the given distances from h's head and tail, propagating into the face beyond h.
  void windowAcross(int32_t h, double toHead, double toTail, double sigma, int32_t origin) {
    const int32_t t = mesh_.twin(h);
    if (t < 0) return;
    const double l = len(h);
    if (!(l > 0)) return;
    // twin's frame: its tail is h's head.
    const Vec2 image = corner(l, toHead, toTail, /*below=*/true);
    addWindow(t, 0, l, image, sigma, origin, -1);
  }

  double len(int32_t h) const { return half_[h].len; }

  /// The angle of face(h) at tail(h).
  double cornerAngle(int32_t h) const { return half_[h].angle; }

  /// The directions in which a shortest path through saddle v may continue: at least π away, on both
  /// sides, from the path it arrived by (a shorter path would cut the corner otherwise). As fan angles
  /// [lo, hi], counted counter-clockwise from vertexHalfedge(v) over the ring's corner angles in `ring_`;
  /// false when the arriving direction is not known (then every direction is kept).
  bool shadowCone(int32_t v, double total, double& lo, double& hi) const {
    const GeodesicParent& parent = out_.parents[v];
    double back = -10;  // fan angle of the direction from v back along the arriving path
    if (parent.halfedge >= 0) {
      const int32_t k = parent.halfedge;
      const int32_t corners[3] = {mesh_.tail(k), mesh_.head(k), mesh_.head(TriMesh::next(k))};
      const Vec2 at[3] = {Vec2{0, 0}, Vec2{len(k), 0}, half_[k].corner};
      int i = 0;
      while (i < 3 && corners[i] != v) ++i;
      if (i == 3) return false;
      const Vec2 edge = at[(i + 1) % 3] - at[i], r = parent.image - at[i];  // corner i's outgoing halfedge
      const int32_t hv = 3 * TriMesh::face(k) + (k % 3 + i) % 3;
      // The arriving ray crosses this face only when v is its corner c (i == 2); at the window's own edge's
      // tail (i == 0) it arrives from the faces clockwise of hv, at its head (i == 1) from beyond the
      // face's other edge: the unfolded angle continues into the ring either way.
      double local = std::atan2(cross(edge, r), dot(edge, r));
      if (i == 1 && local < 0) local += kTwoPi;
      if (i == 2) local = std::clamp(local, 0.0, cornerAngle(hv));
      for (size_t j = 0; j < ring_.size(); ++j)
        if (ring_[j].first == hv) back = ring_[j].second + local;
      if (back < -kPi) return false;  // hv not found
    } else if (parent.origin >= 0) {
      for (size_t j = 0; j < ring_.size(); ++j)
        if (mesh_.head(ring_[j].first) == parent.origin) back = ring_[j].second;
    }
    if (back < -kPi) return false;
    back = std::fmod(back + total, total);
    lo = back + kPi - kConeSlack;
    hi = back + total - kPi + kConeSlack;
    return hi > lo;
  }

  /// A pseudo-source (or the source vertex): its neighbours by their edges, and windows across the
  /// opposite edge of the faces around v — for a saddle only within its shadow cone (shadowCone).
  void emitFromVertex(int32_t v, bool isSource) {
    const double d = out_.distances[v];
    if (!isSource && !(d < emitted_[v])) return;  // stale event, or already emitted at this distance
    emitted_[v] = d;
    ++out_.stats.pseudoSources;
    ring_.clear();
    double total = 0;
    for (int32_t h : mesh_.outgoingHalfedges(v)) {
      ring_.push_back({h, total});
      total += cornerAngle(h);
    }
    double lo = 0, hi = 0;
    const bool cone = prune_ && !isSource && !mesh_.isBoundaryVertex(v) && shadowCone(v, total, lo, hi);
    for (const auto& [h, phi] : ring_) {
      const int32_t p = TriMesh::prev(h), o = TriMesh::next(h);
      update(mesh_.head(h), d + len(h), GeodesicParent{-1, v, Vec2{}});
      update(mesh_.tail(p), d + len(p), GeodesicParent{-1, v, Vec2{}});
      if (!cone) {
        windowAcross(o, len(p), len(h), d, v);
        continue;
      }
      const double gamma = cornerAngle(h);
      for (double shift : {-total, 0.0, total}) {
        const double b0 = std::max(0.0, lo + shift - phi), b1 = std::min(gamma, hi + shift - phi);
        if (b1 > b0) windowAcrossBetween(h, b0, b1, d, v);
      }
    }
  }

  /// The part of the window across next(h) (h leaving the origin v) between the rays at angles b0 < b1
  /// from h.
  void windowAcrossBetween(int32_t h, double b0, double b1, double sigma, int32_t origin) {
    const int32_t o = TriMesh::next(h), t = mesh_.twin(o);
    if (t < 0 || !(len(o) > 0)) return;
    const Vec2 w1{len(h), 0}, w2 = half_[h].corner, v{0, 0};
    const double t0 = lineMeetsSegment(v, Vec2{std::cos(b0), std::sin(b0)}, w1, w2, 0.0);
    const double t1 = lineMeetsSegment(v, Vec2{std::cos(b1), std::sin(b1)}, w1, w2, 1.0);
    const double l = len(o);
    // twin(o) runs from w2 to w1.
    addWindow(t, (1 - t1) * l, (1 - t0) * l, corner(l, len(TriMesh::prev(h)), len(h), /*below=*/true), sigma, origin,
              -1);
  }

  /// Adds the window [b0, b1] on halfedge h unless it is too narrow or the filter (the corners of the face it
  /// leaves, h's endpoints and `third`, a vertex of that face; −1: none) shows it useless.
  void addWindow(int32_t h, double b0, double b1, const Vec2& image, double sigma, int32_t origin, int32_t third) {
    const Halfedge& e = half_[h];
    const double l = e.len;
    b0 = std::max(b0, 0.0);
    b1 = std::min(b1, l);
    if (!(b1 - b0 > kMinWindowRel * l)) return;
    const Vec2 x0{b0, 0}, x1{b1, 0};
    const Window w{
        b0, b1, image, sigma, sigma + unfolding::length(image - x0), sigma + unfolding::length(image - x1), h, origin};
    if (!prune_) {
      if (w.nearest() > cap_) return;
      ++out_.stats.windows;
      push(w);
      return;
    }
    Seen& seen = seen_[e.edge];
    if (dominated(h, e, seen, b0, b1, image, sigma)) {
      ++out_.stats.filtered;
      return;
    }
    const double* d = out_.distances.data();
    if (shorter(d[e.tail] + b1, w.f1) || shorter(d[e.head] + (l - b0), w.f0)) {
      ++out_.stats.filtered;
      return;
    }
    if (third >= 0) {
      // third's position in h's frame: the corner of face(twin(h)) opposite h, below the axis.
      const Vec2& t = half_[e.twin].corner;
      if (cornerShorter(d[third], Vec2{l - t.x, -t.y}, x0, x1, w.nearest())) {
        ++out_.stats.filtered;
        return;
      }
    }
    remember(h, e, seen, b0, b1, image, sigma);
    ++out_.stats.windows;
    push(w);
  }

  /// The filter's test: a path of length `via` is shorter than a window's distance by more than rounding.
  static bool shorter(double via, double window) { return via < window - kFilterMargin * window; }

  /// shorter(dr + max(|r − x0|, |r − x1|), least): corner r at distance dr reaches every point of the interval
  /// x0–x1 more shortly than the window's least distance. Compared squared, without a square root.
  static bool cornerShorter(double dr, const Vec2& r, const Vec2& x0, const Vec2& x1, double least) {
    const double room = least - kFilterMargin * least - dr;  // inf − inf (never reached corner): NaN, false
    if (!(room > 0)) return false;
    const double ry2 = r.y * r.y, d0 = r.x - x0.x, d1 = r.x - x1.x;
    return std::max(d0 * d0, d1 * d1) + ry2 < room * room;
  }

  /// A window as its edge's record, in the frame of the edge's lower-numbered halfedge; b1 < b0: none.
  struct Seen {
    double b0, b1, ix, iy, sigma;
  };

  /// A window's interval and image in the frame of its edge's lower-numbered halfedge.
  static void toEdgeFrame(int32_t h, const Halfedge& e, double& b0, double& b1, double& ix, double& iy) {
    if (h < e.twin) return;
    const double l = e.len, c0 = l - b1, c1 = l - b0;
    b0 = c0;
    b1 = c1;
    ix = l - ix;
    iy = -iy;
  }

  /// Records the window as its edge's latest: the one later windows on the edge are compared with
  /// (dominated). One record per edge catches nearly all of what several would.
  static void remember(int32_t h, const Halfedge& e, Seen& seen, double b0, double b1, const Vec2& image,
                       double sigma) {
    double ix = image.x, iy = image.y;
    toEdgeFrame(h, e, b0, b1, ix, iy);
    seen = Seen{b0, b1, ix, iy, sigma};
  }

  /// True when the window recorded on the same edge (see remember) is shorter, by more than the filter's
  /// margin, at every point of [b0, b1]. Both distances are lengths of real paths, so the rays of this one
  /// are nowhere shortest (a shortest path's own window is never beaten on it by the margin), and any
  /// window is such a path whether or not it is propagated. The difference g(x) = (σ + |image − x|) −
  /// (σs + |images − x|) is monotone between its breakpoints: where both rays meet the axis at the same
  /// angle (x on the line through the two images reflected to one side of the axis), and the images' feet
  /// (kinks when an image is on the axis); so its least value on [b0, b1] is at one of those or an end.
  static bool dominated(int32_t h, const Halfedge& e, const Seen& s, double b0, double b1, const Vec2& image,
                        double sigma) {
    double ix = image.x, iy = image.y;
    toEdgeFrame(h, e, b0, b1, ix, iy);
    if (!(s.b0 <= b0 && s.b1 >= b1)) return false;
    const double ay = std::fabs(iy), sy = std::fabs(s.iy);
    auto beaten = [&](double x) {
      const double dx = ix - x, sx = s.ix - x;
      const double f = sigma + std::sqrt(dx * dx + ay * ay);
      return f - (s.sigma + std::sqrt(sx * sx + sy * sy)) > kFilterMargin * f;
    };
    if (!beaten(b0) || !beaten(b1)) return false;
    if (sy != ay) {
      const double xs = (ix * sy - s.ix * ay) / (sy - ay);
      if (xs > b0 && xs < b1 && !beaten(xs)) return false;
    }
    if (ix > b0 && ix < b1 && !beaten(ix)) return false;
    return !(s.ix > b0 && s.ix < b1 && !beaten(s.ix));
  }

  /// The filter again when the window leaves the queue: the corners' distances may have shrunk since it
  /// was made. (Its edge's endpoints, and the corner c of the face it enters.)
  bool useless(const Window& w, const Halfedge& edge, const Vec2& c, int32_t vc) {
    const double* d = out_.distances.data();
    const double l = edge.len;
    if (shorter(d[edge.tail] + w.b1, w.f1) || shorter(d[edge.head] + (l - w.b0), w.f0) ||
        cornerShorter(d[vc], c, Vec2{w.b0, 0}, Vec2{w.b1, 0}, w.nearest())) {
      ++out_.stats.filtered;
      return true;
    }
    return false;
  }

  /// Carries window w across face(w.halfedge): its rays leave through the other two edges, split at the
  /// opposite corner c, which gets its distance when the window sees it.
  void propagate(const Window& w) {
    const int32_t h = w.halfedge, k = h % 3;  // one division by 3 for both neighbours
    // The face's three records, read once (not through the vector at each use: its calls in between make
    // the compiler load the vector's pointer again).
    const Halfedge& here = half_[h];
    const Halfedge& next = half_[h - k + (k + 1) % 3];  // arithmetic: a select here became a branch that
    const Halfedge& prev = half_[h - k + (k + 2) % 3];  // mispredicts (k is a coin toss)
    const double l = here.len;
    const Vec2 a{0, 0}, b{l, 0}, c = here.corner;
    const Vec2& image = w.image;
    const int32_t vc = prev.tail;
    if (prune_ && useless(w, here, c, vc)) return;
    // Where the ray from the image through c crosses the axis.
    const double depth = c.y - image.y;
    const double xc = depth > 0 ? image.x + (c.x - image.x) * (-image.y) / depth : c.x;
    // c is seen when its ray crosses the window; a ray through c along the window's end is computed in two
    // frames (this window's and its neighbour's), so each side accepts it within rounding.
    const double slack = kSeenSlack * l;
    if (xc >= w.b0 - slack && xc <= w.b1 + slack)
      update(vc, w.sigma + unfolding::length(c - image), GeodesicParent{h, w.origin, image});
    // The part left of c leaves through c–a (child on twin(prev), frame a → c).
    if (xc > w.b0) {
      const int32_t child = prev.twin;
      const double lac = prev.len;
      const double p0 = lineMeetsSegment(image, Vec2{w.b0, 0}, a, c, 0.0) * lac;
      const double p1 = xc < w.b1 ? lac : lineMeetsSegment(image, Vec2{w.b1, 0}, a, c, 1.0) * lac;
      if (p0 <= 0) update(here.tail, w.sigma + unfolding::length(image - a), GeodesicParent{h, w.origin, image});
      if (child >= 0) addWindow(child, p0, p1, inFrame(image, a, here.toCorner), w.sigma, w.origin, here.head);
    }
    // The part right of c leaves through b–c (child on twin(next), frame c → b).
    if (xc < w.b1) {
      const int32_t child = next.twin;
      const double lcb = next.len;
      const double q0 = xc > w.b0 ? 0.0 : lineMeetsSegment(image, Vec2{w.b0, 0}, c, b, 0.0) * lcb;
      const double q1 = lineMeetsSegment(image, Vec2{w.b1, 0}, c, b, 1.0) * lcb;
      if (q1 >= lcb) update(here.head, w.sigma + unfolding::length(image - b), GeodesicParent{h, w.origin, image});
      if (child >= 0) addWindow(child, q0, q1, inFrame(image, c, here.fromCorner), w.sigma, w.origin, here.tail);
    }
  }

  const bool prune_;
  const double cap_;
  const TriMesh& mesh_;
  ExactGeodesics& out_;
  detail::HugeVector<Halfedge> half_;  // per halfedge: what the propagation reads of it (Halfedge)
  std::vector<uint8_t> pseudo_;
  std::vector<double> emitted_;                   // distance at a vertex's last emission
  std::vector<std::pair<int32_t, double>> ring_;  // emitFromVertex's fan: outgoing halfedge, angle before it
  detail::MinQueue<Window> queue_;                // windows and pseudo-source events, by key
  detail::HugeVector<Seen> seen_;                 // per edge: the last window created on it (see remember)
  int64_t reached_ = 0, queueLimit_ = 0;
};

}  // namespace

Expected<ExactGeodesics> exactGeodesics(const TriMesh& mesh, const SurfacePoint& source, const Progress& progress) {
  return guarded([&]() -> Expected<ExactGeodesics> {
    auto valid = validateSurfacePoint(mesh, source);
    if (!valid) return valid.error();
    ExactGeodesics out;
    out.source = valid.value();
    Propagation propagation(mesh, out);
    auto done = propagation.run(out.source, progress);
    if (!done) return done.error();
    return out;
  });
}

namespace detail {

Expected<ExactGeodesics> exactGeodesicsUnpruned(const TriMesh& mesh, const SurfacePoint& source) {
  return guarded([&]() -> Expected<ExactGeodesics> {
    auto valid = validateSurfacePoint(mesh, source);
    if (!valid) return valid.error();
    // Every vertex is within its graph distance; a window farther than all of them improves none, nor do
    // the windows it would make (distances grow along rays).
    double cap = 0;
    for (double d : dijkstraDistances(mesh, valid.value()))
      if (std::isfinite(d)) cap = std::max(cap, d);
    ExactGeodesics out;
    out.source = valid.value();
    Propagation propagation(mesh, out, /*prune=*/false, cap * (1 + 1e-9));
    auto done = propagation.run(out.source, {});
    if (!done) return done.error();
    return out;
  });
}

}  // namespace detail

std::vector<double> exactGeodesicDistances(const TriMesh& mesh, const SurfacePoint& source) {
  auto field = exactGeodesics(mesh, source);
  if (!field) return std::vector<double>(mesh.numVertices(), kInf);
  return std::move(field).value().distances;
}

}  // namespace straightest
