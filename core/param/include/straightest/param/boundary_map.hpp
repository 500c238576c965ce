// boundary_map.hpp — where the boundary loop of a disk goes in the parameter plane.
//
//  - measured: boundary vertex b_i goes to r_i (cos θ_i, sin θ_i), θ_i = 2π · (cumulative 3D angle
//    ∠(b_j − S, b_j+1 − S), j < i) / (sum over the loop), each angle raised to at least kMinAngleStep
//    of the mean (an edge pointing at S would otherwise put two points on one ray), r_i = straightest
//    distance S → b_i. A failed trace, or a reached one longer than kOutlierFactor × the edge-graph distance
//    (an upper bound of the geodesic distance: no straightest path should be that much longer; counted as an
//    outlier), gets fallbackRadii instead: the heat method's distance clamped to [straight line, edge graph].
//    Then the polygon is made convex: a point strictly inside the convex hull moves radially outward
//    onto the hull (a hull corner turning by a sine below 1e-9 counts as straight).
//    Ears and pockets (boundaryEars: faces with three boundary corners, and the ≤ kPocketFaces faces a chord
//    cuts off) would collapse onto straight hull edges. So the apex of each one below its least area is lifted
//    radially (far enough for the ear to hold once its neighbours are projected onto the new hull), the points are
//    projected onto the new hull, and this repeats (points only move out; ≤ kMaxEarRounds rounds). GUARANTEE (when the
//    rounds settle, which they did on every patch measured): for every ear, the triangle of its corners (a pocket: its
//    two ends and the middle of its stretch of the loop) has 2D area ≥ kEarAreaFraction × its 3D area × the map's scale
//    (polygon area / surface area) — worstEarRatio ≥ kEarAreaFraction. An ear that already meets it moves nothing, so a
//    flat convex patch (its ears at their true shape) still reproduces itself exactly.
//    Where an interior mesh edge joining
//    two boundary vertices (a chord) would then lie on one straight hull edge (its triangles collapse: the map could
//    not be bijective; Floater's condition for weakly convex boundaries), the points on that edge are lifted onto a
//    shallow parabola over it (sagitta ≤ kBulge · edge length / 4, limited by the hull's turning angles at both ends),
//    which keeps the polygon convex and makes it strictly convex there. Edges without such a triangle stay straight, so
//    a flat convex patch reproduces itself exactly.
//  - circle: the unit circle, by cumulative 3D boundary edge length.
//  - square: the perimeter of the unit square by the same arc length, the loop's first vertex at a
//    corner; a side is bulged like above only where an all-boundary triangle would collapse.
// The polygon is counter-clockwise (the loop keeps the surface on its left). The source maps to (0, 0)
// for the measured boundary.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "straightest/base/names.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/base/timings.hpp"
#include "straightest/mesh/surface_point.hpp"

