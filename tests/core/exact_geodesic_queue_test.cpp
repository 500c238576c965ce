// The window propagation's bucket queue (private: core/src/exact_geodesic_queue.hpp): every entry comes out
// exactly once, in the order of the keys up to the bucket width, also when keys jump beyond the ring of
// buckets (the far list) and when a key falls before the last one popped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "../../core/geodesics/src/exact_geodesic_queue.hpp"

namespace straightest {
namespace {

struct Item {
  double key;
  int32_t id;
};

TEST(ExactGeodesicQueue, PopsEveryEntryOnceInKeyOrderUpToTheWidth) {
  const double width = 0.01;
  detail::MinQueue<Item> queue(width);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> step(0.0, 3.0), far(0.0, 1e4);
  std::vector<int> popped;
  int32_t next = 0;
  double last = 0;
  // Interleaved: each pop may be followed by pushes at or after its key (most just ahead, some far beyond
  // the ring's reach), as the propagation does.
  for (int i = 0; i < 2000; ++i) {
    const double key = i % 50 == 0 ? far(random) : step(random);
    queue.push(key, Item{key, next++});
  }
  while (!queue.empty()) {
    const Item item = queue.pop();
    EXPECT_GE(item.key, last - width) << item.id;
    last = std::max(last, item.key);
    popped.push_back(item.id);
    if (next < 20000 && item.id % 3 == 0) {
      for (int k = 0; k < 2; ++k) {
        const double key = item.key + (next % 97 == 0 ? far(random) : step(random));
        queue.push(key, Item{key, next++});
      }
    }
  }
  std::sort(popped.begin(), popped.end());
  ASSERT_EQ(popped.size(), static_cast<size_t>(next));
  for (int32_t i = 0; i < next; ++i) ASSERT_EQ(popped[i], i);
}

TEST(ExactGeodesicQueue, AKeyBeforeTheLastPoppedComesNext) {
  detail::MinQueue<Item> queue(1.0);
  queue.push(5.5, Item{5.5, 0});
  queue.push(9.5, Item{9.5, 1});
  EXPECT_EQ(queue.pop().id, 0);
  queue.push(2.0, Item{2.0, 2});  // rounding can put a child an ulp before its parent
  EXPECT_EQ(queue.pop().id, 2);
  EXPECT_EQ(queue.pop().id, 1);
  EXPECT_TRUE(queue.empty());
}

}  // namespace
}  // namespace straightest
