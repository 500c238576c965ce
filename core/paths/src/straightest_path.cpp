// The cutting-plane walk (see straightest_path.hpp for the contract).
//
// Robustness rests on one rule: every vertex gets one signed distance to the cutting plane, snapped to
// exactly 0 when |d| <= kOnPlaneRel · mean edge length, and all decisions use those values. An edge
// is crossed only where its endpoints have strictly opposite signs, so two faces sharing an edge
// always agree on whether and where it is crossed, and a walk can never slip between faces.
#include "straightest/paths/straightest_path.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>

#include "straightest/base/cache_hints.hpp"

namespace straightest {

namespace {

/// Where the walk goes next: a vertex on the plane, or the crossing of a halfedge.
struct Exit {
  bool valid = false;
  bool isVertex = false;
  int32_t vertex = -1;
  int32_t halfedge = -1;  // crossed halfedge (in `face`) when !isVertex
  double t = 0;           // crossing parameter on halfedge
  Vec3 position;
  int32_t face = -1;            // face holding the segment to the exit
  int32_t face2 = -1;           // second face when the segment runs along an edge
  double dTail = 0, dHead = 0;  // signed distances of the crossed halfedge's ends (reused next step)
};

// The per-step helpers of the walk must be inlined into its loop (GCC left segment() out of line, which
// cost the walk a call per step).
#if defined(__GNUC__) || defined(__clang__)
#define STRAIGHTEST_INLINE __attribute__((always_inline)) inline
#else
#define STRAIGHTEST_INLINE inline
#endif

/// Starts loading the record of the face of halfedge k (any k, −1 included). Byte 8k lies in that
/// record (24 bytes from byte 24 (k / 3): corner 0, corner 2 or twin 1), so no division is needed.
inline void prefetchRecordOf(const FaceAdjacency* adjacency, int32_t k) {
  static_assert(sizeof(FaceAdjacency) == 24, "3 corners and 3 twins");
#if defined(__wasm__)
  // WebAssembly has no prefetch: a load whose value an empty asm statement takes (so that it stays)
  // starts the same transfer without waiting for it. Unlike a prefetch it must stay in bounds: k ≥ 0.
  const int32_t value = reinterpret_cast<const int32_t*>(adjacency)[2 * std::max(k, 0)];
  __asm__ volatile("" ::"r"(value));
#else
  detail::prefetch(
      reinterpret_cast<const char*>(reinterpret_cast<uintptr_t>(adjacency) + 8 * static_cast<intptr_t>(k)));
#endif
}

}  // namespace

/// The tracer's state: what is set up once around the source, and the buffers every walk reuses.
struct StraightestPathTracer::Impl {
  Impl(const TriMesh& mesh, const SurfacePoint& source, const TraceOptions& options);
  const StraightestPath& trace(const SurfacePoint& destination);

  struct Walk;
  void walk(const SurfacePoint& destination, const Vec3& direction, bool forwardSide, StraightestPath& out);
  double signedDistance(int32_t v) const;
  void keepAsOtherArc(const StraightestPath& other);  // result_'s other arc: `other`, which also reached D

  /// A few faces (those around a point), tested per step without touching per-face memory: most
  /// faces fail the index-range check; the rest are compared one by one (or by binary search).
  struct FaceSet {
    std::vector<int32_t> faces;  // sorted
    int32_t lo = 0, hi = -1;
    void assign(const std::vector<int32_t>& f);
    bool contains(int32_t f) const {
      if (f < lo || f > hi) return false;
      if (faces.size() > 16) return std::binary_search(faces.begin(), faces.end(), f);
      for (int32_t x : faces)
        if (x == f) return true;
      return false;
    }
  };

