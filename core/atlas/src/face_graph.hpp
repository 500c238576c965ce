// face_graph.hpp — the face-adjacency (dual) graph the charts grow on: faces joined across their edges,
// each step as long as the distance between the two faces' centroids.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/mesh/trimesh.hpp"

namespace straightest::atlas {

/// The face across edge k of face f, or -1 on the boundary.
inline int32_t faceAcross(const TriMesh& mesh, int32_t f, int k) {
  const int32_t h = mesh.adjacency(f).twins[k];
  return h < 0 ? -1 : TriMesh::face(h);
}

/// The length of edge k of face f (from corner k to corner k + 1).
inline double edgeLength(const TriMesh& mesh, int32_t f, int k) {
  const Triangle& t = mesh.triangle(f);
  return norm(mesh.position(t[(k + 1) % 3]) - mesh.position(t[k]));
}

std::vector<Vec3> faceCentroids(const TriMesh& mesh);

/// The edge-connected component of every face, numbered from 0 in the order of their lowest face.
std::vector<int32_t> faceComponents(const TriMesh& mesh, int32_t& count);

/// Shortest dual-graph distances from `sources` (distance 0) into the faces where allowed[f] is nonzero
/// (every face when `allowed` is empty); +inf where unreached. `distance` is updated in place and only
/// lowered, so calling it again with a new source extends a farthest-point sampling.
void lowerDualDistances(const TriMesh& mesh, const std::vector<Vec3>& centroids, const std::vector<int32_t>& sources,
                        const std::vector<uint8_t>& allowed, std::vector<double>& distance);

/// The face of `faces` with the largest finite distance (the lowest index among ties), -1 if none is finite.
int32_t farthestFace(const std::vector<int32_t>& faces, const std::vector<double>& distance);

}  // namespace straightest::atlas
