// Numbers as the engine reads and writes them: a numeric interval (Range: the range of a level
// key, a tunable parameter or a command-line option), a double parsed from text, and a 64-bit digest
// as hex.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

namespace tire {

// An inclusive or exclusive numeric interval, printed as in the reference page: [6, 256], (0, 0.1].
struct Range {
  double min;
  double max;
  bool min_open = false;
  bool max_open = false;
  // False for NaN (every comparison with it is false).
  constexpr bool contains(double v) const {
    return (min_open ? v > min : v >= min) && (max_open ? v < max : v <= max);
  }
  constexpr bool contains(const Range& inner) const {
    return (inner.min > min || (inner.min == min && (!min_open || inner.min_open))) &&
           (inner.max < max || (inner.max == max && (!max_open || inner.max_open)));
  }
  constexpr bool operator==(const Range&) const = default;
  std::string text() const;  // "[6, 256]", "(0, 1e+06]": numbers as std::ostream prints them
};

// A double read from text as std::from_chars reads one (the whole text, '-' but no '+', no leading
// space, no hex; "inf" and "nan" as numbers; out of range is an error), through strtod: the
// libc++ of the browser build (emscripten) has no floating-point std::from_chars. Never depends
// on the locale's decimal point: the programs never call setlocale.
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

// A 64-bit value (a state hash) as 16 lowercase hex digits, as replays and tirectl write it.
std::string to_hex(std::uint64_t value);

}  // namespace tire
