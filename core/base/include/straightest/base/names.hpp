// names.hpp — the user-visible name of an enum value, one table per enum kept beside its enum: the
// parse and name functions, the CLI's usage text and errors and the npm package's name lists all read
// those tables, so a name is spelled once. This file holds only the generic look-ups.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "straightest/base/error.hpp"

namespace straightest {

template <class E>
struct EnumName {
  E value;
  const char* name;
};

/// The word that stands for "let the library choose" wherever a choice is optional (source, boundary).
inline constexpr const char* kAutoName = "auto";

template <class E, size_t N>
const char* nameOf(const EnumName<E> (&table)[N], E value) {
  for (const EnumName<E>& e : table)
    if (e.value == value) return e.name;
  return "unknown";
}

template <class E, size_t N>
std::optional<E> valueOf(const EnumName<E> (&table)[N], std::string_view name) {
  for (const EnumName<E>& e : table)
    if (name == e.name) return e.value;
  return std::nullopt;
}

/// Every name of the table, in its order (plus `extra`, e.g. "auto", when given).
template <class E, size_t N>
std::vector<std::string> namesOf(const EnumName<E> (&table)[N], const char* extra = nullptr) {
  std::vector<std::string> names;
  for (const EnumName<E>& e : table) names.push_back(e.name);
  if (extra) names.push_back(extra);
  return names;
}

/// "a, b or c": the choices as an error message or usage text lists them.
std::string choiceList(const std::vector<std::string>& names, const char* separator = ", ", const char* last = " or ");

/// The name → value step of every parse function: InvalidArgument "unknown <what> '<name>' (use …)".
template <class E, size_t N>
Expected<E> parseName(const EnumName<E> (&table)[N], std::string_view name, const char* what,
                      ErrorCode code = ErrorCode::InvalidArgument) {
  if (auto v = valueOf(table, name)) return *v;
  return Error{code, std::string("unknown ") + what + " '" + std::string(name) + "' (use " +
                         choiceList(namesOf(table)) + ")"};
}

}  // namespace straightest
