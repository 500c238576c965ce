#include "straightest/boundary_polygons.hpp"

#include "straightest/enum_names.hpp"
#include "straightest/parameterize.hpp"

namespace straightest {

std::vector<BoundaryKind> polygonBoundaryKinds() {
  std::vector<BoundaryKind> kinds;
  for (const EnumName<BoundaryKind>& e : kBoundaryKindNames)
    if (e.value != BoundaryKind::Free) kinds.push_back(e.value);
  return kinds;
}

Expected<std::vector<BoundaryPolygon>> boundaryPolygons(const TriMesh& mesh, const std::optional<SurfacePoint>& source,
                                                        const std::vector<BoundaryKind>& kinds,
                                                        const Progress& progress) {
  auto disk = requireDisk(mesh);
  if (!disk) return disk.error();
  for (BoundaryKind kind : kinds)
    if (kind == BoundaryKind::Free) {
      std::vector<std::string> names;
      for (BoundaryKind k : polygonBoundaryKinds()) names.push_back(boundaryKindName(k));
      return Error{ErrorCode::InvalidArgument,
                   "the free boundary has no polygon without its nonlinear refinement (parameterize with boundary "
                   "'free' returns it as boundaryPolygon); polygons exist for " +
                       choiceList(names, ", ", " and ")};
    }
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
