#include "input/pad_script.h"

#include <algorithm>
#include <cmath>

#include "input/frame_range.h"
#include "tire/math/numbers.h"

namespace game {

Sint16 axis_raw(double value) {
  const double v = std::clamp(value, -1.0, 1.0);
  return static_cast<Sint16>(std::lround(v * SDL_JOYSTICK_AXIS_MAX));
}

std::optional<PadPress> parse_pad_press(const std::string& spec, std::string& error) {
  const auto fail = [&](const std::string& why) {
    error = "--pad " + spec + ": " + why;
    return std::nullopt;
  };
  const auto colon = spec.rfind(':');
  if (colon == std::string::npos || colon == 0)
    return fail("expected BUTTON:FRAMES or AXIS=VALUE:FRAMES, e.g. a:140 or leftx=1:0-899");
  PadPress press;
  std::string name = spec.substr(0, colon);
  if (name == "connect" || name == "disconnect") {
    press.plug = name == "connect" ? PadPress::Plug::connect : PadPress::Plug::disconnect;
    const std::string at = spec.substr(colon + 1);
    const auto frame = parse_frame(at);
    if (!frame) return fail("\"" + at + "\" is not a frame");
    press.first = press.last = *frame;
    return press;
  }
  if (const auto eq = name.find('='); eq != std::string::npos) {
    const std::string value = name.substr(eq + 1);
    name = name.substr(0, eq);
    press.is_axis = true;
    press.axis = SDL_GameControllerGetAxisFromString(name.c_str());
    if (press.axis == SDL_CONTROLLER_AXIS_INVALID)
      return fail("unknown axis \"" + name + "\" (leftx, lefty, rightx, righty, lefttrigger, righttrigger)");
    const std::optional<double> v = tire::parse_double(value);
    if (!v || !std::isfinite(*v) || *v < -1.0 || *v > 1.0)
      return fail("the axis value \"" + value + "\" is not a number in [-1, 1]");
    press.value = *v;
  } else {
    press.button = SDL_GameControllerGetButtonFromString(name.c_str());
    if (press.button == SDL_CONTROLLER_BUTTON_INVALID)
      return fail("unknown button \"" + name +
                  "\" (a, b, x, y, back, start, leftshoulder, rightshoulder, dpleft, dpright, dpup, dpdown, "
                  "...; an axis takes a value: leftx=1)");
  }
  const std::string frames = spec.substr(colon + 1);
  const std::optional<FrameRange> range = parse_frame_range(frames);
  if (!range) return fail("\"" + frames + "\" is not a frame or an increasing frame range (FIRST-LAST)");
  press.first = range->first;
  press.last = range->last;
  return press;
}

VirtualPad::~VirtualPad() { detach(); }

std::string VirtualPad::attach() {
  SDL_VirtualJoystickDesc desc{};
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
  desc.naxes = SDL_CONTROLLER_AXIS_MAX;
  desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
  desc.name = "tire-game scripted pad";
  device_ = SDL_JoystickAttachVirtualEx(&desc);
  if (device_ < 0) return std::string("cannot attach a virtual game controller: ") + SDL_GetError();
  // A handle of our own to set its state through; the game opens it as a controller when SDL
  // reports it added, as it would a real pad.
  joystick_ = SDL_JoystickOpen(device_);
  if (joystick_) instance_ = SDL_JoystickInstanceID(joystick_);
  if (!joystick_) {
    const std::string why = SDL_GetError();
    detach();
    return "cannot open the virtual game controller: " + why;
  }
  return "";
}

bool VirtualPad::connects_later() const {
  for (const PadPress& p : presses_)
    if (p.plug == PadPress::Plug::connect) return true;
  return false;
}

std::string VirtualPad::apply(long long frame) {
  for (const PadPress& p : presses_) {
    if (p.first != frame) continue;
    if (p.plug == PadPress::Plug::disconnect) detach();
    if (p.plug == PadPress::Plug::connect && !joystick_)
      if (std::string err = attach(); !err.empty()) return err;
  }
  if (!joystick_) return "";
  for (const PadPress& p : presses_) {
    if (p.last + 1 != frame || p.plug != PadPress::Plug::none) continue;
    if (p.is_axis)
      SDL_JoystickSetVirtualAxis(joystick_, p.axis, 0);
    else
      SDL_JoystickSetVirtualButton(joystick_, p.button, SDL_RELEASED);
  }
  for (const PadPress& p : presses_) {
    if (p.first != frame || p.plug != PadPress::Plug::none) continue;
    if (p.is_axis)
      SDL_JoystickSetVirtualAxis(joystick_, p.axis, axis_raw(p.value));
    else
      SDL_JoystickSetVirtualButton(joystick_, p.button, SDL_PRESSED);
  }
  return "";
}

void VirtualPad::detach() {
  if (joystick_) SDL_JoystickClose(joystick_);
  joystick_ = nullptr;
  // Device indices shift as devices come and go: find ours by its instance id.
  for (int i = 0; instance_ >= 0 && i < SDL_NumJoysticks(); ++i)
    if (SDL_JoystickGetDeviceInstanceID(i) == instance_) device_ = i;
  if (device_ >= 0) SDL_JoystickDetachVirtual(device_);
  device_ = -1;
  instance_ = -1;
}

}  // namespace game
