// surface_point.hpp — a point on a mesh surface: a vertex, a point on an edge, or a point in a face.
// Paths are sequences of surface points plus their 3D positions. An edge point is stored on a
// halfedge h with parameter t: position = (1 − t)·tail(h) + t·head(h). A face point stores
// barycentric coordinates with respect to the face's corners in order.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "straightest/error.hpp"
#include "straightest/trimesh.hpp"

namespace straightest {

struct SurfacePoint {
  enum class Kind : uint8_t { Vertex, Edge, Face };
  Kind kind = Kind::Vertex;
  int32_t index = 0;                  // vertex, halfedge or face
  double t = 0;                       // edge parameter (Kind::Edge)
  std::array<double, 3> bary{1, 0, 0};  // barycentric coordinates (Kind::Face)

  static SurfacePoint vertex(int32_t v) { return {Kind::Vertex, v, 0, {1, 0, 0}}; }
  static SurfacePoint edge(int32_t halfedge, double t) { return {Kind::Edge, halfedge, t, {1, 0, 0}}; }
  static SurfacePoint face(int32_t f, std::array<double, 3> b) { return {Kind::Face, f, 0, b}; }
};

/// 3D position of a surface point (no checks; see validateSurfacePoint).
Vec3 position(const TriMesh& mesh, const SurfacePoint& p);

/// Checks indices and coordinates (barycentric coordinates must be finite, >= -1e-12 and sum to 1
/// within 1e-9; edge t in [0, 1]). Normalizes a point that sits on a vertex or an edge to that
/// simpler kind (t = 0 → vertex, a zero barycentric coordinate → edge), so algorithms see one
/// representation per location.
Expected<SurfacePoint> validateSurfacePoint(const TriMesh& mesh, const SurfacePoint& p);

/// Faces that contain the point: one for a face point, the (one or two) faces of an edge, the fan of a
/// vertex. Appends to out (cleared first).
void incidentFaces(const TriMesh& mesh, const SurfacePoint& p, std::vector<int32_t>& out);

}  // namespace straightest
