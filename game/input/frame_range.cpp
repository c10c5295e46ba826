#include "input/frame_range.h"

#include <charconv>

namespace game {

std::optional<long long> parse_frame(const std::string& text) {
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || value < 0) return std::nullopt;
  return value;
}

std::optional<FrameRange> parse_frame_range(const std::string& text) {
  const auto dash = text.find('-');
  const auto first = parse_frame(text.substr(0, dash));
  const auto last = dash == std::string::npos ? first : parse_frame(text.substr(dash + 1));
  if (!first || !last || *last < *first) return std::nullopt;
  return FrameRange{*first, *last};
}

}  // namespace game
