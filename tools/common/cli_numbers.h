// Checks for the numeric command-line options of tirectl and tire-game. A value is refused unless
// all of it is one finite number (an integer where one is asked) inside the option's range, so
// "nan" and "inf" never reach the program. CLI11 runs a check on the text as typed, before it
// converts it, and puts the option's name in front of the message:
//   --steer: must be a number in [-1, 1], got nan
// Give integer checks with ->transform(), not ->check(): CLI11 keeps a check's text as typed, and
// integer_in passes "1e3" on as "1000", which CLI11's integer conversion would otherwise refuse.
#pragma once

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "tire/math/numbers.h"
#include "tire/math/numbers.h"  // tire::Range: ranges print as the reference pages write them

namespace tire_tools {

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// The number `text` spells, when the whole of it is one finite number.
inline std::optional<double> finite_number(const std::string& text) {
  const std::optional<double> value = tire::parse_double(text);
  if (!value || !std::isfinite(*value)) return std::nullopt;
  return value;
}

// A number in `range`; `integer`: a whole one (keep the range within long long).
inline CLI::Validator number_in(const tire::Range& range, bool integer = false) {
  const std::string expected = std::string(integer ? "an integer" : "a number") + " in " + range.text();
  return CLI::Validator(
      [range, integer, expected](std::string& text) -> std::string {
        const std::optional<double> v = finite_number(text);
        if (!v || !range.contains(*v) || (integer && std::floor(*v) != *v))
          return "must be " + expected + ", got " + text;
        if (integer) text = std::to_string(static_cast<long long>(*v));  // "1e3" reaches CLI11 as "1000"
        return "";
      },
      expected);
}

inline CLI::Validator integer_in(const tire::Range& range) { return number_in(range, true); }

}  // namespace tire_tools