  const TriMesh& mesh_;
  SurfacePoint source_;
  Vec3 sourcePosition_;
  TraceOptions options_;
  BasePlane base_;
  double onPlaneTolerance_ = 0;
  double meanEdge_ = 1;
  int64_t maxSteps_ = 0;
  bool closed_ = false;  // no boundary loop: both directions are walked and the shorter arc returned
  std::vector<int32_t> sourceFaces_;
  std::vector<int32_t> targetFaces_;
  FaceSet sourceSet_, targetSet_;
  bool isSourceFace(int32_t f) const { return sourceSet_.contains(f); }
  bool isTargetFace(int32_t f) const { return targetSet_.contains(f); }
  std::vector<int32_t> fan_;           // scratch: faces around the current vertex
  std::vector<uint32_t> vertexStamp_;  // == epoch_ for vertices passed in the current walk
  uint32_t epoch_ = 0;
  CuttingPlane plane_{};
  StraightestPath result_, second_;
};

struct StraightestPathTracer::Impl::Walk {
  Impl& tr;
  const TriMesh& mesh;
  const SurfacePoint& dest;
  Vec3 D;
  StraightestPath& out;
  double meanEdge;

  void emit(const SurfacePoint& p, const Vec3& x) {
    if (!tr.options_.keepPoints) return;
    out.points.push_back(p);
    out.positions.push_back(x);
  }

  /// X lies on segment PQ, within tol = kOnSegmentRel · mean edge length along and across it (absolute,
  /// so a very short last segment still finds a target that rounding put just past its end).
  bool onSegment(const Vec3& X, const Vec3& P, const Vec3& Q) const {
    const Vec3 v = Q - P;
    const double length = norm(v);
    const double tol = kOnSegmentRel * meanEdge;
    if (!(length > 0)) return norm(X - P) <= tol;
    const double along = dot(X - P, v) / length;
    if (along < -tol || along > length + tol) return false;
    return norm(X - (P + v * (along / length))) <= tol;
  }

  /// Accounts for the segment P→Q in face f1 (and f2 along an edge). Returns true when the walk ends
  /// inside it: at D (reached) or back at S (D is on another component of the section).
  STRAIGHTEST_INLINE bool segment(const Vec3& P, const Vec3& Q, int32_t f1, int32_t f2, bool first) {
    ++out.facesCrossed;
    if ((tr.isTargetFace(f1) || tr.isTargetFace(f2)) && onSegment(D, P, Q)) {
      out.length += norm(D - P);
      emit(dest, D);
      out.status = TraceStatus::Reached;
      return true;
    }
    if (!first && (tr.isSourceFace(f1) || tr.isSourceFace(f2)) && onSegment(tr.sourcePosition_, P, Q)) {
      out.length += norm(tr.sourcePosition_ - P);
      emit(tr.source_, tr.sourcePosition_);
      out.status = TraceStatus::OtherComponent;
      return true;
    }
    out.length += norm(Q - P);
    return false;
  }

  /// The walk reached vertex v at Q. A destination (edge or face point) lying next to v — within the
  /// on-segment tolerance, in a face of v — is reached by one last tiny segment Q → D. Needed because
  /// the plane through such a D puts v on the plane (|d_v| <= |D − v|), so the walk passes through v
  /// exactly and may continue through two faces of v that do not hold D (a fuzzing finding: D at
  /// t = 8e-11 on an edge of v was missed).
  bool endsNextToVertex(int32_t v, const Vec3& Q) {
    if (dest.kind == SurfacePoint::Kind::Vertex || !(norm(D - Q) <= kOnSegmentRel * meanEdge)) return false;
    bool adjacent = false;
    for (int32_t f : tr.targetFaces_) {
      const Triangle& t = mesh.triangle(f);
      adjacent |= t[0] == v || t[1] == v || t[2] == v;
    }
    if (!adjacent) return false;
    ++out.facesCrossed;
    out.length += norm(D - Q);
    emit(dest, D);
    out.status = TraceStatus::Reached;
    return true;
  }

  Exit crossing(int32_t h, int32_t face) const {
    const int32_t a = mesh.tail(h), b = mesh.head(h);
    return crossing(h, face, a, b, tr.signedDistance(a), tr.signedDistance(b));
  }

  /// The crossing of halfedge h (from vertex a to vertex b) whose endpoints have the (snapped,
  /// strictly opposite) signed distances da and db.
  Exit crossing(int32_t h, int32_t face, int32_t a, int32_t b, double da, double db) const {
    Exit e;
    e.valid = true;
    e.halfedge = h;
    e.dTail = da;
    e.dHead = db;
    e.t = da / (da - db);
    e.position = mesh.position(a) * (1 - e.t) + mesh.position(b) * e.t;
    e.face = face;
    return e;
  }

