// The CLI's malloc tunables (core/cli/huge_pages.hpp): added to whatever GLIBC_TUNABLES holds, none
// over a value the user set, and nothing at all once glibc.malloc.hugetlb is named — by the user, or by
// the re-executed program itself, which is what keeps the re-exec from repeating.
#include <gtest/gtest.h>

#include "../../core/cli/huge_pages.hpp"

using straightest::cli::tunablesWithHugePages;

namespace {
const std::string kAll = "glibc.malloc.hugetlb=1:glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=17179869184";
}

TEST(HugePages, AddsTheTunablesWhenUnset) {
  EXPECT_EQ(tunablesWithHugePages(nullptr), kAll);
  EXPECT_EQ(tunablesWithHugePages(""), kAll);
}

TEST(HugePages, KeepsTheOtherTunables) {
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.check=3"), "glibc.malloc.check=3:" + kAll);
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.hugetlbx=2"), "glibc.malloc.hugetlbx=2:" + kAll);
}

TEST(HugePages, KeepsTheUsersOwnValues) {
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.mmap_max=5"),
            "glibc.malloc.mmap_max=5:glibc.malloc.hugetlb=1:glibc.malloc.trim_threshold=17179869184");
}

TEST(HugePages, AddsNothingOnceHugePagesAreNamed) {
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.hugetlb=0"), "");
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.hugetlb=1"), "");
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.check=3:glibc.malloc.hugetlb=2"), "");
}
