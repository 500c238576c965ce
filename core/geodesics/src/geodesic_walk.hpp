// geodesic_walk.hpp (private) — the Polthier–Schmies walk itself (geodesic_shoot.hpp): the start (a
// tangent direction mapped into a face around the source), the straight walk in 2D across flat faces
// (flat_faces.hpp), and the vertex rule. Used by geodesic_shoot.cpp only.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "straightest/base/cache_hints.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/base/tolerances.hpp"
#include "straightest/geodesics/geodesic_shoot.hpp"
#include "straightest/mesh/flat_faces.hpp"
#include "straightest/mesh/unfolding.hpp"

namespace straightest::shooting {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline double signedAngle(const Vec3& a, const Vec3& b, const Vec3& n) {
  return std::atan2(dot(cross(a, b), n), dot(a, b));
}

/// The angle of face(h) at tail(h).
inline double cornerAngle(const TriMesh& mesh, int32_t h) {
  const Vec3& v = mesh.position(mesh.tail(h));
  const Vec3 a = mesh.position(mesh.head(h)) - v, b = mesh.position(mesh.tail(TriMesh::prev(h))) - v;
  return std::atan2(norm(cross(a, b)), dot(a, b));
}

/// The unit direction in face(h) at angle beta from h (counter-clockwise, toward the face), given by its
/// cosine c and sine s.
inline Vec3 directionInFace(const TriMesh& mesh, int32_t h, double c, double s) {
  const Vec3 u = normalized(mesh.position(mesh.head(h)) - mesh.position(mesh.tail(h)));
  return u * c + cross(mesh.faceNormal(TriMesh::face(h)), u) * s;
}

inline Vec3 projected(const Vec3& x, const Vec3& n) { return x - n * dot(x, n); }

inline double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  const double ee = dot(e, e);
  const double t = ee > 0 ? std::clamp(dot(p - a, e) / ee, 0.0, 1.0) : 0.0;
  return norm(p - (a + e * t));
}

inline Error invalid(const std::string& message) { return Error{ErrorCode::InvalidArgument, message}; }

/// The walk in 2D: the state is a face, a point and a unit direction in the face's flat frame
/// (flat_faces.hpp). Crossing an edge moves both into the next face's frame through the corners the two
/// faces share, so a step reads one record (the face entered) and no 3D data; 3D points are made only for
/// the polyline, the miss distance and the end. Records come from `table` when there is one (a
/// GeodesicShooter), else they are computed from the mesh per face (one shot).
class Walk {
 public:
  Walk(const TriMesh& mesh, const FlatFace* table, GeodesicShot& shot, const ShootOptions& options,
       const Progress& progress)
      : mesh_(mesh),
        table_(table),
        shot_(shot),
        progress_(progress),
        report_(progress_, "shoot"),
        keep_(options.keepPoints) {
    const double perEdge = std::min(shot.requestedLength / mesh.meanEdgeLength(), 1e15);
    maxSteps_ = options.maxSteps > 0
                    ? options.maxSteps
                    : 16 * (static_cast<int64_t>(mesh.numFaces()) + static_cast<int64_t>(perEdge)) + 1024;
    vertexTolerance_ = kOnPlaneRel * mesh.meanEdgeLength();
  }

