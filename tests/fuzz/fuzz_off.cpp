// libFuzzer harness: the OFF reader (our strict parser + ear clipping + TriMesh::build).
// Same invariants as fuzz_obj (see fuzz_parse.hpp); the OFF round trip is exact.
#include "fuzz_parse.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::checkParse(std::string_view(reinterpret_cast<const char*>(data), size), straightest::MeshFormat::Off);
  return 0;
}
