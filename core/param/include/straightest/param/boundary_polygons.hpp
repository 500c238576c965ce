// boundary_polygons.hpp — where the boundary of a disk goes under each boundary kind, without
// solving for the interior: the polygon of every requested kind in the [0, 1]² frame that
// parameterize with that boundary puts its uv and boundaryPolygon in (unitSquareFrame of the polygon:
// the convex-combination interior lies inside it). The measured kind traces lengths only.
// What the page overlays on a uv layout to compare the boundaries, at the cost of the traces.
// The free boundary has no polygon before its nonlinear refinement (parameterize with boundary free
// returns it as boundaryPolygon), so it is not one of these kinds.
#pragma once
#include <optional>
#include <vector>

#include "straightest/param/boundary_map.hpp"

namespace straightest {

struct BoundaryPolygon {
  BoundaryKind kind = BoundaryKind::Measured;
  std::vector<int32_t> loop;   // the boundary vertices in order
  std::vector<Vec2> polygon;   // one point per loop vertex, in [0, 1]² (empty when error)
  std::optional<Error> error;  // why this kind has no polygon (e.g. measured with a boundary source)
};

/// The kinds that have a polygon without a solve: every boundary kind but free, in the name table's
/// order (the default list of the bindings).
std::vector<BoundaryKind> polygonBoundaryKinds();

/// One entry per kind, in the given order. A mesh that is not a disk is first cut or filled as
/// parameterize does (progress stage "cut"): the polygons are that disk's, the loop in mesh vertex
/// numbers (a seam vertex appears once per side), its errors the whole call's; `source` (nullopt: the default source)
/// is needed by measured only, and a bad one is that entry's error. Asking for free is an InvalidArgument error for the
/// whole call. Progress stage "trace" (measured); cancelling returns a Cancelled error.
Expected<std::vector<BoundaryPolygon>> boundaryPolygons(const TriMesh& mesh, const std::optional<SurfacePoint>& source,
                                                        const std::vector<BoundaryKind>& kinds,
                                                        const Progress& progress = {});

}  // namespace straightest
