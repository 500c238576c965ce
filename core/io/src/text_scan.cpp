// The text primitives the mesh readers share (see text_scan.hpp): tokens, strict numbers, messages.
#include "straightest/io/text_scan.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <fast_float/fast_float.h>

namespace straightest::text {

Error parseError(int64_t line, const std::string& what) {
  return Error{ErrorCode::Parse, "line " + std::to_string(line) + ": " + what};
}

std::string quoted(std::string_view token) {
  std::string s(token.substr(0, 40));
  for (char& c : s)
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  return "'" + s + (token.size() > 40 ? "...'" : "'");
}

void tokenize(std::string_view line, Tokens& out, size_t max) {
  out.items.clear();
  out.count = 0;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isSpace(line[i])) ++i;
    if (i >= line.size()) break;
    size_t j = i;
    while (j < line.size() && !isSpace(line[j])) ++j;
    if (out.count < max) out.items.push_back(line.substr(i, j - i));
    ++out.count;
    i = j;
  }
}

std::string_view stripComment(std::string_view line) {
  const size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

bool isPlainDecimal(std::string_view t) {
  size_t i = 0;
  auto digits = [&] {
    const size_t start = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i - start;
  };
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  size_t mantissa = digits();
  if (i < t.size() && t[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == t.size();
}

NumberStatus parseDouble(std::string_view token, double& out) {
  if (token.size() > kMaxNumberChars) return NumberStatus::TooLong;
  // Plain decimals (nearly every coordinate) go through fast_float: correctly rounded like strtod, so
  // the same value, but several times faster (musl's strtod in WASM especially). Anything else
  // (hexadecimal floats, inf, nan) keeps strtod's reading and is judged by the callers.
  if (!token.empty() && isPlainDecimal(token)) {
    const char* first = token.data() + (token[0] == '+' ? 1 : 0);  // from_chars takes no '+'
    const char* last = token.data() + token.size();
    const auto r = fast_float::from_chars(first, last, out);
    if (r.ec != std::errc() || r.ptr != last) return NumberStatus::NotANumber;
    return std::isfinite(out) ? NumberStatus::Ok : NumberStatus::NonFinite;
  }
  char buf[kMaxNumberChars + 1];
  std::memcpy(buf, token.data(), token.size());
  buf[token.size()] = 0;
  char* end = nullptr;
  out = std::strtod(buf, &end);
  if (end != buf + token.size() || token.empty()) return NumberStatus::NotANumber;
  if (!std::isfinite(out)) return NumberStatus::NonFinite;
  return NumberStatus::Ok;
}

bool readDecimalInPlace(const char*& p, const char* end, double& out, int maxExponentDigits) {
  const char* first = p;
  if (first == end) return false;
  const char* number = first + (*first == '+' ? 1 : 0);  // from_chars takes no '+'
  const char* mantissa = number + (*first == '-' ? 1 : 0);
  if (mantissa >= end || !(isDigit(*mantissa) || *mantissa == '.')) return false;
  // from_chars stops at the first byte that cannot continue a number, so the whole token is the
  // number exactly when a delimiter follows where it stopped.
  const auto result = fast_float::from_chars(number, end, out);
  const char* last = result.ptr;
  if (result.ec != std::errc() || !std::isfinite(out) || static_cast<size_t>(last - first) > kMaxNumberChars)
    return false;
  if (last < end && !(isInlineSpace(*last) || *last == '#' || *last == '\n' || *last == '\r')) return false;
  if (maxExponentDigits > 0) {
    const char* exponent = last;  // trailing digits are an exponent's when an 'e' (and a sign) precede them
    while (exponent > mantissa && isDigit(exponent[-1])) --exponent;
    if (last - exponent > maxExponentDigits && exponent > mantissa) {
      const char* marker = exponent - (exponent[-1] == '+' || exponent[-1] == '-' ? 1 : 0);
      if (marker > mantissa && (marker[-1] == 'e' || marker[-1] == 'E')) return false;
    }
  }
  p = last;
  return true;
}

bool parseInt64(std::string_view token, int64_t& out) {
  if (token.empty() || token.size() > 19) return false;  // with a sign: at most 18 digits, no overflow
  size_t i = 0;
  bool negative = false;
  if (token[0] == '-' || token[0] == '+') {
    negative = token[0] == '-';
    i = 1;
  }
  if (i == token.size() || token.size() - i > 18) return false;
  int64_t v = 0;
  for (; i < token.size(); ++i) {
    if (token[i] < '0' || token[i] > '9') return false;
    v = v * 10 + (token[i] - '0');
  }
  out = negative ? -v : v;
  return true;
}

}  // namespace straightest::text
