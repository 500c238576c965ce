// geodesic_distance.hpp — shortest-distance companions of the straightest distance: for comparison
// and for the measured boundary's fallback radius.
//
//  - dijkstraDistances: exact shortest paths along edges (an upper bound of the geodesic distance).
//  - HeatMethod (Crane, Weischedel, Wardetzky 2013): cotan Laplacian L and lumped mass M;
//    heat u solves (M + t·L) u = δ_S with t = (mean edge length)²; X = −∇u/|∇u| per face;
//    φ solves L φ = ∇·X, shifted so φ(S) = 0. Both matrices are factored once (sparse Cholesky) and
//    reused for every source. Neumann boundary conditions. Approximate: error shrinks with mesh
//    refinement (a few percent on coarse meshes).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "straightest/base/names.hpp"
#include "straightest/mesh/surface_point.hpp"

namespace straightest {

/// Edge-graph distances from the given source vertices (multi-source); +inf where unreachable.
std::vector<double> dijkstraDistances(const TriMesh& mesh, const std::vector<int32_t>& sources);

/// Dijkstra from a surface point: the point connects to the corners of its face (or edge) by straight
/// segments.
std::vector<double> dijkstraDistances(const TriMesh& mesh, const SurfacePoint& source);

/// "Center of the mesh", the default source: the interior vertex farthest (edge-graph Dijkstra
/// distance) from the boundary; ties → lowest index. Closed mesh: the vertex nearest the
/// area-weighted centroid. A Topology error when a mesh with boundary has no interior vertex.
Expected<int32_t> defaultSource(const TriMesh& mesh);

/// The default source as a point: defaultSource's vertex, or, when every vertex lies on the boundary, the
/// centroid of the largest face (a Topology error only when every face is degenerate too).
Expected<SurfacePoint> defaultSourcePoint(const TriMesh& mesh);

/// The one place "auto" becomes a point: nullopt → defaultSourcePoint; a given point is
/// validated (see validateSurfacePoint). Every caller (core, CLI, npm package) maps its "auto" to nullopt.
Expected<SurfacePoint> resolveSource(const TriMesh& mesh, const std::optional<SurfacePoint>& source);

class HeatMethod {
 public:
  explicit HeatMethod(const TriMesh& mesh);
  ~HeatMethod();
  HeatMethod(HeatMethod&&) noexcept;
  HeatMethod& operator=(HeatMethod&&) noexcept;

  /// Distances from a source point to every vertex (0 at the source; +inf on unreferenced vertices
  /// and components the source does not reach).
  std::vector<double> distances(const SurfacePoint& source) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

enum class DistanceMethod { Heat, Dijkstra, Exact };  // Exact: window propagation (exact_geodesic.hpp)
/// The user-visible names (names.hpp: nameOf, parseName, namesOf).
inline constexpr EnumName<DistanceMethod> kDistanceMethodNames[] = {{DistanceMethod::Heat, "heat"},
                                                                    {DistanceMethod::Dijkstra, "dijkstra"},
                                                                    {DistanceMethod::Exact, "exact"}};
Expected<DistanceMethod> parseDistanceMethod(const std::string& name);

/// Distances from a source to chosen vertices, as `straightest distances` reports them.
struct DistanceTable {
  SurfacePoint source;
  DistanceMethod method = DistanceMethod::Exact;
  std::vector<int32_t> targets;
  std::vector<double> distances;  // one per target
};

/// Distances on one mesh by either method; the heat method's factorization is made at the first heat
/// query and reused by every later one (the mesh must outlive this object).
class GeodesicDistances {
 public:
  explicit GeodesicDistances(const TriMesh& mesh) : mesh_(mesh) {}
  /// Distances from a valid surface point to every vertex.
  std::vector<double> from(const SurfacePoint& source, DistanceMethod method);

 private:
  const TriMesh& mesh_;
  std::unique_ptr<HeatMethod> heat_;
};

}  // namespace straightest
