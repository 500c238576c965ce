// geodesic_shoot.hpp — straightest geodesics as an initial value problem (Polthier & Schmies 1998): from a
// surface point and a tangent direction, walk straight for a given length.
//
// Inside a face the path is a straight segment; across an edge it continues straight in the unfolding of
// the two faces (the angle with the edge is kept). Through a vertex v of total angle θ(v) it leaves so
// that the angle on each side between the incoming and the outgoing segment is θ(v)/2 (the discrete
// straightness of Polthier and Schmies); where the rule leaves along an edge, the path runs along it to
// the next vertex. It stops at the given length, or where it meets the boundary (a boundary edge or a
// boundary vertex: there the rule has no two sides), or after the step bound.
//
// The source's tangent frame: normal n = the area-weighted normal at the source (base_plane.hpp's
// areaWeightedNormal); angle 0 = the reference edge projected onto the tangent plane (a vertex: its first
// outgoing halfedge, mesh.vertexHalfedge(v); an edge point: its halfedge, tail → head; a face point: the
// face's first edge, corner 0 → corner 1); angles grow counter-clockwise about n. A 3D direction is
// projected onto the tangent plane. At a vertex, a tangent direction is mapped into the face whose
// projected sector holds it, at the same fraction of the face's corner angle as of the projected sector;
// at an edge point, into the face on its side, at the same angle with the edge.
//
// Toward a destination D: the direction of D − S projected onto the base plane (base_plane.hpp's basePlane,
// the plane the cutting-plane tracer uses), for the cutting plane's straightest distance to D (unless a
// length is given); `missDistance` is the closest 3D approach of the path to D — the paper's remark that a
// geodesic shot from a direction "may not reach a destination", measured.
#pragma once
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/names.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/mesh/surface_point.hpp"

namespace straightest {

enum class ShootStatus : uint8_t {
  ReachedLength,  // walked the whole length (the only success)
  HitBoundary,    // met a boundary edge or boundary vertex first
  StepLimit,      // more steps than the bound
  NoExit,         // no face continues the path (a degenerate neighbourhood)
};
/// The user-visible names (names.hpp: nameOf, parseName, namesOf).
inline constexpr EnumName<ShootStatus> kShootStatusNames[] = {{ShootStatus::ReachedLength, "reached_length"},
                                                              {ShootStatus::HitBoundary, "hit_boundary"},
                                                              {ShootStatus::StepLimit, "step_limit"},
                                                              {ShootStatus::NoExit, "no_exit"}};
const char* shootStatusName(ShootStatus s);

struct ShootOptions {
  // 0: 16 · (faces + length / mean edge length) + 1024: a geodesic may wind over a face many times, but
  // each step advances (a bound against a walk stuck in a degenerate neighbourhood, not a limit on length).
  int64_t maxSteps = 0;
  // The plane a 3D direction is projected onto, by its normal (default: the area-weighted normal at the
  // source). shootGeodesicToward passes the base normal; a caller shooting many times from one source can
  // compute basePlane once and pass it here.
  std::optional<Vec3> tangentNormal;
  // false: `points` and `positions` hold the source and the end only (the length, status, end and miss
  // distance are the same), for a caller that shoots many times and wants no polylines.
  bool keepPoints = true;
};

struct GeodesicShot {
  SurfacePoint source;  // the point used (canonical, snapped like the tracer's source)
  Vec3 normal;          // the tangent plane's normal at the source
  Vec3 direction;       // the initial unit direction (3D, in the plane of the first face)
  ShootStatus status = ShootStatus::NoExit;
  double requestedLength = 0;
  double length = 0;         // walked (the sum of segment lengths)
  int64_t facesCrossed = 0;  // segments walked
  int64_t vertexPassings = 0;
  std::vector<SurfacePoint> points;  // source, crossings..., end
  std::vector<Vec3> positions;
  SurfacePoint end;
  Vec3 endPosition;
  // Toward a destination (NaN otherwise):
  Vec3 target{std::numeric_limits<double>::quiet_NaN(), 0, 0};
  double straightestDistance = std::numeric_limits<double>::quiet_NaN();  // cutting plane's (NaN: a length was given)
  double missDistance = std::numeric_limits<double>::quiet_NaN();         // closest approach to the target
};

/// The unit axis of angle 0 in the source's tangent frame (see the file comment), and the normal.
struct TangentFrame {
  Vec3 normal, axis0, axis90;
};
Expected<TangentFrame> tangentFrame(const TriMesh& mesh, const SurfacePoint& source);

/// Shoots along a 3D direction (projected onto the tangent plane at the source) for `length`.
Expected<GeodesicShot> shootGeodesic(const TriMesh& mesh, const SurfacePoint& source, const Vec3& direction,
                                     double length, const ShootOptions& options = {}, const Progress& progress = {});

/// Shoots at `angle` (radians) in the source's tangent frame for `length`.
Expected<GeodesicShot> shootGeodesicAtAngle(const TriMesh& mesh, const SurfacePoint& source, double angle,
                                            double length, const ShootOptions& options = {},
                                            const Progress& progress = {});

/// Shoots toward a destination (see the file comment); without a length, for the cutting plane's straightest
/// distance to it (an InvalidArgument error when the cutting plane does not reach it: give a length), which
/// is then reported as straightestDistance.
Expected<GeodesicShot> shootGeodesicToward(const TriMesh& mesh, const SurfacePoint& source,
                                           const SurfacePoint& destination, std::optional<double> length = {},
                                           const ShootOptions& options = {}, const Progress& progress = {});

/// Shoots many geodesics on one mesh (the same results as the functions above, bit for bit), faster: every
/// face laid flat (its corners in 2D, its twins) is recorded once when the shooter is made (a record per
/// face, memory worth spending only on batches; the size is in docs/BENCHMARKS.md), and each shot then reads one record
/// per face it crosses, where the functions make it from the face's 3D corners. The mesh must outlive the
/// shooter; shooting is const and thread-safe.
class GeodesicShooter {
 public:
  static Expected<GeodesicShooter> make(const TriMesh& mesh);
  ~GeodesicShooter();
  GeodesicShooter(GeodesicShooter&&) noexcept;
  GeodesicShooter& operator=(GeodesicShooter&&) noexcept;

  Expected<GeodesicShot> shoot(const SurfacePoint& source, const Vec3& direction, double length,
                               const ShootOptions& options = {}, const Progress& progress = {}) const;
  Expected<GeodesicShot> shootAtAngle(const SurfacePoint& source, double angle, double length,
                                      const ShootOptions& options = {}, const Progress& progress = {}) const;
  Expected<GeodesicShot> shootToward(const SurfacePoint& source, const SurfacePoint& destination,
                                     std::optional<double> length = {}, const ShootOptions& options = {},
                                     const Progress& progress = {}) const;

 private:
  GeodesicShooter();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace straightest
