// The malformed-input corpus (tests/data/bad/), driven by its manifests: every file is rejected with
// the category expected.json gives it (the CLI and the npm tests read the same table), and with a
// message that says what was found and where: expected_messages.json holds the part each message
// must contain (its line, face or vertex, and what is wrong).
#include <string>

#include <gtest/gtest.h>

#include "straightest/io/mesh_io.hpp"
#include "test_util.hpp"

namespace straightest {
namespace {

using testing::dataPath;
using testing::readStringTable;

TEST(MalformedInput, EveryCorpusFileIsRejectedWithItsCategoryAndAMessageSayingWhatAndWhere) {
  const auto categories = readStringTable(dataPath("bad/expected.json"));
  const auto messages = readStringTable(dataPath("bad/expected_messages.json"));
  ASSERT_FALSE(categories.empty());
  for (const auto& [file, category] : categories) {
    SCOPED_TRACE(file);
    auto mesh = loadMeshFile(dataPath("bad/" + file));
    ASSERT_FALSE(mesh.ok()) << "loaded";
    EXPECT_STREQ(errorCodeName(mesh.error().code), category.c_str()) << mesh.error().message;
    const auto expected = messages.find(file);
    ASSERT_NE(expected, messages.end()) << "expected_messages.json has no entry";
    EXPECT_NE(mesh.error().message.find(expected->second), std::string::npos)
        << "message: " << mesh.error().message << "\nshould contain: " << expected->second;
  }
  for (const auto& entry : messages) EXPECT_EQ(categories.count(entry.first), 1u) << entry.first << ": no category";
}

}  // namespace
}  // namespace straightest
