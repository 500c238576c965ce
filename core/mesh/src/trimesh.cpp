// Validation and connectivity for TriMesh. Every pass is linear (edge grouping buckets halfedges by
// their smaller vertex with a counting sort), so hostile meshes cannot make it quadratic.
#include "straightest/mesh/trimesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace straightest {
namespace {

std::string str(const Vec3& p) {
  std::ostringstream s;
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

Error err(ErrorCode code, const std::string& message) { return Error{code, message}; }

/// The unit normal of a triangle with edges e1, e2 and c = e1 × e2, |c| = twiceArea > 0. For edges
/// below ~1e-154 the components of c are subnormal, hold few digits, and c / |c| is not unit length;
/// there the edges are scaled to unit size before the cross product.
Vec3 unitNormal(const Vec3& e1, const Vec3& e2, const Vec3& c, double twiceArea) {
  if (twiceArea > 1e-140) return c / twiceArea;
  const Vec3 scaled = cross(e1 / largestComponent(e1), e2 / largestComponent(e2));
  return scaled / norm(scaled);
}

/// The connected components of the faces, joined across each edge's two halfedges (mate).
int32_t countComponents(const std::vector<int32_t>& mate) {
  std::vector<int32_t> parent(mate.size() / 3);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int32_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];  // path halving
    return f;
  };
  int32_t components = static_cast<int32_t>(parent.size());
  for (size_t h = 0; h < mate.size(); ++h) {
    if (mate[h] < static_cast<int32_t>(h)) continue;  // each edge once (and boundary halfedges never)
    const int32_t a = root(static_cast<int32_t>(h / 3)), b = root(mate[h] / 3);
    if (a == b) continue;
    parent[std::max(a, b)] = std::min(a, b);
    --components;
  }
  return components;
}

}  // namespace

