// parameterize_cut.cpp — a mesh that is not a disk, parameterized through the disk cutToDisk makes of
// it, and the result mapped back onto the mesh's vertices, faces and corners (parameterize_cut.hpp).
#include "parameterize_cut.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "straightest/geodesics/geodesic_distance.hpp"

namespace straightest {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// r such that disk face d's corner (k + r) % 3 copies mesh face f's corner k (a cut keeps each
/// face's orientation; only the numbering of its corners could differ).
int cornerShift(const TriMesh& mesh, const CutDisk& c, int32_t f, int32_t d) {
  const Triangle& t = mesh.triangle(f);
  const Triangle& u = c.cut.disk.triangle(d);
  for (int r = 0; r < 3; ++r)
    if (c.cut.vertexOrigin[u[r]] == t[0]) return r;
  return 0;
}

/// Union–find over face corners.
int32_t findRoot(std::vector<int32_t>& parent, int32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

/// The real faces' corners at one disk vertex form one fan unless virtual faces separate them (a seam
/// vertex on a filled hole's rim): every further fan gets a new vertex (numbered after the disk's,
/// extraOrigin its disk vertex), so the real faces are a manifold.
void splitPinchedVertices(const TriMesh& disk, const std::vector<int32_t>& realOfDisk, std::vector<Triangle>& realFaces,
                          std::vector<int32_t>& extraOrigin) {
  const int32_t n = static_cast<int32_t>(realFaces.size());
  std::vector<int32_t> parent(3 * static_cast<size_t>(n));
  for (int32_t i = 0; i < 3 * n; ++i) parent[i] = i;
  // Corners at the same vertex of two real faces that share an edge belong to one fan.
  for (int32_t h = 0; h < 3 * disk.numFaces(); ++h) {
    const int32_t g = disk.twin(h);
    if (g < h) continue;
    const int32_t a = realOfDisk[TriMesh::face(h)], b = realOfDisk[TriMesh::face(g)];
    if (a < 0 || b < 0) continue;
    // h goes tail → head in face a; g goes head → tail in face b.
    const int32_t tailA = 3 * a + h % 3, headA = 3 * a + TriMesh::next(h) % 3;
    const int32_t headB = 3 * b + g % 3, tailB = 3 * b + TriMesh::next(g) % 3;
    parent[findRoot(parent, tailA)] = findRoot(parent, tailB);
    parent[findRoot(parent, headA)] = findRoot(parent, headB);
  }
  std::vector<int32_t> fanOf(disk.numVertices(), -1);             // the root of the fan that keeps the vertex's number
  std::vector<int32_t> renumber(3 * static_cast<size_t>(n), -1);  // per root: its vertex
  for (int32_t c = 0; c < 3 * n; ++c) {
    const int32_t v = realFaces[c / 3][c % 3], root = findRoot(parent, c);
    if (renumber[root] < 0) {
      if (fanOf[v] < 0) {
        fanOf[v] = root;
        renumber[root] = v;
      } else {
        renumber[root] = disk.numVertices() + static_cast<int32_t>(extraOrigin.size());
        extraOrigin.push_back(v);
      }
    }
    realFaces[c / 3][c % 3] = renumber[root];
  }
}

Error notOnDisk(const std::string& what) {
  return Error{ErrorCode::InvalidArgument,
               "the source must be a point of the parameterized surface, not on its seam: " + what};
}

}  // namespace

Expected<CutDisk> makeCutDisk(const TriMesh& mesh, const Progress& progress) {
  auto cut = cutToDisk(mesh, progress);
  if (!cut) return cut.error();
  // Every component a lone triangle: a triangle soup, whose faces share no vertices (a non-indexed
  // export). Mapping its largest triangle would look like an answer; its vertices need welding first.
  if (cut.value().disk.numFaces() == 1 && cut.value().components > 1)
    return Error{ErrorCode::Topology, "every one of the " + std::to_string(cut.value().components) +
                                          " components is a single triangle: the faces share no vertices"};
  CutDisk c(std::move(cut).value());
  const TriMesh& disk = c.cut.disk;
  c.diskFaceOf.assign(mesh.numFaces(), -1);
  c.copies.assign(mesh.numVertices(), 0);
  c.copyOf.assign(mesh.numVertices(), -1);
  std::vector<Triangle> realFaces;
  realFaces.reserve(disk.numFaces());
  std::vector<int32_t> realOfDisk(disk.numFaces(), -1);
  for (int32_t d = 0; d < disk.numFaces(); ++d) {
    const int32_t f = c.cut.faceOrigin[d];
    if (f < 0) continue;
    c.diskFaceOf[f] = d;
    realOfDisk[d] = static_cast<int32_t>(c.realFaceDisk.size());
    c.realFaceDisk.push_back(d);
    realFaces.push_back(disk.triangle(d));
  }
  for (int32_t v = 0; v < disk.numVertices(); ++v) {
    const int32_t o = c.cut.vertexOrigin[v];
    if (o < 0) {
      ++c.virtualVertices;
    } else {
      if (c.copies[o]++ == 0) c.copyOf[o] = v;
    }
  }
  if (realFaces.size() == static_cast<size_t>(disk.numFaces())) return c;  // nothing filled: real = disk
  splitPinchedVertices(disk, realOfDisk, realFaces, c.realExtraOrigin);
  std::vector<Vec3> positions = disk.positions();
  for (int32_t v : c.realExtraOrigin) positions.push_back(disk.position(v));
  auto real = TriMesh::build(std::move(positions), std::move(realFaces));
  if (!real) return Error{ErrorCode::Internal, "the disk's real faces are not a mesh: " + real.error().message};
  c.realFaces = std::move(real).value();
  return c;
}

Expected<SurfacePoint> pointOnDisk(const TriMesh& mesh, const CutDisk& c, const SurfacePoint& p) {
  const TriMesh& disk = c.cut.disk;
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: {
      if (c.copies[p.index] == 0) return notOnDisk("vertex " + std::to_string(p.index) + " is in another component");
      // Several copies, or one on the disk's boundary that is not on the mesh's (a seam's end).
      const int32_t copy = c.copyOf[p.index];
      if (c.copies[p.index] > 1 || (disk.isBoundaryVertex(copy) && !mesh.isBoundaryVertex(p.index)))
        return notOnDisk("vertex " + std::to_string(p.index) + " is on the seam");
      return SurfacePoint::vertex(copy);
    }
    case SurfacePoint::Kind::Face: {
      const int32_t d = c.diskFaceOf[p.index];
      if (d < 0) return notOnDisk("face " + std::to_string(p.index) + " is in another component");
      const int r = cornerShift(mesh, c, p.index, d);
      std::array<double, 3> b{};
      for (int k = 0; k < 3; ++k) b[(k + r) % 3] = p.bary[k];
      return SurfacePoint::face(d, b);
    }
    case SurfacePoint::Kind::Edge: {
      const int32_t f = TriMesh::face(p.index), d = c.diskFaceOf[f];
      if (d < 0) return notOnDisk("halfedge " + std::to_string(p.index) + " is in another component");
      const int32_t h = 3 * d + (p.index % 3 + cornerShift(mesh, c, f, d)) % 3;
      if (disk.twin(h) < 0 && mesh.twin(p.index) >= 0)
        return notOnDisk("halfedge " + std::to_string(p.index) + " is on the seam");
      return SurfacePoint::edge(h, p.t);
    }
  }
  return notOnDisk("unknown point");
}

