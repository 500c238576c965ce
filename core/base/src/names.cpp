// names.cpp — the one helper of names.hpp that is not a template.
#include "straightest/base/names.hpp"

namespace straightest {

std::string choiceList(const std::vector<std::string>& names, const char* separator, const char* last) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? last : separator;
    out += names[i];
  }
  return out;
}

}  // namespace straightest
