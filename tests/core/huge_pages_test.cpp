// The CLI's huge-page tunable (core/cli/huge_pages.hpp): added to whatever GLIBC_TUNABLES holds, and
// never over a value the user (or the re-executed program itself) already set — which is also what
// keeps the re-exec from repeating.
#include <gtest/gtest.h>

#include "../../core/cli/huge_pages.hpp"

using straightest::cli::tunablesWithHugePages;

TEST(HugePages, AddsTheTunableWhenUnset) {
  EXPECT_EQ(tunablesWithHugePages(nullptr), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunablesWithHugePages(""), "glibc.malloc.hugetlb=1");
}

TEST(HugePages, KeepsTheOtherTunables) {
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.check=3"), "glibc.malloc.check=3:glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.hugetlbx=2"), "glibc.malloc.hugetlbx=2:glibc.malloc.hugetlb=1");
}

TEST(HugePages, LeavesAValueAlreadySetAlone) {
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.hugetlb=0"), "");
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.hugetlb=1"), "");
  EXPECT_EQ(tunablesWithHugePages("glibc.malloc.check=3:glibc.malloc.hugetlb=2"), "");
}
