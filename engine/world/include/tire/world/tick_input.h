// What the player does in one tick, and how near a tire a mouse press grabs it.
#pragma once

namespace tire {

// How near a tread particle a mouse press must be to grab its tire (m).
inline constexpr double kGrabRadius = 0.3;

// The player's input for one tick.
struct TickInput {
  double steer = 0.0;  // [-1, 1]
  bool jump = false;
  double inflate = 0.0;  // [-1, 1]: +1 inflates the player at its inflate_rate, −1 deflates it
};

}  // namespace tire