  /// Maps the tangent vector `tangent` (in the plane of normal n) into a face around the source and walks.
  Expected<void> run(const Vec3& tangent, const Vec3& n) {
    const SurfacePoint& s = shot_.source;
    // The source and the end only, without polylines (one allocation each, not two).
    shot_.points.reserve(keep_ ? 256 : 2);
    shot_.positions.reserve(keep_ ? 256 : 2);
    shot_.points.push_back(s);
    shot_.positions.push_back(position(mesh_, s));
    last_ = shot_.positions.back();
    lastPoint_ = s;
    trackMiss_ = isFinite(shot_.target);
    need3d_ = keep_ || trackMiss_;
    if (trackMiss_) shot_.missDistance = norm(shot_.target - last_);
    if (s.kind == SurfacePoint::Kind::Face) {
      const int32_t f = s.index;
      const Vec3 nf = mesh_.faceNormal(f);
      const Vec3 d = projected(tangent, nf);
      if (!(norm(d) > 1e-12 * norm(tangent))) return invalid("the direction is perpendicular to the source's face");
      shot_.direction = normalized(d);
      enter(f, -1);
      p_ = flat_->at(1) * s.bary[1] + flat_->at(2) * s.bary[2];
      // The direction in the face's frame (x along halfedge 3f, y = n × x).
      const Vec3& a = mesh_.position(mesh_.tail(3 * f));
      const Vec3 x = normalized(mesh_.position(mesh_.head(3 * f)) - a);
      d_ = mesh_.isDegenerateFace(f) ? Vec2{1, 0} : unit(Vec2{dot(d, x), dot(d, cross(nf, x))});
      return walk();
    }
    if (s.kind == SurfacePoint::Kind::Edge) {
      const int32_t h = s.index;
      const Vec3 u = normalized(mesh_.position(mesh_.head(h)) - mesh_.position(mesh_.tail(h)));
      const Vec3 m = cross(n, u);
      const double x = dot(tangent, u), y = dot(tangent, m);
      if (std::fabs(y) <= 1e-12 * norm(tangent)) {  // along the edge, to one of its ends
        const bool toHead = x > 0;
        const int32_t to = toHead ? mesh_.head(h) : mesh_.tail(h);
        shot_.direction = normalized(mesh_.position(to) - last_);
        const int k = h % 3, toCorner = toHead ? (k == 2 ? 0 : k + 1) : k;
        enter(TriMesh::face(h), -1);
        p_ = pointOnEdge(k, s.t);
        const Vec2 corner = flat_->at(toCorner);
        arriveAtVertex(to, unfolding::length(corner - p_));
        if (!passVertex(to, toCorner, p_ - corner)) return finish();
        return walk();
      }
      const int32_t t = y > 0 ? h : mesh_.twin(h);
      if (t < 0) return invalid("the direction points off the surface: the source is on a boundary edge");
      const double beta = y > 0 ? std::atan2(y, x) : std::atan2(-y, -x);
      const double c = std::cos(beta), sine = std::sin(beta);
      shot_.direction = directionInFace(mesh_, t, c, sine);
      enter(TriMesh::face(t), t % 3);
      p_ = pointOnEdge(t % 3, t == h ? s.t : 1 - s.t);
      d_ = turned(t % 3, c, sine);
      return walk();
    }
    auto started = startAtVertex(s.index, tangent, n);
    if (!started) return started.error();
    shot_.direction = directionInFace(mesh_, 3 * face_ + fromCorner_, leftCos_, leftSin_);
    return walk();
  }

 private:
  static Vec2 unit(const Vec2& v) { return v / unfolding::length(v); }

  /// Face f's record: in the table, or made now (it stays valid until the next call).
  const FlatFace* flatOf(int32_t f) {
    if (table_) return table_ + f;
    makeFlatFace(mesh_, f, made_);
    return &made_;
  }

  /// The walk is now in face f, entered across its edge `through` (−1: it starts inside).
  void enter(int32_t f, int through) {
    face_ = f;
    flat_ = flatOf(f);
    entered_ = through;
    fromCorner_ = -1;
  }

  static constexpr int kNext[3] = {1, 2, 0};
  static int nextCorner(int k) { return kNext[k]; }
  /// The point at t along edge k (corner k → corner k + 1) of the current face.
  Vec2 pointOnEdge(int k, double t) const {
    const Vec2 a = flat_->at(k);
    return a + (flat_->at(nextCorner(k)) - a) * t;
  }
  /// The unit direction at angle beta from edge k (counter-clockwise, toward the face), given by its
  /// cosine c and sine s.
  Vec2 turned(int k, double c, double s) const {
    const Vec2 u = unit(flat_->at(nextCorner(k)) - flat_->at(k));
    return Vec2{u.x * c - u.y * s, u.x * s + u.y * c};
  }

