// surface_point.hpp — a point on a mesh surface (a vertex, a point on an edge, or a point in a face) and
// its one canonical representation per location.
//
// An edge point is stored on a halfedge h with parameter t: position = (1 − t)·tail(h) + t·head(h). A
// face point stores barycentric coordinates with respect to the face's corners in order.
//
// Canonical form (canonical(); validateSurfacePoint returns it): a point at a corner is a Vertex point;
// a point inside an edge is an Edge point on the edge's halfedge with the smaller index (a boundary edge
// has only one halfedge) with 0 < t < 1; a point inside a face is a Face point with every coordinate
// above the snapping tolerance. So two canonical points at one location compare equal (==), whichever
// face, halfedge or kind they were given as. (Moving to the other halfedge turns t into 1 − t, which is
// exact for t in [0.5, 1) and within an ulp otherwise.)
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest {

struct SurfacePoint {
  enum class Kind : uint8_t { Vertex, Edge, Face };
  Kind kind = Kind::Vertex;
  int32_t index = 0;                    // vertex, halfedge or face
  double t = 0;                         // edge parameter (Kind::Edge)
  std::array<double, 3> bary{1, 0, 0};  // barycentric coordinates (Kind::Face)

  static SurfacePoint vertex(int32_t v) { return {Kind::Vertex, v, 0, {1, 0, 0}}; }
  static SurfacePoint edge(int32_t halfedge, double t) { return {Kind::Edge, halfedge, t, {1, 0, 0}}; }
  static SurfacePoint face(int32_t f, std::array<double, 3> b) { return {Kind::Face, f, 0, b}; }

  /// Same representation: kind and index, and t (edge) or the barycentric coordinates (face). Compare
  /// canonical points to compare locations.
  friend bool operator==(const SurfacePoint& a, const SurfacePoint& b) {
    if (a.kind != b.kind || a.index != b.index) return false;
    switch (a.kind) {
      case Kind::Vertex: return true;
      case Kind::Edge: return a.t == b.t;
      case Kind::Face: return a.bary == b.bary;
    }
    return false;
  }
  friend bool operator!=(const SurfacePoint& a, const SurfacePoint& b) { return !(a == b); }
};

/// 3D position of a surface point (no checks; see validateSurfacePoint).
Vec3 position(const TriMesh& mesh, const SurfacePoint& p);

/// The canonical form of p (see the file comment), moving it onto an edge or a vertex that lies within
/// snapTolerance: an edge parameter t <= snapTolerance becomes the halfedge's tail, t >= 1 −
/// snapTolerance its head; barycentric coordinates <= snapTolerance become 0 and the others are divided
/// by the sum of all three (one zero: a point on the opposite edge; two: the remaining corner). A face
/// point with every coordinate above the tolerance comes back unchanged (not rescaled). This is the one
/// snapping rule: validateSurfacePoint uses it with kExactSnap, the tracer and parameterize's
/// interior-source check with kSnapSource. p's index must be valid for its kind.
SurfacePoint canonical(const TriMesh& mesh, SurfacePoint p, double snapTolerance);

/// Checks indices and coordinates (barycentric coordinates must be finite, >= −kExactSnap and sum to 1
/// within kBarycentricSumTolerance; edge t in [−kExactSnap, 1 + kExactSnap]) and returns the canonical
/// form with kExactSnap, barycentric coordinates divided by their sum, so algorithms see one
/// representation per location.
Expected<SurfacePoint> validateSurfacePoint(const TriMesh& mesh, const SurfacePoint& p);

/// Faces that contain the point: one for a face point, the (one or two) faces of an edge, the fan of a
/// vertex. Appends to out (cleared first).
void incidentFaces(const TriMesh& mesh, const SurfacePoint& p, std::vector<int32_t>& out);

}  // namespace straightest
