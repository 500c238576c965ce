// Parameterizing what is not a disk: holes filled virtually (annulus, a disk with three holes, an open
// tube), closed surfaces of genus 0–2 cut along a seam, several components. What must hold: the
// convex-combination maps are bijective on the real faces, the map per face corner agrees with the
// vertex map everywhere but across the seam and really splits there, filled vertices never reach the
// output, and the OBJ export keeps the seam split.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/boundary_polygons.hpp"
#include "straightest/param/compare_parameterizations.hpp"
#include "straightest/param/parameterize.hpp"
#include "test_meshes.hpp"
#include "test_util.hpp"

namespace straightest {
namespace {

using Edge = std::pair<int32_t, int32_t>;
Edge undirected(int32_t a, int32_t b) { return {std::min(a, b), std::max(a, b)}; }

/// parameterize with the free boundary's refinement capped at 50 iterations (failures reported, not thrown).
Parameterization cappedParam(const TriMesh& mesh, std::optional<BoundaryKind> b,
                             WeightKind w = WeightKind::ShapePreserving) {
  ParamOptions o;
  o.boundary = b;
  o.weights = w;
  o.free.maxIterations = 50;
  auto r = parameterize(mesh, o);
  if (!r) ADD_FAILURE() << r.error().message;
  return std::move(r).value();
}

/// Two meshes side by side as one (b's vertices after a's, moved by `shift`).
TriMesh sideBySide(const TriMesh& a, const TriMesh& b, Vec3 shift) {
  std::vector<Vec3> p = a.positions();
  std::vector<Triangle> t = a.triangles();
  for (const Vec3& x : b.positions()) p.push_back(x + shift);
  for (Triangle u : b.triangles()) {
    for (int32_t& v : u) v += a.numVertices();
    t.push_back(u);
  }
  return testing::buildOrFail(std::move(p), std::move(t));
}

/// A cylinder tube open at both ends (annulus topology): radius 1, height h, `around` × `rings` vertices.
TriMesh openTube(double h, int around, int rings) {
  std::vector<Vec3> p;
  std::vector<Triangle> t;
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2 * testing::kPi * i / around;
      p.push_back({std::cos(a), std::sin(a), h * j / (rings - 1)});
    }
  for (int j = 0; j + 1 < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const int a = j * around + i, b = j * around + (i + 1) % around, c = a + around, d = b + around;
      t.push_back({a, b, d});
      t.push_back({a, d, c});
    }
  return testing::buildOrFail(std::move(p), std::move(t));
}

/// What every result of a mesh that is not a disk must satisfy: sizes; per-corner uv in [0, 1]² on the
/// parameterized faces, NaN elsewhere; corners equal to the vertex map except at seam vertices; the two
/// faces of an edge agree on its ends unless it is a seam edge, and differ there; every seam edge twice
/// on the boundary loop (a cut) or the outer loop kept (a fill).
void expectConsistentCut(const TriMesh& mesh, const Parameterization& p, const std::string& what) {
  SCOPED_TRACE(what);
  const int32_t nf = mesh.numFaces();
  ASSERT_EQ(p.uv.size(), static_cast<size_t>(mesh.numVertices()));
  ASSERT_EQ(p.cornerUv.size(), 3 * static_cast<size_t>(nf));
  ASSERT_EQ(p.metrics.faceStretch.size(), static_cast<size_t>(nf));
  std::set<Edge> seam;
  std::set<int32_t> seamVertices;
  for (const auto& e : p.seam) {
    seam.insert(undirected(e[0], e[1]));
    seamVertices.insert(e[0]);
    seamVertices.insert(e[1]);
  }
  EXPECT_EQ(seam.size(), p.seam.size()) << "each seam edge once";
  int64_t parameterized = 0;
  for (int32_t f = 0; f < nf; ++f) {
    const bool inside = std::isfinite(p.cornerUv[3 * f].x);
    parameterized += inside;
    EXPECT_EQ(inside, !std::isnan(p.metrics.faceStretch[f])) << "face " << f;
    for (int k = 0; k < 3; ++k) {
      const Vec2& c = p.cornerUv[3 * f + k];
      if (!inside) {
        ASSERT_TRUE(std::isnan(c.x) && std::isnan(c.y)) << "face " << f;
        continue;
      }
      ASSERT_TRUE(c.x >= -1e-12 && c.x <= 1 + 1e-12 && c.y >= -1e-12 && c.y <= 1 + 1e-12) << "face " << f;
      const int32_t v = mesh.triangle(f)[k];
      if (!seamVertices.count(v)) {
        ASSERT_EQ(c, p.uv[v]) << "face " << f << " corner " << k;
      }
    }
  }
  EXPECT_GT(parameterized, 0);
  // Across every edge: the same uv at both ends, except across the seam, where they differ.
  for (int32_t h = 0; h < 3 * nf; ++h) {
    const int32_t g = mesh.twin(h);
    if (g < h) continue;  // boundary edge, or seen from the other side
    const int32_t f = TriMesh::face(h), fg = TriMesh::face(g);
    if (!std::isfinite(p.cornerUv[3 * f].x)) continue;
    const Vec2 &a1 = p.cornerUv[h], &b1 = p.cornerUv[TriMesh::next(h)];  // tail and head of h, seen from f
    const Vec2 &b2 = p.cornerUv[g], &a2 = p.cornerUv[TriMesh::next(g)];  // the same ends seen from fg
    const bool same = a1 == a2 && b1 == b2;
    if (seam.count(undirected(mesh.tail(h), mesh.head(h))))
      EXPECT_FALSE(same) << "seam edge " << mesh.tail(h) << "-" << mesh.head(h) << " is not split";
    else ASSERT_TRUE(same) << "edge " << mesh.tail(h) << "-" << mesh.head(h) << " (faces " << f << ", " << fg << ")";
  }
  // A seam edge appears exactly twice along the cut disk's boundary loop (in mesh vertex numbers).
  std::map<Edge, int> onLoop;
  for (size_t i = 0; i < p.boundaryLoop.size(); ++i)
    ++onLoop[undirected(p.boundaryLoop[i], p.boundaryLoop[(i + 1) % p.boundaryLoop.size()])];
  for (const Edge& e : seam) EXPECT_EQ(onLoop[e], 2) << "seam edge " << e.first << "-" << e.second;
  EXPECT_EQ(p.boundaryPolygon.size(), p.boundaryLoop.size());
  EXPECT_EQ(p.seamLength > 0, !seam.empty());
}

void expectBijective(const Parameterization& p, const std::string& what) {
  EXPECT_TRUE(p.metrics.bijective) << what << ": " << p.metrics.flipped << " flipped, " << p.metrics.degenerate
                                   << " degenerate, " << p.metrics.overlaps << " overlaps";
  EXPECT_TRUE(std::isfinite(p.metrics.l2)) << what;
  EXPECT_GE(p.metrics.l2, 1 - 1e-9) << what;
  EXPECT_GE(p.metrics.linf, p.metrics.l2) << what;
}

const std::vector<BoundaryKind> kFixed = {BoundaryKind::Measured, BoundaryKind::Circle, BoundaryKind::Square};
const std::vector<WeightKind> kConvex = {WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Uniform};

TEST(ParameterizeHoles, AnAnnulusAndADiskWithThreeHolesAreBijectiveUnderEveryConvexMapAndFree) {
  for (const auto& [name, mesh] : {std::pair<std::string, TriMesh>{"annulus", testing::loadGood("good/annulus.off")},
                                   {"holes", makeSample("holes").value()}}) {
    const size_t holes = mesh.boundaryLoops().size() - 1;
    for (BoundaryKind b : kFixed)
      for (WeightKind w : kConvex) {
        const std::string what = name + " " + boundaryKindName(b) + " " + weightKindName(w);
        const Parameterization p = cappedParam(mesh, b, w);
        EXPECT_EQ(p.cut, CutMethod::Fill) << what;
        EXPECT_EQ(p.filledLoops.size(), holes) << what;
        EXPECT_EQ(p.virtualVertices, static_cast<int64_t>(holes)) << what << ": one centre per filled hole";
        EXPECT_TRUE(p.seam.empty()) << what;
        EXPECT_EQ(p.genus, 0);
        expectConsistentCut(mesh, p, what);
        expectBijective(p, what);
        // No seam: the corners are the vertex map (filled vertices have no number in the output).
        for (int32_t f = 0; f < mesh.numFaces(); ++f)
          for (int k = 0; k < 3; ++k) ASSERT_EQ(p.cornerUv[3 * f + k], p.uv[mesh.triangle(f)[k]]) << what;
        // The outer boundary is the loop that was not filled.
        std::vector<int32_t> outer;
        for (size_t i = 0; i < mesh.boundaryLoops().size(); ++i)
          if (std::find(p.filledLoops.begin(), p.filledLoops.end(), static_cast<int32_t>(i)) == p.filledLoops.end())
            outer = mesh.boundaryLoops()[i];
        EXPECT_EQ(std::set<int32_t>(p.boundaryLoop.begin(), p.boundaryLoop.end()),
                  std::set<int32_t>(outer.begin(), outer.end()))
            << what;
      }
    if (name == "annulus") continue;
    // Free: refined on the real faces with the holes free, from a bijective start: stays bijective.
    const Parameterization free = cappedParam(mesh, BoundaryKind::Free);
    expectConsistentCut(mesh, free, name + " free");
    expectBijective(free, name + " free");
    EXPECT_EQ(free.metrics.overlaps, 0);
    EXPECT_LE(free.metrics.l2, free.candidates.front().l2) << "never worse than its start";
  }
}

TEST(ParameterizeHoles, AShortOpenTubeIsFilledAtOneEndAndMapsWithLowStretch) {
  // A band of height 0.3 around the unit circle: an annulus of the plane is nearly its isometric image.
  const TriMesh tube = openTube(0.3, 64, 6);
  const Parameterization circle = cappedParam(tube, BoundaryKind::Circle);
  EXPECT_EQ(circle.cut, CutMethod::Fill);
  EXPECT_EQ(circle.filledLoops.size(), 1u);
  expectConsistentCut(tube, circle, "tube circle");
  expectBijective(circle, "tube circle");
  const Parameterization free = cappedParam(tube, BoundaryKind::Free);
  expectBijective(free, "tube free");
  EXPECT_LT(free.metrics.l2, 1.05);
  EXPECT_LT(free.metrics.l2, circle.metrics.l2);
}

TEST(ParameterizeClosed, SphereTorusCubeAndGenusTwoAreCutAndBijectiveWithConvexWeightsAndFixedBoundaries) {
  const std::vector<std::tuple<std::string, TriMesh, int>> meshes = {{"sphere", makeSample("sphere").value(), 0},
                                                                     {"cube", testing::voxelSurface({{0, 0, 0}}), 0},
                                                                     {"torus", makeSample("torus").value(), 1},
                                                                     {"genus 2", testing::genusSlab(2), 2}};
  for (const auto& [name, mesh, genus] : meshes) {
    for (BoundaryKind b : {BoundaryKind::Circle, BoundaryKind::Square})
      for (WeightKind w : kConvex) {
        const std::string what = name + " " + boundaryKindName(b) + " " + weightKindName(w);
        const Parameterization p = cappedParam(mesh, b, w);
        EXPECT_EQ(p.cut, genus == 0 ? CutMethod::Path : CutMethod::CutGraph) << what;
        EXPECT_EQ(p.genus, genus) << what;
        EXPECT_FALSE(p.seam.empty()) << what;
        EXPECT_EQ(p.virtualVertices, 0) << what;
        EXPECT_EQ(p.components, 1);
        expectConsistentCut(mesh, p, what);
        expectBijective(p, what);
      }
    // Measured and free: a result with finite numbers or, for measured, a clear error; free from a
    // bijective start is bijective.
    const Parameterization free = cappedParam(mesh, BoundaryKind::Free);
    expectConsistentCut(mesh, free, name + " free");
    expectBijective(free, name + " free");
    ParamOptions o;
    auto measured = parameterize(mesh, o);
    if (measured) expectConsistentCut(mesh, measured.value(), name + " measured");
    else EXPECT_FALSE(measured.error().message.empty());
  }
}

/// The mesh without the faces `drop` says to remove (vertices kept: unreferenced ones are allowed).
template <class Drop>
TriMesh without(const TriMesh& mesh, Drop drop) {
  std::vector<Triangle> kept;
  for (int32_t f = 0; f < mesh.numFaces(); ++f)
    if (!drop(f)) kept.push_back(mesh.triangle(f));
  return testing::buildOrFail(mesh.positions(), std::move(kept));
}

TEST(ParameterizeClosed, AGenusOneMeshWithManyHolesIsFilledAndCutAndStaysBijective) {
  // Small holes all over a torus: every loop is filled and the cut graph runs between them, through
  // the holes' rims (where the real faces can meet at a single seam vertex: split for the stretch).
  const TriMesh torus = makeTorus(1.0, 0.4, 32, 16);
  const TriMesh holed = without(torus, [](int32_t f) { return f % 46 == 7; });
  ASSERT_EQ(holed.summary().components, 1);
  const int64_t holes = static_cast<int64_t>(holed.boundaryLoops().size());
  ASSERT_GT(holes, 10);
  for (BoundaryKind b : {BoundaryKind::Circle, BoundaryKind::Free}) {
    const std::string what = std::string("holed torus ") + boundaryKindName(b);
    const Parameterization p = cappedParam(holed, b, WeightKind::MeanValue);
    EXPECT_EQ(p.cut, CutMethod::CutGraph) << what;
    EXPECT_EQ(p.genus, 1) << what;
    EXPECT_EQ(static_cast<int64_t>(p.filledLoops.size()), holes) << what;
    EXPECT_EQ(p.virtualVertices, holes) << what;
    expectConsistentCut(holed, p, what);
    expectBijective(p, what);
  }
}

TEST(ParameterizeClosed, TheSourceMustNotLieOnTheSeamAndComesBackInMeshNumbers) {
  const TriMesh mesh = makeSample("sphere").value();
  const Parameterization circle = cappedParam(mesh, BoundaryKind::Circle);
  ParamOptions o;
  o.boundary = BoundaryKind::Measured;
  o.source = SurfacePoint::vertex(circle.seam.front()[0]);
  auto onSeam = parameterize(mesh, o);
  ASSERT_FALSE(onSeam.ok());
  EXPECT_EQ(onSeam.error().code, ErrorCode::InvalidArgument);
  EXPECT_NE(onSeam.error().message.find("seam"), std::string::npos) << onSeam.error().message;
  // A face far from the seam: the source comes back as the same face point.
  int32_t far = -1;
  for (int32_t f = 0; f < mesh.numFaces() && far < 0; ++f) {
    bool touches = false;
    for (const auto& e : circle.seam)
      for (int32_t v : mesh.triangle(f)) touches = touches || v == e[0] || v == e[1];
    if (!touches) far = f;
  }
  ASSERT_GE(far, 0);
  o.source = SurfacePoint::face(far, {0.2, 0.3, 0.5});
  auto inside = parameterize(mesh, o);
  ASSERT_TRUE(inside.ok()) << inside.error().message;
  EXPECT_EQ(inside.value().source.kind, SurfacePoint::Kind::Face);
  EXPECT_EQ(inside.value().source.index, far);
  EXPECT_NEAR(inside.value().source.bary[0], 0.2, 1e-15);
  EXPECT_NEAR(inside.value().source.bary[2], 0.5, 1e-15);
  // A hole's rim is the mesh's boundary: not a source, as on a disk.
  const TriMesh holes = makeSample("holes").value();
  o.source = SurfacePoint::vertex(holes.boundaryLoops().back()[0]);
  auto onRim = parameterize(holes, o);
  ASSERT_FALSE(onRim.ok());
  EXPECT_EQ(onRim.error().code, ErrorCode::InvalidArgument);
}

TEST(ParameterizeClosed, SeveralComponentsParameterizeTheLargestAndSaySo) {
  const TriMesh cap = makeSample("cap").value(), sphere = makeIcosphere(1, 2);  // cap: 817 faces, sphere: 320
  const TriMesh mesh = sideBySide(sphere, cap, Vec3{4, 0, 0});
  const Parameterization p = cappedParam(mesh, BoundaryKind::Circle);
  EXPECT_EQ(p.components, 2);
  EXPECT_EQ(p.component, 1) << "the cap's faces come after the sphere's";
  EXPECT_EQ(p.cut, CutMethod::Disk) << "the cap is a disk already";
  expectConsistentCut(mesh, p, "cap beside a sphere");
  expectBijective(p, "cap beside a sphere");
  for (int32_t f = 0; f < sphere.numFaces(); ++f) EXPECT_TRUE(std::isnan(p.cornerUv[3 * f].x));
  for (int32_t v = 0; v < sphere.numVertices(); ++v) EXPECT_EQ(p.uv[v], (Vec2{0, 0}));
  for (int32_t f = sphere.numFaces(); f < mesh.numFaces(); ++f) EXPECT_TRUE(std::isfinite(p.metrics.faceStretch[f]));
}

TEST(ParameterizeClosed, RefiningACutMapIsWhatTheFreeBoundaryGives) {
  const TriMesh mesh = makeSample("holes").value();
  ParamOptions o;
  o.boundary = BoundaryKind::Measured;
  const Parameterization measured = parameterize(mesh, o).value();
  ASSERT_TRUE(measured.metrics.bijective);
  o.boundary = BoundaryKind::Free;
  const Parameterization free = parameterize(mesh, o).value();
  const Parameterization refined = refineParameterization(mesh, measured, o.free).value();
  EXPECT_EQ(refined.cornerUv, free.cornerUv);
  EXPECT_EQ(refined.uv, free.uv);
  EXPECT_EQ(refined.cut, CutMethod::Fill);
}

TEST(ParameterizeClosed, PolygonsAndTheComparisonWorkOnCutMeshes) {
  const TriMesh mesh = makeSample("torus").value();
  auto polygons = boundaryPolygons(mesh, std::nullopt, {BoundaryKind::Circle, BoundaryKind::Square});
  ASSERT_TRUE(polygons.ok()) << polygons.error().message;
  for (const BoundaryPolygon& entry : polygons.value()) {
    const Parameterization p = cappedParam(mesh, entry.kind);
    EXPECT_EQ(entry.loop, p.boundaryLoop);
    ASSERT_EQ(entry.polygon.size(), p.boundaryPolygon.size());
    for (size_t i = 0; i < entry.polygon.size(); ++i) EXPECT_NEAR(entry.polygon[i].x, p.boundaryPolygon[i].x, 1e-12);
  }
  auto comparison = compareParameterizations(mesh, std::nullopt, {BoundaryKind::Circle, BoundaryKind::Free},
                                             {WeightKind::MeanValue});
  ASSERT_TRUE(comparison.ok()) << comparison.error().message;
  for (const ComparisonRow& row : comparison.value().rows) {
    EXPECT_FALSE(row.error) << boundaryKindName(row.boundary) << ": " << row.error->message;
    EXPECT_TRUE(row.bijective) << boundaryKindName(row.boundary);
  }
}

TEST(ParameterizeClosed, CuttingReportsItsStageAndCanBeCancelled) {
  const TriMesh mesh = makeSample("torus").value();
  std::vector<std::string> stages;
  ParamOptions o;
  o.boundary = BoundaryKind::Circle;
  Timings timings;
  o.timings = &timings;
  ASSERT_TRUE(parameterize(mesh, o, [&](const char* stage, double) {
                stages.push_back(stage);
                return true;
              }).ok());
  ASSERT_FALSE(stages.empty());
  EXPECT_EQ(stages.front(), "cut");
  EXPECT_GT(timings["cut"], 0);
  EXPECT_GE(timings["total"], timings["cut"]);
  auto cancelled = parameterize(mesh, o, [](const char* stage, double) { return std::string(stage) != "cut"; });
  ASSERT_FALSE(cancelled.ok());
  EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
}

/// The OBJ text's vt coordinates and, per face, its vt indices (0 for a face written without vt).
struct ObjTexture {
  std::vector<Vec2> vt;
  std::vector<std::array<int32_t, 3>> faceVt;
};
ObjTexture readTexture(const std::string& text) {
  ObjTexture out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "vt") {
      Vec2 t;
      words >> t.x >> t.y;
      out.vt.push_back(t);
    } else if (key == "f") {
      std::array<int32_t, 3> ids{0, 0, 0};
      for (int k = 0; k < 3; ++k) {
        std::string corner;
        words >> corner;
        const size_t slash = corner.find('/');
        ids[k] = slash == std::string::npos ? 0 : std::stoi(corner.substr(slash + 1));
      }
      out.faceVt.push_back(ids);
    }
  }
  return out;
}

