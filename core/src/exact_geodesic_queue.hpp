// exact_geodesic_queue.hpp (private) — the window propagation's priority queue: a radix heap of
// (key, payload) entries.
//
// The propagation pops every window it creates, tens of millions on large meshes, and the pop of the
// 4-ary heap this replaced took about half of its time (a sift-down of unpredictable branches, then a
// cache miss on the payload). The
// propagation's keys are monotone: a window's least distance is at least that of the window it came
// from, and a vertex's distance at least that of the window that set it. A radix heap uses that: a
// non-negative double's bits order like the double, and an entry sits in the bucket numbered by the
// highest bit in which its key differs from the last key popped. Pushing is one count-leading-zeros;
// popping takes bucket 0 (keys equal to the last one) or empties the first non-empty bucket, whose
// least key becomes the last one, into lower buckets. An entry moves down at most 64 times, in practice
// a few. Payloads live in the entries: popping from the back of bucket 0 then reads memory just
// written, where a pool of payloads indexed from the heap cost a cache miss per pop.
//
// A key below the last one popped (rounding can make a child's least distance fall an ulp short of its
// parent's) is queued as equal to it: it is popped next instead of in its exact place. The propagation
// stays exact in any pop order (every window it drops is dominated by a path it measured); the order
// only decides how much it prunes.
#pragma once
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace straightest::detail {

template <typename Payload>
class MinQueue {
 public:
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }

  /// Queues payload with key (≥ 0; a key below the last one popped counts as the last one).
  void push(double key, const Payload& payload) {
    uint64_t bits = orderBits(key);
    if (!(bits > last_)) bits = last_;
    buckets_[bucketOf(bits)].push_back(Entry{bits, payload});
    ++size_;
  }

  /// Removes an entry of least key (ties: any) and returns its payload. Not on an empty queue.
  Payload pop() {
    if (buckets_[0].empty()) {
      size_t b = 1;
      while (buckets_[b].empty()) ++b;
      std::vector<Entry>& from = buckets_[b];
      uint64_t least = from.front().bits;
      for (const Entry& e : from) least = e.bits < least ? e.bits : least;
      last_ = least;
      for (const Entry& e : from) buckets_[bucketOf(e.bits)].push_back(e);  // all land below b
      from.clear();
    }
    const Payload payload = buckets_[0].back().payload;
    buckets_[0].pop_back();
    --size_;
    return payload;
  }

 private:
  struct Entry {
    uint64_t bits;  // the key's bits (orderBits)
    Payload payload;
  };

  /// A non-negative double's bits, which order like the double (−0 is taken as +0).
  static uint64_t orderBits(double key) {
    key += 0.0;
    uint64_t bits;
    std::memcpy(&bits, &key, sizeof bits);
    return bits >> 63 ? 0 : bits;  // a negative key (never made by the propagation) counts as 0
  }

  /// 0 for the last key popped, else 1 + the index of the highest bit in which bits differs from it.
  size_t bucketOf(uint64_t bits) const {
    const uint64_t differ = bits ^ last_;
    return differ == 0 ? 0 : 64 - static_cast<size_t>(__builtin_clzll(differ));
  }

  std::array<std::vector<Entry>, 65> buckets_;
  uint64_t last_ = 0;
  size_t size_ = 0;
};

}  // namespace straightest::detail
