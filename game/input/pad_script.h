// A scripted game controller for automation, as --press is a scripted keyboard:
// `--pad leftx=1:0-899 --pad a:140`. A spec is an SDL controller axis with a value in [-1, 1] over
// a frame or an inclusive frame range ("leftx=-0.5:10-20": held there, back to 0 on frame 21), or a
// button at a frame or over a range ("a:140": pressed on frame 140, released on 141). Names are
// SDL's (leftx, lefty, rightx, righty, lefttrigger, righttrigger; a, b, x, y, back, guide, start,
// leftstick, rightstick, leftshoulder, rightshoulder, dpup, dpdown, dpleft, dpright).
// "connect:FRAME" plugs the pad in on that frame instead of before the first, "disconnect:FRAME"
// pulls it out: the game sees both through SDL's hot-plug events.
//
// VirtualPad attaches an SDL virtual joystick that SDL sees as a game controller and sets its axes
// and buttons at those frames, so the game reads it through SDL's real events, hot-plug included.
#pragma once

#include <SDL.h>

#include <optional>
#include <string>
#include <vector>

namespace game {

struct PadPress {
  enum class Plug { none, connect, disconnect };
  Plug plug = Plug::none;  // connect / disconnect at `first`
  bool is_axis = false;
  SDL_GameControllerAxis axis = SDL_CONTROLLER_AXIS_INVALID;
  SDL_GameControllerButton button = SDL_CONTROLLER_BUTTON_INVALID;
  double value = 0.0;   // axis value in [-1, 1]
  long long first = 0;  // frame it is set / pressed
  long long last = 0;   // last frame it holds (back to 0 / released on last + 1)
};

// Parses one spec; on failure returns nullopt and sets `error`.
std::optional<PadPress> parse_pad_press(const std::string& spec, std::string& error);

// A raw axis value (SDL's -32768 … 32767) for a value in [-1, 1].
Sint16 axis_raw(double value);

class VirtualPad {
 public:
  VirtualPad() = default;
  ~VirtualPad();
  VirtualPad(const VirtualPad&) = delete;
  VirtualPad& operator=(const VirtualPad&) = delete;

  void add(const PadPress& press) { presses_.push_back(press); }
  bool empty() const { return presses_.empty(); }
  // Whether the script plugs the pad in later (connect:FRAME) rather than before the first frame.
  bool connects_later() const;
  // Attaches the virtual controller (SDL's joystick subsystem must be up); "" or why it failed.
  std::string attach();
  // Plugs in or pulls out, then sets the axes and buttons that change on `frame` (releases first).
  // "" or why the pad could not be attached.
  std::string apply(long long frame);
  void detach();

 private:
  std::vector<PadPress> presses_;
  int device_ = -1;
  SDL_JoystickID instance_ = -1;
  SDL_Joystick* joystick_ = nullptr;
};

}  // namespace game
