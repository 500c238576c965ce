// geodesic_shoot.cpp — shooting straightest geodesics (geodesic_shoot.hpp): the input checked, the tangent
// plane and frame, shooting toward a destination, the GeodesicShooter's table; the walk is geodesic_walk.hpp.
#include "straightest/geodesics/geodesic_shoot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "geodesic_walk.hpp"
#include "straightest/base/names.hpp"
#include "straightest/base/tolerances.hpp"
#include "straightest/mesh/flat_faces.hpp"
#include "straightest/paths/base_plane.hpp"
#include "straightest/paths/straightest_path.hpp"

namespace straightest {

const char* shootStatusName(ShootStatus s) { return nameOf(kShootStatusNames, s); }

namespace {

using shooting::invalid;
using shooting::projected;
using shooting::Walk;

/// Validates the source and the length; the source snapped as the tracer snaps its own.
Expected<SurfacePoint> prepare(const TriMesh& mesh, const SurfacePoint& source, double length, bool needLength) {
  auto valid = validateSurfacePoint(mesh, source);
  if (!valid) return valid.error();
  if (needLength && !(length > 0 && std::isfinite(length)))
    return invalid("the length must be a positive finite number, got " + numberText(length));
  return canonical(mesh, valid.value(), kSnapSource);
}

Expected<GeodesicShot> shoot(const TriMesh& mesh, const FlatFace* table, GeodesicShot shot, const Vec3& tangent,
                             const Vec3& n, const ShootOptions& options, const Progress& progress) {
  Walk walk(mesh, table, shot, options, progress);
  auto done = walk.run(tangent, n);
  if (!done) return done.error();
  return shot;
}

Expected<GeodesicShot> shootAlong(const TriMesh& mesh, const FlatFace* table, const SurfacePoint& source,
                                  const Vec3& direction, double length, const ShootOptions& options,
                                  const Progress& progress) {
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
    return shoot(mesh, table, std::move(shot), normalized(tangent), n, options, progress);
  });
}

Expected<GeodesicShot> shootAtAngle(const TriMesh& mesh, const FlatFace* table, const SurfacePoint& source,
                                    double angle, double length, const ShootOptions& options,
                                    const Progress& progress) {
  if (!std::isfinite(angle)) return invalid("the angle is not finite");
  auto frame = tangentFrame(mesh, source);
  if (!frame) return frame.error();
  const TangentFrame& f = frame.value();
  return shootAlong(mesh, table, source, f.axis0 * std::cos(angle) + f.axis90 * std::sin(angle), length, options,
                    progress);
}

Expected<GeodesicShot> shootToward(const TriMesh& mesh, const FlatFace* table, const SurfacePoint& source,
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
    const double straightest = path.status == TraceStatus::Reached ? path.length : shooting::kInf;
    if (!length && straightest == shooting::kInf)
      return invalid(std::string("the cutting plane does not reach the destination (") + traceStatusName(path.status) +
                     "): give the length to shoot");
    GeodesicShot shot;
    shot.source = s.value();
    shot.normal = base.normal;
    shot.requestedLength = length ? *length : straightest;
    shot.target = target;
    if (straightest < shooting::kInf) shot.straightestDistance = straightest;
    auto result = shoot(mesh, table, std::move(shot), *tangent, base.normal, options, progress);
    return result;  // the walk measured missDistance as it went
  });
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
  return shootAlong(mesh, nullptr, source, direction, length, options, progress);
}

Expected<GeodesicShot> shootGeodesicAtAngle(const TriMesh& mesh, const SurfacePoint& source, double angle,
                                            double length, const ShootOptions& options, const Progress& progress) {
  return shootAtAngle(mesh, nullptr, source, angle, length, options, progress);
}

Expected<GeodesicShot> shootGeodesicToward(const TriMesh& mesh, const SurfacePoint& source,
                                           const SurfacePoint& destination, std::optional<double> length,
                                           const ShootOptions& options, const Progress& progress) {
  return shootToward(mesh, nullptr, source, destination, length, options, progress);
}

struct GeodesicShooter::Impl {
  const TriMesh& mesh;
  std::vector<FlatFace> faces;
};

Expected<GeodesicShooter> GeodesicShooter::make(const TriMesh& mesh) {
  return guarded([&]() -> Expected<GeodesicShooter> {
    GeodesicShooter shooter;
    shooter.impl_ = std::make_unique<Impl>(Impl{mesh, flatFaces(mesh)});
    return shooter;
  });
}
GeodesicShooter::GeodesicShooter() = default;
GeodesicShooter::~GeodesicShooter() = default;
GeodesicShooter::GeodesicShooter(GeodesicShooter&&) noexcept = default;
GeodesicShooter& GeodesicShooter::operator=(GeodesicShooter&&) noexcept = default;

Expected<GeodesicShot> GeodesicShooter::shoot(const SurfacePoint& source, const Vec3& direction, double length,
                                              const ShootOptions& options, const Progress& progress) const {
  return shootAlong(impl_->mesh, impl_->faces.data(), source, direction, length, options, progress);
}

Expected<GeodesicShot> GeodesicShooter::shootAtAngle(const SurfacePoint& source, double angle, double length,
                                                     const ShootOptions& options, const Progress& progress) const {
  return straightest::shootAtAngle(impl_->mesh, impl_->faces.data(), source, angle, length, options, progress);
}

Expected<GeodesicShot> GeodesicShooter::shootToward(const SurfacePoint& source, const SurfacePoint& destination,
                                                    std::optional<double> length, const ShootOptions& options,
                                                    const Progress& progress) const {
  return straightest::shootToward(impl_->mesh, impl_->faces.data(), source, destination, length, options, progress);
}

}  // namespace straightest
