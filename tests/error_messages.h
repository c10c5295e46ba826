// Reading the validator's messages in tests: whether one holds a phrase, and all of them as one
// text for a failure report.
#pragma once

#include <string>
#include <vector>

namespace tire_test {

inline bool has(const std::vector<std::string>& errors, const std::string& needle) {
  for (const std::string& e : errors)
    if (e.find(needle) != std::string::npos) return true;
  return false;
}

// One message a line, each cut at `max_chars` (a hostile file's messages can quote a lot).
inline std::string joined(const std::vector<std::string>& errors, std::size_t max_chars = std::string::npos) {
  std::string out;
  for (const std::string& e : errors) out += e.substr(0, max_chars) + "\n";
  return out;
}

}  // namespace tire_test
