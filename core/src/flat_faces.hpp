// flat_faces.hpp (private) — every face laid flat in the frame of its first halfedge, with its twins: all
// a straight walk across faces reads per face, in one 64-byte record (one cache line).
//
// Frame of face f: corner 0 at (0, 0), corner 1 on the positive x axis, corner 2 above it (y ≥ 0); edge
// k runs from corner k to corner k + 1 (halfedge 3f + k), and twins[k] is its twin (−1 on the boundary).
// The zeros are stored too, so that a walk picks a corner by its number without a branch.
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

#include "straightest/trimesh.hpp"
#include "straightest/vec3.hpp"

namespace straightest {

struct alignas(64) FlatFace {
  std::array<double, 3> x{}, y{};  // corner k at (x[k], y[k]): (0, 0), (length of edge 0, 0), above the x axis
  std::array<int32_t, 3> twins{-1, -1, -1};

  /// Corner k (0, 1 or 2) in the face's frame.
  Vec2 at(int k) const { return Vec2{x[k], y[k]}; }
};
static_assert(sizeof(FlatFace) == 64, "one cache line per face");

/// The record of face f, from the mesh's positions, into r (inline: a walk without a table makes one
/// per face it enters).
inline void makeFlatFace(const TriMesh& mesh, int32_t f, FlatFace& r) {
  const FaceAdjacency& face = mesh.adjacency(f);
  r.twins = face.twins;
  if (mesh.isDegenerateFace(f)) {
    r.x = {0, 0, 0};
    r.y = {0, 0, 0};
    return;
  }
  const Vec3& a = mesh.position(face.corners[0]);
  const Vec3 e = mesh.position(face.corners[1]) - a, w = mesh.position(face.corners[2]) - a;
  const double length = std::sqrt(dot(e, e)), inverse = 1 / length;
  r.x = {0, length, dot(w, e) * inverse};
  r.y = {0, 0, norm(cross(e, w)) * inverse};
}

/// Every face's record, computed on all threads.
std::vector<FlatFace> flatFaces(const TriMesh& mesh);

}  // namespace straightest
