// text_scan.hpp — the text primitives the mesh readers share: lines, whitespace-separated tokens,
// strict numbers, and error messages that name the line and quote the offending token. Private to
// core/src (the readers' public face is mesh_io.hpp).
//
// Numbers are strict on purpose: a coordinate is a plain decimal ("-1.5e-3"), read correctly rounded
// (fast_float, the same value strtod gives); hexadecimal floats, "inf", "nan" and tokens over 64
// characters are reported, never read as something else.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "straightest/base/error.hpp"

namespace straightest::text {

/// Longer numeric tokens are rejected (keeps every number's reading linear and bounded).
constexpr size_t kMaxNumberChars = 64;

/// Error{Parse, "line N: what"}.
Error parseError(int64_t line, const std::string& what);

/// The token in single quotes, cut to 40 characters, unprintable bytes shown as '?'.
std::string quoted(std::string_view token);

/// Where the line starting at `pos` ends: the first '\n' or '\r' from there, or text.size().
/// (memchr twice is several times faster than find_first_of on long files.)
inline size_t lineEnd(std::string_view text, size_t pos) {
  const char* first = text.data() + pos;
  const void* newline = std::memchr(first, '\n', text.size() - pos);
  const size_t end = newline ? static_cast<size_t>(static_cast<const char*>(newline) - text.data()) : text.size();
  const void* carriageReturn = std::memchr(first, '\r', end - pos);
  return carriageReturn ? static_cast<size_t>(static_cast<const char*>(carriageReturn) - text.data()) : end;
}

/// Splits text into lines ending in "\n", "\r\n" or a lone "\r", calling fn(lineNumber, line) (line
/// numbers from 1, the terminator excluded) until fn returns false. Linear.
template <class Fn>
void forEachLine(std::string_view text, Fn&& fn) {
  int64_t number = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t end = lineEnd(text, pos);
    if (!fn(++number, text.substr(pos, end - pos))) return;
    pos = end + ((end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n') ? 2 : 1);
  }
}

/// Space, tab, CR, vertical tab and form feed separate tokens.
inline bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
inline bool isDigit(char c) { return c >= '0' && c <= '9'; }

/// Whitespace-separated tokens of a line: `count` of them, the first `max` stored in `items`.
struct Tokens {
  std::vector<std::string_view> items;
  size_t count = 0;
};
void tokenize(std::string_view line, Tokens& out, size_t max = 64);

/// The line up to its first '#'.
std::string_view stripComment(std::string_view line);

/// [+-]? (digits [. digits*] | . digits) ([eE] [+-]? digits)?
bool isPlainDecimal(std::string_view token);

enum class NumberStatus { Ok, NotANumber, NonFinite, TooLong };

/// Reads a whole token as a double: plain decimals correctly rounded; anything else through strtod,
/// so that "nan", "inf" and overflowing numbers are NonFinite (the caller decides whether a
/// non-decimal form such as "0x1p3" is acceptable).
NumberStatus parseDouble(std::string_view token, double& out);

// In-place reading for the readers' fast paths: a line of the common form is read straight from the
// bytes (no line split, no token copies); each function returns false, or nullptr, when the bytes are
// not of that form, and the caller then reads the line strictly.

/// Space, tab, vertical tab and form feed: what separates tokens inside a line.
inline bool isInlineSpace(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
inline const char* skipInlineSpace(const char* p, const char* end) {
  while (p < end && isInlineSpace(*p)) ++p;
  return p;
}

/// If `p` is at the end of a line (the end of the text, "\n", "\r\n" or a lone "\r"), where the next
/// line starts; otherwise nullptr.
inline const char* nextLineAt(const char* p, const char* end) {
  if (p == end) return end;
  if (*p == '\n') return p + 1;
  if (*p == '\r') return p + ((p + 1 < end && p[1] == '\n') ? 2 : 1);
  return nullptr;
}

/// The common coordinate read in place: the token at `p` (no leading blanks) is a plain decimal of at
/// most 64 characters that starts, after one optional sign, with a digit or '.', reads as a finite
/// double, and ends at a blank, '#', a line end or the end of the text. Then `p` moves past it and
/// `out` is exactly what parseDouble gives; otherwise false (parseDouble decides). With
/// `maxExponentDigits`, an exponent of more digits is refused too.
bool readDecimalInPlace(const char*& p, const char* end, double& out, int maxExponentDigits = 0);

/// An unsigned integer of 1 to 18 digits at `p` (no leading blanks), followed by a blank, '#', a
/// line end or the end of the text; `p` moves past it.
inline bool readCountInPlace(const char*& p, const char* end, int64_t& out) {
  const char* digits = p;
  int64_t value = 0;
  for (; p < end && isDigit(*p); ++p) {
    if (p - digits == 18) return false;
    value = value * 10 + (*p - '0');
  }
  out = value;
  return p > digits && (p == end || isInlineSpace(*p) || *p == '#' || *p == '\n' || *p == '\r');
}

/// A whole token as a signed integer of at most 18 digits (so it never overflows int64).
bool parseInt64(std::string_view token, int64_t& out);

}  // namespace straightest::text
