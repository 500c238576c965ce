// boundary_polygons.cpp — every kind's boundary polygon without a solve, a non-disk's through its cut disk.
#include "straightest/param/boundary_polygons.hpp"

#include "parameterize_cut.hpp"
#include "straightest/base/names.hpp"
#include "straightest/param/parameterize.hpp"

namespace straightest {
namespace {

/// Not a disk: the polygons of the disk parameterize cuts it into (the same cut, the same default
/// source), with the loop in mesh vertex numbers. A source on the seam is the measured entry's error.
Expected<std::vector<BoundaryPolygon>> cutBoundaryPolygons(const TriMesh& mesh,
                                                           const std::optional<SurfacePoint>& source,
                                                           const std::vector<BoundaryKind>& kinds,
                                                           const Progress& progress) {
  auto made = makeCutDisk(mesh, progress);
  if (!made) return made.error();
  const CutDisk& c = made.value();
  Expected<SurfacePoint> onDisk = Error{ErrorCode::Internal, "no source"};
  if (source) {
    auto s = interiorSource(mesh, source);
    onDisk = s ? pointOnDisk(mesh, c, canonical(mesh, s.value(), kSnapSource)) : Expected<SurfacePoint>(s.error());
  } else {
    onDisk = diskDefaultSource(c);
  }
  const bool measuredError = !onDisk;
  auto polygons = boundaryPolygons(c.cut.disk, onDisk ? std::optional<SurfacePoint>(onDisk.value()) : std::nullopt,
                                   kinds, progress);
  if (!polygons) return polygons;
  for (BoundaryPolygon& entry : polygons.value()) {
    for (int32_t& v : entry.loop) v = c.cut.vertexOrigin[v];
    if (entry.kind == BoundaryKind::Measured && measuredError) {
      entry.polygon.clear();
      entry.error = onDisk.error();
    }
  }
  return polygons;
}

}  // namespace

std::vector<BoundaryKind> polygonBoundaryKinds() {
  std::vector<BoundaryKind> kinds;
  for (const EnumName<BoundaryKind>& e : kBoundaryKindNames)
    if (e.value != BoundaryKind::Free) kinds.push_back(e.value);
  return kinds;
}

Expected<std::vector<BoundaryPolygon>> boundaryPolygons(const TriMesh& mesh, const std::optional<SurfacePoint>& source,
                                                        const std::vector<BoundaryKind>& kinds,
                                                        const Progress& progress) {
  for (BoundaryKind kind : kinds)
    if (kind == BoundaryKind::Free) {
      std::vector<std::string> names;
      for (BoundaryKind k : polygonBoundaryKinds()) names.push_back(boundaryKindName(k));
      return Error{ErrorCode::InvalidArgument,
                   "the free boundary has no polygon without its nonlinear refinement (parameterize with boundary "
                   "'free' returns it as boundaryPolygon); polygons exist for " +
                       choiceList(names, ", ", " and ")};
    }
  if (!requireDisk(mesh)) return cutBoundaryPolygons(mesh, source, kinds, progress);
  std::vector<BoundaryPolygon> out;
  for (BoundaryKind kind : kinds) {
    BoundaryPolygon entry;
    entry.kind = kind;
    entry.loop = mesh.boundaryLoops().at(0);
    Expected<BoundaryMap> map = Error{ErrorCode::Topology, "no boundary map"};
    switch (kind) {
      case BoundaryKind::Measured: {
        auto s = interiorSource(mesh, source);
        if (!s) {
          map = s.error();
          break;
        }
        map = measuredBoundary(mesh, s.value(), progress);
        if (!map && map.error().code == ErrorCode::Cancelled) return map.error();
        break;
      }
      case BoundaryKind::Circle: map = circleBoundary(mesh); break;
      case BoundaryKind::Square: map = squareBoundary(mesh); break;
      case BoundaryKind::Free: break;  // refused above
    }
    if (map) {
      const UnitSquareFrame frame = unitSquareFrame(map.value().polygon);
      for (const Vec2& q : map.value().polygon) entry.polygon.push_back(frame(q));
    } else {
      entry.error = map.error();
    }
    out.push_back(std::move(entry));
  }
  return out;
}

}  // namespace straightest