  /// At a vertex source: the face whose projected sector holds the tangent, at the same fraction of its
  /// corner angle; an interior vertex whose projection folds falls back to the angle scaled by θ/2π.
  Expected<void> startAtVertex(int32_t v, const Vec3& tangent, const Vec3& n) {
    const Vec3& pv = mesh_.position(v);
    const double tangent2 = dot(tangent, tangent);
    int32_t first = -1;
    for (int32_t h : mesh_.outgoingHalfedges(v)) {
      if (first < 0) first = h;
      const Vec3 p1 = projected(mesh_.position(mesh_.head(h)) - pv, n);
      // Sectors that certainly fail the test below are passed without its two arctangents (the same
      // choice, sooner): a = signedAngle(p1, tangent, n) = atan2(y, x) is below 0 wherever y < 0 and y / x
      // does not underflow; and where a ≥ 0 and sector > 0, both are in [0, π], so a − sector is the angle
      // from p2 to the tangent, whose sine (yy, scaled) clearly above 0 puts a above sector by far more
      // than the arctangents' rounding.
      const double y = dot(cross(p1, tangent), n), x = dot(p1, tangent);
      if (y < 0 && !(-y < std::fabs(x) * 0x1p-800)) continue;
      const Vec3 p2 = projected(mesh_.position(mesh_.tail(TriMesh::prev(h))) - pv, n);
      const double yy = dot(cross(p2, tangent), n);
      if (yy > 0 && yy * yy > 1e-18 * dot(p2, p2) * tangent2) continue;
      const double sector = signedAngle(p1, p2, n), a = std::atan2(y, x);
      if (sector > 0 && a >= 0 && a <= sector) {
        leaveVertex(h, cornerAngle(mesh_, h) * a / sector);
        return {};
      }
    }
    if (first < 0) return invalid("the source vertex is not used by any face");
    if (mesh_.isBoundaryVertex(v)) return invalid("the direction points off the surface at the boundary source vertex");
    double a = signedAngle(projected(mesh_.position(mesh_.head(first)) - pv, n), tangent, n);
    if (a < 0) a += kTwoPi;
    double total = 0;
    for (int32_t h : mesh_.outgoingHalfedges(v)) total += cornerAngle(mesh_, h);
    turnAround(first, a * total / kTwoPi);
    return {};
  }

  /// Leaves tail(h) into face(h) at angle beta from h: the walk then looks only at the opposite edge.
  void leaveVertex(int32_t h, double beta) {
    const int k = h % 3;
    enter(TriMesh::face(h), -1);
    fromCorner_ = k;
    p_ = flat_->at(k);
    leftCos_ = std::cos(beta);
    leftSin_ = std::sin(beta);
    d_ = turned(k, leftCos_, leftSin_);
  }

  /// Leaves tail(h) at the angle `angle` counter-clockwise from halfedge h (reduced modulo the fan).
  void turnAround(int32_t h, double angle) {
    for (int guard = 0; guard < 1 << 20; ++guard) {
      const double c = cornerAngle(mesh_, h);
      if (angle <= c) break;
      const int32_t next = mesh_.nextOutgoing(h);
      if (next < 0) {
        angle = c;  // rounding past a boundary fan's last edge: leave along it
        break;
      }
      angle -= c;
      h = next;
    }
    leaveVertex(h, std::max(angle, 0.0));
  }

