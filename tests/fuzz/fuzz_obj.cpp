// libFuzzer harness: the OBJ reader (our line scan + tinyobjloader + ear clipping + TriMesh::build).
// Invariants: an error has a known category and a message, and agrees between parsePolygonSoup and
// loadMesh; a soup never refers to a missing vertex; build's answer matches an independent oracle
// (fuzz_common.hpp); an accepted mesh satisfies every TriMesh invariant and survives writing it
// as OFF and OBJ (with and without uv) and reading it back unchanged.
#include "fuzz_parse.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::checkParse(std::string_view(reinterpret_cast<const char*>(data), size), straightest::MeshFormat::Obj);
  return 0;
}