TEST(ObjWithCornerUv, TheRoundTripKeepsTheSeamSplitAndTheExactUv) {
  const TriMesh mesh = makeSample("torus").value();
  const Parameterization p = cappedParam(mesh, BoundaryKind::Circle);
  const std::string text = writeObjWithCornerUv(mesh, p.cornerUv);
  const TriMesh back = loadMesh(text, MeshFormat::Obj).value();
  ASSERT_EQ(back.numVertices(), mesh.numVertices());
  for (int32_t v = 0; v < mesh.numVertices(); ++v) ASSERT_EQ(norm(back.position(v) - mesh.position(v)), 0.0);
  EXPECT_EQ(back.triangles(), mesh.triangles());
  const ObjTexture tex = readTexture(text);
  ASSERT_EQ(tex.faceVt.size(), static_cast<size_t>(mesh.numFaces()));
  std::set<std::pair<double, double>> distinct;
  for (const Vec2& c : p.cornerUv) distinct.insert({c.x == 0 ? 0.0 : c.x, c.y == 0 ? 0.0 : c.y});
  EXPECT_EQ(tex.vt.size(), distinct.size()) << "one vt per distinct uv";
  EXPECT_GT(tex.vt.size(), static_cast<size_t>(mesh.numVertices())) << "seam vertices have a vt per side";
  for (int32_t f = 0; f < mesh.numFaces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int32_t id = tex.faceVt[f][k];
      ASSERT_GE(id, 1);
      ASSERT_EQ(tex.vt[id - 1], p.cornerUv[3 * f + k]) << "face " << f;
    }
  // Across a seam edge the two faces name different vt; across any other edge the same.
  std::set<Edge> seam;
  for (const auto& e : p.seam) seam.insert(undirected(e[0], e[1]));
  for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h) {
    const int32_t g = mesh.twin(h);
    if (g < h) continue;
    const bool same = tex.faceVt[h / 3][h % 3] == tex.faceVt[g / 3][TriMesh::next(g) % 3] &&
                      tex.faceVt[h / 3][TriMesh::next(h) % 3] == tex.faceVt[g / 3][g % 3];
    EXPECT_EQ(same, !seam.count(undirected(mesh.tail(h), mesh.head(h))));
  }
  // Faces outside the parameterized component are written without vt.
  const TriMesh two = sideBySide(makeIcosphere(1, 1), makeSample("cap").value(), Vec3{4, 0, 0});
  const ObjTexture partial = readTexture(writeObjWithCornerUv(two, cappedParam(two, BoundaryKind::Circle).cornerUv));
  for (int32_t f = 0; f < two.numFaces(); ++f)
    EXPECT_EQ(partial.faceVt[f][0] == 0, f < makeIcosphere(1, 1).numFaces()) << "face " << f;
}

}  // namespace
}  // namespace straightest