  /// The exit from point P (at vertex atVertex, or -1) through the given faces, best aligned with
  /// dir (unit) and with cosine > minCos; faces ex1/ex2 are skipped (the way we came). A P inside an
  /// edge passes halfedge onEdge (else -1): the plane crosses that edge at P itself, so its crossing is
  /// no exit. (Computed, it lands up to ~1e-6 away from P when the plane is within ~1e-7 rad of the
  /// edge, far enough to pass for a step and send the walk back through the edge to S: a fuzzing
  /// finding.)
  Exit bestExit(const Vec3& P, int32_t atVertex, int32_t onEdge, const std::vector<int32_t>& faces, int32_t ex1,
                int32_t ex2, const Vec3& dir, double minCos) const {
    const int32_t onTwin = onEdge >= 0 ? mesh.twin(onEdge) : -1;
    Exit best;
    double bestCos = minCos;
    auto consider = [&](Exit e) {
      const Vec3 v = e.position - P;
      const double len = norm(v);
      if (!(len > tr.onPlaneTolerance_)) return;
      const double c = dot(v, dir) / len;
      if (c > bestCos) {
        bestCos = c;
        best = e;
      }
    };
    for (int32_t f : faces) {
      if (f == ex1 || f == ex2) continue;
      const Triangle& tri = mesh.triangle(f);
      const double d[3] = {tr.signedDistance(tri[0]), tr.signedDistance(tri[1]), tr.signedDistance(tri[2])};
      for (int k = 0; k < 3; ++k) {
        if (d[k] == 0 && tri[k] != atVertex) {
          Exit e;
          e.valid = true;
          e.isVertex = true;
          e.vertex = tri[k];
          e.position = mesh.position(tri[k]);
          e.face = f;
          if (atVertex >= 0) {  // the segment runs along edge (atVertex, tri[k]): note its other face
            for (int j = 0; j < 3; ++j) {
              const int32_t h = 3 * f + j;
              const bool alongEdge = (mesh.tail(h) == atVertex && mesh.head(h) == tri[k]) ||
                                     (mesh.head(h) == atVertex && mesh.tail(h) == tri[k]);
              if (alongEdge && mesh.twin(h) >= 0) e.face2 = TriMesh::face(mesh.twin(h));
            }
          }
          consider(e);
        }
        const int k1 = (k + 1) % 3;
        const int32_t h = 3 * f + k;
        if (h == onEdge || h == onTwin) continue;
        if ((d[k] < 0 && d[k1] > 0) || (d[k] > 0 && d[k1] < 0)) consider(crossing(h, f));
      }
    }
    return best;
  }

  void run(const Vec3& startDir) {
    emit(tr.source_, tr.sourcePosition_);
    Vec3 P = tr.sourcePosition_;
    const int32_t sourceVertex = tr.source_.kind == SurfacePoint::Kind::Vertex ? tr.source_.index : -1;
    // Leave S on D's side (strictly positive cosine with the direction).
    const int32_t sourceEdge = tr.source_.kind == SurfacePoint::Kind::Edge ? tr.source_.index : -1;
    Exit e = bestExit(P, sourceVertex, sourceEdge, tr.sourceFaces_, -1, -1, startDir, 0.0);
    if (!e.valid) {
      out.status = sourceOnBoundary() ? TraceStatus::HitBoundary : TraceStatus::NoExit;
      return;
    }
    bool first = true;
    int32_t pieceStart = -1;  // first halfedge crossed since S or the last vertex passing
    for (int64_t step = 0;;) {
      if (step > tr.maxSteps_) {
        out.status = TraceStatus::StepLimit;
        return;
      }
      if (e.isVertex) {
        const Vec3 Q = e.position;
        if (segment(P, Q, e.face, e.face2, first)) return;
        first = false;
        emit(SurfacePoint::vertex(e.vertex), Q);
        if (step < tr.maxSteps_ && endsNextToVertex(e.vertex, Q)) return;
        if (tr.vertexStamp_.empty()) tr.vertexStamp_.assign(mesh.numVertices(), 0);
        if (tr.vertexStamp_[e.vertex] == tr.epoch_) {
          out.status = TraceStatus::Loop;
          return;
        }
        tr.vertexStamp_[e.vertex] = tr.epoch_;
        pieceStart = -1;  // a new 1-manifold piece of the section starts here
        const Vec3 dirIn = normalized(Q - P);
        P = Q;
        incidentFaces(mesh, SurfacePoint::vertex(e.vertex), tr.fan_);
        const int32_t v = e.vertex;
        e = bestExit(P, v, -1, tr.fan_, e.face, e.face2, dirIn, -std::numeric_limits<double>::infinity());
        if (!e.valid) {
          out.status = mesh.isBoundaryVertex(v) ? TraceStatus::HitBoundary : TraceStatus::NoExit;
          return;
        }
        ++step;
        continue;
      }
      if (crossEdges(e, P, first, pieceStart, step)) return;
    }
  }

