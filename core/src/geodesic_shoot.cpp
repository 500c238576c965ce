// geodesic_shoot.cpp — the Polthier–Schmies walk (geodesic_shoot.hpp): the start (a tangent direction
// mapped into a face around the source), the straight walk across faces, and the vertex rule.
#include "straightest/geodesic_shoot.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "straightest/base_plane.hpp"
#include "straightest/enum_names.hpp"
#include "straightest/straightest_path.hpp"
#include "straightest/tolerances.hpp"

namespace straightest {

const char* shootStatusName(ShootStatus s) { return nameOf(kShootStatusNames, s); }

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double signedAngle(const Vec3& a, const Vec3& b, const Vec3& n) { return std::atan2(dot(cross(a, b), n), dot(a, b)); }

/// The angle of face(h) at tail(h).
double cornerAngle(const TriMesh& mesh, int32_t h) {
  const Vec3& v = mesh.position(mesh.tail(h));
  const Vec3 a = mesh.position(mesh.head(h)) - v, b = mesh.position(mesh.tail(TriMesh::prev(h))) - v;
  return std::atan2(norm(cross(a, b)), dot(a, b));
}

/// The unit direction in face(h) at angle beta from h (counter-clockwise, toward the face).
Vec3 directionInFace(const TriMesh& mesh, int32_t h, double beta) {
  const Vec3 u = normalized(mesh.position(mesh.head(h)) - mesh.position(mesh.tail(h)));
  return u * std::cos(beta) + cross(mesh.faceNormal(TriMesh::face(h)), u) * std::sin(beta);
}

Vec3 projected(const Vec3& x, const Vec3& n) { return x - n * dot(x, n); }

double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 e = b - a;
  const double ee = dot(e, e);
  const double t = ee > 0 ? std::clamp(dot(p - a, e) / ee, 0.0, 1.0) : 0.0;
  return norm(p - (a + e * t));
}

/// A hint to start loading two cache lines (a no-op where the compiler has no prefetch).
inline void prefetch(const void* a, const void* b) {
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(a);
  __builtin_prefetch(b);
#else
  (void)a;
  (void)b;
#endif
}

Error invalid(const std::string& message) { return Error{ErrorCode::InvalidArgument, message}; }

class Walk {
 public:
  Walk(const TriMesh& mesh, GeodesicShot& shot, const ShootOptions& options, const Progress& progress)
      : mesh_(mesh), shot_(shot), progress_(progress), report_(progress_, "shoot"), keep_(options.keepPoints) {
    const double perEdge = std::min(shot.requestedLength / mesh.meanEdgeLength(), 1e15);
    maxSteps_ = options.maxSteps > 0
                    ? options.maxSteps
                    : 16 * (static_cast<int64_t>(mesh.numFaces()) + static_cast<int64_t>(perEdge)) + 1024;
    vertexTolerance_ = kOnPlaneRel * mesh.meanEdgeLength();
  }

  /// Maps the tangent vector `tangent` (in the plane of normal n) into a face around the source and walks.
  Expected<bool> run(const Vec3& tangent, const Vec3& n) {
    const SurfacePoint& s = shot_.source;
    if (keep_) {
      shot_.points.reserve(256);
      shot_.positions.reserve(256);
    }
    shot_.points.push_back(s);
    shot_.positions.push_back(position(mesh_, s));
    p_ = last_ = before_ = shot_.positions.back();
    lastPoint_ = s;
    trackMiss_ = isFinite(shot_.target);
    if (trackMiss_) shot_.missDistance = norm(shot_.target - p_);
    bool along = false;  // the start runs along an edge to vertex alongTo
    int32_t alongTo = -1, alongFace = -1;
    if (s.kind == SurfacePoint::Kind::Face) {
      face_ = s.index;
      const Vec3 nf = mesh_.faceNormal(face_);
      d_ = projected(tangent, nf);
      if (!(norm(d_) > 1e-12 * norm(tangent))) return invalid("the direction is perpendicular to the source's face");
      d_ = normalized(d_);
    } else if (s.kind == SurfacePoint::Kind::Edge) {
      const int32_t h = s.index;
      const Vec3 u = normalized(mesh_.position(mesh_.head(h)) - mesh_.position(mesh_.tail(h)));
      const Vec3 m = cross(n, u);
      const double x = dot(tangent, u), y = dot(tangent, m);
      if (std::fabs(y) <= 1e-12 * norm(tangent)) {
        along = true;
        alongTo = x > 0 ? mesh_.head(h) : mesh_.tail(h);
        alongFace = TriMesh::face(h);
      } else if (y > 0) {
        face_ = TriMesh::face(h);
        skip_ = h;
        d_ = directionInFace(mesh_, h, std::atan2(y, x));
      } else {
        const int32_t t = mesh_.twin(h);
        if (t < 0) return invalid("the direction points off the surface: the source is on a boundary edge");
        face_ = TriMesh::face(t);
        skip_ = t;
        d_ = directionInFace(mesh_, t, std::atan2(-y, -x));
      }
    } else {
      auto started = startAtVertex(s.index, tangent, n);
      if (!started) return started.error();
    }
    shot_.direction = along ? normalized(mesh_.position(alongTo) - p_) : d_;
    if (along) {
      d_ = shot_.direction;
      arriveAtVertex(alongTo);
      if (!passVertex(alongTo, alongFace)) return finish();
    }
    return walk();
  }

