// libFuzzer harness: TriMesh::build (validation, orientation repair, half-edge tables, summary),
// meshFromFlatArrays and triangulatePolygon, on meshes made from the bytes:
//  - "soup": a few vertices (lattice coordinates that coincide and line up, or raw doubles, or
//    NaN/Inf/huge) and small integer triangles over them (some indices out of range or negative);
//  - "edited": a valid mesh (grid, tetrahedron, octahedron, strip) with a few random edits: faces
//    flipped, deleted, duplicated, re-pointed, added;
//  - "flat arrays": the same through meshFromFlatArrays, with non-integer and negative indices;
//  - "polygon": triangulatePolygon on a random polygon.
// Invariants: build's answer (error category, or success) agrees with an independent oracle; an
// accepted mesh has symmetric reversed twins, consistently oriented neighbours, boundary loops that
// cover every boundary halfedge once, single vertex fans, V−E+F and summary counts recomputed from
// scratch, positions kept and faces kept or flipped (the minority of each component); errors have a
// known category and a message. Polygons split into exactly n−2 triangles over their own corners.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdlib>
#include <limits>

#include "fuzz_common.hpp"
#include "straightest/io/mesh_io.hpp"

using namespace straightest;

namespace {

double specialValue(FuzzedDataProvider& in) {
  static const double values[] = {std::numeric_limits<double>::quiet_NaN(),
                                  std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity(),
                                  1e151,
                                  -1e151,
                                  kMaxCoordinate,
                                  -0.0,
                                  5e-324,
                                  1e-300,
                                  1e150 * 0.999,
                                  1e100,
                                  1e-12};
  return values[in.ConsumeIntegralInRange<size_t>(0, sizeof values / sizeof values[0] - 1)];
}

double coordinate(FuzzedDataProvider& in, int style) {
  switch (style) {
    case 0: return in.ConsumeIntegralInRange<int>(0, 3);              // coincident, collinear
    case 1: return in.ConsumeIntegralInRange<int>(-100, 100) * 0.01;  // a fine lattice
    case 2: return in.ConsumeFloatingPoint<double>();                 // anything finite
    default: return in.ConsumeBool() ? specialValue(in) : in.ConsumeIntegralInRange<int>(0, 3);
  }
}

int32_t index(FuzzedDataProvider& in, int32_t nv) {
  const int32_t i = in.ConsumeIntegralInRange<int32_t>(-1, nv);  // -1 and nv are out of range
  if (i == nv && in.ConsumeBool()) return std::numeric_limits<int32_t>::max();
  return i;
}

void soup(FuzzedDataProvider& in, std::vector<Vec3>& P, std::vector<Triangle>& T) {
  const int style = in.ConsumeIntegralInRange(0, 3);
  const int32_t nv = in.ConsumeIntegralInRange<int32_t>(0, 24);
  for (int32_t v = 0; v < nv; ++v) P.push_back({coordinate(in, style), coordinate(in, style), coordinate(in, style)});
  const int32_t nf = in.ConsumeIntegralInRange<int32_t>(0, 48);
  for (int32_t f = 0; f < nf && in.remaining_bytes() > 0; ++f) {
    // Mostly valid indices (the oracle then decides the topology), sometimes out of range.
    if (in.ConsumeIntegralInRange(0, 15) == 0) {
      T.push_back({index(in, nv), index(in, nv), index(in, nv)});
    } else {
      const int32_t hi = std::max(0, nv - 1);
      T.push_back({in.ConsumeIntegralInRange<int32_t>(0, hi), in.ConsumeIntegralInRange<int32_t>(0, hi),
                   in.ConsumeIntegralInRange<int32_t>(0, hi)});
    }
  }
}

void baseMesh(FuzzedDataProvider& in, std::vector<Vec3>& P, std::vector<Triangle>& T) {
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0: {  // grid, either diagonal per cell
      const int n = in.ConsumeIntegralInRange(2, 6);
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) P.push_back({double(i), double(j), in.ConsumeIntegralInRange(0, 2) * 0.5});
      for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
          const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
          if (in.ConsumeBool()) {
            T.push_back({a, b, d});
            T.push_back({a, d, c});
          } else {
            T.push_back({a, b, c});
            T.push_back({b, d, c});
          }
        }
      break;
    }
    case 1:  // tetrahedron
      P = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      T = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
      break;
    case 2:  // octahedron
      P = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      T = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
      break;
    default: {  // a strip (a band when closed: an annulus or, with a twist, a Möbius strip)
      const int n = in.ConsumeIntegralInRange(3, 8);
      const bool closed = in.ConsumeBool(), twist = closed && in.ConsumeBool();
      for (int i = 0; i < n; ++i) {
        const double a = 6.283185307179586 * i / n;
        P.push_back({std::cos(a), std::sin(a), -0.2});
        P.push_back({std::cos(a), std::sin(a), 0.2});
      }
      for (int i = 0; i + 1 < n + (closed ? 1 : 0); ++i) {
        int a = 2 * i, b = 2 * i + 1, c = 2 * ((i + 1) % n), d = c + 1;
        if (twist && i == n - 1) std::swap(c, d);
        T.push_back({a, c, d});
        T.push_back({a, d, b});
      }
      break;
    }
  }
  const int edits = in.ConsumeIntegralInRange(0, 4);
  for (int e = 0; e < edits && !T.empty(); ++e) {
    const size_t f = in.ConsumeIntegralInRange<size_t>(0, T.size() - 1);
    const int32_t nv = static_cast<int32_t>(P.size());
    switch (in.ConsumeIntegralInRange(0, 6)) {
      case 0:
      case 1: std::swap(T[f][1], T[f][2]); break;                          // flip (repairable)
      case 2: T.erase(T.begin() + static_cast<std::ptrdiff_t>(f)); break;  // delete
      case 3: T.push_back(T[f]); break;                                    // duplicate
      case 4: T[f][in.ConsumeIntegralInRange(0, 2)] = in.ConsumeIntegralInRange<int32_t>(0, nv - 1); break;
      case 5:
        T.push_back({in.ConsumeIntegralInRange<int32_t>(0, nv - 1), in.ConsumeIntegralInRange<int32_t>(0, nv - 1),
                     in.ConsumeIntegralInRange<int32_t>(0, nv - 1)});
        break;
      default: P.push_back({in.ConsumeProbability<double>(), 0, 0}); break;  // an unreferenced vertex
    }
  }
}