  /// Walks from P through the crossing e and the edge crossings after it, until the walk ends (returns
  /// true) or the section meets a vertex (e becomes that vertex exit; returns false). This is where the
  /// walk spends its time, so it runs in two passes over blocks of up to 64 steps, with its state in
  /// locals. The first pass follows the section from face to face: per face, the twin halfedge to
  /// follow (kept from the face before, not looked up again), one record, one new vertex and its signed
  /// distance: a short chain of dependent loads, whose branch the processor predicts well. The second
  /// computes the block's crossing points and adds the segments' lengths, in order and with the same
  /// arithmetic as crossing() and segment() (so the same bits); its steps do not depend on each other
  /// (but for the sum), so the processor overlaps their divisions and square roots, which in one pass
  /// stood in every step's chain. Faces of S and D, where a segment must be tested against the end
  /// points, are walked one at a time. (The choice of exit keeps its branch, which the processor predicts
  /// well: see STRAIGHTEST_KEEP_BRANCH. Figures in docs/BENCHMARKS.md.) The face step enters face g through
  /// k = 3g + j (u → w, signs strictly opposite: k runs opposite to the crossed halfedge, so u is its head) and
  /// leaves through the vertex o on the plane, or through next(k) (w → o) or prev(k) (o → u), whichever has
  /// opposite signs: only o is new. It starts loading the records of g's two other neighbours, one of which
  /// it enters next, so that memory latency overlaps the work on g. Between vertex passings every crossed edge
  /// has one way in and one way out, so a cycle first comes back to the piece's first crossing (in either
  /// direction): the walk stops there. The step stays in this loop: made a
  /// function returning its next crossing, its exit became a select (about two thirds slower).
  STRAIGHTEST_INLINE bool crossEdges(Exit& e, Vec3& P, bool& first, int32_t& pieceStart, int64_t& step) {
    const FaceAdjacency* adjacency = mesh.adjacencyData();
    const Vec3* positions = mesh.positions().data();
    const Vec3 normal = tr.plane_.normal, origin = tr.plane_.origin;
    const double onPlane = tr.onPlaneTolerance_;
    const int64_t maxSteps = tr.maxSteps_;
    // The crossing the walk is at: halfedge h = a → b in face f, with the ends' signed distances.
    int32_t h = e.halfedge, f = e.face, a = mesh.tail(h), b = mesh.head(h);
    int32_t k = adjacency[f].twins[h - 3 * f];  // twin(h)
    double da = e.dTail, db = e.dHead;
    double length = out.length;
    int64_t crossed = out.facesCrossed;
    Crossing block[kBlock];
    int32_t vertex = -1, vertexFace = -1;  // End::Vertex: the vertex on the plane, in face vertexFace
    for (;;) {
      int m = 0;  // pass 1: the faces
      End end = End::None;
      for (;;) {
        if (tr.isTargetFace(f) || tr.isSourceFace(f)) {
          if (m > 0) {  // the segments before this one first
            end = End::Test;
            break;
          }
          const EndFaceStep stepped = segmentInEndFace(Crossing{h, a, b, da, db}, f, P, first);
          ++crossed;
          length += stepped.length;
          if (stepped.ends) return finish(*stepped.ends, length, crossed);
          first = false;
          P = stepped.to;
        } else {
          block[m++] = Crossing{h, a, b, da, db};
        }
        if (k < 0 || h == pieceStart || k == pieceStart) {
          end = k < 0 ? End::Boundary : End::Loop;
          break;
        }
        if (pieceStart < 0) pieceStart = h;
        const int32_t g = static_cast<int32_t>(static_cast<uint32_t>(k) / 3u), j = k - 3 * g, j1 = j == 2 ? 0 : j + 1,
                      j2 = j1 == 2 ? 0 : j1 + 1;
        const FaceAdjacency& face = adjacency[g];
        const int32_t u = face.corners[j], w = face.corners[j1], o = face.corners[j2];
        const int32_t kNext = face.twins[j1], kPrev = face.twins[j2];
        prefetchRecordOf(adjacency, kNext);
        prefetchRecordOf(adjacency, kPrev);
        const double du = db, dw = da;
        double dO = dot(normal, positions[o] - origin);  // signedDistance(o)
        if (std::abs(dO) <= onPlane) dO = 0.0;
        ++step;
        if (dO == 0 || step > maxSteps) {
          end = dO == 0 ? End::Vertex : End::StepLimit;
          vertex = o, vertexFace = g;
          break;
        }
        if ((dO > 0) != (du > 0)) {
          STRAIGHTEST_KEEP_BRANCH();
          h = 3 * g + j2, k = kPrev, a = o, b = u, da = dO, db = du;
        } else {
          h = 3 * g + j1, k = kNext, a = w, b = o, da = dw, db = dO;
        }
        f = g;
        if (m == kBlock) break;
      }
      length = walkBlock(block, m, P, length);
      crossed += m;
      if (m > 0) first = false;
      switch (end) {
        case End::None:
        case End::Test: continue;
        case End::Boundary: return finish(TraceStatus::HitBoundary, length, crossed);
        case End::Loop: return finish(TraceStatus::Loop, length, crossed);
        case End::StepLimit: return finish(TraceStatus::StepLimit, length, crossed);
        case End::Vertex:
          writeBack(length, crossed);
          e = vertexExit(vertex, vertexFace);
          return false;
      }
    }
  }