Expected<TriMesh> TriMesh::build(std::vector<Vec3> positions, std::vector<Triangle> triangles,
                                 const BuildLimits& limits, std::vector<std::string> notes) {
  const int64_t nv = static_cast<int64_t>(positions.size());
  const int64_t nf = static_cast<int64_t>(triangles.size());
  if (nv > limits.maxVertices || nv > std::numeric_limits<int32_t>::max() / 2)
    return err(ErrorCode::TooLarge, "mesh has " + std::to_string(nv) + " vertices, more than the limit of " +
                                        std::to_string(limits.maxVertices));
  if (nf > limits.maxFaces || nf > std::numeric_limits<int32_t>::max() / 4)
    return err(ErrorCode::TooLarge,
               "mesh has " + std::to_string(nf) + " faces, more than the limit of " + std::to_string(limits.maxFaces));
  if (nv == 0) return err(ErrorCode::Empty, "mesh has no vertices");
  if (nf == 0) return err(ErrorCode::Empty, "mesh has no faces (" + std::to_string(nv) + " vertices)");

  for (int64_t v = 0; v < nv; ++v) {
    const Vec3& p = positions[v];
    if (!isFinite(p))
      return err(ErrorCode::NonFinite, "vertex " + std::to_string(v) + " has a non-finite coordinate " + str(p));
    if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kMaxCoordinate)
      return err(ErrorCode::NonFinite, "vertex " + std::to_string(v) + " has a coordinate too large to compute with " +
                                           str(p) + " (|x| > 1e50 overflows)");
  }

  for (int64_t f = 0; f < nf; ++f) {
    const Triangle& t = triangles[f];
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || t[k] >= nv)
        return err(ErrorCode::IndexOutOfRange, "face " + std::to_string(f) + " refers to vertex " +
                                                   std::to_string(t[k]) + ", but the mesh has " + std::to_string(nv) +
                                                   " vertices (valid: 0.." + std::to_string(nv - 1) + ")");
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      return err(ErrorCode::InvalidFace, "face " + std::to_string(f) + " uses a vertex twice (" + std::to_string(t[0]) +
                                             ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")");
  }

  // Group halfedges by undirected edge: bucket by the smaller endpoint (counting sort), then sort
  // each small bucket by the larger endpoint. A bucket entry is the key (larger endpoint << 32 |
  // halfedge), so the sort compares plain integers in place instead of looking up each halfedge's
  // endpoints again (the order is the same: by the larger endpoint, then by halfedge).
  const int32_t nh = static_cast<int32_t>(3 * nf);
  auto tailOf = [&](int32_t h) { return triangles[h / 3][h % 3]; };
  auto headOf = [&](int32_t h) { return triangles[h / 3][(h % 3 + 1) % 3]; };
  std::vector<int32_t> bucketStart(nv + 1, 0);
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) ++bucketStart[std::min(t[k], t[k == 2 ? 0 : k + 1]) + 1];
  std::partial_sum(bucketStart.begin(), bucketStart.end(), bucketStart.begin());
  std::vector<uint64_t> bucket(nh);
  {
    std::vector<int32_t> fill(bucketStart.begin(), bucketStart.end() - 1);
    for (int32_t f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) {
        const int32_t a = triangles[f][k], b = triangles[f][k == 2 ? 0 : k + 1];
        bucket[fill[std::min(a, b)]++] = uint64_t(uint32_t(std::max(a, b))) << 32 | uint32_t(3 * f + k);
      }
  }
  auto halfedgeOf = [](uint64_t key) { return static_cast<int32_t>(key & 0xffffffffu); };
  auto otherEndOf = [](uint64_t key) { return static_cast<int32_t>(key >> 32); };
  std::vector<int32_t> mate(nh, -1);          // the other halfedge of the same edge (before orientation repair)
  std::vector<uint8_t> sameDirection(nh, 0);  // mate runs the same way: one of the two faces is flipped
  bool anySameDirection = false;
  for (int64_t v = 0; v < nv; ++v) {
    auto first = bucket.begin() + bucketStart[v], last = bucket.begin() + bucketStart[v + 1];
    std::sort(first, last);
    for (auto it = first; it != last;) {
      const int32_t other = otherEndOf(*it);
      auto end = it;
      while (end != last && otherEndOf(*end) == other) ++end;
      const auto count = end - it;
      if (count > 2) {
        std::string fs;
        for (auto j = it; j != end && j - it < 6; ++j) fs += (j == it ? "" : ", ") + std::to_string(halfedgeOf(*j) / 3);
        return err(ErrorCode::NonManifoldEdge, "edge (" + std::to_string(v) + ", " + std::to_string(other) +
                                                   ") is shared by " + std::to_string(count) + " faces (" + fs +
                                                   (count > 6 ? ", ..." : "") + ")");
      }
      if (count == 2) {
        const int32_t a = halfedgeOf(it[0]), b = halfedgeOf(it[1]);
        if (a / 3 == b / 3) {  // cannot happen without a repeated vertex, which was rejected above
          return err(ErrorCode::InvalidFace, "face " + std::to_string(a / 3) + " uses an edge twice");
        }
        if (tailOf(a) == tailOf(b)) {
          // Same direction: either inconsistent orientation, or a duplicate face. Check duplicates.
          const Triangle& ta = triangles[a / 3];
          const Triangle& tb = triangles[b / 3];
          auto sorted = [](Triangle t) {
            std::sort(t.begin(), t.end());
            return t;
          };
          if (sorted(ta) == sorted(tb))
            return err(ErrorCode::DuplicateFace, "faces " + std::to_string(a / 3) + " and " + std::to_string(b / 3) +
                                                     " have the same vertices (" + std::to_string(ta[0]) + ", " +
                                                     std::to_string(ta[1]) + ", " + std::to_string(ta[2]) + ")");
          sameDirection[a] = sameDirection[b] = 1;
          anySameDirection = true;
        }
        mate[a] = b;
        mate[b] = a;
      }
      it = end;
    }
  }
  // Opposite-direction duplicates (f and its mirror) share all three edges: detect them too.
  for (int64_t f = 0; f < nf; ++f) {
    const int32_t m0 = mate[3 * f], m1 = mate[3 * f + 1], m2 = mate[3 * f + 2];
    if (m0 >= 0 && m1 >= 0 && m2 >= 0 && m0 / 3 == m1 / 3 && m1 / 3 == m2 / 3)
      return err(ErrorCode::DuplicateFace, "faces " + std::to_string(f) + " and " + std::to_string(m0 / 3) +
                                               " have the same vertices (" + std::to_string(triangles[f][0]) + ", " +
                                               std::to_string(triangles[f][1]) + ", " +
                                               std::to_string(triangles[f][2]) + ")");
  }

  // Orientation: breadth-first over faces through shared edges; flip[g] = flip[f] xor sameDirection.
  // When no edge is crossed by two same-direction halfedges the faces already agree: nothing is
  // flipped and nothing can conflict, so only the components are counted, by union–find over the
  // mates in face order (nearby in memory, where the breadth-first walk jumps across the mesh).
  std::vector<int8_t> flip(nf, anySameDirection ? -1 : 0);
  int32_t components = 0;
  int64_t reoriented = 0;
  if (!anySameDirection) {
    components = countComponents(mate);
  } else {
    std::vector<int32_t> queue;
    queue.reserve(nf);
    for (int32_t seed = 0; seed < nf; ++seed) {
      if (flip[seed] >= 0) continue;
      const size_t begin = queue.size();
      flip[seed] = 0;
      queue.push_back(seed);
      for (size_t q = begin; q < queue.size(); ++q) {
        const int32_t f = queue[q];
        for (int k = 0; k < 3; ++k) {
          const int32_t h = 3 * f + k, m = mate[h];
          if (m < 0) continue;
          const int32_t g = m / 3;
          const int8_t want = static_cast<int8_t>(flip[f] ^ sameDirection[h]);
          if (flip[g] < 0) {
            flip[g] = want;
            queue.push_back(g);
          } else if (flip[g] != want) {
            return err(ErrorCode::NonOrientable, "the surface is not orientable (like a Möbius strip): faces " +
                                                     std::to_string(f) + " and " + std::to_string(g) +
                                                     " across edge (" + std::to_string(tailOf(h)) + ", " +
                                                     std::to_string(headOf(h)) + ") cannot be oriented consistently");
          }
        }
      }
      const size_t size = queue.size() - begin;
      size_t flipped = 0;
      for (size_t q = begin; q < queue.size(); ++q) flipped += flip[queue[q]];
      if (2 * flipped > size) {  // keep the majority's orientation
        for (size_t q = begin; q < queue.size(); ++q) flip[queue[q]] ^= 1;
        flipped = size - flipped;
      }
      reoriented += static_cast<int64_t>(flipped);
      ++components;
    }
  }

  TriMesh mesh;
  // Apply flips: (a, b, c) -> (a, c, b). Halfedge k of a flipped face becomes halfedge 2 - k.
  auto newHalfedge = [&](int32_t h) {
    const int32_t f = h / 3, k = h % 3;
    return 3 * f + (flip[f] ? 2 - k : k);
  };
  for (int64_t f = 0; f < nf; ++f)
    if (flip[f]) std::swap(triangles[f][1], triangles[f][2]);
  std::vector<int32_t> twin(nh, -1);
  int64_t edges = 0;
  for (int32_t h = 0; h < nh; ++h) {
    if (mate[h] >= 0) {
      twin[newHalfedge(h)] = newHalfedge(mate[h]);
      if (h < mate[h]) ++edges;
    } else {
      ++edges;
    }
  }
  mesh.positions_ = std::move(positions);
  mesh.triangles_ = std::move(triangles);
  mesh.adjacency_.resize(nf);
  for (int32_t f = 0; f < nf; ++f)
    mesh.adjacency_[f] = {mesh.triangles_[f], {twin[3 * f], twin[3 * f + 1], twin[3 * f + 2]}};

  // Vertex fans: one outgoing halfedge per vertex (the boundary one when there is one); a vertex whose
  // faces are not reached by rotating around it from there is non-manifold (several fans).
  std::vector<int32_t> cornerCount(nv, 0);
  mesh.vertexHalfedge_.assign(nv, -1);
  mesh.isBoundaryVertex_.assign(nv, 0);
  for (int32_t h = 0; h < nh; ++h) {
    const int32_t v = mesh.tail(h);
    ++cornerCount[v];
    if (twin[h] < 0) {
      if (mesh.isBoundaryVertex_[v])
        return err(ErrorCode::NonManifoldVertex, "vertex " + std::to_string(v) +
                                                     " is where separate pieces of surface touch (two boundary "
                                                     "edges leave it, e.g. two triangles sharing only this corner)");
      mesh.isBoundaryVertex_[v] = 1;
      mesh.vertexHalfedge_[v] = h;
    } else if (mesh.vertexHalfedge_[v] < 0) {
      mesh.vertexHalfedge_[v] = h;
    }
  }
  int64_t unreferenced = 0;
  for (int32_t v = 0; v < nv; ++v) {
    if (mesh.vertexHalfedge_[v] < 0) {
      ++unreferenced;
      continue;
    }
    int32_t count = 0;
    for (int32_t h : mesh.outgoingHalfedges(v)) {
      (void)h;
      if (++count > cornerCount[v]) break;
    }
    if (count != cornerCount[v])
      return err(ErrorCode::NonManifoldVertex,
                 "vertex " + std::to_string(v) + " joins " + std::to_string(cornerCount[v]) +
                     " faces that do not form a single fan around it (separate pieces of surface touch there)");
  }

  // Boundary loops, following boundary halfedges (the surface on the left), longest first.
  std::vector<uint8_t> visited(nh, 0);
  for (int32_t h0 = 0; h0 < nh; ++h0) {
    if (twin[h0] >= 0 || visited[h0]) continue;
    std::vector<int32_t> loop;
    int32_t h = h0;
    while (!visited[h]) {
      visited[h] = 1;
      loop.push_back(mesh.tail(h));
      h = mesh.vertexHalfedge_[mesh.head(h)];  // the unique outgoing boundary halfedge of the head
    }
    mesh.boundaryLoops_.push_back(std::move(loop));
  }
  std::stable_sort(mesh.boundaryLoops_.begin(), mesh.boundaryLoops_.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });

  // Face geometry.
  mesh.faceNormals_.resize(nf);
  mesh.faceAreas_.resize(nf);
  mesh.degenerate_.assign(nf, 0);
  int64_t degenerate = 0;
  double edgeLengthSum = 0;  // an interior edge is seen from both faces: half from each
  for (int32_t f = 0; f < nf; ++f) {
    const Triangle& t = mesh.triangles_[f];
    const Vec3 e1 = mesh.positions_[t[1]] - mesh.positions_[t[0]];
    const Vec3 e2 = mesh.positions_[t[2]] - mesh.positions_[t[0]];
    const double lengths[3] = {robustNorm(e1), robustNorm(mesh.positions_[t[2]] - mesh.positions_[t[1]]),
                               robustNorm(e2)};
    for (int k = 0; k < 3; ++k) edgeLengthSum += twin[3 * f + k] < 0 ? lengths[k] : 0.5 * lengths[k];
    const Vec3 c = cross(e1, e2);
    const double twiceArea = robustNorm(c);
    mesh.faceAreas_[f] = 0.5 * twiceArea;
    const bool isDegenerate = !(twiceArea > kDegenerateRel * lengths[0] * lengths[2]) || !std::isfinite(twiceArea);
    mesh.degenerate_[f] = isDegenerate;
    degenerate += isDegenerate;
    mesh.faceNormals_[f] = isDegenerate ? Vec3{} : unitNormal(e1, e2, c, twiceArea);
  }

  if (edges > 0 && edgeLengthSum > 0) mesh.meanEdgeLength_ = edgeLengthSum / static_cast<double>(edges);
  if (degenerate == nf)
    return err(ErrorCode::Degenerate, "every face (" + std::to_string(nf) +
                                          ") has zero area: the vertices of each "
                                          "face are collinear or coincide");

  MeshSummary& s = mesh.summary_;
  s.vertices = nv;
  s.faces = nf;
  s.edges = edges;
  for (const auto& loop : mesh.boundaryLoops_) s.boundaryLoopSizes.push_back(static_cast<int64_t>(loop.size()));
  s.eulerCharacteristic = (nv - unreferenced) - edges + nf;
  s.components = components;
  s.degenerateFaces = degenerate;
  s.reorientedFaces = reoriented;
  s.unreferencedVertices = unreferenced;
  s.bbox.min = s.bbox.max = mesh.positions_[0];
  for (const Vec3& p : mesh.positions_) {
    s.bbox.min = {std::min(s.bbox.min.x, p.x), std::min(s.bbox.min.y, p.y), std::min(s.bbox.min.z, p.z)};
    s.bbox.max = {std::max(s.bbox.max.x, p.x), std::max(s.bbox.max.y, p.y), std::max(s.bbox.max.z, p.z)};
  }
  std::vector<int32_t>().swap(twin);  // now in adjacency_
  s.problems = std::move(notes);
  if (reoriented > 0)
    s.problems.push_back(std::to_string(reoriented) +
                         " faces had the opposite orientation of their neighbours "
                         "and were flipped");
  if (degenerate > 0) s.problems.push_back(std::to_string(degenerate) + " degenerate (zero-area) faces");
  if (unreferenced > 0)
    s.problems.push_back(std::to_string(unreferenced) + " vertices are not used by any face (kept, ignored)");
  if (components > 1) s.problems.push_back("the mesh has " + std::to_string(components) + " connected components");
  return mesh;
}