namespace {

/// A disk point as the mesh's (the disk's points are real: the source is never a virtual point).
SurfacePoint pointOnMesh(const TriMesh& mesh, const CutDisk& c, const SurfacePoint& p) {
  const TriMesh& disk = c.cut.disk;
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: return SurfacePoint::vertex(c.cut.vertexOrigin[p.index]);
    case SurfacePoint::Kind::Face: {
      const int32_t f = c.cut.faceOrigin[p.index];
      if (f < 0) return p;
      const int r = cornerShift(mesh, c, f, p.index);
      std::array<double, 3> b{};
      for (int k = 0; k < 3; ++k) b[k] = p.bary[(k + r) % 3];
      return SurfacePoint::face(f, b);
    }
    case SurfacePoint::Kind::Edge: {
      const int32_t d = TriMesh::face(p.index), f = c.cut.faceOrigin[d];
      if (f < 0) return p;
      const int r = cornerShift(mesh, c, f, d);
      return canonical(mesh, SurfacePoint::edge(3 * f + (p.index % 3 + 3 - r) % 3, p.t), kExactSnap);
    }
  }
  (void)disk;
  return p;
}

}  // namespace

Expected<SurfacePoint> diskDefaultSource(const CutDisk& c) {
  const TriMesh& disk = c.cut.disk;
  const TriMesh& real = c.real();
  auto v = defaultSource(disk);
  if (!v) {
    // No vertex inside the disk: the middle of its largest real face (defaultSourcePoint).
    auto p = defaultSourcePoint(real);
    if (!p) return p.error();
    SurfacePoint onDisk = p.value();
    if (c.realFaces) onDisk.index = c.realFaceDisk[onDisk.index];
    return onDisk;
  }
  const auto usable = [&](int32_t u) {
    return c.cut.vertexOrigin[u] >= 0 && real.vertexHalfedge(u) >= 0 && !real.isBoundaryVertex(u);
  };
  if (usable(v.value())) return SurfacePoint::vertex(v.value());
  // The centre of a filled hole (or a vertex on its rim) is not a point of the surface: the real vertex
  // deepest inside the disk instead.
  const std::vector<double> dist = dijkstraDistances(disk, disk.boundaryLoops().at(0));
  int32_t best = -1;
  for (int32_t u = 0; u < disk.numVertices(); ++u)
    if (usable(u) && std::isfinite(dist[u]) && (best < 0 || dist[u] > dist[best])) best = u;
  if (best >= 0) return SurfacePoint::vertex(best);
  // No real vertex off every boundary (a thin annulus): a real one on a filled hole's rim, interior to the
  // disk (a source the measured boundary can still trace from), else the first real one.
  for (int32_t u = 0; u < disk.numVertices(); ++u)
    if (c.cut.vertexOrigin[u] >= 0 && real.vertexHalfedge(u) >= 0 && (best < 0 || !disk.isBoundaryVertex(u))) {
      best = u;
      if (!disk.isBoundaryVertex(u)) break;
    }
  if (best < 0) return Error{ErrorCode::Topology, "the parameterized surface has no vertex"};
  return SurfacePoint::vertex(best);
}