  // crossEdges' parts off its face-to-face loop: each takes and returns values, so that the loop's state
  // stays in registers (a reference to a local would keep it in memory).

  /// A crossing of crossEdges: halfedge h = a → b, its ends' signed distances.
  struct Crossing {
    int32_t h, a, b;
    double da, db;
  };
  /// The pieces of the section crossEdges collects before it computes their points (its pass 2).
  static constexpr int kBlock = 64;
  /// Why crossEdges' face-to-face pass stopped.
  enum class End { None, Test, Boundary, Loop, Vertex, StepLimit };

  /// The crossing point as crossing() computes it (the same bits), its parameter on the edge in t.
  Vec3 crossingPoint(const Crossing& c, double& t) const {
    t = c.da / (c.da - c.db);
    return mesh.position(c.a) * (1 - t) + mesh.position(c.b) * t;
  }

  /// Pass 2 of crossEdges: the block's crossing points from P, in order, with the same arithmetic as
  /// segment(); the length after them. P ends at the last point.
  double walkBlock(const Crossing* block, int m, Vec3& P, double length) {
    const bool keep = tr.options_.keepPoints;
    for (int i = 0; i < m; ++i) {
      double t;
      const Vec3 X = crossingPoint(block[i], t);
      length += norm(X - P);
      if (keep) emit(SurfacePoint::edge(block[i].h, t), X);
      P = X;
    }
    return length;
  }

  struct EndFaceStep {
    std::optional<TraceStatus> ends;  // the walk ends at D or at S (another component's way back)
    Vec3 to;                          // else: the crossing point it goes on from
    double length;                    // the segment's length either way
  };

