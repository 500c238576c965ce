// exact_geodesic_reference.hpp (private) — window propagation without its pruning, the reference the
// pruned propagation is tested against (tests/core/exact_geodesic_reference_test.cpp).
//
// The pruned propagation drops windows (ICH's filter through the corners of the faces, windows beaten by
// their edge's last one) and emits a saddle's windows only in its shadow cone; each of those is argued
// sound, and this shows it: here every window is propagated and every pseudo-source emits all around, and
// only windows whose least distance exceeds every vertex's graph distance (an upper bound) are dropped.
// The number of windows grows fast with the mesh: for small meshes only.
#pragma once
#include "straightest/geodesics/exact_geodesic.hpp"

namespace straightest::detail {

/// exactGeodesics without its pruning (see the file comment); same distances up to rounding.
Expected<ExactGeodesics> exactGeodesicsUnpruned(const TriMesh& mesh, const SurfacePoint& source);

}  // namespace straightest::detail