void flatArrays(FuzzedDataProvider& in) {
  std::vector<double> xyz, indices;
  const size_t nx = in.ConsumeIntegralInRange<size_t>(0, 40), ni = in.ConsumeIntegralInRange<size_t>(0, 60);
  for (size_t i = 0; i < nx; ++i) xyz.push_back(in.ConsumeBool() ? specialValue(in) : in.ConsumeIntegralInRange(0, 3));
  const int32_t nv = static_cast<int32_t>(nx / 3);
  for (size_t i = 0; i < ni; ++i) {
    switch (in.ConsumeIntegralInRange(0, 7)) {
      case 0: indices.push_back(specialValue(in)); break;
      case 1: indices.push_back(in.ConsumeIntegralInRange(-2, nv + 1) + 0.5); break;
      case 2: indices.push_back(4294967296.0 + in.ConsumeIntegralInRange(0, 3)); break;
      default: indices.push_back(in.ConsumeIntegralInRange(0, std::max(0, nv - 1))); break;
    }
  }
  auto r = meshFromFlatArrays(xyz, indices);
  bool allIntegers = xyz.size() % 3 == 0 && indices.size() % 3 == 0;
  for (double x : indices) allIntegers &= x >= 0 && x <= std::numeric_limits<int32_t>::max() && x == std::floor(x);
  if (!allIntegers) {
    FUZZ_CHECK(!r.ok(), "meshFromFlatArrays accepted bad arrays");
    fuzz::checkError(r.error(), "meshFromFlatArrays");
    FUZZ_CHECK(r.error().code == ErrorCode::InvalidArgument || r.error().code == ErrorCode::IndexOutOfRange,
               "meshFromFlatArrays: unexpected category %s", errorCodeName(r.error().code));
    return;
  }
  std::vector<Vec3> P(nx / 3);
  for (size_t v = 0; v < P.size(); ++v) P[v] = {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
  std::vector<Triangle> T(indices.size() / 3);
  for (size_t i = 0; i < indices.size(); ++i) T[i / 3][i % 3] = static_cast<int32_t>(indices[i]);
  fuzz::checkBuildResult(P, T, r, "meshFromFlatArrays");
}

void polygon(FuzzedDataProvider& in) {
  std::vector<Vec3> P;
  const int style = in.ConsumeIntegralInRange(0, 2);
  const int32_t nv = in.ConsumeIntegralInRange<int32_t>(3, 300);
  // A star polygon gets all its corners (radius 0.1 once the bytes run out) so it stays simple.
  for (int32_t v = 0; v < nv && (v < 3 || style == 0 || in.remaining_bytes() > 0); ++v) {
    if (style == 0) {  // a star-shaped planar polygon with random radii
      const double a = 6.283185307179586 * v / nv, r = 0.1 + in.ConsumeProbability<double>();
      P.push_back({r * std::cos(a), r * std::sin(a), 0});
    } else {
      P.push_back({coordinate(in, style == 1 ? 0 : 1), coordinate(in, 1), coordinate(in, 0)});
    }
  }
  std::vector<int32_t> poly(P.size());
  std::iota(poly.begin(), poly.end(), 0);
  if (style == 2 && in.ConsumeBool() && poly.size() > 3) poly[3] = poly[0];  // a repeated corner
  if (std::getenv("FUZZ_VERBOSE")) {
    std::fprintf(stderr, "polygon:");
    for (int32_t v : poly) std::fprintf(stderr, " (%.17g, %.17g, %.17g)", P[v].x, P[v].y, P[v].z);
    std::fprintf(stderr, "\n");
  }
  std::vector<Triangle> out;
  triangulatePolygon(P, poly, out);
  FUZZ_CHECK(out.size() == poly.size() - 2, "polygon of %zu corners gave %zu triangles", poly.size(), out.size());
  std::vector<int> uses(P.size(), 0);
  for (const Triangle& t : out)
    for (int k = 0; k < 3; ++k) {
      FUZZ_CHECK(t[k] >= 0 && t[k] < static_cast<int32_t>(P.size()), "triangle corner %d not in the polygon", t[k]);
      ++uses[t[k]];
    }
  for (int32_t v : poly) FUZZ_CHECK(uses[v] > 0, "polygon corner %d unused", v);
  if (style == 0) {  // a simple polygon: the triangles tile it (areas add up, none inverted)
    double area = 0, sum = 0;
    for (size_t i = 0; i < P.size(); ++i) {
      const Vec3 &a = P[i], &b = P[(i + 1) % P.size()];
      area += 0.5 * (a.x * b.y - b.x * a.y);
    }
    for (const Triangle& t : out) {
      const Vec3 c = cross(P[t[1]] - P[t[0]], P[t[2]] - P[t[0]]);
      FUZZ_CHECK(P.size() > 256 || c.z >= -1e-12, "ear clipping produced an inverted triangle");
      sum += 0.5 * std::abs(c.z);
    }
    FUZZ_CHECK(P.size() > 256 || std::abs(sum - area) <= 1e-9 * area, "triangles cover %.17g of the polygon's %.17g",
               sum, area);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider in(data, size);
  const int mode = in.ConsumeIntegralInRange(0, 9);
  if (mode == 8) {
    flatArrays(in);
    return 0;
  }
  if (mode == 9) {
    polygon(in);
    return 0;
  }
  std::vector<Vec3> P;
  std::vector<Triangle> T;
  if (mode < 4) soup(in, P, T);
  else baseMesh(in, P, T);
  fuzz::checkBuildResult(P, T, TriMesh::build(P, T), "build");
  return 0;
}
