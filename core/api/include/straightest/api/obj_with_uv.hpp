// obj_with_uv.hpp — which OBJ a map is written as, decided once for the CLI and the npm package: a uv per
// vertex gives a vt per vertex; a uv per face corner (a cut mesh, an atlas) a vt per distinct corner uv, so
// seams split.
#pragma once
#include <string>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/param/parameterize.hpp"

namespace straightest {

/// OBJ text of the mesh with `uv`: one per vertex (every one finite, else NonFinite naming the vertex) or 3
/// per face (cornerUv; a NaN corner's face is written without vt). Per vertex wins when both sizes fit.
/// Errors: InvalidArgument for any other size, NonFinite.
Expected<std::string> objWithUv(const TriMesh& mesh, const std::vector<Vec2>& uv);

/// The OBJ of a parameterization: per vertex for a disk mapped as it is, per corner when it was cut or filled.
std::string objOfParameterization(const TriMesh& mesh, const Parameterization& p);

}  // namespace straightest
