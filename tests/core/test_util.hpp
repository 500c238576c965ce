// Helpers shared by the core tests (native and WASM run the same sources; fixtures are read by
// path relative to the repository root, the tests' working directory).
#pragma once
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "straightest/io/mesh_io.hpp"

namespace straightest::testing {

inline std::string dataPath(const std::string& relative) { return "tests/data/" + relative; }

/// Loads a fixture that must be valid. Otherwise throws, which GoogleTest reports as this test's
/// failure with the loader's message (the other tests still run).
inline TriMesh loadGood(const std::string& relative) {
  auto mesh = loadMeshFile(dataPath(relative));
  if (!mesh) throw std::runtime_error(relative + " did not load: " + mesh.error().message);
  return std::move(mesh).value();
}

/// The whole file as bytes ("" when it cannot be read).
inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/// A JSON object whose values are all strings ({"name": "value", ...}), as a map; enough for the
/// fixture manifests. Throws on anything else.
inline std::map<std::string, std::string> readStringTable(const std::string& path) {
  const std::string json = readFile(path);
  size_t i = 0;
  auto skipSpace = [&] {
    while (i < json.size() && std::isspace(static_cast<unsigned char>(json[i]))) ++i;
  };
  auto expect = [&](char c) {
    skipSpace();
    if (i >= json.size() || json[i] != c)
      throw std::runtime_error(path + ": expected '" + std::string(1, c) + "' at byte " + std::to_string(i));
    ++i;
  };
  auto string = [&] {
    expect('"');
    std::string s;
    while (i < json.size() && json[i] != '"') {
      if (json[i] == '\\' && i + 1 < json.size()) ++i;  // \" and \\ (the manifests need no other escape)
      s += json[i++];
    }
    expect('"');
    return s;
  };
  std::map<std::string, std::string> table;
  expect('{');
  skipSpace();
  while (i < json.size() && json[i] != '}') {
    std::string key = string();
    expect(':');
    table[key] = string();
    skipSpace();
    if (i < json.size() && json[i] == ',') ++i;
    skipSpace();
  }
  expect('}');
  return table;
}

}  // namespace straightest::testing
