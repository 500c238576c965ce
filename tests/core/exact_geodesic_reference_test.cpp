// The pruned window propagation against the unpruned reference (private: core/src/exact_geodesic_reference.hpp):
// the filter through the faces' corners, dropping windows beaten by their edge's last one and the saddles'
// shadow cones keep every vertex's distance, on bumpy height fields (most vertices are saddles there) and a
// cone, from vertices, edge points and face points; and they do prune.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "../../core/geodesics/src/exact_geodesic_reference.hpp"
#include "geodesic_surfaces.hpp"
#include "straightest/geodesics/exact_geodesic.hpp"
#include "straightest/mesh/samples.hpp"

namespace straightest {
namespace {

/// The largest relative difference between the pruned and the unpruned distances, and the window counts.
struct Comparison {
  double worst = 0;
  int64_t pruned = 0, unpruned = 0;
};

Comparison compare(const TriMesh& mesh, const SurfacePoint& source) {
  const ExactGeodesics pruned = exactGeodesics(mesh, source).value();
  const ExactGeodesics reference = detail::exactGeodesicsUnpruned(mesh, source).value();
  Comparison c{0, pruned.stats.windows, reference.stats.windows};
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    const double a = pruned.distances[v], b = reference.distances[v];
    EXPECT_EQ(std::isfinite(a), std::isfinite(b)) << v;
    if (!std::isfinite(a) || !std::isfinite(b) || b == 0) continue;
    c.worst = std::max(c.worst, std::fabs(a - b) / b);
  }
  return c;
}

TEST(ExactGeodesicReference, PruningKeepsTheDistancesOnHeightFields) {
  for (int n : {8, 11, 14}) {
    const TriMesh mesh = makeHeightField(n);
    const int32_t middle = (n / 2) * n + n / 2;
    for (const SurfacePoint& s : {SurfacePoint::vertex(middle), SurfacePoint::vertex(1), SurfacePoint::edge(7, 0.37),
                                  SurfacePoint::face(mesh.numFaces() / 3, {0.2, 0.5, 0.3})}) {
      const Comparison c = compare(mesh, s);
      EXPECT_LE(c.worst, 1e-12) << "height field " << n << ", source index " << s.index;
      EXPECT_LT(c.pruned, c.unpruned);
    }
  }
}

TEST(ExactGeodesicReference, PruningKeepsTheDistancesOnObtuseUnequalTriangles) {
  // Columns spaced geometrically (edges from 0.02 to 0.5: the queue's buckets are a fraction of the mean
  // edge) and rows sheared by a jitter, so that many triangles are obtuse; bumps make saddles; a boundary.
  const int n = 12;
  const TriMesh mesh = makeGrid(
      n,
      [](int i, int j) {
        const double x = 0.04 * (std::pow(1.35, i) - 1), y = 0.15 * j + 0.09 * ((i * 7 + j * 3) % 5) / 4.0;
        return Vec3{x, y, 0.12 * std::sin(5 * x) * std::cos(4 * y)};
      },
      GridDiagonals::Alternating);
  for (const SurfacePoint& s : {SurfacePoint::vertex(0), SurfacePoint::vertex(5 * n + 6),
                                SurfacePoint::face(mesh.numFaces() / 2, {0.6, 0.3, 0.1})}) {
    const Comparison c = compare(mesh, s);
    EXPECT_LE(c.worst, 1e-12) << "source index " << s.index;
    EXPECT_LT(c.pruned, c.unpruned);
  }
}

TEST(ExactGeodesicReference, PruningKeepsTheDistancesOnRandomBumpyGrids) {
  // Heights and in-plane offsets drawn at random per vertex (a fixed generator): rough surfaces where
  // windows of very different depths overlap on one edge, the case the same-edge domination test must
  // weigh point by point rather than only at the ends.
  std::mt19937 rng(20261202);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3), height(-0.6, 0.6);
  for (int trial = 0; trial < 24; ++trial) {
    const int n = 9 + trial % 4;
    std::vector<Vec3> points;
    for (int k = 0; k < n * n; ++k) points.push_back({jitter(rng), jitter(rng), height(rng)});
    const TriMesh mesh = makeGrid(
        n,
        [&](int i, int j) {
          const Vec3& d = points[static_cast<size_t>(j) * n + i];
          return Vec3{i + d[0], j + d[1], d[2]};
        },
        trial % 2 ? GridDiagonals::Alternating : GridDiagonals::Same);
    const int32_t source = static_cast<int32_t>(rng() % static_cast<uint32_t>(mesh.numVertices()));
    EXPECT_LE(compare(mesh, SurfacePoint::vertex(source)).worst, 1e-12) << "trial " << trial;
  }
}

TEST(ExactGeodesicReference, PruningKeepsTheDistancesOnAClosedTorus) {
  // No boundary; the inner half's vertices are saddles (negative curvature), the outer half's are not.
  const TriMesh mesh = makeTorus(1.0, 0.4, 14, 8);
  for (int32_t source : {int32_t(0), int32_t(3), int32_t(61)}) {
    const Comparison c = compare(mesh, SurfacePoint::vertex(source));
    EXPECT_LE(c.worst, 1e-12) << "source " << source;
    EXPECT_LT(c.pruned, c.unpruned);
  }
}

TEST(ExactGeodesicReference, PruningKeepsTheDistancesOnACone) {
  const testing::Cone cone = testing::cone(6, 1.0, 1.0, 6);
  for (int32_t source : {cone.apex, int32_t(20), int32_t(41)}) {
    const Comparison c = compare(cone.mesh, SurfacePoint::vertex(source));
    EXPECT_LE(c.worst, 1e-12) << "source " << source;
    EXPECT_LE(c.pruned, c.unpruned);  // from the apex nothing overlaps: nothing to prune
  }
}

}  // namespace
}  // namespace straightest