  /// The segment from P across crossing c in face f, a face of S or D, tested as segment() tests it.
  EndFaceStep segmentInEndFace(const Crossing& c, int32_t f, const Vec3& P, bool first) {
    double t;
    const Vec3 X = crossingPoint(c, t);
    if (tr.isTargetFace(f) && onSegment(D, P, X)) {
      emit(dest, D);
      return {TraceStatus::Reached, D, norm(D - P)};
    }
    if (!first && tr.isSourceFace(f) && onSegment(tr.sourcePosition_, P, X)) {
      emit(tr.source_, tr.sourcePosition_);
      return {TraceStatus::OtherComponent, tr.sourcePosition_, norm(tr.sourcePosition_ - P)};
    }
    if (tr.options_.keepPoints) emit(SurfacePoint::edge(c.h, t), X);
    return {std::nullopt, X, norm(X - P)};
  }

  /// crossEdges' length and count of crossed faces, written back to the result.
  void writeBack(double length, int64_t crossed) {
    out.length = length;
    out.facesCrossed = crossed;
  }

  /// crossEdges' end: its length and count written back, the walk ended with `status`.
  bool finish(TraceStatus status, double length, int64_t crossed) {
    writeBack(length, crossed);
    out.status = status;
    return true;
  }

  /// The exit through a vertex of face f on the plane, where crossEdges hands the walk back to run().
  Exit vertexExit(int32_t vertex, int32_t f) const {
    Exit exit;
    exit.valid = true;
    exit.isVertex = true;
    exit.vertex = vertex;
    exit.position = mesh.position(vertex);
    exit.face = f;
    return exit;
  }

