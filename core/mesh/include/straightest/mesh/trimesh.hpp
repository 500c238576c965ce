// trimesh.hpp — the validated, immutable triangle mesh every algorithm works on.
//
// Contract: TriMesh::build() takes positions and triangles in the file's order (0-based, no welding,
// no reordering; unreferenced vertices are kept and reported) and either returns a mesh that is a
// manifold, consistently oriented (faces flipped to agree with the majority of their connected
// component; the count is reported) triangle mesh with finite coordinates, or an Error saying what
// was found and where. Zero-area faces are reported, not rejected: each algorithm decides whether
// it can cope.
//
// Connectivity is a half-edge table with implicit halfedges: halfedge h = 3*f + k goes from corner k
// of face f to corner (k+1)%3; next(h) stays in the face; twin(h) is the opposite halfedge or -1 on
// the boundary. Boundary loops are ordered along the boundary halfedges (so they follow the faces'
// orientation: the surface lies to the left when walking a loop).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/tolerances.hpp"
#include "straightest/base/vec3.hpp"

namespace straightest {

using Triangle = std::array<int32_t, 3>;

/// One face's corners and the twins of its three halfedges, side by side (24 bytes): a walk across
/// faces reads both for every face it enters, so they come in one cache line instead of two.
struct FaceAdjacency {
  Triangle corners;
  std::array<int32_t, 3> twins;
};

struct BuildLimits {
  int64_t maxVertices = 50'000'000;
  int64_t maxFaces = 100'000'000;
};

struct BoundingBox {
  Vec3 min, max;
  double diagonal() const { return norm(max - min); }
};

/// A one-look summary of a mesh, as `straightest info` and `mesh.info()` report it.
struct MeshSummary {
  int64_t vertices = 0;
  int64_t faces = 0;
  int64_t edges = 0;
  std::vector<int64_t> boundaryLoopSizes;  // longest first
  int64_t eulerCharacteristic = 0;         // V - E + F over referenced vertices
  int64_t components = 0;
  int64_t degenerateFaces = 0;
  int64_t reorientedFaces = 0;
  int64_t unreferencedVertices = 0;
  BoundingBox bbox;
  std::vector<std::string> problems;  // human-readable notes on what was found and repaired
};

enum class RingItem { OutgoingHalfedge, Face, Neighbour };
template <RingItem Item>
class VertexRing;

class TriMesh {
 public:
  /// Validates and builds. See the file comment for what is checked and repaired. `notes` (e.g. from a
  /// loader: "3 polygons were triangulated") are prepended to the summary's problems.
  static Expected<TriMesh> build(std::vector<Vec3> positions, std::vector<Triangle> triangles,
                                 const BuildLimits& limits = {}, std::vector<std::string> notes = {});

