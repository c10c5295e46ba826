#include "tire/math/numbers.h"

#include <sstream>

namespace tire {

std::string Range::text() const {
  std::ostringstream s;
  s << (min_open ? '(' : '[') << min << ", " << max << (max_open ? ')' : ']');
  return s.str();
}

std::string to_hex(std::uint64_t value) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i, value >>= 4) out[static_cast<std::size_t>(i)] = digits[value & 0xf];
  return out;
}

}  // namespace tire
