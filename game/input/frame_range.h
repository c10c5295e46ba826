// The frames of a scripted input (--press, --pad): "F" or "F-L", counted from the first frame 0.
#pragma once

#include <optional>
#include <string>

namespace game {

struct FrameRange {
  long long first = 0;
  long long last = 0;  // inclusive
};

// A whole non-negative number of frames, nothing else.
std::optional<long long> parse_frame(const std::string& text);
// "F" (first = last = F) or "F-L" with F <= L.
std::optional<FrameRange> parse_frame_range(const std::string& text);

}  // namespace game
