// Validation and connectivity for TriMesh. Every pass is linear (edge grouping buckets halfedges by
// their smaller vertex with a counting sort), so hostile meshes cannot make it quadratic.
#include "straightest/mesh/trimesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
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

/// The sizes against the limits, then every coordinate finite and every face three distinct vertices of
/// the mesh: the first thing wrong, if any.
std::optional<Error> checkInput(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
                                const BuildLimits& limits) {
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
  return std::nullopt;
}

/// Each halfedge's mate: the other halfedge of its undirected edge, before the orientation is repaired.
struct EdgeMates {
  std::vector<int32_t> mate;           // −1 on the boundary
  std::vector<uint8_t> sameDirection;  // mate runs the same way: one of the two faces is flipped
  bool anySameDirection = false;
};

/// Group halfedges by undirected edge: bucket by the smaller endpoint (counting sort), then sort
/// each small bucket by the larger endpoint. A bucket entry is the key (larger endpoint << 32 |
/// halfedge), so the sort compares plain integers in place instead of looking up each halfedge's
/// endpoints again (the order is the same: by the larger endpoint, then by halfedge). An edge of more
/// than two faces, and two faces with the same vertices, are errors.
Expected<EdgeMates> matchEdges(const std::vector<Triangle>& triangles, int64_t nv) {
  const int64_t nf = static_cast<int64_t>(triangles.size());
  const int32_t nh = static_cast<int32_t>(3 * nf);
  auto tailOf = [&](int32_t h) { return triangles[h / 3][h % 3]; };
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
  EdgeMates e;
  e.mate.assign(nh, -1);
  e.sameDirection.assign(nh, 0);
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
          e.sameDirection[a] = e.sameDirection[b] = 1;
          e.anySameDirection = true;
        }
        e.mate[a] = b;
        e.mate[b] = a;
      }
      it = end;
    }
  }
  // Opposite-direction duplicates (f and its mirror) share all three edges: detect them too.
  for (int64_t f = 0; f < nf; ++f) {
    const int32_t m0 = e.mate[3 * f], m1 = e.mate[3 * f + 1], m2 = e.mate[3 * f + 2];
    if (m0 >= 0 && m1 >= 0 && m2 >= 0 && m0 / 3 == m1 / 3 && m1 / 3 == m2 / 3)
      return err(ErrorCode::DuplicateFace, "faces " + std::to_string(f) + " and " + std::to_string(m0 / 3) +
                                               " have the same vertices (" + std::to_string(triangles[f][0]) + ", " +
                                               std::to_string(triangles[f][1]) + ", " +
                                               std::to_string(triangles[f][2]) + ")");
  }
  return e;
}

/// Which faces to flip so that every edge's two halfedges run opposite ways, and what that found.
struct Orientation {
  std::vector<int8_t> flip;
  int32_t components = 0;
  int64_t reoriented = 0;
};

/// Orientation: breadth-first over faces through shared edges; flip[g] = flip[f] xor sameDirection.
/// When no edge is crossed by two same-direction halfedges the faces already agree: nothing is
/// flipped and nothing can conflict, so only the components are counted, by union–find over the
/// mates in face order (nearby in memory, where the breadth-first walk jumps across the mesh).
Expected<Orientation> orientFaces(const std::vector<Triangle>& triangles, const EdgeMates& e) {
  const int64_t nf = static_cast<int64_t>(triangles.size());
  const std::vector<int32_t>& mate = e.mate;
  auto tailOf = [&](int32_t h) { return triangles[h / 3][h % 3]; };
  auto headOf = [&](int32_t h) { return triangles[h / 3][(h % 3 + 1) % 3]; };
  Orientation o;
  o.flip.assign(nf, e.anySameDirection ? -1 : 0);
  std::vector<int8_t>& flip = o.flip;
  if (!e.anySameDirection) {
    o.components = countComponents(mate);
    return o;
  }
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
        const int8_t want = static_cast<int8_t>(flip[f] ^ e.sameDirection[h]);
        if (flip[g] < 0) {
          flip[g] = want;
          queue.push_back(g);
        } else if (flip[g] != want) {
          return err(ErrorCode::NonOrientable, "the surface is not orientable (like a Möbius strip): faces " +
                                                   std::to_string(f) + " and " + std::to_string(g) + " across edge (" +
                                                   std::to_string(tailOf(h)) + ", " + std::to_string(headOf(h)) +
                                                   ") cannot be oriented consistently");
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
    o.reoriented += static_cast<int64_t>(flipped);
    ++o.components;
  }
  return o;
}