  int32_t numVertices() const { return static_cast<int32_t>(positions_.size()); }
  int32_t numFaces() const { return static_cast<int32_t>(triangles_.size()); }
  const std::vector<Vec3>& positions() const { return positions_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  const Vec3& position(int32_t v) const { return positions_[v]; }
  const Triangle& triangle(int32_t f) const { return triangles_[f]; }

  // Half-edge connectivity (see file comment).
  static int32_t face(int32_t h) { return h / 3; }
  static int32_t next(int32_t h) { return h - h % 3 + (h % 3 + 1) % 3; }
  static int32_t prev(int32_t h) { return h - h % 3 + (h % 3 + 2) % 3; }
  int32_t twin(int32_t h) const { return adjacency_[h / 3].twins[h % 3]; }
  const FaceAdjacency& adjacency(int32_t f) const { return adjacency_[f]; }
  const FaceAdjacency* adjacencyData() const { return adjacency_.data(); }
  int32_t tail(int32_t h) const { return triangles_[h / 3][h % 3]; }
  int32_t head(int32_t h) const { return triangles_[h / 3][(h % 3 + 1) % 3]; }
  bool isBoundaryHalfedge(int32_t h) const { return twin(h) < 0; }
  /// The next outgoing halfedge counter-clockwise around tail(h): twin(prev(h)), −1 at the boundary
  /// (with one division by 3 instead of two).
  int32_t nextOutgoing(int32_t h) const {
    const int32_t f = h / 3, k = h - 3 * f;
    return adjacency_[f].twins[k == 0 ? 2 : k - 1];
  }
  /// An outgoing halfedge of v (tail(h) == v), -1 if v is unreferenced. For a boundary vertex it is
  /// the outgoing boundary halfedge, so rotating counter-clockwise with h = twin(prev(h)) from it visits
  /// the whole fan (until -1); for an interior vertex the rotation comes back to where it started.
  int32_t vertexHalfedge(int32_t v) const { return vertexHalfedge_[v]; }
  bool isBoundaryVertex(int32_t v) const { return isBoundaryVertex_[v] != 0; }

  // The one-ring of vertex v, counter-clockwise from vertexHalfedge(v) (see VertexRing below); empty for
  // an unreferenced vertex. `for (int32_t h : mesh.outgoingHalfedges(v))` instead of hand-written
  // rotations.
  /// Every halfedge leaving v, one per face around v.
  VertexRing<RingItem::OutgoingHalfedge> outgoingHalfedges(int32_t v) const;
  /// Every face around v (face(h) of each outgoing halfedge).
  VertexRing<RingItem::Face> vertexFaces(int32_t v) const;
  /// Every vertex joined to v by an edge: head(h) of each outgoing halfedge, and for a boundary vertex
  /// last the tail of the incoming boundary halfedge (the fan's other boundary neighbour).
  VertexRing<RingItem::Neighbour> vertexNeighbours(int32_t v) const;

  const std::vector<std::vector<int32_t>>& boundaryLoops() const { return boundaryLoops_; }
  /// Unit normal of face f (zero for a degenerate face) and its area.
  const Vec3& faceNormal(int32_t f) const { return faceNormals_[f]; }
  double faceArea(int32_t f) const { return faceAreas_[f]; }
  /// Mean length of the mesh's edges (each counted once), the scale of its relative tolerances.
  double meanEdgeLength() const { return meanEdgeLength_; }
  bool isDegenerateFace(int32_t f) const { return degenerate_[f] != 0; }

  const MeshSummary& summary() const { return summary_; }

 private:
  TriMesh() = default;
  std::vector<Vec3> positions_;
  std::vector<Triangle> triangles_;
  std::vector<FaceAdjacency> adjacency_;
  std::vector<int32_t> vertexHalfedge_;
  std::vector<uint8_t> isBoundaryVertex_;
  std::vector<std::vector<int32_t>> boundaryLoops_;
  std::vector<Vec3> faceNormals_;
  std::vector<double> faceAreas_;
  std::vector<uint8_t> degenerate_;
  double meanEdgeLength_ = 1;
  MeshSummary summary_;
};

/// A range over the one-ring of a vertex, rotating counter-clockwise with h → twin(prev(h))
/// (TriMesh::nextOutgoing) from vertexHalfedge(v). For a boundary vertex that is the outgoing boundary
/// halfedge, so the rotation visits the whole fan and stops where it meets the boundary again
/// (twin = −1); for an interior vertex it stops when it is back at the start. Each step is one twin look-up; nothing is
/// allocated. (The rotation always ends: twin∘prev is one-to-one, so it can only come back to its start or stop.)
template <RingItem Item>
class VertexRing {
 public:
  class iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = int32_t;
    using difference_type = std::ptrdiff_t;
    using pointer = const int32_t*;
    using reference = int32_t;

    iterator() = default;
    iterator(const TriMesh* mesh, int32_t h) : mesh_(mesh), h_(h), start_(h) {}
    int32_t operator*() const {
      if constexpr (Item == RingItem::OutgoingHalfedge) return h_;
      else if constexpr (Item == RingItem::Face) return TriMesh::face(h_);
      else return closing_ ? mesh_->tail(TriMesh::prev(h_)) : mesh_->head(h_);
    }
    iterator& operator++() {
      if constexpr (Item == RingItem::Neighbour) {
        if (closing_) {  // the boundary neighbour was the last one
          closing_ = false;
          h_ = -1;
          return *this;
        }
        const int32_t n = mesh_->nextOutgoing(h_);
        if (n < 0) closing_ = true;  // stay on h_: its prev's tail is the last neighbour
        else h_ = n == start_ ? -1 : n;
      } else {
        h_ = mesh_->nextOutgoing(h_);
        if (h_ == start_) h_ = -1;
      }
      return *this;
    }
    iterator operator++(int) {
      iterator old = *this;
      ++*this;
      return old;
    }
    bool operator==(const iterator& o) const { return h_ == o.h_ && closing_ == o.closing_; }
    bool operator!=(const iterator& o) const { return !(*this == o); }

   private:
    const TriMesh* mesh_ = nullptr;
    int32_t h_ = -1, start_ = -1;
    bool closing_ = false;
  };

  VertexRing(const TriMesh& mesh, int32_t v) : mesh_(&mesh), first_(mesh.vertexHalfedge(v)) {}
  iterator begin() const { return first_ < 0 ? end() : iterator(mesh_, first_); }
  iterator end() const { return iterator(); }

 private:
  const TriMesh* mesh_;
  int32_t first_;
};

inline VertexRing<RingItem::OutgoingHalfedge> TriMesh::outgoingHalfedges(int32_t v) const { return {*this, v}; }
inline VertexRing<RingItem::Face> TriMesh::vertexFaces(int32_t v) const { return {*this, v}; }
inline VertexRing<RingItem::Neighbour> TriMesh::vertexNeighbours(int32_t v) const { return {*this, v}; }

/// Builds from flat arrays as a caller (JS, a file-less API) hands them: xyz has 3 coordinates per
/// vertex, indices 3 vertex indices per face. Checks the lengths and that every index is a
/// non-negative integer before TriMesh::build does the rest.
Expected<TriMesh> meshFromFlatArrays(const std::vector<double>& xyz, const std::vector<double>& indices,
                                     const BuildLimits& limits = {});

}  // namespace straightest
