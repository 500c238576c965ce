#include "straightest/geodesic_distance.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>

namespace straightest {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Source as weights on vertices: a vertex, or the corners of its edge/face with their coordinates.
void sourceWeights(const TriMesh& mesh, const SurfacePoint& p, std::vector<std::pair<int32_t, double>>& out) {
  out.clear();
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: out.push_back({p.index, 1.0}); break;
    case SurfacePoint::Kind::Edge:
      out.push_back({mesh.tail(p.index), 1 - p.t});
      out.push_back({mesh.head(p.index), p.t});
      break;
    case SurfacePoint::Kind::Face:
      for (int k = 0; k < 3; ++k) out.push_back({mesh.triangle(p.index)[k], p.bary[k]});
      break;
  }
}

std::vector<double> dijkstraFrom(const TriMesh& mesh, const std::vector<std::pair<int32_t, double>>& seeds) {
  std::vector<double> dist(mesh.numVertices(), kInf);
  using Item = std::pair<double, int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (const auto& [v, d] : seeds)
    if (d < dist[v]) {
      dist[v] = d;
      queue.push({d, v});
    }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    const int32_t start = mesh.vertexHalfedge(v);
    int32_t h = start;
    // Rotate around v; on a boundary vertex also visit the last neighbour (head of the final prev).
    while (h >= 0) {
      const int32_t w = mesh.head(h);
      const double nd = d + norm(mesh.position(w) - mesh.position(v));
      if (nd < dist[w]) {
        dist[w] = nd;
        queue.push({nd, w});
      }
      const int32_t p = TriMesh::prev(h);
      if (mesh.twin(p) < 0) {
        const int32_t u = mesh.tail(p);
        const double nu = d + norm(mesh.position(u) - mesh.position(v));
        if (nu < dist[u]) {
          dist[u] = nu;
          queue.push({nu, u});
        }
      }
      h = mesh.twin(p);
      if (h == start) break;
    }
  }
  return dist;
}

}  // namespace

std::vector<double> dijkstraDistances(const TriMesh& mesh, const std::vector<int32_t>& sources) {
  std::vector<std::pair<int32_t, double>> seeds;
  for (int32_t s : sources) seeds.push_back({s, 0.0});
  return dijkstraFrom(mesh, seeds);
}

std::vector<double> dijkstraDistances(const TriMesh& mesh, const SurfacePoint& source) {
  std::vector<std::pair<int32_t, double>> weights;
  sourceWeights(mesh, source, weights);
  const Vec3 s = position(mesh, source);
  for (auto& [v, w] : weights) w = norm(mesh.position(v) - s);
  return dijkstraFrom(mesh, weights);
}

Expected<int32_t> defaultSource(const TriMesh& mesh) {
  if (mesh.boundaryLoops().empty()) {
    Vec3 centroid;
    double area = 0;
    for (int32_t f = 0; f < mesh.numFaces(); ++f) {
      const Triangle& t = mesh.triangle(f);
      centroid += (mesh.position(t[0]) + mesh.position(t[1]) + mesh.position(t[2])) * (mesh.faceArea(f) / 3);
      area += mesh.faceArea(f);
    }
    if (area > 0) centroid = centroid / area;
    int32_t best = -1;
    double bestDist = kInf;
    for (int32_t v = 0; v < mesh.numVertices(); ++v) {
      if (mesh.vertexHalfedge(v) < 0) continue;
      const double d = squaredNorm(mesh.position(v) - centroid);
      if (d < bestDist) { bestDist = d; best = v; }
    }
    return best;
  }
  std::vector<int32_t> boundary;
  for (const auto& loop : mesh.boundaryLoops()) boundary.insert(boundary.end(), loop.begin(), loop.end());
  const std::vector<double> dist = dijkstraDistances(mesh, boundary);
  int32_t best = -1;
  double bestDist = -1;
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (mesh.vertexHalfedge(v) >= 0 && !mesh.isBoundaryVertex(v) && dist[v] != kInf && dist[v] > bestDist) {
      bestDist = dist[v];
      best = v;
    }
  if (best < 0)
    return Error{ErrorCode::Topology, "the mesh has no interior vertex to use as the default source (" +
                                          std::to_string(mesh.numVertices()) + " vertices, all on the boundary)"};
  return best;
}

struct HeatMethod::Impl {
  const TriMesh& mesh;
  std::vector<double> mass;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> heat, poisson;
  std::vector<uint8_t> used;
  explicit Impl(const TriMesh& m) : mesh(m) {}
};