/// Each vertex's outgoing halfedge (the boundary one when there is one), whether it is on the boundary,
/// and its number of corners; a vertex two boundary edges leave is an error.
struct VertexFans {
  std::vector<int32_t> vertexHalfedge;
  std::vector<uint8_t> isBoundary;
  std::vector<int32_t> cornerCount;
};

Expected<VertexFans> vertexFans(const TriMesh& mesh, const std::vector<int32_t>& twin, int64_t nv) {
  const auto nh = static_cast<int32_t>(twin.size());
  VertexFans fans;
  fans.cornerCount.assign(nv, 0);
  fans.vertexHalfedge.assign(nv, -1);
  fans.isBoundary.assign(nv, 0);
  for (int32_t h = 0; h < nh; ++h) {
    const int32_t v = mesh.tail(h);
    ++fans.cornerCount[v];
    if (twin[h] < 0) {
      if (fans.isBoundary[v])
        return err(ErrorCode::NonManifoldVertex, "vertex " + std::to_string(v) +
                                                     " is where separate pieces of surface touch (two boundary "
                                                     "edges leave it, e.g. two triangles sharing only this corner)");
      fans.isBoundary[v] = 1;
      fans.vertexHalfedge[v] = h;
    } else if (fans.vertexHalfedge[v] < 0) {
      fans.vertexHalfedge[v] = h;
    }
  }
  return fans;
}

