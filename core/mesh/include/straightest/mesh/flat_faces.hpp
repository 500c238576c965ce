// flat_faces.hpp (private) — every face laid flat in the frame of its first halfedge, with its twins: all
// a straight walk across faces reads per face, in one 64-byte record (one cache line).
//
// Frame of face f: corner 0 at (0, 0), corner 1 on the positive x axis, corner 2 above it (y ≥ 0); edge
// k runs from corner k to corner k + 1 (halfedge 3f + k), and twins[k] is its twin (−1 on the boundary).
// A walk crossing edge k moves into the frame of face(twins[k]) with the two faces' corners on that edge
// alone. Records come from 3D positions (corner 2 by projection, not from edge lengths, so a thin face
// keeps its accuracy); a degenerate face (trimesh.hpp) has all corners at (0, 0), which no ray leaves.
// About the bytes per face of the 3D data a walk would read (corners and twins, normal, positions), in one
// load instead of two dependent ones.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "straightest/base/vec3.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest {

struct alignas(64) FlatFace {
  double length = 0;  // corner 1 at (length, 0)
  Vec2 corner;        // corner 2
  std::array<int32_t, 3> twins{-1, -1, -1};
  // Two faces ahead: beyond[2k], beyond[2k + 1] are the faces across the other two edges of face(twins[k])
  // (flatFaces: the face itself where there is none, so that a prefetch needs no test; −1 in a record made
  // alone, which no walk prefetches from), so that a walk can start loading them one face earlier.
  std::array<int32_t, 6> beyond{-1, -1, -1, -1, -1, -1};

  /// Corner k (0, 1 or 2) in the face's frame: x picked from a small array, y by a select (no products by
  /// 0 or 1: fewer instructions a step). The same bits as the products one · length + two · corner.x,
  /// two · corner.y (one = (k == 1), two = (k == 2)) on every record: makeFlatFace stores corner.x + 0.0
  /// (never −0), and the records are finite (TriMesh::build rejects coordinates above 1e50), so 0 · x = +0.
  Vec2 at(int k) const {
    const double x[3] = {0.0, length, corner.x};
    return Vec2{x[k], k == 2 ? corner.y : 0.0};
  }
};
/// The record of face f, from the mesh's positions, into r (inline: a walk without a table makes one
/// per face it enters).
inline void makeFlatFace(const TriMesh& mesh, int32_t f, FlatFace& r) {
  const FaceAdjacency& face = mesh.adjacency(f);
  r.twins = face.twins;
  if (mesh.isDegenerateFace(f)) {
    r.length = 0;
    r.corner = Vec2{};
    return;
  }
  const Vec3& a = mesh.position(face.corners[0]);
  const Vec3 e = mesh.position(face.corners[1]) - a, w = mesh.position(face.corners[2]) - a;
  const double length = std::sqrt(dot(e, e)), inverse = 1 / length;
  r.length = length;
  r.corner = Vec2{dot(w, e) * inverse + 0.0, norm(cross(e, w)) * inverse};  // + 0.0: −0 made +0 (see at)
}

/// Every face's record, with the faces two ahead (`beyond`), computed on all threads.
std::vector<FlatFace> flatFaces(const TriMesh& mesh);

}  // namespace straightest