Parameterization mapBack(const TriMesh& mesh, const CutDisk& c, Parameterization p) {
  const TriMesh& real = c.real();
  p.source = pointOnMesh(mesh, c, p.source);
  // uv per disk vertex (a fixed boundary) or per real vertex (the free one): the corners read it
  // through the real faces, whose extra vertices (split fans) have their own uv only in the latter.
  const bool perDiskVertex = p.uv.size() < static_cast<size_t>(real.numVertices());
  const std::vector<Vec2> realUv = perDiskVertex ? onRealVertices(std::move(p.uv), c.realExtraOrigin) : std::move(p.uv);
  p.uv.assign(mesh.numVertices(), Vec2{0, 0});
  for (int32_t o = 0; o < mesh.numVertices(); ++o)
    if (c.copyOf[o] >= 0) p.uv[o] = realUv[c.copyOf[o]];
  p.cornerUv.assign(3 * static_cast<size_t>(mesh.numFaces()), Vec2{kNaN, kNaN});
  for (size_t i = 0; i < c.realFaceDisk.size(); ++i) {
    const int32_t d = c.realFaceDisk[i], f = c.cut.faceOrigin[d];
    const int r = cornerShift(mesh, c, f, d);
    for (int k = 0; k < 3; ++k) p.cornerUv[3 * f + k] = realUv[real.triangle(static_cast<int32_t>(i))[(k + r) % 3]];
  }
  for (int32_t& v : p.boundaryLoop) v = c.cut.vertexOrigin[v];
  std::vector<float> realStretch = std::move(p.metrics.faceStretch);
  p.metrics.faceStretch.assign(mesh.numFaces(), std::numeric_limits<float>::quiet_NaN());
  for (size_t i = 0; i < realStretch.size() && i < c.realFaceDisk.size(); ++i)
    p.metrics.faceStretch[c.cut.faceOrigin[c.realFaceDisk[i]]] = realStretch[i];
  p.cut = c.cut.method;
  p.seam = c.cut.seam;
  p.filledLoops = c.cut.filledLoops;
  p.genus = c.cut.genus;
  p.seamLength = c.cut.seamLength;
  p.component = c.cut.component;
  p.components = c.cut.components;
  p.virtualVertices = c.virtualVertices;
  return p;
}

