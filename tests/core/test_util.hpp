// Helpers shared by the core tests (native and WASM run the same sources; fixtures are read by
// path relative to the repository root, the tests' working directory).
#pragma once
#include <string>

#include <gtest/gtest.h>

#include "straightest/mesh_io.hpp"

namespace straightest::testing {

inline std::string dataPath(const std::string& relative) { return "tests/data/" + relative; }

/// Loads a fixture that must be valid; fails the test with the loader's message otherwise.
inline TriMesh loadGood(const std::string& relative) {
  auto mesh = loadMeshFile(dataPath(relative));
  if (!mesh) ADD_FAILURE() << relative << ": " << mesh.error().message;
  return std::move(mesh).value();
}

}  // namespace straightest::testing
