// libFuzzer harness: straightest paths (StraightestPathTracer, traceStraightestPaths) on random valid
// meshes (height-field grids, flat grids, spherical caps, closed bumpy spheres, open tubes; rotated,
// scaled 1e-6..1e6, offset) between random sources and targets (vertices, edge points, face points).
// Invariants for every path: a status < kTraceStatusCount; points and positions agree, start at the
// source, are valid surface points, and consecutive points share a face; the length is the sum of
// the segment lengths; facesCrossed == segments ≤ the step bound (+1); every point lies on the
// cutting plane (|m·(p − S)| ≤ 1e-7 · bbox diagonal). When reached: the last point is the target and
// length ≥ chord. DegeneratePlane exactly when cuttingPlane() has no plane (except a target in a face
// of the source, joined directly). On a flat mesh with a
// convex boundary every target is reached along the straight segment (length = chord). Tracing
// without points gives the same status/length/count; traceStraightestPaths gives the same paths, and
// without points the same status/length/count;
// a small step bound is honoured; the tracer moves a source by at most 1e-6 (snapping it onto a
// nearby edge or vertex). validateSurfacePoint keeps positions and rejects invalid points.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdlib>

#include "fuzz_meshes.hpp"
#include "straightest/paths/straightest_path.hpp"

using namespace straightest;

