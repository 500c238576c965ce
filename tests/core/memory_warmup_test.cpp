// The CLI's memory warm-up (core/cli/memory_warmup.hpp): how much heap `param` touches ahead, from what
// is known before the mesh is read — heightfield:N's vertex count, or an OBJ, OFF or PLY file's size —
// and nothing for the other inputs. (The CLI is native only.)
#include <gtest/gtest.h>

#ifndef __EMSCRIPTEN__
#include <cstdio>
#include <fstream>
#include <string>

#include "../../core/cli/memory_warmup.hpp"

using straightest::cli::parameterizationBytes;

namespace {

std::string fileOfSize(const std::string& name, std::size_t bytes) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << std::string(bytes, 'v');
  return path;
}

TEST(MemoryWarmup, HeightFieldsGetTheirVertexCountTimesTheBytesAParameterizationTakesPerVertex) {
  EXPECT_EQ(parameterizationBytes("heightfield:1000"), 315000000u);
  EXPECT_EQ(parameterizationBytes("heightfield:250"), 19687500u);
}

TEST(MemoryWarmup, ObjOffAndPlyFilesGetALittleMoreThanTheirSizeAndOtherInputsNothing) {
  for (const char* name : {"warm.obj", "warm.OFF", "warm.ply"}) {
    const std::string path = fileOfSize(name, 200000);
    EXPECT_EQ(parameterizationBytes(path), 210000u) << name;
    std::remove(path.c_str());
  }
  const std::string stl = fileOfSize("warm.stl", 200000);
  EXPECT_EQ(parameterizationBytes(stl), 0u);  // ASCII STL takes ~500 bytes per vertex: no safe estimate
  std::remove(stl.c_str());
  EXPECT_EQ(parameterizationBytes(::testing::TempDir() + "missing.obj"), 0u);
  EXPECT_EQ(parameterizationBytes("sample:mountain"), 0u);
}

}  // namespace
#endif