 private:
  /// At a vertex source: the face whose projected sector holds the tangent, at the same fraction of its
  /// corner angle; an interior vertex whose projection folds falls back to the angle scaled by θ/2π.
  Expected<bool> startAtVertex(int32_t v, const Vec3& tangent, const Vec3& n) {
    const Vec3& pv = mesh_.position(v);
    int32_t first = -1;
    for (int32_t h : mesh_.outgoingHalfedges(v)) {
      if (first < 0) first = h;
      const Vec3 p1 = projected(mesh_.position(mesh_.head(h)) - pv, n);
      const Vec3 p2 = projected(mesh_.position(mesh_.tail(TriMesh::prev(h))) - pv, n);
      const double sector = signedAngle(p1, p2, n), a = signedAngle(p1, tangent, n);
      if (sector > 0 && a >= 0 && a <= sector) {
        leaveVertex(v, h, cornerAngle(mesh_, h) * a / sector);
        return true;
      }
    }
    if (first < 0) return invalid("the source vertex is not used by any face");
    if (mesh_.isBoundaryVertex(v)) return invalid("the direction points off the surface at the boundary source vertex");
    double a = signedAngle(projected(mesh_.position(mesh_.head(first)) - pv, n), tangent, n);
    if (a < 0) a += kTwoPi;
    double total = 0;
    for (int32_t h : mesh_.outgoingHalfedges(v)) total += cornerAngle(mesh_, h);
    turnAround(v, first, a * total / kTwoPi);
    return true;
  }

  /// Leaves vertex v into face(h) at angle beta from h: the walk then looks only at the opposite edge.
  void leaveVertex(int32_t v, int32_t h, double beta) {
    face_ = TriMesh::face(h);
    d_ = directionInFace(mesh_, h, beta);
    p_ = mesh_.position(v);
    only_ = TriMesh::next(h);
    skip_ = -1;
  }

  /// Leaves v at the angle `angle` counter-clockwise from halfedge h (reduced modulo the fan).
  void turnAround(int32_t v, int32_t h, double angle) {
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
    leaveVertex(v, h, std::max(angle, 0.0));
  }

  /// The walk's next point: its segment's length and the closest approach to a target counted, the point
  /// kept when the polyline is (keepPoints).
  void record(const SurfacePoint& sp, const Vec3& x) {
    shot_.length += norm(x - last_);
    if (trackMiss_) shot_.missDistance = std::min(shot_.missDistance, segmentDistance(shot_.target, last_, x));
    if (keep_) {
      shot_.points.push_back(sp);
      shot_.positions.push_back(x);
    }
    ++shot_.facesCrossed;
    before_ = last_;
    last_ = p_ = x;
    lastPoint_ = sp;
  }

  void arriveAtVertex(int32_t v) { record(SurfacePoint::vertex(v), mesh_.position(v)); }

