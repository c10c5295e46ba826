// A numeric interval, inclusive or exclusive at either end: the range of a level key, a tunable
// parameter or a command-line option. One definition, printed as the reference pages write it.
#pragma once

#include <string>

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

}  // namespace tire