namespace straightest {

inline constexpr double kBulge = 0.05;           // end slope of the parabola (sagitta = kBulge · L / 4)
inline constexpr double kMinAngleStep = 0.01;    // measured: least polar-angle step, as a fraction of the mean
inline constexpr double kEarAreaFraction = 0.1;  // measured: least 2D area of an ear / (its 3D area × map scale)
inline constexpr double kEarLiftTarget = 1.5;    // a lifted ear aims at this multiple of its least area
inline constexpr int64_t kPocketFaces = 16;      // a chord's side of at most this many faces is a pocket
inline constexpr double kMaxEarLift = 2;         // a lift at most doubles an apex's radius in one round
inline constexpr int kMaxEarRounds = 64;         // lift-and-project rounds before giving up (never seen reached)
inline constexpr double kOutlierFactor = 1.5;    // measured: a reached trace longer than this × graph distance

// Free: no fixed polygon; the boundary moves with the distortion-minimizing refinement
// (free_boundary.hpp, run by parameterize).
enum class BoundaryKind { Measured, Circle, Square, Free };
/// The user-visible names (names.hpp: nameOf, parseName, namesOf).
inline constexpr EnumName<BoundaryKind> kBoundaryKindNames[] = {{BoundaryKind::Measured, "measured"},
                                                                {BoundaryKind::Circle, "circle"},
                                                                {BoundaryKind::Square, "square"},
                                                                {BoundaryKind::Free, "free"}};
const char* boundaryKindName(BoundaryKind k);
/// A boundary kind, or "auto" (nullopt: try every kind and keep the preferred map). One enum plus
/// "auto" rather than a second enum that repeats the kinds: every list of kinds (name tables, the
/// comparison, the polygons) is then a list of BoundaryKind, and "auto" reads the same as the
/// source's "auto" (nullopt).
Expected<std::optional<BoundaryKind>> parseBoundaryChoice(const std::string& name);

struct BoundaryMap {
  BoundaryKind kind = BoundaryKind::Circle;
  std::vector<int32_t> loop;  // boundary vertices in order
  std::vector<Vec2> polygon;  // their positions in the plane
  int64_t fallbacks = 0;      // measured: traces that failed and used the Dijkstra radius
  int64_t movedToHull = 0;    // measured: points moved outward by the convexification
  int64_t outliers = 0;       // measured: reached traces implausibly long (see kOutlierFactor), radius replaced
};

/// The radius a failed or outlying trace gets, per vertex: the heat method's geodesic distance from the source,
/// kept between the straight-line distance (no path is shorter; on coarse patches the heat method can fall far
/// below it) and the edge-graph distance (an upper bound, which overestimates on real patches).
std::vector<double> fallbackRadii(const TriMesh& mesh, const SurfacePoint& source);

/// Requires a disk (checked by the caller). `source` must be an interior surface point for measured.
/// Records the time of its traces as "trace" in `timings`.
Expected<BoundaryMap> measuredBoundary(const TriMesh& mesh, const SurfacePoint& source, const Progress& progress = {},
                                       Timings* timings = nullptr);
BoundaryMap circleBoundary(const TriMesh& mesh);
BoundaryMap squareBoundary(const TriMesh& mesh);

/// The frame a parameterization is shown in: the polygon's bounding box moved to the origin and
/// scaled by its longer side into [0, 1]² (aspect kept). The convex-combination interior lies inside
/// the convex boundary polygon, so this is also the bounding box of the whole uv map: the polygon
/// alone, before any solve, fixes where every uv lands.
struct UnitSquareFrame {
  Vec2 origin;
  double scale = 1;
  Vec2 operator()(const Vec2& q) const { return (q - origin) / scale; }
};
UnitSquareFrame unitSquareFrame(const std::vector<Vec2>& polygon);

/// Interior edges of the mesh whose two ends are both on the loop ("chords"), as indices into the loop.
std::vector<std::array<int32_t, 2>> boundaryChords(const TriMesh& mesh, const std::vector<int32_t>& loop);

/// A face whose three corners are all on the loop (an "ear"): its corners as indices into the loop, its 3D area.
struct BoundaryEar {
  std::array<int32_t, 3> corners;
  double area3D = 0;
};
std::vector<BoundaryEar> boundaryEars(const TriMesh& mesh, const std::vector<int32_t>& loop);

/// The least over the ears (of positive 3D area) of (2D area in the polygon) / (3D area × scale), where the
/// scale is the polygon's area over surfaceArea (the mean area ratio of a map with that boundary); +inf
/// without ears.
double worstEarRatio(const std::vector<Vec2>& polygon, const std::vector<BoundaryEar>& ears, double surfaceArea);

/// Moves points strictly inside the convex hull of `points` radially (from the origin) onto the hull,
/// then bulges the hull edges along which one of `chords` (pairs of indices into points) would lie (its
/// triangles would collapse; see the file comment). The origin must be strictly inside the hull; returns the number of
/// points moved onto the hull, or -1 when the origin is not inside.
/// With `ears` (and the surface's area), every ear's apex is first lifted until worstEarRatio ≥ kEarAreaFraction
/// (see the file comment).
int64_t convexify(std::vector<Vec2>& points, const std::vector<std::array<int32_t, 2>>& chords,
                  const std::vector<BoundaryEar>& ears = {}, double surfaceArea = 0);

}  // namespace straightest