  /// The walk's next point, `segment` from the previous one: its length and the closest approach to a
  /// target counted, the point kept when the polyline is (keepPoints). `x` makes its 3D position, which
  /// is needed only then (and at the end: see finish).
  template <class Position>
  void record(const SurfacePoint& sp, double segment, const Position& x) {
    shot_.length += segment;
    ++shot_.facesCrossed;
    lastPoint_ = sp;
    lastEdge_ = -1;
    have3d_ = need3d_;
    if (need3d_) record3d(sp, x());
  }

  /// The 3D side of record: the miss distance, the polyline.
  void record3d(const SurfacePoint& sp, const Vec3& q) {
    if (trackMiss_) shot_.missDistance = std::min(shot_.missDistance, segmentDistance(shot_.target, last_, q));
    if (keep_) {
      shot_.points.push_back(sp);
      shot_.positions.push_back(q);
    }
    last_ = q;
  }

  /// The point at t on halfedge h (its twin `twin`), once counted: its surface point is made at the end
  /// only, unless 3D points are needed as the walk goes.
  void crossEdge(int32_t h, int32_t twin, double t) {
    if (need3d_) {
      lastPoint_ = edgePoint(h, twin, t);
      lastEdge_ = -1;
      record3d(lastPoint_, edgePosition(h, t));
      return;
    }
    lastEdge_ = h;
    lastTwin_ = twin;
    lastT_ = t;
    have3d_ = false;
  }

  Vec3 edgePosition(int32_t h, double t) const {
    return mesh_.position(mesh_.tail(h)) * (1 - t) + mesh_.position(mesh_.head(h)) * t;
  }

  /// The canonical edge point (the smaller halfedge; t is away from the ends, which are vertex passings).
  static SurfacePoint edgePoint(int32_t h, int32_t twin, double t) {
    return twin >= 0 && twin < h ? SurfacePoint::edge(twin, 1 - t) : SurfacePoint::edge(h, t);
  }

  void arriveAtVertex(int32_t v, double segment) {
    record(SurfacePoint::vertex(v), segment, [&] { return mesh_.position(v); });
  }

  /// The vertex rule: half of θ(v) on each side. v is corner k of the current face; `back` points from v
  /// to the previous point (in the face's frame). False when the walk stops here (a boundary vertex).
  bool passVertex(int32_t v, int k, Vec2 back) {
    ++shot_.vertexPassings;
    if (mesh_.isBoundaryVertex(v)) {
      shot_.status = ShootStatus::HitBoundary;
      return false;
    }
    const int32_t hv = 3 * face_ + k;
    if (!(dot(back, back) > 0)) back = -d_;
    const Vec2 u = flat_->at(nextCorner(k)) - flat_->at(k);
    const double alpha = std::clamp(std::atan2(cross(u, back), dot(u, back)), 0.0, cornerAngle(mesh_, hv));
    double total = 0;
    for (int32_t h : mesh_.outgoingHalfedges(v)) total += cornerAngle(mesh_, h);
    turnAround(hv, alpha + total / 2);
    return true;
  }

  Expected<void> finish() {
    if (!have3d_) {  // the same 3D point as a walk that made them all
      last_ = lastEdge_ >= 0 ? edgePosition(lastEdge_, lastT_) : position(mesh_, lastPoint_);
      if (lastEdge_ >= 0) lastPoint_ = edgePoint(lastEdge_, lastTwin_, lastT_);
    }
    shot_.end = lastPoint_;
    shot_.endPosition = last_;
    if (!keep_ && shot_.points.size() == 1 && shot_.facesCrossed > 0) {
      shot_.points.push_back(shot_.end);
      shot_.positions.push_back(shot_.endPosition);
    }
    return {};
  }

  Expected<void> walk() { return table_ ? walkWith<true>() : walkWith<false>(); }