  /// The vertex rule: half of θ(v) on each side. The incoming segment (from the previous point) lies in
  /// face f. False when the walk stops here (a boundary vertex).
  bool passVertex(int32_t v, int32_t f) {
    ++shot_.vertexPassings;
    if (mesh_.isBoundaryVertex(v)) {
      shot_.status = ShootStatus::HitBoundary;
      return false;
    }
    int32_t hv = -1;
    for (int k = 0; k < 3; ++k)
      if (mesh_.tail(3 * f + k) == v) hv = 3 * f + k;
    const Vec3& pv = mesh_.position(v);
    Vec3 back = before_ - pv;
    if (!(norm(back) > 0)) back = -d_;
    const Vec3 u = mesh_.position(mesh_.head(hv)) - pv;
    const double alpha = std::clamp(signedAngle(u, back, mesh_.faceNormal(f)), 0.0, cornerAngle(mesh_, hv));
    double total = 0;
    for (int32_t h : mesh_.outgoingHalfedges(v)) total += cornerAngle(mesh_, h);
    turnAround(v, hv, alpha + total / 2);
    return true;
  }

  Expected<bool> finish() {
    shot_.end = lastPoint_;
    shot_.endPosition = last_;
    if (!keep_ && shot_.points.size() == 1 && shot_.facesCrossed > 0) {
      shot_.points.push_back(lastPoint_);
      shot_.positions.push_back(last_);
    }
    return true;
  }

  Expected<bool> walk() {
    const double requested = shot_.requestedLength;
    for (int64_t step = 0;; ++step) {
      if (step >= maxSteps_) {
        shot_.status = ShootStatus::StepLimit;
        return finish();
      }
      if ((step & 65535) == 65535 && !report_(shot_.length / requested)) return cancelledError("geodesic shooting");
      const double remaining = requested - shot_.length;
      if (remaining <= 0) {  // a vertex passing ended within rounding of the length
        shot_.status = ShootStatus::ReachedLength;
        return finish();
      }
      const Vec3 n = mesh_.faceNormal(face_);
      // Corners and twins of the face in one cache line (the walk visits faces all over the mesh).
      const FaceAdjacency& adjacency = mesh_.adjacency(face_);
      const int32_t first = 3 * face_;
      int32_t exit = -1;
      double exitS = kInf, exitT = 0;
      // Triple products [x, y, n] as x · (y × n): d × n once per face, e × n once per edge considered.
      const Vec3 dn = cross(d_, n);
      auto consider = [&](int32_t h) {
        const int32_t k = h - first;
        const Vec3 a = mesh_.position(adjacency.corners[k]);
        const Vec3 en = cross(mesh_.position(adjacency.corners[k == 2 ? 0 : k + 1]) - a, n);
        const double den = dot(d_, en);
        if (!(den > 0)) return;  // the ray does not leave through this edge
        const Vec3 ap = a - p_;
        const double inverse = 1 / den;
        const double s = dot(ap, en) * inverse;
        if (s < exitS) {
          exitS = s;
          exitT = dot(ap, dn) * inverse;
          exit = h;
        }
      };
      if (skip_ >= 0) {
        // Entered through skip_: the ray leaves through the edge on the side of the opposite corner it passes.
        const int32_t nextH = TriMesh::next(skip_), prevH = TriMesh::prev(skip_);
        // The walk is bound by memory latency (faces all over the mesh): start loading both faces it may
        // enter next while this one is worked out.
        for (int32_t beyond : {adjacency.twins[nextH - first], adjacency.twins[prevH - first]})
          if (beyond >= 0) prefetch(&mesh_.adjacency(TriMesh::face(beyond)), &mesh_.faceNormal(TriMesh::face(beyond)));
        const Vec3 c = mesh_.position(adjacency.corners[(skip_ - first + 2) % 3]);
        consider(dot(c - p_, dn) < 0 ? nextH : prevH);
        if (exit < 0) {  // rounding at the corner: let both edges compete
          consider(nextH);
          consider(prevH);
        }
      } else {
        for (int k = 0; k < 3; ++k) {
          const int32_t h = 3 * face_ + k;
          if (only_ < 0 || h == only_) consider(h);
        }
      }
      if (exit < 0) {
        shot_.status = ShootStatus::NoExit;
        return finish();
      }
      exitS = std::max(exitS, 0.0);
      if (remaining <= exitS) {  // the length ends inside this face
        const Vec3 q = p_ + d_ * remaining;
        record(canonical(mesh_, faceCoordinates(face_, q), kExactSnap), q);
        shot_.length = requested;  // the sum of the segments, but the last one is exactly what remained
        shot_.status = ShootStatus::ReachedLength;
        return finish();
      }
      const int32_t exitK = exit - first;
      const int32_t tail = adjacency.corners[exitK], head = adjacency.corners[exitK == 2 ? 0 : exitK + 1];
      const Vec3 edge = mesh_.position(head) - mesh_.position(tail);
      const double edgeLength2 = dot(edge, edge), tolerance2 = vertexTolerance_ * vertexTolerance_;
      const double t = std::clamp(exitT, 0.0, 1.0);
      const int32_t vertex = t * t * edgeLength2 <= tolerance2               ? tail
                             : (1 - t) * (1 - t) * edgeLength2 <= tolerance2 ? head
                                                                             : -1;
      if (vertex >= 0) {
        arriveAtVertex(vertex);
        if (!passVertex(vertex, face_)) return finish();
        continue;
      }
      const Vec3 x = mesh_.position(tail) * (1 - t) + mesh_.position(head) * t;
      const int32_t twin = adjacency.twins[exitK];
      // The canonical edge point (the smaller halfedge; t is away from the ends, which are vertex passings).
      record(twin >= 0 && twin < exit ? SurfacePoint::edge(twin, 1 - t) : SurfacePoint::edge(exit, t), x);
      if (twin < 0) {
        shot_.status = ShootStatus::HitBoundary;
        return finish();
      }
      // Unfold: keep the components along the edge and across it (into the next face).
      const int32_t next = TriMesh::face(twin);
      // (A rotation about the edge e: d = e (d·e)/|e|² + (n×e)(d·(n×e))/|e|² becomes the same with the next
      // face's normal; the length stays 1 up to rounding, renormalized now and then.)
      d_ = (edge * dot(d_, edge) + cross(mesh_.faceNormal(next), edge) * dot(d_, cross(n, edge))) / edgeLength2;
      if ((step & 63) == 0) d_ = normalized(d_);
      face_ = next;
      skip_ = twin;
      only_ = -1;
    }
  }

