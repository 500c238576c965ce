// base_plane.hpp — the base plane at a source and the cutting plane toward a destination
// (Lee, Han, Lee: "Straightest Paths on Meshes By Cutting Planes").
//
// Base normal at S (mesh with boundary): the normalized mean of the unit normals of the virtual
// triangles (S, b_i, b_i+1) fanned from S over consecutive vertices of the longest boundary loop
// (closing the loop), oriented to agree with the area-weighted normal at S (the surface's side; the
// mesh's total normal sum would flip it near the hole of a nearly closed surface). The paper's definition is
// kept however short the mean is (a nearly closed cap's mean is ~0.016 long, and still the right plane), except
// where it is numerically zero: |sum| ≤ kBaseNormalCancel · (sum of the unit normals' lengths). Summing k unit
// vectors rounds each component by ~k · 1e-16, so a sum below 1e-12 of k is rounding noise with no direction
// (e.g. a sphere slit along a meridian, whose virtual faces pair up with opposite normals); there, and where
// every virtual face is degenerate, the area-weighted normal at S is used and `fallback` says so. Closed
// meshes: the area-weighted normal at S, also reported as a fallback.
//
// Cutting plane for D: through S with normal m = normalize(n × (D − S)); undefined (nullopt) when
// D == S or D − S is within kCuttingPlaneMinSine of the base normal (|n × (D − S)| <= 1e-8 · |D − S|):
// m's rounding error is ~1e-16 / sin, so below 1e-8 the plane would miss D (and carry the path off
// its own plane) by more than 1e-8 of |D − S| — fuzzing found a 1e-12 threshold leaving D 8e-7 off.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "straightest/mesh/surface_point.hpp"

namespace straightest {

inline constexpr double kBaseNormalCancel = 1e-12;
inline constexpr double kCuttingPlaneMinSine = 1e-8;

struct BasePlane {
  Vec3 origin;            // S
  Vec3 normal;            // unit
  bool fallback = false;  // true when the area-weighted normal at S was used instead of virtual faces (closed, too)
  std::string note;       // why, when fallback (or "closed mesh")
};

/// Area-weighted normal at a surface point (unit; zero only if every incident face is degenerate).
Vec3 areaWeightedNormal(const TriMesh& mesh, const SurfacePoint& p);

/// areaWeightedNormal at every vertex in one pass over the faces (zero for unreferenced vertices):
/// the shading normals the page draws with.
std::vector<Vec3> vertexNormals(const TriMesh& mesh);

BasePlane basePlane(const TriMesh& mesh, const SurfacePoint& source);

struct CuttingPlane {
  Vec3 origin;  // S
  Vec3 normal;  // m, unit, perpendicular to the base normal
};

std::optional<CuttingPlane> cuttingPlane(const BasePlane& base, const Vec3& destination);

/// The unit direction from S toward D within the base plane (D − S without its base-normal
/// component): the walk's first heading, and with the base normal the span of the cutting plane.
/// nullopt exactly where cuttingPlane is.
std::optional<Vec3> inPlaneDirection(const BasePlane& base, const Vec3& destination);

}  // namespace straightest