  /// The walk, specialized on whether records come from a table (kTable) or are made per face.
  template <bool kTable>
  Expected<void> walkWith() {
    const double requested = shot_.requestedLength, tolerance2 = vertexTolerance_ * vertexTolerance_;
    const FlatFace* const table = table_;
    // The state lives in locals (registers) while the walk crosses edges; the members are written back
    // around the rare events that read and change them (a vertex, the end, a 3D point).
    int32_t face;
    const FlatFace* flat;
    int entered, fromCorner;
    // The point and the direction as four doubles, not two Vec2: carried across steps as structs, GCC
    // keeps them in general registers and moves them through the stack every step (measured: the round
    // trip sat on the step's critical path).
    double px, py, dx, dy;
    double length;
    int64_t faces;
    // The current face's corners in the order of its entered edge r: b → a is that edge, o the corner
    // opposite it, j1 (a → o) and j2 (o → b) the edges out (valid while entered ≥ 0). Set by one switch
    // when the walk enters a face, so that the step picks nothing by index.
    Vec2 a, b, o;
    int j1 = 0, j2 = 0;
    auto turn = [&] {
      const Vec2 c0{0.0, 0.0}, c1{flat->length, 0.0}, c2 = flat->corner;  // flat->at(k), the same bits
      switch (entered) {
        case 0: b = c0, a = c1, o = c2, j1 = 1, j2 = 2; break;
        case 1: b = c1, a = c2, o = c0, j1 = 2, j2 = 0; break;
        default: b = c2, a = c0, o = c1, j1 = 0, j2 = 1; break;
      }
    };
    // The last edge crossed since load(), kept here and written to the members by store() (without 3D
    // points, crossEdge would store them every step).
    int32_t lastH = -1, lastTwin = -1;
    double lastT = 0;
    const bool need3d = need3d_;
    auto store = [&] {
      face_ = face;
      flat_ = flat;
      entered_ = entered;
      fromCorner_ = fromCorner;
      p_ = Vec2{px, py};
      d_ = Vec2{dx, dy};
      shot_.length = length;
      shot_.facesCrossed = faces;
      if (lastH >= 0) {
        lastEdge_ = lastH;
        lastTwin_ = lastTwin;
        lastT_ = lastT;
        have3d_ = false;
        lastH = -1;
      }
    };
    auto load = [&] {
      face = face_;
      flat = flat_;
      entered = entered_;
      fromCorner = fromCorner_;
      px = p_.x;
      py = p_.y;
      dx = d_.x;
      dy = d_.y;
      length = shot_.length;
      faces = shot_.facesCrossed;
      if (entered >= 0) turn();
    };
    load();
    auto stop = [&](ShootStatus status) {
      store();
      shot_.status = status;
      return finish();
    };
    // One test a step for both the step bound and the progress report (every 65536 steps).
    const int64_t maxSteps = maxSteps_;
    int64_t checkAt = std::min<int64_t>(maxSteps, 65535);
    for (int64_t step = 0;; ++step) {
      if (step >= checkAt) {
        if (step >= maxSteps) return stop(ShootStatus::StepLimit);
        if (!report_(length / requested)) return cancelledError("geodesic shooting");
        checkAt = std::min(maxSteps, step + 65536);
      }
      const Vec2 p{px, py}, d{dx, dy};
      const double remaining = requested - length;
      if (remaining <= 0) return stop(ShootStatus::ReachedLength);  // a vertex passing ended within rounding
      int exit = -1, exitHead = -1;                                 // the edge left through, its head
      double exitS = kInf, exitT = 0;
      Vec2 from, edge;  // the exit edge's tail and extent, its squared length and that's inverse
      double edgeLength2 = -1, inverseLength2 = 0;
      bool picked = false;
      if (entered >= 0) {
        // Entered through edge b → a: the ray leaves through the edge on the side of the opposite corner o
        // it passes, j1 or j2. The side of o first, then the one edge it picks: the same operations on
        // the same values as working out both edges and picking one (the walk before), at half the
        // arithmetic. A branch, not a select: the next record's address depends on the side, and
        // predicted, its load need not wait for the arithmetic (as in the tracer: STRAIGHTEST_KEEP_BRANCH).
        const Vec2 ap2 = o - p;
        Vec2 tail, head, ap;
        int k, kHead;
        if (cross(ap2, d) < 0) {
          STRAIGHTEST_KEEP_BRANCH();
          tail = a, head = o, ap = a - p, k = j1, kHead = j2;
        } else {
          tail = o, head = b, ap = ap2, k = j2, kHead = entered;
        }
        // On a large mesh the walk waits for memory (faces all over it): start loading the records of the
        // two faces the walk may enter after the next one. (Loading all four a face earlier, before the
        // side is known, or all six, measured no faster, at ~10 more instructions a face.)
        if constexpr (kTable) {
          detail::prefetch(table + flat->beyond[2 * k]);
          detail::prefetch(table + flat->beyond[2 * k + 1]);
        }
        const Vec2 e = head - tail;
        const double den = cross(d, e), inverse = 1 / den;
        const double s = cross(ap, e) * inverse;
        if (den > 0 && s < kInf) {  // as exitOf would take it
          exit = k;
          exitHead = kHead;
          exitS = s;
          exitT = cross(ap, d) * inverse;
          from = tail;
          edge = e;
          edgeLength2 = dot(e, e);
          inverseLength2 = 1 / edgeLength2;
          picked = true;
        }
      }
      if (!picked) {
        if (entered >= 0) {  // rounding at the corner: let both edges compete
          exitOf(flat, p, d, j1, j2, exit, exitS, exitT);
        } else if (fromCorner >= 0) {  // only the edge opposite the corner left
          exitOf(flat, p, d, nextCorner(fromCorner), -1, exit, exitS, exitT);
        } else {
          exitOf(flat, p, d, 0, 1, exit, exitS, exitT);
          exitOf(flat, p, d, 2, -1, exit, exitS, exitT);
        }
        if (exit < 0) return stop(ShootStatus::NoExit);
        exitHead = nextCorner(exit);
        from = flat->at(exit);
        edge = flat->at(exitHead) - from;
        edgeLength2 = dot(edge, edge);
        inverseLength2 = 1 / edgeLength2;
      }
      exitS = std::max(exitS, 0.0);
      if (remaining <= exitS) {  // the length ends inside this face
        store();
        endInFace(p + d * remaining, remaining);
        return finish();
      }
      const double t = std::clamp(exitT, 0.0, 1.0);
      const int vertexCorner = t * t * edgeLength2 <= tolerance2               ? exit
                               : (1 - t) * (1 - t) * edgeLength2 <= tolerance2 ? exitHead
                                                                               : -1;
      if (vertexCorner >= 0) {
        const Vec2 at = flat->at(vertexCorner);
        const int32_t vertex = mesh_.tail(3 * face + vertexCorner);
        store();
        arriveAtVertex(vertex, unfolding::length(at - p));
        if (!passVertex(vertex, vertexCorner, p - at)) return finish();
        load();
        continue;
      }
      const int32_t h = 3 * face + exit, twin = flat->twins[exit];
      const double segment = unfolding::length(from + edge * t - p);
      length += segment;
      ++faces;
      if (need3d) {
        crossEdge(h, twin, t);
      } else {
        lastH = h;
        lastTwin = twin;
        lastT = t;
      }
      if (twin < 0) return stop(ShootStatus::HitBoundary);
      // Unfold: the twin runs from this edge's head to its tail, its face on the other side. The motion
      // into the next face's frame takes `edge` to −g (g: the twin, tail to head, in that frame) and this
      // edge's tail to the twin's head; d keeps its components along the edge and across it.
      const double along = dot(d, edge), across = cross(edge, d);
      face = static_cast<int32_t>(static_cast<uint32_t>(twin) / 3u);
      entered = twin - 3 * face;
      fromCorner = -1;
      if constexpr (kTable) {
        flat = table + face;
      } else {
        flat = flatOf(face);
      }
      turn();
      const Vec2 g = a - b;  // the twin: tail b, head a
      // d = (−g · along + perp(−g) · across) / |edge|², perp(x, y) = (−y, x).
      Vec2 nextD = Vec2{-g.x * along + g.y * across, -g.y * along - g.x * across} * inverseLength2;
      if ((step & 63) == 0) nextD = unit(nextD);
      const Vec2 nextP = a - g * t;
      px = nextP.x;
      py = nextP.y;
      dx = nextD.x;
      dy = nextD.y;
    }
  }

