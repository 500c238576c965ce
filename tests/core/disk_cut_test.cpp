// cutToDisk: every manifold mesh made a disk — the largest component, holes filled, closed surfaces cut
// along a path (genus 0) or a tree–cotree cut graph (genus ≥ 1) — and the maps back to the mesh.
#include "straightest/cut/disk_cut.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "test_meshes.hpp"

namespace straightest {
namespace {

using testing::buildOrFail;
using testing::genusSlab;
using testing::voxelSurface;

using Edge = std::pair<int32_t, int32_t>;
Edge edge(int32_t a, int32_t b) { return {std::min(a, b), std::max(a, b)}; }

DiskCut cutOrFail(const TriMesh& mesh) {
  auto cut = cutToDisk(mesh);
  if (!cut) throw std::runtime_error("cutToDisk failed: " + cut.error().message);
  return std::move(cut).value();
}

/// The faces of the mesh's component `component` (numbered by lowest face index).
std::vector<int32_t> componentFaces(const TriMesh& mesh, int32_t component) {
  std::vector<int32_t> id(mesh.numFaces(), -1), faces;
  int32_t next = 0;
  for (int32_t seed = 0; seed < mesh.numFaces(); ++seed) {
    if (id[seed] >= 0) continue;
    std::vector<int32_t> stack{seed};
    id[seed] = next;
    while (!stack.empty()) {
      const int32_t f = stack.back();
      stack.pop_back();
      if (next == component) faces.push_back(f);
      for (int32_t t : mesh.adjacency(f).twins)
        if (t >= 0 && id[t / 3] < 0) id[t / 3] = next, stack.push_back(t / 3);
    }
    ++next;
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

/// Every property of the contract that does not depend on the method.
void expectDisk(const TriMesh& mesh, const DiskCut& cut) {
  const MeshSummary& s = cut.disk.summary();
  ASSERT_EQ(s.boundaryLoopSizes.size(), 1u);
  EXPECT_EQ(s.eulerCharacteristic, 1);
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.reorientedFaces, 0);
  ASSERT_EQ(cut.vertexOrigin.size(), size_t(cut.disk.numVertices()));
  ASSERT_EQ(cut.faceOrigin.size(), size_t(cut.disk.numFaces()));

  // faceOrigin: a bijection from the real disk faces onto the component's faces, corners kept in order.
  const std::vector<int32_t> expected = componentFaces(mesh, cut.component);
  EXPECT_EQ(int64_t(expected.size()), cut.faces);
  std::vector<int32_t> real;
  for (int32_t f = 0; f < cut.disk.numFaces(); ++f) {
    const int32_t origin = cut.faceOrigin[f];
    if (origin < 0) continue;
    real.push_back(origin);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(cut.vertexOrigin[cut.disk.triangle(f)[k]], mesh.triangle(origin)[k]);
  }
  std::sort(real.begin(), real.end());
  EXPECT_EQ(real, expected);

  // One virtual vertex per filled loop, never on the boundary, fanned to the loop: one face per loop edge.
  EXPECT_EQ(std::count(cut.vertexOrigin.begin(), cut.vertexOrigin.end(), -1), int64_t(cut.filledLoops.size()));
  size_t fanFaces = 0;
  for (int32_t loop : cut.filledLoops) fanFaces += mesh.boundaryLoops()[loop].size();
  EXPECT_EQ(std::count(cut.faceOrigin.begin(), cut.faceOrigin.end(), -1), int64_t(fanFaces));
  for (int32_t f = 0; f < cut.disk.numFaces(); ++f) {
    if (cut.faceOrigin[f] >= 0) continue;  // a fan face: its centre and two consecutive loop vertices
    const Triangle& corners = cut.disk.triangle(f);
    EXPECT_EQ(std::count_if(corners.begin(), corners.end(), [&](int32_t v) { return cut.vertexOrigin[v] < 0; }), 1);
  }

  // The boundary: each seam edge twice; the rest is the loop left open (edges of the mesh's boundary).
  std::map<Edge, int> boundary;
  const std::vector<int32_t>& loop = cut.disk.boundaryLoops()[0];
  for (size_t i = 0; i < loop.size(); ++i) {
    const int32_t a = cut.vertexOrigin[loop[i]], b = cut.vertexOrigin[loop[(i + 1) % loop.size()]];
    ASSERT_GE(a, 0);
    ASSERT_GE(b, 0);
    ++boundary[edge(a, b)];
  }
  double length = 0;
  std::set<Edge> seam;
  for (const auto& e : cut.seam) {
    EXPECT_TRUE(seam.insert(edge(e[0], e[1])).second) << "seam edge listed twice";
    EXPECT_EQ(boundary[edge(e[0], e[1])], 2);
    length += norm(mesh.position(e[0]) - mesh.position(e[1]));
  }
  EXPECT_NEAR(cut.seamLength, length, 1e-12 * (1 + length));
  for (const auto& [e, count] : boundary)
    if (!seam.count(e)) {
      EXPECT_EQ(count, 1);
      EXPECT_TRUE(mesh.isBoundaryVertex(e.first) && mesh.isBoundaryVertex(e.second));
    }
  if (cut.method == CutMethod::Path || cut.method == CutMethod::CutGraph) EXPECT_EQ(loop.size(), 2 * cut.seam.size());
  else EXPECT_TRUE(cut.seam.empty());
}

/// V − E of the seam as a graph.
int64_t seamEuler(const DiskCut& cut) {
  std::set<int32_t> vertices;
  for (const auto& e : cut.seam) vertices.insert({e[0], e[1]});
  return int64_t(vertices.size()) - int64_t(cut.seam.size());
}

TriMesh twoComponents() {
  const TriMesh small = testing::flatGrid(3, testing::GridPattern::Regular);
  const TriMesh large = testing::flatGrid(5, testing::GridPattern::UnionJack);
  std::vector<Vec3> p = small.positions();
  std::vector<Triangle> t = small.triangles();
  for (const Vec3& x : large.positions()) p.push_back(x + Vec3{10, 0, 0});
  for (Triangle f : large.triangles()) t.push_back({f[0] + 9, f[1] + 9, f[2] + 9});
  return buildOrFail(p, t);
}

TEST(DiskCut, MethodNames) {
  EXPECT_STREQ(cutMethodName(CutMethod::Disk), "disk");
  EXPECT_STREQ(cutMethodName(CutMethod::Fill), "fill");
  EXPECT_STREQ(cutMethodName(CutMethod::Path), "path");
  EXPECT_STREQ(cutMethodName(CutMethod::CutGraph), "cut-graph");
}

TEST(DiskCut, ADiskIsLeftAsItIs) {
  const TriMesh mesh = testing::flatGrid(6, testing::GridPattern::UnionJack);
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  EXPECT_EQ(cut.method, CutMethod::Disk);
  EXPECT_EQ(cut.genus, 0);
  EXPECT_EQ(cut.components, 1);
  EXPECT_TRUE(cut.filledLoops.empty());
  for (int32_t v = 0; v < mesh.numVertices(); ++v) EXPECT_EQ(norm(cut.disk.position(v) - mesh.position(v)), 0);
  EXPECT_EQ(cut.disk.triangles(), mesh.triangles());
  for (int32_t v = 0; v < mesh.numVertices(); ++v) EXPECT_EQ(cut.vertexOrigin[v], v);
  for (int32_t f = 0; f < mesh.numFaces(); ++f) EXPECT_EQ(cut.faceOrigin[f], f);
}

TEST(DiskCut, UnreferencedVerticesAreLeftOut) {
  const TriMesh grid = testing::flatGrid(4, testing::GridPattern::Regular);
  std::vector<Vec3> p{{-5, -5, 0}};  // vertex 0 belongs to no face
  for (const Vec3& x : grid.positions()) p.push_back(x);
  std::vector<Triangle> t;
  for (Triangle f : grid.triangles()) t.push_back({f[0] + 1, f[1] + 1, f[2] + 1});
  const TriMesh mesh = buildOrFail(p, t);
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  EXPECT_EQ(cut.method, CutMethod::Disk);
  ASSERT_EQ(cut.disk.numVertices(), 16);
  for (int32_t v = 0; v < 16; ++v) EXPECT_EQ(cut.vertexOrigin[v], v + 1);
}

TEST(DiskCut, TheLargestComponentIsCut) {
  const TriMesh mesh = twoComponents();  // 8 faces, then 32
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  EXPECT_EQ(cut.components, 2);
  EXPECT_EQ(cut.component, 1);
  EXPECT_EQ(cut.faces, 32);
  EXPECT_EQ(cut.disk.numVertices(), 25);
  for (int32_t v : cut.vertexOrigin) EXPECT_GE(v, 9);
  EXPECT_EQ(cut.method, CutMethod::Disk);
}

/// The two meshes side by side (b's vertices after a's, moved by `offset`).
TriMesh sideBySide(const TriMesh& a, const TriMesh& b, Vec3 offset) {
  std::vector<Vec3> p = a.positions();
  std::vector<Triangle> t = a.triangles();
  const int32_t n = a.numVertices();
  for (const Vec3& x : b.positions()) p.push_back(x + offset);
  for (Triangle f : b.triangles()) t.push_back({f[0] + n, f[1] + n, f[2] + n});
  return buildOrFail(p, t);
}

TEST(DiskCut, OnlyTheChosenComponentsLoopsAreFilled) {
  // A small annulus first (its two loops come first), then a larger grid with two holes.
  const TriMesh annulus = testing::gridOfCells(4, [](int i, int j) { return !(i == 1 && j == 1); });
  const TriMesh mesh = sideBySide(annulus, testing::gridWithout({{2, 2}, {5, 5}}), {20, 0, 0});
  ASSERT_EQ(mesh.boundaryLoops().size(), 5u);
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  EXPECT_EQ(cut.component, 1);
  EXPECT_EQ(cut.method, CutMethod::Fill);
  ASSERT_EQ(cut.filledLoops.size(), 2u);
  for (int32_t loop : cut.filledLoops) {
    EXPECT_EQ(mesh.boundaryLoops()[loop].size(), 4u);
    EXPECT_GE(mesh.boundaryLoops()[loop][0], annulus.numVertices());
  }
  // A torus beside the annulus: closed, so nothing is filled though the mesh has loops.
  const TriMesh withTorus = sideBySide(annulus, makeTorus(3, 1, 16, 8), {20, 0, 0});
  const DiskCut torus = cutOrFail(withTorus);
  expectDisk(withTorus, torus);
  EXPECT_EQ(torus.method, CutMethod::CutGraph);
  EXPECT_TRUE(torus.filledLoops.empty());
  // Two equal components: the first.
  const TriMesh grid = testing::flatGrid(4, testing::GridPattern::Regular);
  EXPECT_EQ(cutOrFail(sideBySide(grid, grid, {10, 0, 0})).component, 0);
}

TEST(DiskCut, HolesAreFilledAndTheLongestLoopStaysTheBoundary) {
  const TriMesh mesh = testing::gridWithout({{2, 2}, {5, 2}, {3, 5}});
  ASSERT_EQ(mesh.boundaryLoops().size(), 4u);
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  EXPECT_EQ(cut.method, CutMethod::Fill);
  EXPECT_EQ(cut.genus, 0);
  ASSERT_EQ(cut.filledLoops.size(), 3u);
  EXPECT_EQ(cut.disk.boundaryLoops()[0].size(), 32u);  // the 8 × 8 square's outline
  // Each hole's virtual vertex sits at the centre of its unit square.
  std::vector<Vec3> centres;
  for (int32_t v = 0; v < cut.disk.numVertices(); ++v)
    if (cut.vertexOrigin[v] < 0) centres.push_back(cut.disk.position(v));
  ASSERT_EQ(centres.size(), 3u);
  for (Vec3 expected : {Vec3{2.5, 2.5, 0}, Vec3{5.5, 2.5, 0}, Vec3{3.5, 5.5, 0}}) {
    double nearest = 1e9;
    for (const Vec3& c : centres) nearest = std::min(nearest, norm(c - expected));
    EXPECT_LT(nearest, 1e-12);
  }
}

TEST(DiskCut, AnAnnulusIsFilled) {
  const TriMesh mesh = testing::gridWithout({{3, 3}, {4, 3}, {3, 4}, {4, 4}});
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  EXPECT_EQ(cut.method, CutMethod::Fill);
  ASSERT_EQ(cut.filledLoops.size(), 1u);
  EXPECT_EQ(mesh.boundaryLoops()[cut.filledLoops[0]].size(), 8u);  // the inner loop, not the outer one
}

TEST(DiskCut, ACubeIsCutAlongAPath) {
  const TriMesh mesh = voxelSurface({{0, 0, 0}});
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  EXPECT_EQ(cut.method, CutMethod::Path);
  EXPECT_EQ(cut.genus, 0);
  // The seam joins opposite corners (graph distance 2 on the triangulated cube ... or 3 along edges).
  const Vec3 a = mesh.position(cut.seamEnds[0]), b = mesh.position(cut.seamEnds[1]);
  EXPECT_NEAR(norm(a - b), std::sqrt(3.0), 1e-12);
}

TEST(DiskCut, ASphereIsCutAlongAPathJoiningItsEnds) {
  const TriMesh mesh = testing::icosphere(3);
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  EXPECT_EQ(cut.method, CutMethod::Path);
  EXPECT_EQ(seamEuler(cut), 1);  // a path
  // The seam is a path from seamEnds[0] to seamEnds[1]: the ends have degree 1, the rest degree 2.
  std::map<int32_t, int> degree;
  for (const auto& e : cut.seam) ++degree[e[0]], ++degree[e[1]];
  for (const auto& [v, d] : degree) EXPECT_EQ(d, v == cut.seamEnds[0] || v == cut.seamEnds[1] ? 1 : 2);
  // Far apart: nearly antipodal, and the seam no longer than a half great circle by much (edge paths zigzag).
  const Vec3 a = mesh.position(cut.seamEnds[0]), b = mesh.position(cut.seamEnds[1]);
  EXPECT_GT(norm(a - b), 1.9);
  EXPECT_GT(cut.seamLength, testing::kPi * 0.99);
  EXPECT_LT(cut.seamLength, testing::kPi * 1.2);
}

TEST(DiskCut, AnEllipsoidIsCutFromEndToEnd) {
  const TriMesh sphere = testing::icosphere(2);
  std::vector<Vec3> p;
  for (const Vec3& x : sphere.positions()) p.push_back({4 * x.x, x.y, x.z});
  const TriMesh mesh = buildOrFail(p, sphere.triangles());
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  const Vec3 a = mesh.position(cut.seamEnds[0]), b = mesh.position(cut.seamEnds[1]);
  double maxX = 0;
  for (const Vec3& x : p) maxX = std::max(maxX, x.x);
  EXPECT_GT(std::abs(a.x - b.x), 0.9 * 2 * maxX);  // at the two ends of the long axis
}

TEST(DiskCut, ATorusIsCutAlongTwoLoops) {
  const TriMesh mesh = makeTorus(3, 1, 24, 12);
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  EXPECT_EQ(cut.method, CutMethod::CutGraph);
  EXPECT_EQ(cut.genus, 1);
  EXPECT_EQ(seamEuler(cut), -1);
  EXPECT_EQ(cut.seamEnds[0], -1);
  // One loop winds around the hole, so the seam is at least as long as the inner equator (a 24-gon of
  // radius R − r = 2); the shortest pair of loops is that equator and a tube circle (a 12-gon of radius 1):
  // loops through a shortest-path tree are short, within a quarter of it here.
  const double equator = 24 * 2 * 2 * std::sin(testing::kPi / 24), tube = 12 * 2 * std::sin(testing::kPi / 12);
  EXPECT_GT(cut.seamLength, equator * std::cos(testing::kPi / 24));
  EXPECT_LT(cut.seamLength, 1.25 * (equator + tube));
}

TEST(DiskCut, ClosedSurfacesOfGenusTwoAndThree) {
  for (int g : {1, 2, 3}) {
    SCOPED_TRACE(g);
    const TriMesh mesh = genusSlab(g);
    ASSERT_EQ(mesh.summary().eulerCharacteristic, 2 - 2 * g);
    const DiskCut cut = cutOrFail(mesh);
    expectDisk(mesh, cut);
    EXPECT_EQ(cut.method, CutMethod::CutGraph);
    EXPECT_EQ(cut.genus, g);
    EXPECT_EQ(seamEuler(cut), 1 - 2 * g);  // 2g independent loops
  }
}

TEST(DiskCut, AHandleWithHolesIsFilledEverywhereAndCut) {
  // A genus-2 slab with two of its outer squares removed: genus 2, two boundary loops, both filled.
  const TriMesh closed = genusSlab(2);
  std::vector<Triangle> t = closed.triangles();
  t.erase(t.begin(), t.begin() + 2);  // the first voxel side
  t.erase(t.end() - 2, t.end());      // the last one
  const TriMesh mesh = buildOrFail(closed.positions(), t);
  ASSERT_EQ(mesh.boundaryLoops().size(), 2u);
  const DiskCut cut = cutOrFail(mesh);
  expectDisk(mesh, cut);
  EXPECT_EQ(cut.method, CutMethod::CutGraph);
  EXPECT_EQ(cut.genus, 2);
  EXPECT_EQ(cut.filledLoops.size(), 2u);
  EXPECT_EQ(seamEuler(cut), -3);
}

TEST(DiskCut, CancellingReturnsCancelled) {
  for (const TriMesh& mesh :
       {testing::icosphere(2), makeTorus(3, 1, 12, 6), testing::flatGrid(4, testing::GridPattern::Regular)}) {
    auto cut = cutToDisk(mesh, [](const char* stage, double) { return std::string(stage) != "cut"; });
    ASSERT_FALSE(cut.ok());
    EXPECT_EQ(cut.error().code, ErrorCode::Cancelled);
  }
  // Cancelled while the surface is being cut open (after the seam was found).
  auto opening = cutToDisk(testing::icosphere(2), [](const char*, double f) { return !(f >= 0.75 && f < 0.9); });
  ASSERT_FALSE(opening.ok());
  EXPECT_EQ(opening.error().code, ErrorCode::Cancelled);
  int calls = 0;
  auto late = cutToDisk(makeTorus(3, 1, 12, 6), [&](const char*, double f) { return ++calls < 3 || f < 0; });
  ASSERT_FALSE(late.ok());
  EXPECT_EQ(late.error().code, ErrorCode::Cancelled);
}

TEST(DiskCut, ProgressRunsFromZeroToOneInStageCut) {
  std::vector<double> seen;
  auto cut = cutToDisk(genusSlab(2), [&](const char* stage, double f) {
    EXPECT_STREQ(stage, "cut");
    seen.push_back(f);
    return true;
  });
  ASSERT_TRUE(cut.ok());
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front(), 0);
  EXPECT_EQ(seen.back(), 1);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
}

}  // namespace
}  // namespace straightest
