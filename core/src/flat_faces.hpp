// flat_faces.hpp (private) — every face laid flat in the frame of its first halfedge, with its twins: all
// a straight walk across faces reads per face, in one 40-byte record.
//
// Frame of face f: corner 0 at (0, 0), corner 1 at (length, 0), corner 2 at `corner` (y ≥ 0); edge k
// runs from corner k to corner k + 1 (halfedge 3f + k), and twins[k] is its twin (−1 on the boundary).
// A walk crossing edge k moves into the frame of face(twins[k]) with the two faces' corners on that edge
// alone. Records come from 3D positions (corner 2 by projection, not from edge lengths, so a thin face
// keeps its accuracy); a degenerate face (trimesh.hpp) has all corners at (0, 0), which no ray leaves.
// Half the bytes per face of the walk's 3D data (corners, twins, normal, positions), and no dependent loads.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "straightest/trimesh.hpp"
#include "straightest/vec3.hpp"

namespace straightest {

struct FlatFace {
  double length = 0;  // |corner 1 − corner 0|
  Vec2 corner;
  std::array<int32_t, 3> twins{-1, -1, -1};
  int32_t unused = 0;

  /// Corner k (0, 1 or 2) in the face's frame.
  Vec2 at(int k) const { return k == 0 ? Vec2{} : k == 1 ? Vec2{length, 0} : corner; }
};
static_assert(sizeof(FlatFace) == 40, "records packed: a face's record spans one or two cache lines");

/// The record of face f, from the mesh's positions.
FlatFace flatFace(const TriMesh& mesh, int32_t f);

/// Every face's record, computed on all threads.
std::vector<FlatFace> flatFaces(const TriMesh& mesh);

}  // namespace straightest