namespace {

struct Copy {
  TraceStatus status;
  double length;
  int64_t facesCrossed;
  bool reversed;
  std::vector<SurfacePoint> points;
  std::vector<Vec3> positions;
};

bool sharesFace(const TriMesh& m, const SurfacePoint& a, const SurfacePoint& b) {
  std::vector<int32_t> fa, fb;
  incidentFaces(m, a, fa);
  incidentFaces(m, b, fb);
  for (int32_t f : fa)
    if (std::find(fb.begin(), fb.end(), f) != fb.end()) return true;
  return false;
}

const char* kindName(const SurfacePoint& p) {
  return p.kind == SurfacePoint::Kind::Vertex ? "vertex" : p.kind == SurfacePoint::Kind::Edge ? "edge" : "face";
}

void describe(const TriMesh& m, const char* what, const SurfacePoint& p) {
  const Vec3 x = position(m, p);
  std::fprintf(stderr, "%s: %s %d t=%.17g bary=(%.17g, %.17g, %.17g) at (%.17g, %.17g, %.17g)\n", what, kindName(p),
               p.index, p.t, p.bary[0], p.bary[1], p.bary[2], x.x, x.y, x.z);
}

void dump(const TriMesh& m, const StraightestPathTracer& tracer, const SurfacePoint& dst, const StraightestPath& p) {
  std::fprintf(stderr, "mesh: %d vertices, %d faces, bbox diagonal %.17g\n", m.numVertices(), m.numFaces(),
               m.summary().bbox.diagonal());
  for (int32_t v = 0; v < m.numVertices(); ++v)
    std::fprintf(stderr, "  v %d: %.17g %.17g %.17g\n", v, m.position(v).x, m.position(v).y, m.position(v).z);
  for (int32_t f = 0; f < m.numFaces(); ++f)
    std::fprintf(stderr, "  f %d: %d %d %d\n", f, m.triangle(f)[0], m.triangle(f)[1], m.triangle(f)[2]);
  describe(m, "source", tracer.source());
  describe(m, "target", dst);
  const Vec3 n = tracer.base().normal;
  std::fprintf(stderr, "base normal (%.17g, %.17g, %.17g)%s\n", n.x, n.y, n.z,
               tracer.base().fallback ? " (fallback)" : "");
  std::fprintf(stderr, "status %s, length %.17g, %lld faces crossed, reversed %d, %zu points:\n",
               traceStatusName(p.status), p.length, (long long)p.facesCrossed, p.reversed, p.points.size());
  for (size_t i = 0; i < p.points.size(); ++i) describe(m, "  point", p.points[i]);
}

void checkPath(const TriMesh& m, const StraightestPathTracer& tracer, const SurfacePoint& dst, const StraightestPath& p,
               bool flatConvex, const char* meshKind) {
  if (std::getenv("FUZZ_VERBOSE")) dump(m, tracer, dst, p);
  const double diag = m.summary().bbox.diagonal();
  const Vec3 S = position(m, tracer.source()), D = position(m, dst);
  const int st = static_cast<int>(p.status);
  const char* name = traceStatusName(p.status);
  FUZZ_CHECK(st >= 0 && st < kTraceStatusCount, "status %d out of range", st);
  FUZZ_CHECK(p.points.size() == p.positions.size() && !p.points.empty(), "%s: %zu points, %zu positions", name,
             p.points.size(), p.positions.size());
  FUZZ_CHECK(norm(p.positions[0] - S) <= 1e-12 * diag, "%s: path does not start at the source", name);
  FUZZ_CHECK(std::isfinite(p.length) && p.length >= 0, "%s: length %g", name, p.length);
  const int64_t maxSteps = 2 * static_cast<int64_t>(m.numFaces()) + m.numVertices() + 16;
  FUZZ_CHECK(p.facesCrossed >= 0 && p.facesCrossed <= maxSteps + 1, "%s: facesCrossed %lld over the bound %lld", name,
             (long long)p.facesCrossed, (long long)maxSteps + 1);
  FUZZ_CHECK(p.facesCrossed == static_cast<int64_t>(p.points.size()) - 1, "%s: facesCrossed %lld but %zu points", name,
             (long long)p.facesCrossed, p.points.size());
  double sum = 0;
  for (size_t i = 0; i < p.points.size(); ++i) {
    auto valid = validateSurfacePoint(m, p.points[i]);
    FUZZ_CHECK(valid.ok(), "%s: path point %zu (%s %d) invalid: %s", name, i, kindName(p.points[i]), p.points[i].index,
               valid.ok() ? "" : valid.error().message.c_str());
    FUZZ_CHECK(norm(position(m, p.points[i]) - p.positions[i]) <= 1e-9 * diag,
               "%s: point %zu's position disagrees with its surface point", name, i);
    if (i > 0) {
      FUZZ_CHECK(sharesFace(m, p.points[i - 1], p.points[i]),
                 "%s: consecutive points %zu (%s %d) and %zu (%s %d) share no face", name, i - 1,
                 kindName(p.points[i - 1]), p.points[i - 1].index, i, kindName(p.points[i]), p.points[i].index);
      sum += norm(p.positions[i] - p.positions[i - 1]);
    }
  }
  FUZZ_CHECK(std::abs(sum - p.length) <= 1e-9 * (sum + diag), "%s: length %.17g, segments sum to %.17g", name, p.length,
             sum);
  const auto plane = cuttingPlane(tracer.base(), D);
  const bool samePoint = norm(D - S) <= kOnPlaneRel * diag;  // generous: the tracer uses the mean edge
  if (p.status == TraceStatus::DegeneratePlane) {
    FUZZ_CHECK(!plane, "degenerate_plane but cuttingPlane() has a plane");
    FUZZ_CHECK(p.points.size() == 1 && p.length == 0, "degenerate_plane with a path");
  } else if (p.points.size() > 1 && !plane) {
    // Source and target in one face are joined directly, even along the base normal (no plane).
    FUZZ_CHECK(p.status == TraceStatus::Reached && p.points.size() == 2 && sharesFace(m, tracer.source(), dst),
               "%s: a path without a cutting plane", name);
  } else if (p.points.size() > 1) {
    FUZZ_CHECK(plane.has_value(), "%s: a path without a cutting plane", name);
    for (size_t i = 0; i < p.positions.size(); ++i) {
      const double off = std::abs(dot(plane->normal, p.positions[i] - S));
      FUZZ_CHECK(off <= 1e-7 * diag, "%s: point %zu is %.3g off the cutting plane (bbox diagonal %.3g)", name, i, off,
                 diag);
    }
  } else if (!samePoint) {
    FUZZ_CHECK(p.status != TraceStatus::Reached, "reached a distinct target with a single point");
  }
  if (p.status == TraceStatus::Reached) {
    const double chord = norm(D - S);
    FUZZ_CHECK(norm(p.positions.back() - D) <= 1e-9 * diag, "reached, but the last point is %.3g from the target",
               norm(p.positions.back() - D));
    if (p.points.size() == 1)  // the target is at the source (within the tracer's tolerance)
      FUZZ_CHECK(chord <= kOnPlaneRel * diag, "reached without moving, but the target is %.3g away", chord);
    else
      FUZZ_CHECK(p.length >= chord * (1 - 1e-12) - 1e-12 * diag, "reached with length %.17g below the chord %.17g",
                 p.length, chord);
  }
  // The other arc (closed meshes only): both ways reached D, the returned one is the shorter, and the
  // other's points run from S to D with the reported length.
  if (!std::isnan(p.otherArcLength)) {
    FUZZ_CHECK(m.boundaryLoops().empty(), "%s: an other arc on a mesh with a boundary", name);
    FUZZ_CHECK(p.status == TraceStatus::Reached && p.otherArcLength >= p.length, "%s: other arc %.17g, returned %.17g",
               name, p.otherArcLength, p.length);
    const auto& o = p.otherPositions;
    FUZZ_CHECK(o.size() >= 2 && norm(o.front() - S) <= 1e-12 * diag && norm(o.back() - D) <= 1e-9 * diag,
               "%s: the other arc's %zu points do not run from S to D", name, o.size());
    double other = 0;
    for (size_t i = 1; i < o.size(); ++i) other += norm(o[i] - o[i - 1]);
    FUZZ_CHECK(std::abs(other - p.otherArcLength) <= 1e-9 * (other + diag), "%s: other arc %.17g, segments %.17g", name,
               p.otherArcLength, other);
  } else {
    FUZZ_CHECK(p.otherPositions.empty(), "%s: other points without an other arc", name);
  }
  if (flatConvex && !samePoint) {
    FUZZ_CHECK(p.status == TraceStatus::Reached, "flat convex %s mesh: target not reached (%s)", meshKind, name);
    const double chord = norm(D - S);
    FUZZ_CHECK(std::abs(p.length - chord) <= 1e-9 * diag, "flat convex mesh: length %.17g, chord %.17g", p.length,
               chord);
  }
}

Copy copyOf(const StraightestPath& p) {
  return {p.status, p.length, p.facesCrossed, p.reversed, p.points, p.positions};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  fuzz::RandomMesh gen;
  switch (in.ConsumeIntegralInRange(0, 5)) {
    case 0:
    case 1:
    case 2: gen = fuzz::heightGrid(in, 10); break;
    case 3: gen = fuzz::cap(in, true); break;
    default: gen = fuzz::sphereOrTube(in); break;
  }
  const TriMesh mesh = fuzz::transformAndBuild(in, gen);
  const double diag = mesh.summary().bbox.diagonal();

  // Surface points: valid ones keep their position when normalized, invalid ones are refused.
  auto pick = [&]() {
    const SurfacePoint raw = fuzz::randomPoint(in, mesh);
    auto p = validateSurfacePoint(mesh, raw);
    FUZZ_CHECK(p.ok(), "valid %s point refused: %s", kindName(raw), p.ok() ? "" : p.error().message.c_str());
    FUZZ_CHECK(norm(position(mesh, p.value()) - position(mesh, raw)) <= 1e-9 * diag, "normalizing moved a point");
    auto again = validateSurfacePoint(mesh, p.value());
    FUZZ_CHECK(again.ok() && again.value().kind == p.value().kind && again.value().index == p.value().index,
               "normalizing twice changed the point");
    return p.value();
  };
  if (in.ConsumeIntegralInRange(0, 7) == 0) {
    auto bad = validateSurfacePoint(mesh, fuzz::invalidPoint(in, mesh));
    FUZZ_CHECK(!bad.ok(), "an invalid surface point was accepted");
    fuzz::checkError(bad.error(), "validateSurfacePoint");
    FUZZ_CHECK(bad.error().code == ErrorCode::InvalidArgument, "invalid point: %s", errorCodeName(bad.error().code));
  }
  const SurfacePoint source = pick();
  const size_t count = in.ConsumeIntegralInRange<size_t>(1, 8);
  std::vector<SurfacePoint> targets;
  for (size_t i = 0; i < count; ++i) targets.push_back(pick());
  if (in.ConsumeBool()) targets.push_back(source);

  StraightestPathTracer tracer(mesh, source);
  // The tracer may move a source lying within 1e-6 of an edge or vertex onto it; never farther.
  FUZZ_CHECK(validateSurfacePoint(mesh, tracer.source()).ok(), "tracer source invalid");
  FUZZ_CHECK(norm(position(mesh, tracer.source()) - position(mesh, source)) <= 2e-6 * diag,
             "the tracer moved the source by %.3g (bbox diagonal %.3g)",
             norm(position(mesh, tracer.source()) - position(mesh, source)), diag);
  const Vec3 n = tracer.base().normal;
  FUZZ_CHECK(isFinite(n) && (std::abs(norm(n) - 1) < 1e-9 || norm(n) == 0), "base normal %g %g %g", n.x, n.y, n.z);
  TraceOptions lean;
  lean.keepPoints = false;
  StraightestPathTracer leanTracer(mesh, source, lean);
  TraceOptions bounded;
  bounded.maxSteps = in.ConsumeIntegralInRange(1, 4);
  StraightestPathTracer boundedTracer(mesh, source, bounded);

  std::vector<Copy> paths;
  for (const SurfacePoint& t : targets) {
    const StraightestPath& p = tracer.trace(t);
    checkPath(mesh, tracer, t, p, gen.flatConvex, gen.kind);
    paths.push_back(copyOf(p));
    const StraightestPath& q = leanTracer.trace(t);
    FUZZ_CHECK(q.status == p.status && q.length == p.length && q.facesCrossed == p.facesCrossed &&
                   q.reversed == p.reversed && q.points.empty() && q.otherPositions.empty() &&
                   (q.otherArcLength == p.otherArcLength ||
                    (std::isnan(q.otherArcLength) && std::isnan(p.otherArcLength))),
               "keepPoints=false changed the result (%s vs %s)", traceStatusName(q.status), traceStatusName(p.status));
    const StraightestPath& b = boundedTracer.trace(t);
    FUZZ_CHECK(static_cast<int>(b.status) < kTraceStatusCount && b.facesCrossed <= bounded.maxSteps + 1,
               "maxSteps %lld: %lld faces crossed", (long long)bounded.maxSteps, (long long)b.facesCrossed);
    if (b.status != TraceStatus::StepLimit)
      FUZZ_CHECK(b.status == paths.back().status || b.facesCrossed <= bounded.maxSteps + 1,
                 "bounded trace ended differently without hitting the bound");
  }
  // The batch API gives the same paths, packed.
  const PathBatch batch = traceStraightestPaths(mesh, source, targets, TraceOptions{true}).value();
  FUZZ_CHECK(batch.status.size() == targets.size() && batch.offsets.size() == targets.size() + 1 &&
                 batch.length.size() == targets.size(),
             "batch sizes");
  int64_t reached = 0;
  for (size_t i = 0; i < targets.size(); ++i) {
    const Copy& c = paths[i];
    reached += c.status == TraceStatus::Reached;
    FUZZ_CHECK(batch.status[i] == c.status && batch.length[i] == c.length && batch.facesCrossed[i] == c.facesCrossed &&
                   (batch.reversed[i] != 0) == c.reversed,
               "batch path %zu differs from the single trace (%s vs %s)", i, traceStatusName(batch.status[i]),
               traceStatusName(c.status));
    FUZZ_CHECK(batch.offsets[i + 1] - batch.offsets[i] == static_cast<int64_t>(c.positions.size()),
               "batch path %zu has %lld points, single trace %zu", i,
               (long long)(batch.offsets[i + 1] - batch.offsets[i]), c.positions.size());
    for (size_t k = 0; k < c.positions.size(); ++k) {
      const Vec3 &a = batch.points[batch.offsets[i] + k], &b = c.positions[k];
      FUZZ_CHECK(a.x == b.x && a.y == b.y && a.z == b.z, "batch path %zu point %zu differs", i, k);
    }
  }
  FUZZ_CHECK(summarize(batch).reached == reached, "summarize(batch).reached");
  // Lengths only (as the measured boundary traces): every single trace's result, bit for bit.
  const PathBatch lengths = traceStraightestPaths(mesh, source, targets, TraceOptions{false}).value();
  FUZZ_CHECK(lengths.status.size() == targets.size() && lengths.offsets.size() == targets.size() + 1 &&
                 lengths.points.empty(),
             "lengths-only batch sizes");
  for (size_t i = 0; i < targets.size(); ++i) {
    const Copy& c = paths[i];
    FUZZ_CHECK(lengths.status[i] == c.status && lengths.length[i] == c.length &&
                   lengths.facesCrossed[i] == c.facesCrossed && (lengths.reversed[i] != 0) == c.reversed,
               "lengths-only batch path %zu differs from the single trace (%s vs %s, length %.17g vs %.17g)", i,
               traceStatusName(lengths.status[i]), traceStatusName(c.status), lengths.length[i], c.length);
  }
  // Tracing again from the same tracer is deterministic (the stamps are reused).
  for (size_t i = 0; i < targets.size(); ++i) {
    const StraightestPath& p = tracer.trace(targets[i]);
    FUZZ_CHECK(p.status == paths[i].status && p.length == paths[i].length, "tracing again changed path %zu", i);
  }
  return 0;
}