  /// The exit through edge k1 (and k2 ≥ 0) of the face, where the ray p + s d crosses from the face's side
  /// (den > 0) first: exit, exitS and exitT updated when one is before exitS.
  static void exitOf(const FlatFace* flat, const Vec2& p, const Vec2& d, int k1, int k2, int& exit, double& exitS,
                     double& exitT) {
    for (int k : {k1, k2}) {
      if (k < 0) continue;
      const Vec2 a = flat->at(k), e = flat->at(nextCorner(k)) - a;
      const double den = cross(d, e);
      if (!(den > 0)) continue;
      const Vec2 ap = a - p;
      const double inverse = 1 / den;
      const double s = cross(ap, e) * inverse;
      if (s < exitS) {
        exitS = s;
        exitT = cross(ap, d) * inverse;
        exit = k;
      }
    }
  }

  /// The walk's length ends at q (in the face's frame), `segment` from the previous point.
  void endInFace(const Vec2& q, double segment) {
    const int32_t f = face_;
    const Vec2 c = flat_->at(2);
    // Barycentric coordinates of q with respect to the face's corners.
    const double w2 = c.y > 0 ? q.y / c.y : 0;
    const double w1 = flat_->length > 0 ? (q.x - w2 * c.x) / flat_->length : 0;
    const double w[3] = {1 - w1 - w2, w1, w2};
    std::array<double, 3> bary{};
    double sum = 0;
    for (int j = 0; j < 3; ++j) sum += bary[j] = std::max(w[j], 0.0);
    for (double& b : bary) b /= sum;
    const Triangle& corners = mesh_.triangle(f);
    const Vec3& a = mesh_.position(corners[0]);
    const Vec3 x = a + (mesh_.position(corners[1]) - a) * w1 + (mesh_.position(corners[2]) - a) * w2;
    record(canonical(mesh_, SurfacePoint::face(f, bary), kExactSnap), segment, [&] { return x; });
    last_ = x;
    have3d_ = true;
    shot_.length = shot_.requestedLength;  // the sum of the segments, but the last one is exactly what remained
    shot_.status = ShootStatus::ReachedLength;
  }

  const TriMesh& mesh_;
  const FlatFace* table_;
  GeodesicShot& shot_;
  const Progress& progress_;
  ThrottledProgress report_;
  int64_t maxSteps_ = 0;
  double vertexTolerance_ = 0;
  bool keep_ = true, trackMiss_ = false, need3d_ = false, have3d_ = true;
  // The face and its record; entered across its edge entered_, or leaving its corner fromCorner_ (then
  // only the opposite edge is an exit), or neither (−1, −1: a start inside the face or on an edge).
  int32_t face_ = -1;
  const FlatFace* flat_ = nullptr;
  FlatFace made_;  // the record of the current face, without a table
  int entered_ = -1, fromCorner_ = -1;
  Vec2 p_, d_;
  double leftCos_ = 1, leftSin_ = 0;  // the cosine and sine of the angle of the last leaveVertex
  Vec3 last_;                         // the last point recorded in 3D (the source, when none was made since)
  SurfacePoint lastPoint_;
  int32_t lastEdge_ = -1, lastTwin_ = -1;  // the last point, when it is an edge crossing not yet made a point
  double lastT_ = 0;
};

}  // namespace straightest::shooting