/// A vertex whose faces are not reached by rotating around it from its halfedge is non-manifold
/// (several fans). Returns the number of vertices no face uses.
Expected<int64_t> checkSingleFans(const TriMesh& mesh, const std::vector<int32_t>& cornerCount) {
  int64_t unreferenced = 0;
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    if (mesh.vertexHalfedge(v) < 0) {
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
  return unreferenced;
}

/// Boundary loops, following boundary halfedges (the surface on the left), longest first.
std::vector<std::vector<int32_t>> traceBoundaryLoops(const TriMesh& mesh, const std::vector<int32_t>& twin) {
  const auto nh = static_cast<int32_t>(twin.size());
  std::vector<std::vector<int32_t>> loops;
  std::vector<uint8_t> visited(nh, 0);
  for (int32_t h0 = 0; h0 < nh; ++h0) {
    if (twin[h0] >= 0 || visited[h0]) continue;
    std::vector<int32_t> loop;
    int32_t h = h0;
    while (!visited[h]) {
      visited[h] = 1;
      loop.push_back(mesh.tail(h));
      h = mesh.vertexHalfedge(mesh.head(h));  // the unique outgoing boundary halfedge of the head
    }
    loops.push_back(std::move(loop));
  }
  std::stable_sort(loops.begin(), loops.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return loops;
}

/// Face geometry: unit normals, areas, which faces are degenerate, and the sum of edge lengths.
struct FaceGeometry {
  std::vector<Vec3> normals;
  std::vector<double> areas;
  std::vector<uint8_t> degenerate;
  int64_t degenerateCount = 0;
  double edgeLengthSum = 0;  // an interior edge is seen from both faces: half from each
};

FaceGeometry faceGeometry(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
                          const std::vector<int32_t>& twin) {
  const auto nf = static_cast<int32_t>(triangles.size());
  FaceGeometry g;
  g.normals.resize(nf);
  g.areas.resize(nf);
  g.degenerate.assign(nf, 0);
  for (int32_t f = 0; f < nf; ++f) {
    const Triangle& t = triangles[f];
    const Vec3 e1 = positions[t[1]] - positions[t[0]];
    const Vec3 e2 = positions[t[2]] - positions[t[0]];
    const double lengths[3] = {robustNorm(e1), robustNorm(positions[t[2]] - positions[t[1]]), robustNorm(e2)};
    for (int k = 0; k < 3; ++k) g.edgeLengthSum += twin[3 * f + k] < 0 ? lengths[k] : 0.5 * lengths[k];
    const Vec3 c = cross(e1, e2);
    const double twiceArea = robustNorm(c);
    g.areas[f] = 0.5 * twiceArea;
    const bool isDegenerate = !(twiceArea > kDegenerateRel * lengths[0] * lengths[2]) || !std::isfinite(twiceArea);
    g.degenerate[f] = isDegenerate;
    g.degenerateCount += isDegenerate;
    g.normals[f] = isDegenerate ? Vec3{} : unitNormal(e1, e2, c, twiceArea);
  }
  return g;
}

/// The counts and the notes the summary reports.
MeshSummary summarize(const TriMesh& mesh, int64_t edges, int64_t unreferenced, int64_t degenerate,
                      const Orientation& orientation, std::vector<std::string> notes) {
  const int64_t nv = mesh.numVertices(), nf = mesh.numFaces();
  const int32_t components = orientation.components;
  const int64_t reoriented = orientation.reoriented;
  MeshSummary s;
  s.vertices = nv;
  s.faces = nf;
  s.edges = edges;
  for (const auto& loop : mesh.boundaryLoops()) s.boundaryLoopSizes.push_back(static_cast<int64_t>(loop.size()));
  s.eulerCharacteristic = (nv - unreferenced) - edges + nf;
  s.components = components;
  s.degenerateFaces = degenerate;
  s.reorientedFaces = reoriented;
  s.unreferencedVertices = unreferenced;
  s.bbox.min = s.bbox.max = mesh.positions()[0];
  for (const Vec3& p : mesh.positions()) {
    s.bbox.min = {std::min(s.bbox.min.x, p.x), std::min(s.bbox.min.y, p.y), std::min(s.bbox.min.z, p.z)};
    s.bbox.max = {std::max(s.bbox.max.x, p.x), std::max(s.bbox.max.y, p.y), std::max(s.bbox.max.z, p.z)};
  }
  s.problems = std::move(notes);
  if (reoriented > 0)
    s.problems.push_back(std::to_string(reoriented) +
                         " faces had the opposite orientation of their neighbours "
                         "and were flipped");
  if (degenerate > 0) s.problems.push_back(std::to_string(degenerate) + " degenerate (zero-area) faces");
  if (unreferenced > 0)
    s.problems.push_back(std::to_string(unreferenced) + " vertices are not used by any face (kept, ignored)");
  if (components > 1) s.problems.push_back("the mesh has " + std::to_string(components) + " connected components");
  return s;
}

}  // namespace

Expected<TriMesh> TriMesh::build(std::vector<Vec3> positions, std::vector<Triangle> triangles,
                                 const BuildLimits& limits, std::vector<std::string> notes) {
  if (auto bad = checkInput(positions, triangles, limits)) return *bad;
  const int64_t nv = static_cast<int64_t>(positions.size());
  const int64_t nf = static_cast<int64_t>(triangles.size());
  const int32_t nh = static_cast<int32_t>(3 * nf);
  auto mates = matchEdges(triangles, nv);
  if (!mates) return mates.error();
  const std::vector<int32_t>& mate = mates.value().mate;
  auto oriented = orientFaces(triangles, mates.value());
  if (!oriented) return oriented.error();
  const std::vector<int8_t>& flip = oriented.value().flip;

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

  auto fans = vertexFans(mesh, twin, nv);
  if (!fans) return fans.error();
  mesh.vertexHalfedge_ = std::move(fans.value().vertexHalfedge);
  mesh.isBoundaryVertex_ = std::move(fans.value().isBoundary);
  auto unreferenced = checkSingleFans(mesh, fans.value().cornerCount);
  if (!unreferenced) return unreferenced.error();
  mesh.boundaryLoops_ = traceBoundaryLoops(mesh, twin);

  FaceGeometry geometry = faceGeometry(mesh.positions_, mesh.triangles_, twin);
  mesh.faceNormals_ = std::move(geometry.normals);
  mesh.faceAreas_ = std::move(geometry.areas);
  mesh.degenerate_ = std::move(geometry.degenerate);
  const int64_t degenerate = geometry.degenerateCount;
  if (edges > 0 && geometry.edgeLengthSum > 0)
    mesh.meanEdgeLength_ = geometry.edgeLengthSum / static_cast<double>(edges);
  if (degenerate == nf)
    return err(ErrorCode::Degenerate, "every face (" + std::to_string(nf) +
                                          ") has zero area: the vertices of each "
                                          "face are collinear or coincide");
  std::vector<int32_t>().swap(twin);  // now in adjacency_
  mesh.summary_ = summarize(mesh, edges, unreferenced.value(), degenerate, oriented.value(), std::move(notes));
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
