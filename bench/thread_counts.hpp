// thread_counts.hpp — the benches' `--threads N,N,...` list, parsed once for all of them.
#pragma once
#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

/// "1,2" → {1, 2}; 0 = every core.
inline std::vector<int> threadCounts(const std::string& list) {
  std::vector<int> counts;
  for (size_t at = 0; at <= list.size();) {
    const size_t comma = std::min(list.find(',', at), list.size());
    counts.push_back(std::max(0, std::atoi(list.substr(at, comma - at).c_str())));
    at = comma + 1;
  }
  return counts;
}
