// geodesic_distance.cpp — the shortest-distance companions (Dijkstra, heat method, exact) and the default source.
#include "straightest/geodesics/geodesic_distance.hpp"

#include "straightest/base/names.hpp"
#include "straightest/geodesics/exact_geodesic.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
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

/// Monotone priority queue of (distance, vertex) for Dijkstra: a radix heap (Ahuja, Mehlhorn, Orlin,
/// Tarjan 1990) on the bit patterns of the distances (non-negative doubles order like their patterns
/// as unsigned integers). An item sits in the bucket of the highest bit in which its key differs from
/// the last key popped; popping refills bucket 0 from the first non-empty bucket, and an item moves
/// down a bucket at a time, so it is touched a few times in all instead of log(queue) times per
/// operation. Pushed keys must not be below the last popped key, which Dijkstra guarantees.
/// Which of equal keys comes first does not matter: every vertex's final distance is the minimum
/// over its neighbours settled before it, whatever the order.
class RadixHeap {
 public:
  bool empty() const { return size_ == 0; }
  void push(double key, int32_t v) {
    const uint64_t k = bits(key);
    buckets_[bucket(k)].push_back({k, v});
    ++size_;
  }
  std::pair<double, int32_t> pop() {
    if (buckets_[0].empty()) {
      int b = 1;
      while (buckets_[b].empty()) ++b;
      std::vector<Item>& from = buckets_[b];
      last_ = from.front().first;
      for (const Item& it : from) last_ = std::min(last_, it.first);
      for (const Item& it : from) buckets_[bucket(it.first)].push_back(it);  // all land below b
      from.clear();
    }
    const Item it = buckets_[0].back();
    buckets_[0].pop_back();
    --size_;
    double key;
    std::memcpy(&key, &it.first, sizeof key);
    return {key, it.second};
  }

 private:
  using Item = std::pair<uint64_t, int32_t>;
  static uint64_t bits(double key) {
    key += 0.0;  // −0 → +0
    uint64_t k;
    std::memcpy(&k, &key, sizeof k);
    return k;
  }
  int bucket(uint64_t k) const { return k == last_ ? 0 : 64 - __builtin_clzll(k ^ last_); }

  std::vector<Item> buckets_[65];
  uint64_t last_ = 0;
  size_t size_ = 0;
};

/// The edge graph in compressed rows: neighbours of v and the edge lengths, in the order of a rotation
/// around v (on a boundary vertex the rotation's last neighbour too).
struct EdgeGraph {
  std::vector<int32_t> start, neighbour;
  std::vector<double> length;
};

EdgeGraph edgeGraph(const TriMesh& mesh) {
  EdgeGraph g;
  const int32_t nv = mesh.numVertices();
  g.start.resize(static_cast<size_t>(nv) + 1);
  // Every neighbour in a rotation is one face corner, plus one at a boundary vertex: 3·faces + nv is
  // enough for a valid mesh. Entries are written in place (no push_back: in WebAssembly a possible
  // reallocation per entry doubled this loop's time); the capacity check only guards the bound.
  size_t capacity = 3 * static_cast<size_t>(mesh.numFaces()) + nv, used = 0;
  g.neighbour.resize(capacity);
  g.length.resize(capacity);
  for (int32_t v = 0; v < nv; ++v) {
    g.start[v] = static_cast<int32_t>(used);
    const Vec3& pv = mesh.position(v);
    auto add = [&](int32_t w) {
      if (used == capacity) {
        capacity = 2 * capacity + 16;
        g.neighbour.resize(capacity);
        g.length.resize(capacity);
      }
      g.neighbour[used] = w;
      g.length[used++] = norm(mesh.position(w) - pv);
    };
    for (int32_t w : mesh.vertexNeighbours(v)) add(w);
  }
  g.start[nv] = static_cast<int32_t>(used);
  return g;
}

/// Dijkstra on the edge graph. The graph is gathered first, in vertex order: the search's wavefront
/// visits vertices all over the mesh, and walking the half-edge structure there cost a cache miss
/// per triangle, twin and position (at 1M vertices, most of the time); the gathered rows are
/// contiguous per vertex. Lengths and sums are the same expressions as on the mesh, so distances
/// are bit for bit those of a search on the half-edges.
std::vector<double> dijkstraFrom(const TriMesh& mesh, const std::vector<std::pair<int32_t, double>>& seeds) {
  std::vector<double> dist(mesh.numVertices(), kInf);
  const EdgeGraph g = edgeGraph(mesh);
  RadixHeap queue;
  for (const auto& [v, d] : seeds)
    if (d < dist[v]) {
      dist[v] = d;
      queue.push(d, v);
    }
  while (!queue.empty()) {
    const auto [d, v] = queue.pop();
    if (d > dist[v]) continue;
    for (int32_t k = g.start[v]; k < g.start[v + 1]; ++k) {
      const int32_t w = g.neighbour[k];
      const double nd = d + g.length[k];
      if (nd < dist[w]) {
        dist[w] = nd;
        queue.push(nd, w);
        // w's row is read when w is settled, later and far from here in memory: most of the search's
        // time was the wait for it. A prefetch does not change what is computed; WebAssembly has none and ignores it.
        __builtin_prefetch(&g.neighbour[g.start[w]]);
        __builtin_prefetch(&g.length[g.start[w]]);
      }
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
      if (d < bestDist) {
        bestDist = d;
        best = v;
      }
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

Expected<SurfacePoint> defaultSourcePoint(const TriMesh& mesh) {
  auto v = defaultSource(mesh);
  if (v) return SurfacePoint::vertex(v.value());
  // Every vertex on the boundary (a lone triangle, a strip of quads): no vertex is inside, but the middle
  // of a face is, and the largest face's is the farthest such point from the boundary among the centroids.
  int32_t largest = -1;
  for (int32_t f = 0; f < mesh.numFaces(); ++f)
    if (!mesh.isDegenerateFace(f) && (largest < 0 || mesh.faceArea(f) > mesh.faceArea(largest))) largest = f;
  if (largest < 0) return v.error();
  return SurfacePoint::face(largest, {1.0 / 3, 1.0 / 3, 1.0 / 3});
}

Expected<SurfacePoint> resolveSource(const TriMesh& mesh, const std::optional<SurfacePoint>& source) {
  if (source) return validateSurfacePoint(mesh, *source);
  return defaultSourcePoint(mesh);
}

Expected<DistanceMethod> parseDistanceMethod(const std::string& name) {
  return parseName(kDistanceMethodNames, name, "distance method");
}

std::vector<double> GeodesicDistances::from(const SurfacePoint& source, DistanceMethod method) {
  if (method == DistanceMethod::Dijkstra) return dijkstraDistances(mesh_, source);
  if (method == DistanceMethod::Exact) return exactGeodesicDistances(mesh_, source);
  if (!heat_) heat_ = std::make_unique<HeatMethod>(mesh_);
  return heat_->distances(source);
}

}  // namespace straightest
