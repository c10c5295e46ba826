// Game controllers through SDL's GameController API, hot-plugged: a pad plugged in mid-game is
// opened when SDL reports it (SDL_CONTROLLERDEVICEADDED) and closed when it goes away. The left
// stick steers in proportion (past a dead zone), the d-pad steers fully; the right trigger inflates
// and the left deflates, in proportion; buttons become actions the app maps to what the keys do (A
// jump, Start pause, Back restart, shoulders change level). Driving a vehicle, the left stick's x is
// the throttle, its y the lean, and A held the brake.
#pragma once

#include <SDL.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace game {

// The stick's dead zone, as a fraction of its travel: closer to the centre reads as 0 (a pad at
// rest never reads exactly 0). Past it the travel is rescaled so that full tilt is exactly ±1.
constexpr double kStickDeadZone = 0.2;

// Steering from a stick axis reading (SDL's -32768 … 32767): 0 inside the dead zone, else in
// [-1, 1], ±1 exactly at full tilt.
double stick_steer(Sint16 raw);

enum class PadAction { none, jump, pause, restart, next_level, previous_level, menu_up, menu_down, back };

class Gamepads {
 public:
  Gamepads() = default;
  ~Gamepads();
  Gamepads(const Gamepads&) = delete;
  Gamepads& operator=(const Gamepads&) = delete;

  // Starts SDL's game-controller subsystem; "" or why it failed (the game goes on without pads).
  std::string init();
  // Takes device added / removed, axis and button events; returns what a button press asks for.
  // Messages for the player (a pad connected or gone) go into `messages`.
  PadAction handle_event(const SDL_Event& event, std::vector<std::string>& messages);

  // The steering the pads ask for now, in [-1, 1] (the d-pad wins over the stick).
  double steer() const;
  // Inflating (+) or deflating (−) the pads ask for now, in [-1, 1]: right trigger less left.
  double inflate() const;
  // A vehicle's lean the pads ask for now, in [-1, 1] (left stick up: +1, leaning back), and its brake
  // (A held on any pad).
  double lean() const;
  bool brake() const;
  std::size_t connected() const { return pads_.size(); }
  void close_all();

 private:
  struct Pad {
    SDL_GameController* controller = nullptr;
    double stick = 0.0;  // left stick x, after the dead zone
    bool left = false, right = false;
    double left_trigger = 0.0, right_trigger = 0.0;  // [0, 1], after the dead zone
    double stick_y = 0.0;                            // left stick y, after the dead zone (SDL's: + is down)
    bool a = false;                                  // the A button held
  };
  std::map<SDL_JoystickID, Pad> pads_;
  bool started_ = false;
};

}  // namespace game
