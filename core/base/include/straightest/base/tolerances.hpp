// tolerances.hpp — the numerical tolerances that more than one module relies on, in one place, each with
// the reason for its value. Tolerances private to one algorithm (the hull's collinearity, the base
// plane's cancellation, the UV degeneracy) stay next to it.
#pragma once

namespace straightest {

/// Largest accepted |coordinate| (TriMesh::build, the loaders). The algorithms form products of up to
/// four coordinates (a face's squared area, |e1 × e2|²); with |x| <= 1e50 these stay below ~1e202, far
/// from overflow, while 1e100 already gave faces of infinite area (a fuzzing finding). No real mesh
/// comes near either bound.
inline constexpr double kMaxCoordinate = 1e50;

/// Relative threshold below which a face counts as degenerate: |e1 × e2| <= kDegenerateRel * |e1| * |e2|
/// (the sine of the face's angle at its first corner is below it) or an edge has zero length. About
/// 4500 times the double epsilon: a face that flat has a normal dominated by rounding.
inline constexpr double kDegenerateRel = 1e-12;

/// A caller's surface point (validateSurfacePoint): a barycentric coordinate or edge parameter within
/// kExactSnap of 0 (or 1) is taken as exactly 0 (1), and coordinates down to −kExactSnap are accepted.
/// Points computed as "on this edge" or "at this corner" (by a caller, or a path point fed back) carry
/// rounding of a few ulps; 1e-12 absorbs that without moving any point a caller meant to be inside.
inline constexpr double kExactSnap = 1e-12;

/// Barycentric coordinates must sum to 1 within this (validateSurfacePoint): loose enough for
/// coordinates written out in ~10 decimal digits, tight enough to catch unnormalized input.
inline constexpr double kBarycentricSumTolerance = 1e-9;

/// A trace source within kSnapSource (barycentric coordinate or edge parameter) of an edge or a vertex
/// is moved onto it (the tracer, and parameterize's interior-source check, which must see the same
/// point). Leaving a point 1e-9 away from an edge, the walk's first crossing would be closer than its
/// on-segment tolerance (kOnSegmentRel) and could be missed (a fuzzing finding).
inline constexpr double kSnapSource = 1e-6;

/// "The cutting plane passes through this vertex": |signed distance| <= kOnPlaneRel · mean edge length.
/// Decided once per vertex so that neighbouring faces agree; far above the ~1e-16 relative rounding of
/// a signed distance, far below any real feature size.
inline constexpr double kOnPlaneRel = 1e-9;

/// "The destination (or the source) lies on this segment of the walk": within kOnSegmentRel · mean
/// edge length along and across it. Absolute (not relative to the segment), so a very short last
/// segment still finds a target that rounding put just past its end; it also bounds how far a
/// destination next to a passed vertex may be (a fuzzing finding: D at t = 8e-11 on an edge of v).
inline constexpr double kOnSegmentRel = 1e-6;

}  // namespace straightest