Expected<TriMesh> meshFromFlatArrays(const std::vector<double>& xyz, const std::vector<double>& indices,
                                     const BuildLimits& limits) {
  if (xyz.size() % 3 != 0)
    return err(ErrorCode::InvalidArgument,
               "positions has " + std::to_string(xyz.size()) + " numbers, not a multiple of 3 (x, y, z per vertex)");
  if (indices.size() % 3 != 0)
    return err(ErrorCode::InvalidArgument, "indices has " + std::to_string(indices.size()) +
                                               " numbers, not a multiple of 3 (3 vertices per triangle)");
  if (static_cast<int64_t>(xyz.size() / 3) > limits.maxVertices)
    return err(ErrorCode::TooLarge,
               std::to_string(xyz.size() / 3) + " vertices, over the limit of " + std::to_string(limits.maxVertices));
  if (static_cast<int64_t>(indices.size() / 3) > limits.maxFaces)
    return err(ErrorCode::TooLarge,
               std::to_string(indices.size() / 3) + " faces, over the limit of " + std::to_string(limits.maxFaces));
  std::vector<Vec3> positions(xyz.size() / 3);
  for (size_t v = 0; v < positions.size(); ++v) positions[v] = {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
  std::vector<Triangle> triangles(indices.size() / 3);
  for (size_t i = 0; i < indices.size(); ++i) {
    const double index = indices[i];
    if (!(index >= 0 && index <= std::numeric_limits<int32_t>::max() && index == std::floor(index)))
      return err(ErrorCode::IndexOutOfRange, "indices[" + std::to_string(i) + "] (face " + std::to_string(i / 3) +
                                                 ") is " + std::to_string(index) + ", not a vertex index");
    triangles[i / 3][i % 3] = static_cast<int32_t>(index);
  }
  return TriMesh::build(std::move(positions), std::move(triangles), limits);
}

}  // namespace straightest
