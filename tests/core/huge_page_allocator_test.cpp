// The huge-page allocator (private: core/src/huge_page_allocator.hpp): large and small vectors hold, grow
// and copy their elements like std::vector's; large ones start on a 2 MiB boundary where huge pages are asked
// for (Linux).
#include <gtest/gtest.h>

#include <cstdint>

#include "straightest/base/huge_page_allocator.hpp"

namespace straightest {
namespace {

TEST(HugePageAllocator, LargeAndSmallVectorsHoldTheirElements) {
  for (size_t n : {size_t{10}, size_t{100000}, size_t{700000}}) {
    detail::HugeVector<double> v(n, 1.5);
    for (size_t i = 0; i < n; ++i) v[i] += static_cast<double>(i);
    v.push_back(-1);  // grows: moves the elements to a new allocation
    const detail::HugeVector<double> copy = v;
    ASSERT_EQ(copy.size(), n + 1);
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(copy[i], 1.5 + static_cast<double>(i)) << n;
    EXPECT_EQ(copy.back(), -1);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (n * sizeof(double) >= (size_t{1} << 20)) {
      EXPECT_EQ(reinterpret_cast<uintptr_t>(v.data()) % (size_t{2} << 20), 0u) << n;
    }
#endif
  }
}

}  // namespace
}  // namespace straightest
