// What the player does in one tick.
#pragma once

namespace tire {

// The player's input for one tick.
struct TickInput {
  double steer = 0.0;  // [-1, 1]
  bool jump = false;
  double inflate = 0.0;  // [-1, 1]: +1 inflates the player at its inflate_rate, −1 deflates it
};

}  // namespace tire
