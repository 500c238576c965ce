// Shared by the libFuzzer harnesses: a failing-invariant macro, independent checks of a built
// TriMesh, an independent oracle for what TriMesh::build must answer on given input, and checks of
// Error values. Everything here recomputes from scratch (sorting, union-find) rather than reusing
// the library's own tables, so a bug in the library cannot hide behind the same bug in the check.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace fuzz {

using namespace straightest;

[[noreturn]] inline void fail(const char* file, int line, const char* cond, const char* fmt, ...) {
  std::fprintf(stderr, "\n==== INVARIANT VIOLATED at %s:%d: %s\n     ", file, line, cond);
  va_list args;
  va_start(args, fmt);
  std::vfprintf(stderr, fmt, args);
  va_end(args);
  std::fprintf(stderr, "\n");
  std::fflush(stderr);
  std::abort();
}

// CHECK(condition, printf-style message...): aborts (a libFuzzer crash) with the message.
#define FUZZ_CHECK(cond, ...)                                          \
  do {                                                                 \
    if (!(cond)) ::fuzz::fail(__FILE__, __LINE__, #cond, __VA_ARGS__); \
  } while (0)

/// Every error carries a known category and a non-empty message.
inline void checkError(const Error& e, const char* where) {
  const char* name = errorCodeName(e.code);
  FUZZ_CHECK(name != nullptr && std::strcmp(name, "unknown") != 0, "%s: error with an invalid category %d", where,
             static_cast<int>(e.code));
  FUZZ_CHECK(!e.message.empty(), "%s: error '%s' with an empty message", where, name);
  FUZZ_CHECK(e.message.size() < 100000, "%s: error message of %zu bytes", where, e.message.size());
}

// ---------------------------------------------------------------- small helpers

struct UnionFind {
  std::vector<int32_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int32_t find(int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int32_t a, int32_t b) { parent[find(a)] = find(b); }
};

inline uint64_t edgeKey(int32_t a, int32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

// ---------------------------------------------------------------- invariants of a built mesh

/// Checks a mesh that TriMesh::build accepted. When the input is given, also that positions are kept
/// and every face is either kept or flipped (a, b, c) -> (a, c, b), consistently with the summary.
inline void checkMesh(const TriMesh& m, const std::vector<Vec3>* inPositions = nullptr,
                      const std::vector<Triangle>* inTriangles = nullptr) {
  const int32_t V = m.numVertices(), F = m.numFaces();
  const int32_t H = 3 * F;
  FUZZ_CHECK(V > 0 && F > 0, "built mesh with %d vertices and %d faces", V, F);
  FUZZ_CHECK(static_cast<int32_t>(m.positions().size()) == V && static_cast<int32_t>(m.triangles().size()) == F,
             "array sizes");

  // Faces: indices in range, three distinct corners.
  std::vector<int32_t> corners(V, 0);
  for (int32_t f = 0; f < F; ++f) {
    const Triangle& t = m.triangle(f);
    for (int k = 0; k < 3; ++k) {
      FUZZ_CHECK(t[k] >= 0 && t[k] < V, "face %d corner %d = %d out of range", f, k, t[k]);
      ++corners[t[k]];
    }
    FUZZ_CHECK(t[0] != t[1] && t[1] != t[2] && t[0] != t[2], "face %d repeats a vertex", f);
  }

  // Twins: symmetric and reversed.
  int64_t boundaryHalfedges = 0;
  for (int32_t h = 0; h < H; ++h) {
    FUZZ_CHECK(m.tail(h) == m.triangle(h / 3)[h % 3] && m.head(h) == m.tail(TriMesh::next(h)), "tail/head of %d", h);
    FUZZ_CHECK(TriMesh::next(TriMesh::prev(h)) == h && TriMesh::face(TriMesh::next(h)) == h / 3, "next/prev of %d", h);
    const int32_t t = m.twin(h);
    FUZZ_CHECK(t >= -1 && t < H, "twin(%d) = %d out of range", h, t);
    if (t < 0) {
      ++boundaryHalfedges;
      FUZZ_CHECK(m.isBoundaryHalfedge(h), "isBoundaryHalfedge(%d)", h);
      continue;
    }
    FUZZ_CHECK(t != h && TriMesh::face(t) != TriMesh::face(h), "twin(%d) = %d in the same face", h, t);
    FUZZ_CHECK(m.twin(t) == h, "twin(twin(%d)) = %d", h, m.twin(t));
    FUZZ_CHECK(m.tail(t) == m.head(h) && m.head(t) == m.tail(h),
               "twin %d -> %d is not reversed: (%d,%d) vs (%d,%d): neighbouring faces %d and %d are not consistently "
               "oriented",
               h, t, m.tail(h), m.head(h), m.tail(t), m.head(t), h / 3, t / 3);
  }

  // Undirected edges from scratch: each used once (boundary) or twice (twins, opposite directions).
  std::vector<std::pair<uint64_t, int32_t>> keyed(H);
  for (int32_t h = 0; h < H; ++h) keyed[h] = {edgeKey(m.tail(h), m.head(h)), h};
  std::sort(keyed.begin(), keyed.end());
  int64_t edges = 0;
  for (size_t i = 0; i < keyed.size();) {
    size_t j = i;
    while (j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
    ++edges;
    FUZZ_CHECK(j - i <= 2, "edge (%d,%d) used by %zu faces", m.tail(keyed[i].second), m.head(keyed[i].second), j - i);
    if (j - i == 2) {
      const int32_t a = keyed[i].second, b = keyed[i + 1].second;
      FUZZ_CHECK(m.twin(a) == b && m.twin(b) == a, "halfedges %d and %d share an edge but are not twins", a, b);
      FUZZ_CHECK(m.tail(a) == m.head(b), "faces %d and %d run edge (%d,%d) the same way (inconsistent orientation)",
                 a / 3, b / 3, m.tail(a), m.head(a));
    } else {
      FUZZ_CHECK(m.twin(keyed[i].second) < 0, "lone halfedge %d has a twin", keyed[i].second);
    }
    i = j;
  }

  // Vertices: outgoing halfedge, boundary flag, fans.
  std::vector<int32_t> outBoundary(V, -1);
  for (int32_t h = 0; h < H; ++h)
    if (m.twin(h) < 0) {
      FUZZ_CHECK(outBoundary[m.tail(h)] < 0, "vertex %d has two outgoing boundary halfedges", m.tail(h));
      outBoundary[m.tail(h)] = h;
    }
  int64_t referenced = 0;
  for (int32_t v = 0; v < V; ++v) {
    const int32_t vh = m.vertexHalfedge(v);
    if (corners[v] == 0) {
      FUZZ_CHECK(vh == -1, "unreferenced vertex %d has halfedge %d", v, vh);
      FUZZ_CHECK(!m.isBoundaryVertex(v), "unreferenced vertex %d is a boundary vertex", v);
      continue;
    }
    ++referenced;
    FUZZ_CHECK(vh >= 0 && vh < H && m.tail(vh) == v, "vertexHalfedge(%d) = %d does not leave it", v, vh);
    FUZZ_CHECK(m.isBoundaryVertex(v) == (outBoundary[v] >= 0), "isBoundaryVertex(%d) wrong", v);
    if (m.isBoundaryVertex(v)) FUZZ_CHECK(vh == outBoundary[v], "boundary vertex %d: not its boundary halfedge", v);
    int32_t count = 0, h = vh;
    std::vector<int32_t> fan;
    do {
      FUZZ_CHECK(m.tail(h) == v, "fan of %d leaves it", v);
      fan.push_back(h / 3);
      ++count;
      h = m.twin(TriMesh::prev(h));
    } while (h >= 0 && h != vh && count <= corners[v]);
    FUZZ_CHECK(count == corners[v], "fan of vertex %d visits %d of its %d faces", v, count, corners[v]);
    FUZZ_CHECK((h < 0) == m.isBoundaryVertex(v), "fan of vertex %d: open=%d but boundary=%d", v, h < 0,
               m.isBoundaryVertex(v));
    std::sort(fan.begin(), fan.end());
    FUZZ_CHECK(std::adjacent_find(fan.begin(), fan.end()) == fan.end(), "fan of %d repeats a face", v);
  }

  // Boundary loops: every loop vertex on the boundary, every boundary halfedge exactly once.
  std::vector<uint8_t> used(H, 0);
  int64_t covered = 0;
  const auto& loops = m.boundaryLoops();
  for (size_t l = 0; l < loops.size(); ++l) {
    const auto& loop = loops[l];
    FUZZ_CHECK(loop.size() >= 3, "boundary loop %zu has %zu vertices", l, loop.size());
    if (l > 0) FUZZ_CHECK(loops[l - 1].size() >= loop.size(), "boundary loops not longest first");
    for (size_t i = 0; i < loop.size(); ++i) {
      const int32_t a = loop[i], b = loop[(i + 1) % loop.size()];
      FUZZ_CHECK(a >= 0 && a < V && m.isBoundaryVertex(a), "loop %zu vertex %d not a boundary vertex", l, a);
      const int32_t h = outBoundary[a];
      FUZZ_CHECK(h >= 0 && m.head(h) == b, "loop %zu: no boundary halfedge %d -> %d", l, a, b);
      FUZZ_CHECK(!used[h], "boundary halfedge %d covered twice", h);
      used[h] = 1;
      ++covered;
    }
  }
  FUZZ_CHECK(covered == boundaryHalfedges, "loops cover %lld of %lld boundary halfedges", (long long)covered,
             (long long)boundaryHalfedges);

  // Components from scratch.
  UnionFind uf(F);
  for (int32_t h = 0; h < H; ++h)
    if (m.twin(h) >= 0) uf.unite(h / 3, m.twin(h) / 3);
  int64_t components = 0;
  for (int32_t f = 0; f < F; ++f) components += uf.find(f) == f;

  // Geometry.
  int64_t degenerate = 0;
  for (int32_t f = 0; f < F; ++f) {
    const Triangle& t = m.triangle(f);
    const Vec3 c = cross(m.position(t[1]) - m.position(t[0]), m.position(t[2]) - m.position(t[0]));
    const double area = m.faceArea(f);
    FUZZ_CHECK(std::isfinite(area) && area >= 0, "face %d area %g", f, area);
    FUZZ_CHECK(std::abs(area - 0.5 * robustNorm(c)) <= 1e-12 * (1 + area), "face %d area %g vs %g", f, area,
               0.5 * robustNorm(c));
    const Vec3& n = m.faceNormal(f);
    degenerate += m.isDegenerateFace(f);
    if (m.isDegenerateFace(f)) {
      FUZZ_CHECK(n.x == 0 && n.y == 0 && n.z == 0, "degenerate face %d has a normal", f);
    } else {
      FUZZ_CHECK(std::abs(norm(n) - 1) < 1e-9, "face %d normal has length 1%+.3g", f, norm(n) - 1);
      FUZZ_CHECK(dot(n, c) > 0, "face %d normal points against its winding", f);
    }
  }
  for (int32_t v = 0; v < V; ++v) FUZZ_CHECK(isFinite(m.position(v)), "vertex %d not finite", v);

  // Summary.
  const MeshSummary& s = m.summary();
  FUZZ_CHECK(s.vertices == V && s.faces == F, "summary counts %lld/%lld vs %d/%d", (long long)s.vertices,
             (long long)s.faces, V, F);
  FUZZ_CHECK(s.edges == edges, "summary edges %lld vs %lld", (long long)s.edges, (long long)edges);
  FUZZ_CHECK(s.unreferencedVertices == V - referenced, "summary unreferenced %lld vs %lld",
             (long long)s.unreferencedVertices, (long long)(V - referenced));
  FUZZ_CHECK(s.eulerCharacteristic == referenced - edges + F, "Euler characteristic %lld vs V-E+F = %lld",
             (long long)s.eulerCharacteristic, (long long)(referenced - edges + F));
  FUZZ_CHECK(s.components == components, "summary components %lld vs %lld", (long long)s.components,
             (long long)components);
  FUZZ_CHECK(s.degenerateFaces == degenerate, "summary degenerate %lld vs %lld", (long long)s.degenerateFaces,
             (long long)degenerate);
  FUZZ_CHECK(s.boundaryLoopSizes.size() == loops.size(), "summary loop count");
  for (size_t l = 0; l < loops.size(); ++l)
    FUZZ_CHECK(s.boundaryLoopSizes[l] == static_cast<int64_t>(loops[l].size()), "summary loop %zu size", l);
  Vec3 lo = m.position(0), hi = m.position(0);
  for (const Vec3& p : m.positions()) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  FUZZ_CHECK(s.bbox.min.x == lo.x && s.bbox.min.y == lo.y && s.bbox.min.z == lo.z && s.bbox.max.x == hi.x &&
                 s.bbox.max.y == hi.y && s.bbox.max.z == hi.z,
             "summary bbox");
  FUZZ_CHECK(std::isfinite(s.bbox.diagonal()), "bbox diagonal not finite");

  // Against the input.
  if (inPositions) {
    FUZZ_CHECK(static_cast<int32_t>(inPositions->size()) == V, "vertex count changed");
    for (int32_t v = 0; v < V; ++v) {
      const Vec3 &a = (*inPositions)[v], &b = m.position(v);
      FUZZ_CHECK(a.x == b.x && a.y == b.y && a.z == b.z, "vertex %d moved", v);
    }
  }
  if (inTriangles) {
    FUZZ_CHECK(static_cast<int32_t>(inTriangles->size()) == F, "face count changed");
    std::vector<int64_t> flippedIn(F, 0);
    int64_t flipped = 0;
    for (int32_t f = 0; f < F; ++f) {
      const Triangle &a = (*inTriangles)[f], &b = m.triangle(f);
      const bool same = a == b, swapped = a[0] == b[0] && a[1] == b[2] && a[2] == b[1];
      FUZZ_CHECK(same || swapped, "face %d (%d,%d,%d) became (%d,%d,%d)", f, a[0], a[1], a[2], b[0], b[1], b[2]);
      if (!same) {
        ++flipped;
        ++flippedIn[uf.find(f)];
      }
    }
    FUZZ_CHECK(flipped == s.reorientedFaces, "reoriented %lld vs summary %lld", (long long)flipped,
               (long long)s.reorientedFaces);
    std::vector<int64_t> size(F, 0);
    for (int32_t f = 0; f < F; ++f) ++size[uf.find(f)];
    for (int32_t f = 0; f < F; ++f)
      FUZZ_CHECK(2 * flippedIn[f] <= size[f], "component of face %d: %lld of %lld faces flipped (not the minority)", f,
                 (long long)flippedIn[f], (long long)size[f]);
  }
}

// ---------------------------------------------------------------- what build() must answer

/// Independent judgement of positions + triangles, in TriMesh::build's order of checks. `allowed`
/// lists the acceptable error categories; empty means build must succeed.
struct Verdict {
  std::vector<ErrorCode> allowed;
  std::string why;
};

inline bool faceDegenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const double twice = robustNorm(cross(e1, e2));  // as TriMesh::build measures it
  return !(twice > kDegenerateRel * robustNorm(e1) * robustNorm(e2)) || !std::isfinite(twice);
}

inline Verdict judge(const std::vector<Vec3>& P, const std::vector<Triangle>& T) {
  const int64_t nv = static_cast<int64_t>(P.size()), nf = static_cast<int64_t>(T.size());
  if (nv == 0 || nf == 0) return {{ErrorCode::Empty}, "empty"};
  for (const Vec3& p : P)
    for (double c : {p.x, p.y, p.z})
      if (!(std::abs(c) <= kMaxCoordinate)) return {{ErrorCode::NonFinite}, "non-finite or huge coordinate"};
  for (const Triangle& t : T) {
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || t[k] >= nv) return {{ErrorCode::IndexOutOfRange}, "index out of range"};
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return {{ErrorCode::InvalidFace}, "repeated corner"};
  }
  // Edge multiplicities and duplicate faces.
  std::map<uint64_t, std::vector<int32_t>> edgeFaces;  // halfedges per undirected edge
  for (int32_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) edgeFaces[edgeKey(T[f][k], T[f][(k + 1) % 3])].push_back(3 * f + k);
  bool nonManifoldEdge = false;
  for (const auto& [key, hs] : edgeFaces) nonManifoldEdge |= hs.size() > 2;
  std::map<Triangle, int32_t> sortedFaces;
  bool duplicate = false;
  for (int32_t f = 0; f < nf; ++f) {
    Triangle s = T[f];
    std::sort(s.begin(), s.end());
    duplicate |= !sortedFaces.emplace(s, f).second;
  }
  if (nonManifoldEdge && duplicate) return {{ErrorCode::NonManifoldEdge, ErrorCode::DuplicateFace}, "edge/duplicate"};
  if (nonManifoldEdge) return {{ErrorCode::NonManifoldEdge}, "edge with more than two faces"};
  if (duplicate) return {{ErrorCode::DuplicateFace}, "duplicate face"};
  // Orientability: union-find with parity over the face graph.
  std::vector<int32_t> parent(nf), rank(nf, 0);
  std::vector<uint8_t> parity(nf, 0);  // orientation relative to the parent
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int32_t x) {  // union by rank keeps the trees shallow; no compression needed
    uint8_t p = 0;
    while (parent[x] != x) {
      p ^= parity[x];
      x = parent[x];
    }
    return std::make_pair(x, p);
  };
  auto tailOf = [&](int32_t h) { return T[h / 3][h % 3]; };
  for (const auto& [key, hs] : edgeFaces) {
    if (hs.size() != 2) continue;
    const uint8_t rel = tailOf(hs[0]) == tailOf(hs[1]);  // same direction: one must flip
    auto [ra, pa] = find(hs[0] / 3);
    auto [rb, pb] = find(hs[1] / 3);
    if (ra == rb) {
      if ((pa ^ pb) != rel) return {{ErrorCode::NonOrientable}, "not orientable"};
    } else {
      if (rank[ra] > rank[rb]) std::swap(ra, rb);
      parent[ra] = rb;
      parity[ra] = pa ^ pb ^ rel;
      if (rank[ra] == rank[rb]) ++rank[rb];
    }
  }
  // Vertex manifoldness: the faces around each vertex form one fan (connected through the edges at v).
  std::vector<std::vector<int32_t>> facesOf(nv);
  for (int32_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) facesOf[T[f][k]].push_back(f);
  for (int32_t v = 0; v < nv; ++v) {
    const auto& fs = facesOf[v];
    if (fs.size() <= 1) continue;
    std::map<int32_t, int32_t> local;
    for (size_t i = 0; i < fs.size(); ++i) local[fs[i]] = static_cast<int32_t>(i);
    UnionFind uf(fs.size());
    for (int32_t f : fs)
      for (int k = 0; k < 3; ++k) {
        const int32_t w = T[f][k];
        if (w == v) continue;
        for (int32_t h : edgeFaces[edgeKey(v, w)]) uf.unite(local[f], local[h / 3]);
      }
    int roots = 0;
    for (size_t i = 0; i < fs.size(); ++i) roots += uf.find(static_cast<int32_t>(i)) == static_cast<int32_t>(i);
    if (roots > 1) return {{ErrorCode::NonManifoldVertex}, "vertex with several fans"};
  }
  bool allDegenerate = true;
  for (const Triangle& t : T) allDegenerate &= faceDegenerate(P[t[0]], P[t[1]], P[t[2]]);
  if (allDegenerate) return {{ErrorCode::Degenerate}, "every face degenerate"};
  return {{}, "valid"};
}

/// Checks a build result against the oracle (and, on success, every mesh invariant).
inline void checkBuildResult(const std::vector<Vec3>& P, const std::vector<Triangle>& T, const Expected<TriMesh>& r,
                             const char* where) {
  const Verdict v = judge(P, T);
  if (r.ok()) {
    FUZZ_CHECK(v.allowed.empty(), "%s: build accepted a mesh the oracle rejects (%s)", where, v.why.c_str());
    checkMesh(r.value(), &P, &T);
  } else {
    checkError(r.error(), where);
    FUZZ_CHECK(!v.allowed.empty(), "%s: build rejected a valid mesh: %s: %s", where, errorCodeName(r.error().code),
               r.error().message.c_str());
    FUZZ_CHECK(std::find(v.allowed.begin(), v.allowed.end(), r.error().code) != v.allowed.end(),
               "%s: build said %s (%s), the oracle expected %s (%s)", where, errorCodeName(r.error().code),
               r.error().message.c_str(), errorCodeName(v.allowed[0]), v.why.c_str());
  }
}

}  // namespace fuzz