  SurfacePoint faceCoordinates(int32_t f, const Vec3& q) const {
    const Triangle& t = mesh_.triangle(f);
    const Vec3 a = mesh_.position(t[0]), b = mesh_.position(t[1]), c = mesh_.position(t[2]);
    const Vec3 n = cross(b - a, c - a);
    const double area = dot(n, n);
    const double wa = dot(cross(c - b, q - b), n) / area, wb = dot(cross(a - c, q - c), n) / area;
    const double ca = std::max(wa, 0.0), cb = std::max(wb, 0.0), cc = std::max(1 - wa - wb, 0.0);
    const double sum = ca + cb + cc;
    return SurfacePoint::face(f, {ca / sum, cb / sum, cc / sum});
  }

  const TriMesh& mesh_;
  GeodesicShot& shot_;
  const Progress& progress_;
  ThrottledProgress report_;
  int64_t maxSteps_ = 0;
  double vertexTolerance_ = 0;
  bool keep_ = true, trackMiss_ = false;
  int32_t face_ = -1, skip_ = -1, only_ = -1;
  Vec3 p_, d_;
  Vec3 last_, before_;  // the last point recorded, and the one before it (the segment into a vertex)
  SurfacePoint lastPoint_;
};

/// Validates the source and the length; the source snapped as the tracer snaps its own.
Expected<SurfacePoint> prepare(const TriMesh& mesh, const SurfacePoint& source, double length, bool needLength) {
  auto valid = validateSurfacePoint(mesh, source);
  if (!valid) return valid.error();
  if (needLength && !(length > 0 && std::isfinite(length)))
    return invalid("the length must be a positive finite number, got " + std::to_string(length));
  return canonical(mesh, valid.value(), kSnapSource);
}

Expected<GeodesicShot> shoot(const TriMesh& mesh, GeodesicShot shot, const Vec3& tangent, const Vec3& n,
                             const ShootOptions& options, const Progress& progress) {
  Walk walk(mesh, shot, options, progress);
  auto done = walk.run(tangent, n);
  if (!done) return done.error();
  return shot;
}

}  // namespace

