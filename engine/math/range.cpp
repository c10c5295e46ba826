#include "tire/math/range.h"

#include <sstream>

namespace tire {

std::string Range::text() const {
  std::ostringstream s;
  s << (min_open ? '(' : '[') << min << ", " << max << (max_open ? ')' : ']');
  return s.str();
}

}  // namespace tire
