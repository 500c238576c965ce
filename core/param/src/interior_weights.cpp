// interior_weights.cpp — the interior convex-combination weights and the system they make with a fixed boundary.
#include "straightest/param/interior_weights.hpp"

#include <algorithm>
#include <cmath>

#include "straightest/base/parallel_for.hpp"

namespace straightest {
namespace {

double angleBetween(const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

double cotAngle(const Vec3& a, const Vec3& b) {
  const double s = norm(cross(a, b));
  return s > 0 ? dot(a, b) / s : 0.0;
}

/// Barycentric coordinates of the origin in the 2D triangle (a, b, c); false if degenerate.
bool originBarycentric(const Vec2& a, const Vec2& b, const Vec2& c, double out[3]) {
  const Vec2 ab = b - a, ac = c - a, ao = Vec2{} - a;
  const double det = cross(ab, ac);
  if (!(std::abs(det) > 0)) return false;
  out[1] = cross(ao, ac) / det;
  out[2] = cross(ab, ao) / det;
  out[0] = 1 - out[1] - out[2];
  return true;
}

/// Scratch space for one row, reused across the rows of a chunk.
struct RowScratch {
  std::vector<int32_t> ring;
  std::vector<Vec3> e;
  std::vector<double> l, theta, w;
  std::vector<Vec2> q;
};

/// Ring indices wrap with a compare, not `%`: an integer division per access was a noticeable part of
/// the weights' cost.
inline size_t nextIn(size_t d, size_t k) { return k + 1 == d ? 0 : k + 1; }
inline size_t previousIn(size_t d, size_t k) { return k == 0 ? d - 1 : k - 1; }

/// v's one ring in counter-clockwise order (neighbours k and k+1 span face(h_k)), its edge vectors and
/// lengths, and the angles at v between them (s.theta, summing to *thetaSum). False if the ring is too
/// small or has a zero or non-finite edge or angle sum.
bool ringGeometry(const TriMesh& mesh, int32_t v, RowScratch& s, double& thetaSum) {
  s.ring.clear();
  for (int32_t neighbour : mesh.vertexNeighbours(v)) s.ring.push_back(neighbour);
  const size_t d = s.ring.size();
  const Vec3 p = mesh.position(v);
  s.e.resize(d);
  s.l.resize(d);
  s.theta.resize(d);
  s.w.assign(d, 0.0);
  bool ok = d >= 3;
  thetaSum = 0;
  for (size_t k = 0; k < d && ok; ++k) {
    s.e[k] = mesh.position(s.ring[k]) - p;
    s.l[k] = norm(s.e[k]);
    ok = s.l[k] > 0 && std::isfinite(s.l[k]);
  }
  for (size_t k = 0; k < d && ok; ++k) {
    s.theta[k] = angleBetween(s.e[k], s.e[nextIn(d, k)]);  // angle at v in face (v, k, k+1)
    thetaSum += s.theta[k];
  }
  return ok && thetaSum > 0;
}

void cotanWeights(const TriMesh& mesh, int32_t v, RowScratch& s) {
  const size_t d = s.ring.size();
  const Vec3 p = mesh.position(v);
  for (size_t k = 0; k < d; ++k) {
    const Vec3& pk = mesh.position(s.ring[k]);
    const Vec3& pn = mesh.position(s.ring[nextIn(d, k)]);      // third vertex of face (v, k, k+1)
    const Vec3& pp = mesh.position(s.ring[previousIn(d, k)]);  // third vertex of face (v, k-1, k)
    s.w[k] = cotAngle(p - pn, pk - pn) + cotAngle(p - pp, pk - pp);
  }
}

/// Floater's shape-preserving weights: the ring's geodesic polar map, then for each neighbour the
/// barycentric coordinates of the origin in a triangle it makes with an opposite segment, averaged.
/// False if some neighbour has no such triangle.
bool shapePreservingWeights(RowScratch& s, double thetaSum) {
  const size_t d = s.ring.size();
  std::vector<Vec2>& q = s.q;
  q.resize(d);
  double psi = 0;
  for (size_t k = 0; k < d; ++k) {
    q[k] = Vec2{std::cos(psi), std::sin(psi)} * s.l[k];
    psi += s.theta[k] * kTwoPi / thetaSum;
  }
  for (size_t k = 0; k < d; ++k) {
    bool found = false;
    for (size_t step = 1, a = nextIn(d, k); step + 1 < d && !found; ++step, a = nextIn(d, a)) {
      const size_t b = nextIn(d, a);  // the segment (q_a, q_b), a = k + step
      double mu[3];
      if (!originBarycentric(q[k], q[a], q[b], mu)) continue;
      if (mu[0] >= -1e-12 && mu[1] >= -1e-12 && mu[2] >= -1e-12) {
        s.w[k] += mu[0];
        s.w[a] += mu[1];
        s.w[b] += mu[2];
        found = true;
      }
    }
    if (!found) return false;
  }
  return true;
}

/// The weights of `kind` into s.w (unnormalized); false if they cannot be formed.
bool kindWeights(const TriMesh& mesh, int32_t v, WeightKind kind, RowScratch& s, double thetaSum) {
  const size_t d = s.ring.size();
  switch (kind) {
    case WeightKind::Uniform:
      for (size_t k = 0; k < d; ++k) s.w[k] = 1;
      return true;
    case WeightKind::MeanValue:
      for (size_t k = 0; k < d; ++k)
        s.w[k] = (std::tan(s.theta[previousIn(d, k)] / 2) + std::tan(s.theta[k] / 2)) / s.l[k];
      return true;
    case WeightKind::Cotan: cotanWeights(mesh, v, s); return true;
    case WeightKind::ShapePreserving: return shapePreservingWeights(s, thetaSum);
  }
  return false;
}

/// Interior vertex v's row: its one ring in counter-clockwise order (s.ring) and the normalized
/// weights (s.w). False when the weights fell back to uniform.
bool rowWeights(const TriMesh& mesh, int32_t v, WeightKind kind, RowScratch& s) {
  double thetaSum = 0;
  bool ok = ringGeometry(mesh, v, s, thetaSum) && kindWeights(mesh, v, kind, s, thetaSum);
  const size_t d = s.ring.size();
  std::vector<double>& w = s.w;
  double sum = 0;
  for (size_t k = 0; k < d && ok; ++k) {
    ok = std::isfinite(w[k]);
    sum += w[k];
  }
  const bool uniformFallback = !ok || !(sum > 0);
  if (uniformFallback) {
    w.assign(d, 1.0);
    sum = static_cast<double>(d);
  }
  for (size_t k = 0; k < d; ++k) w[k] /= sum;
  return !uniformFallback;
}

bool isInteriorRow(const TriMesh& mesh, int32_t v) { return mesh.vertexHalfedge(v) >= 0 && !mesh.isBoundaryVertex(v); }

}  // namespace

InteriorWeights interiorWeights(const TriMesh& mesh, WeightKind kind) {
  InteriorWeights W;
  CsrMatrix& M = W.weights;
  const int32_t nv = mesh.numVertices();
  // Rows are independent: vertices in chunks on every thread. First each interior vertex's row length
  // (its ring size), so that the rows' places in the matrix are known and the second pass writes each
  // row in place (no per-chunk copies to join; the matrix is the same for any thread count).
  constexpr size_t kVerticesPerChunk = 8192;
  std::vector<int32_t> rowLength(nv, 0);
  detail::parallelFor(nv, kVerticesPerChunk, [&](size_t, size_t begin, size_t end) {
    for (auto v = static_cast<int32_t>(begin); v < static_cast<int32_t>(end); ++v) {
      if (!isInteriorRow(mesh, v)) continue;
      int32_t d = 0;
      for (int32_t neighbour : mesh.vertexNeighbours(v)) {
        (void)neighbour;
        ++d;
      }
      rowLength[v] = d;
    }
  });
  std::vector<int32_t> rowOf(nv, -1);
  W.rows.reserve(nv);
  M.start.reserve(static_cast<size_t>(nv) + 1);
  // int32 is enough: a TriMesh numbers its 3·faces halfedges in int32, and a row holds one entry per
  // halfedge leaving its vertex.
  int32_t entries = 0;
  for (int32_t v = 0; v < nv; ++v) {
    if (!isInteriorRow(mesh, v)) continue;
    rowOf[v] = static_cast<int32_t>(W.rows.size());
    W.rows.push_back(v);
    entries += rowLength[v];
    M.start.push_back(entries);
  }
  M.col.resize(entries);
  M.value.resize(entries);
  std::vector<int64_t> fallbacks(detail::chunkCount(nv, kVerticesPerChunk), 0);
  detail::parallelFor(nv, kVerticesPerChunk, [&](size_t chunk, size_t begin, size_t end) {
    RowScratch scratch;
    for (auto v = static_cast<int32_t>(begin); v < static_cast<int32_t>(end); ++v) {
      if (rowOf[v] < 0) continue;
      if (!rowWeights(mesh, v, kind, scratch)) ++fallbacks[chunk];
      const size_t at = static_cast<size_t>(M.start[rowOf[v]]);
      std::copy(scratch.ring.begin(), scratch.ring.end(), M.col.begin() + at);
      std::copy(scratch.w.begin(), scratch.w.end(), M.value.begin() + at);
    }
  });
  for (int64_t f : fallbacks) W.uniformFallbacks += f;
  M.rows = static_cast<int32_t>(W.rows.size());
  M.cols = nv;
  return W;
}

InteriorSystem assembleInteriorSystem(const InteriorWeights& W, const std::vector<Vec2>& fixed) {
  const auto n = static_cast<int32_t>(W.rows.size());
  const CsrMatrix& M = W.weights;
  std::vector<int32_t> index(fixed.size(), -1);  // vertex → interior row
  for (int32_t r = 0; r < n; ++r) index[W.rows[r]] = r;
  InteriorSystem system;
  CsrMatrix& A = system.A;
  std::vector<double>& rhs = system.rhs;
  A.rows = A.cols = n;
  A.start.reserve(static_cast<size_t>(n) + 1);
  A.col.reserve(M.col.size() + n);
  A.value.reserve(M.col.size() + n);
  rhs.assign(2 * static_cast<size_t>(n), 0.0);
  for (int32_t r = 0; r < n; ++r) {
    A.col.push_back(r);
    A.value.push_back(1.0);
    for (int32_t k = M.start[r]; k < M.start[r + 1]; ++k) {
      const int32_t j = M.col[k];
      if (index[j] >= 0) {
        A.col.push_back(index[j]);
        A.value.push_back(-M.value[k]);
      } else {
        rhs[2 * r] += M.value[k] * fixed[j][0];
        rhs[2 * r + 1] += M.value[k] * fixed[j][1];
      }
    }
    A.start.push_back(static_cast<int32_t>(A.col.size()));
  }
  return system;
}

const char* weightKindName(WeightKind k) { return nameOf(kWeightKindNames, k); }
Expected<WeightKind> parseWeightKind(const std::string& name) { return parseName(kWeightKindNames, name, "weights"); }

}  // namespace straightest
