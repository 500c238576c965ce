// libFuzzer harness: the STL reader (ASCII and binary) + TriMesh::build. Same invariants as fuzz_obj (see
// fuzz_parse.hpp), with exact OFF and OBJ round trips of every accepted mesh.
#include "fuzz_parse.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::checkParse(std::string_view(reinterpret_cast<const char*>(data), size), straightest::MeshFormat::Stl);
  return 0;
}