  bool sourceOnBoundary() const {
    switch (tr.source_.kind) {
      case SurfacePoint::Kind::Vertex: return mesh.isBoundaryVertex(tr.source_.index);
      case SurfacePoint::Kind::Edge: return mesh.twin(tr.source_.index) < 0;
      case SurfacePoint::Kind::Face: return false;
    }
    return false;
  }
};

StraightestPathTracer::StraightestPathTracer(const TriMesh& mesh, const SurfacePoint& source,
                                             const TraceOptions& options)
    : impl_(std::make_unique<Impl>(mesh, source, options)) {}
StraightestPathTracer::~StraightestPathTracer() = default;
StraightestPathTracer::StraightestPathTracer(StraightestPathTracer&&) noexcept = default;
StraightestPathTracer& StraightestPathTracer::operator=(StraightestPathTracer&&) noexcept = default;
const BasePlane& StraightestPathTracer::base() const { return impl_->base_; }
const SurfacePoint& StraightestPathTracer::source() const { return impl_->source_; }
const StraightestPath& StraightestPathTracer::trace(const SurfacePoint& destination) {
  return impl_->trace(destination);
}

StraightestPathTracer::Impl::Impl(const TriMesh& mesh, const SurfacePoint& source, const TraceOptions& options)
    : mesh_(mesh), source_(canonical(mesh, source, kSnapSource)), options_(options) {
  sourcePosition_ = position(mesh, source_);
  base_ = basePlane(mesh, source_);
  meanEdge_ = mesh.meanEdgeLength();
  onPlaneTolerance_ = kOnPlaneRel * meanEdge_;
  closed_ = mesh.boundaryLoops().empty();
  maxSteps_ = options.maxSteps > 0 ? options.maxSteps
                                   : 2 * static_cast<int64_t>(mesh.numFaces()) + mesh.numVertices() + 16;
  incidentFaces(mesh, source_, sourceFaces_);
  sourceSet_.assign(sourceFaces_);
}

void StraightestPathTracer::Impl::FaceSet::assign(const std::vector<int32_t>& f) {
  faces = f;
  std::sort(faces.begin(), faces.end());
  lo = faces.empty() ? 0 : faces.front();
  hi = faces.empty() ? -1 : faces.back();
}

double StraightestPathTracer::Impl::signedDistance(int32_t v) const {
  const double d = dot(plane_.normal, mesh_.position(v) - plane_.origin);
  return std::abs(d) <= onPlaneTolerance_ ? 0.0 : d;
}

void StraightestPathTracer::Impl::walk(const SurfacePoint& destination, const Vec3& direction, bool forwardSide,
                                       StraightestPath& out) {
  out.status = TraceStatus::NoExit;
  out.length = 0;
  out.facesCrossed = 0;
  out.reversed = !forwardSide;
  out.otherArcLength = std::numeric_limits<double>::quiet_NaN();
  out.points.clear();
  out.positions.clear();
  out.otherPositions.clear();
  if (++epoch_ == 0) {  // wrapped around: clear the stamps once every 2^32 walks
    std::fill(vertexStamp_.begin(), vertexStamp_.end(), 0);
    epoch_ = 1;
  }
  Walk w{*this, mesh_, destination, position(mesh_, destination), out, meanEdge_};
  w.run(direction);
}

const StraightestPath& StraightestPathTracer::Impl::trace(const SurfacePoint& destination) {
  StraightestPath& r = result_;
  const Vec3 D = position(mesh_, destination);
  const Vec3 SD = D - sourcePosition_;
  const bool samePoint = (destination.kind == SurfacePoint::Kind::Vertex &&
                          source_.kind == SurfacePoint::Kind::Vertex && destination.index == source_.index) ||
                         norm(SD) <= onPlaneTolerance_;
  // A destination at the source is reached with length 0; one along the base normal has no plane.
  auto singlePoint = [&](TraceStatus status) -> const StraightestPath& {
    r.status = status;
    r.length = 0;
    r.facesCrossed = 0;
    r.reversed = false;
    r.otherArcLength = std::numeric_limits<double>::quiet_NaN();
    r.points.clear();
    r.positions.clear();
    r.otherPositions.clear();
    if (options_.keepPoints) {
      r.points.push_back(source_);
      r.positions.push_back(sourcePosition_);
    }
    return r;
  };
  if (samePoint) return singlePoint(TraceStatus::Reached);
  // Source and destination in one face: the section of that face runs straight from S to D. (Also the
  // robust answer when D is so close to S that the direction D − S is dominated by rounding.)
  incidentFaces(mesh_, destination, targetFaces_);
  const auto plane = cuttingPlane(base_, D);
  for (int32_t f : targetFaces_)
    if (isSourceFace(f)) {
      singlePoint(TraceStatus::Reached);
      r.length = norm(SD);
      r.facesCrossed = 1;
      if (options_.keepPoints) {
        r.points.push_back(destination);
        r.positions.push_back(D);
      }
      // On a closed surface the section also closes the long way round: walk it from S away from D.
      if (closed_ && plane) {
        plane_ = *plane;
        targetSet_.assign(targetFaces_);
        walk(destination, -*inPlaneDirection(base_, D), false, second_);
        if (second_.status == TraceStatus::Reached) keepAsOtherArc(second_);
      }
      return r;
    }
  if (!plane) return singlePoint(TraceStatus::DegeneratePlane);
  plane_ = *plane;
  targetSet_.assign(targetFaces_);
  const Vec3 t = *inPlaneDirection(base_, D);
  walk(destination, t, true, r);
  if (closed_) {
    walk(destination, -t, false, second_);
    const bool forward = r.status == TraceStatus::Reached, backward = second_.status == TraceStatus::Reached;
    if (forward && backward) {
      if (second_.length < result_.length) std::swap(result_, second_);
      keepAsOtherArc(second_);
    } else if (backward ||
               (!forward && r.status != TraceStatus::OtherComponent && second_.status == TraceStatus::OtherComponent)) {
      // The walk that came back to S is the more precise diagnosis than a loop or a step limit.
      std::swap(result_, second_);
    }
    return result_;
  }
  if (r.status != TraceStatus::Reached) {
    walk(destination, -t, false, second_);
    if (second_.status == TraceStatus::Reached) std::swap(result_, second_);
  }
  return result_;
}

void StraightestPathTracer::Impl::keepAsOtherArc(const StraightestPath& other) {
  result_.otherArcLength = other.length;
  result_.otherPositions.assign(other.positions.begin(), other.positions.end());  // empty unless keepPoints
}

const char* traceStatusName(TraceStatus s) { return nameOf(kTraceStatusNames, s); }

}  // namespace straightest