HeatMethod::HeatMethod(const TriMesh& mesh) : impl_(std::make_unique<Impl>(mesh)) {
  const int32_t n = mesh.numVertices();
  std::vector<Eigen::Triplet<double>> lap;
  lap.reserve(12 * static_cast<size_t>(mesh.numFaces()));
  impl_->mass.assign(n, 0.0);
  impl_->used.assign(n, 0);
  double edgeSum = 0;
  int64_t edgeCount = 0;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    if (mesh.isDegenerateFace(f)) continue;
    const Triangle& t = mesh.triangle(f);
    const double area = mesh.faceArea(f);
    for (int k = 0; k < 3; ++k) {
      const int32_t i = t[k], j = t[(k + 1) % 3], o = t[(k + 2) % 3];
      const Vec3 a = mesh.position(i) - mesh.position(o), b = mesh.position(j) - mesh.position(o);
      const double cot = dot(a, b) / norm(cross(a, b));
      const double w = 0.5 * cot;  // half the cotangent of the angle opposite edge (i, j)
      lap.emplace_back(i, j, -w);
      lap.emplace_back(j, i, -w);
      lap.emplace_back(i, i, w);
      lap.emplace_back(j, j, w);
      impl_->mass[i] += area / 3;
      impl_->used[i] = 1;
      edgeSum += norm(mesh.position(j) - mesh.position(i));
      ++edgeCount;
    }
  }
  Eigen::SparseMatrix<double> L(n, n), M(n, n);
  L.setFromTriplets(lap.begin(), lap.end());
  std::vector<Eigen::Triplet<double>> m;
  double meanMass = 0;
  for (int32_t i = 0; i < n; ++i) meanMass += impl_->mass[i];
  meanMass = n > 0 ? meanMass / n : 1;
  for (int32_t i = 0; i < n; ++i)
    m.emplace_back(i, i, impl_->used[i] ? impl_->mass[i] : meanMass);  // unused vertices: decoupled rows
  M.setFromTriplets(m.begin(), m.end());
  const double h = edgeCount > 0 ? edgeSum / edgeCount : 1.0;
  impl_->heat.compute(M + h * h * L);
  // L is singular (constants); a tiny mass shift makes it definite without moving the solution's
  // gradient beyond rounding (φ is shifted afterwards anyway).
  impl_->poisson.compute(L + 1e-10 * M);
  if (impl_->heat.info() != Eigen::Success || impl_->poisson.info() != Eigen::Success)
    throw std::runtime_error("heat method: sparse Cholesky factorization failed");
}

HeatMethod::~HeatMethod() = default;
HeatMethod::HeatMethod(HeatMethod&&) noexcept = default;
HeatMethod& HeatMethod::operator=(HeatMethod&&) noexcept = default;

std::vector<double> HeatMethod::distances(const SurfacePoint& source) const {
  const TriMesh& mesh = impl_->mesh;
  const int32_t n = mesh.numVertices();
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(n);
  std::vector<std::pair<int32_t, double>> weights;
  sourceWeights(mesh, source, weights);
  for (const auto& [v, w] : weights) delta[v] += w;
  const Eigen::VectorXd u = impl_->heat.solve(delta);
  Eigen::VectorXd div = Eigen::VectorXd::Zero(n);
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    if (mesh.isDegenerateFace(f)) continue;
    const Triangle& t = mesh.triangle(f);
    const Vec3& N = mesh.faceNormal(f);
    const double area = mesh.faceArea(f);
    Vec3 grad;
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = mesh.position(t[(k + 2) % 3]) - mesh.position(t[(k + 1) % 3]);  // edge opposite corner k
      grad += cross(N, e) * u[t[k]];
    }
    grad = grad / (2 * area);
    const Vec3 X = -normalized(grad);
    for (int k = 0; k < 3; ++k) {
      const int32_t i = t[k];
      const Vec3 pi = mesh.position(i), p1 = mesh.position(t[(k + 1) % 3]), p2 = mesh.position(t[(k + 2) % 3]);
      const Vec3 e1 = p1 - pi, e2 = p2 - pi;
      auto cotAt = [](const Vec3& a, const Vec3& b) { return dot(a, b) / norm(cross(a, b)); };
      const double cot1 = cotAt(pi - p2, p1 - p2);  // angle at p2, opposite e1
      const double cot2 = cotAt(pi - p1, p2 - p1);  // angle at p1, opposite e2
      div[i] += 0.5 * (cot1 * dot(e1, X) + cot2 * dot(e2, X));
    }
  }
  // L φ = ∇·X with our L (positive semi-definite) means solving L φ = −div.
  Eigen::VectorXd phi = impl_->poisson.solve(-div);
  double shift = 0;
  for (const auto& [v, w] : weights) shift += w * phi[v];
  std::vector<double> out(n);
  for (int32_t i = 0; i < n; ++i) out[i] = impl_->used[i] ? phi[i] - shift : kInf;
  return out;
}

}  // namespace straightest
