// A double read from text as std::from_chars reads one (the whole text, '-' but no '+', no leading
// space, no hex; "inf" and "nan" as numbers; out of range is an error), through strtod: the
// libc++ of the browser build (emscripten) has no floating-point std::from_chars. Never depends
// on the locale's decimal point: the programs never call setlocale.
#pragma once

#include <cerrno>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

namespace tire {

inline std::optional<double> parse_double(std::string_view text) {
  if (text.empty() || text.front() == '+' || text.front() == ' ' || text.front() == '\t' ||
      text.front() == '\n' || text.front() == '\r' || text.front() == '\f' || text.front() == '\v')
    return std::nullopt;
  const std::string_view digits = text.front() == '-' ? text.substr(1) : text;
  if (digits.size() >= 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) return std::nullopt;
  if (!digits.empty() && (digits.front() == '+' || digits.front() == '-' || digits.front() == ' '))
    return std::nullopt;
  const std::string copy(text);  // strtod wants a terminated string
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size()) return std::nullopt;
  // Out of range: beyond the largest double, or below the smallest subnormal (a subnormal result,
  // for which strtod also sets ERANGE, is a number).
  if (errno == ERANGE && (value == 0.0 || value > 1.0e308 || value < -1.0e308)) return std::nullopt;
  return value;
}

}  // namespace tire