Expected<Parameterization> parameterizeByCut(const TriMesh& mesh, const ParamOptions& options,
                                             const Progress& progress) {
  const Error cancelled = cancelledError("parameterization");
  if (!report(progress, "cut", 0)) return cancelled;
  const Stopwatch stage;
  auto made = makeCutDisk(mesh, progress);
  if (!made) return made.error().code == ErrorCode::Cancelled ? cancelled : made.error();
  const CutDisk& c = made.value();
  const double cutMs = stage.ms();
  ParamOptions o = options;
  if (options.source) {
    // The mesh's own rule first (an interior point of the mesh, holes' rims included), then the seam's.
    const bool needsSource = !options.boundary || *options.boundary == BoundaryKind::Measured ||
                             *options.boundary == BoundaryKind::Free;
    auto s = needsSource ? interiorSource(mesh, options.source) : resolveSource(mesh, options.source);
    if (!s) return s.error();
    auto onDisk = pointOnDisk(mesh, c, canonical(mesh, s.value(), kSnapSource));
    if (!onDisk) return onDisk.error();
    o.source = onDisk.value();
  } else {
    auto s = diskDefaultSource(c);
    if (!s) return s.error();
    o.source = s.value();
  }
  auto solved = parameterizeDisk(c.cut.disk, c.real(), c.realExtraOrigin, o, progress);
  if (!solved) return solved.error();
  record(options.timings, "cut", cutMs);
  record(options.timings, "total", cutMs);
  return mapBack(mesh, c, std::move(solved).value());
}

Expected<Parameterization> refineByCut(const TriMesh& mesh, const Parameterization& start,
                                       const FreeBoundaryOptions& options, const Progress& progress, Timings* timings) {
  if (start.cornerUv.size() != 3 * static_cast<size_t>(mesh.numFaces()))
    return Error{ErrorCode::InvalidArgument, "the start map has " + std::to_string(start.cornerUv.size()) +
                                                 " corner uv for a mesh of " + std::to_string(mesh.numFaces()) +
                                                 " faces (3 per face)"};
  auto made = makeCutDisk(mesh, progress);
  if (!made) return made.error().code == ErrorCode::Cancelled ? cancelledError("parameterization") : made.error();
  const CutDisk& c = made.value();
  const TriMesh& disk = c.cut.disk;
  const TriMesh& real = c.real();
  Parameterization onDisk = start;
  onDisk.uv.assign(real.numVertices(), Vec2{0, 0});  // per real vertex: the start's corners
  for (size_t i = 0; i < c.realFaceDisk.size(); ++i) {
    const int32_t d = c.realFaceDisk[i], f = c.cut.faceOrigin[d];
    const int r = cornerShift(mesh, c, f, d);
    for (int k = 0; k < 3; ++k)
      onDisk.uv[real.triangle(static_cast<int32_t>(i))[(k + r) % 3]] = start.cornerUv[3 * f + k];
  }
  onDisk.boundaryLoop = disk.boundaryLoops().at(0);
  auto refined = refineOnDisk(c.real(), onDisk, options, progress, timings);
  if (!refined) return refined.error();
  Parameterization p = mapBack(mesh, c, std::move(refined).value());
  p.source = start.source;
  return p;
}

}  // namespace straightest