Expected<TangentFrame> tangentFrame(const TriMesh& mesh, const SurfacePoint& source) {
  auto valid = validateSurfacePoint(mesh, source);
  if (!valid) return valid.error();
  const SurfacePoint s = canonical(mesh, valid.value(), kSnapSource);
  const Vec3 n = areaWeightedNormal(mesh, s);
  if (!(norm(n) > 0)) return Error{ErrorCode::Degenerate, "every face around the source is degenerate"};
  const int32_t h = s.kind == SurfacePoint::Kind::Vertex ? mesh.vertexHalfedge(s.index)
                    : s.kind == SurfacePoint::Kind::Edge ? s.index
                                                         : 3 * s.index;
  Vec3 axis = projected(mesh.position(mesh.head(h)) - mesh.position(mesh.tail(h)), n);
  if (!(norm(axis) > 0)) return Error{ErrorCode::Degenerate, "the source's reference edge is along its normal"};
  axis = normalized(axis);
  return TangentFrame{n, axis, cross(n, axis)};
}

Expected<GeodesicShot> shootGeodesic(const TriMesh& mesh, const SurfacePoint& source, const Vec3& direction,
                                     double length, const ShootOptions& options, const Progress& progress) {
  return guarded([&]() -> Expected<GeodesicShot> {
    if (!isFinite(direction)) return invalid("the direction is not finite");
    if (!(norm(direction) > 0)) return invalid("the direction has zero length");
    auto s = prepare(mesh, source, length, true);
    if (!s) return s.error();
    Vec3 n;
    if (options.tangentNormal && norm(*options.tangentNormal) > 0 && isFinite(*options.tangentNormal)) {
      n = normalized(*options.tangentNormal);
    } else {
      auto frame = tangentFrame(mesh, s.value());
      if (!frame) return frame.error();
      n = frame.value().normal;
    }
    const Vec3 tangent = projected(direction, n);
    if (!(norm(tangent) > 1e-12 * norm(direction)))
      return invalid("the direction is along the surface normal at the source (no tangent component)");
    GeodesicShot shot;
    shot.source = s.value();
    shot.normal = n;
    shot.requestedLength = length;
    return shoot(mesh, std::move(shot), normalized(tangent), n, options, progress);
  });
}

Expected<GeodesicShot> shootGeodesicAtAngle(const TriMesh& mesh, const SurfacePoint& source, double angle,
                                            double length, const ShootOptions& options, const Progress& progress) {
  if (!std::isfinite(angle)) return invalid("the angle is not finite");
  auto frame = tangentFrame(mesh, source);
  if (!frame) return frame.error();
  const TangentFrame& f = frame.value();
  return shootGeodesic(mesh, source, f.axis0 * std::cos(angle) + f.axis90 * std::sin(angle), length, options, progress);
}

Expected<GeodesicShot> shootGeodesicToward(const TriMesh& mesh, const SurfacePoint& source,
                                           const SurfacePoint& destination, std::optional<double> length,
                                           const ShootOptions& options, const Progress& progress) {
  return guarded([&]() -> Expected<GeodesicShot> {
    auto s = prepare(mesh, source, length.value_or(1.0), true);
    if (!s) return s.error();
    auto d = validateSurfacePoint(mesh, destination);
    if (!d) return Error{d.error().code, "destination: " + d.error().message};
    const Vec3 target = position(mesh, d.value());
    const BasePlane base = basePlane(mesh, s.value());
    const std::optional<Vec3> tangent = inPlaneDirection(base, target);
    if (!tangent) return invalid("the destination is the source, or straight along the base normal from it");
    StraightestPathTracer tracer(mesh, s.value(), TraceOptions{false});
    const StraightestPath& path = tracer.trace(d.value());
    const double straightest = path.status == TraceStatus::Reached ? path.length : kInf;
    if (!length && straightest == kInf)
      return invalid(std::string("the cutting plane does not reach the destination (") + traceStatusName(path.status) +
                     "): give the length to shoot");
    GeodesicShot shot;
    shot.source = s.value();
    shot.normal = base.normal;
    shot.requestedLength = length ? *length : straightest;
    shot.target = target;
    if (straightest < kInf) shot.straightestDistance = straightest;
    auto result = shoot(mesh, std::move(shot), *tangent, base.normal, options, progress);
    return result;  // the walk measured missDistance as it went
  });
}

}  // namespace straightest
