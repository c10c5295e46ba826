#include "input/gamepad.h"

#include <algorithm>
#include <cmath>

namespace game {

double stick_steer(Sint16 raw) {
  const double v = std::clamp(static_cast<double>(raw) / SDL_JOYSTICK_AXIS_MAX, -1.0, 1.0);
  const double magnitude = std::abs(v);
  if (magnitude <= kStickDeadZone) return 0.0;
  const double scaled = std::min(1.0, (magnitude - kStickDeadZone) / (1.0 - kStickDeadZone));
  return v < 0.0 ? -scaled : scaled;
}

Gamepads::~Gamepads() { close_all(); }

std::string Gamepads::init() {
  if (started_) return "";
  if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0) return SDL_GetError();
  started_ = true;
  // Pads present at start come as SDL_CONTROLLERDEVICEADDED events too.
  return "";
}

void Gamepads::close_all() {
  for (auto& [id, pad] : pads_) SDL_GameControllerClose(pad.controller);
  pads_.clear();
  if (started_) SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
  started_ = false;
}

PadAction Gamepads::handle_event(const SDL_Event& e, std::vector<std::string>& messages) {
  switch (e.type) {
    case SDL_CONTROLLERDEVICEADDED: {
      // e.cdevice.which is a device index here.
      SDL_GameController* c = SDL_GameControllerOpen(e.cdevice.which);
      if (!c) {
        messages.push_back(std::string("cannot open the game controller: ") + SDL_GetError());
        return PadAction::none;
      }
      const SDL_JoystickID id = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(c));
      if (pads_.contains(id)) {
        SDL_GameControllerClose(c);  // already open (SDL reports a pad present at start once more)
        return PadAction::none;
      }
      // A stick already tilted or a d-pad already held when the pad is opened sends no event.
      Pad pad{c};
      pad.stick = stick_steer(SDL_GameControllerGetAxis(c, SDL_CONTROLLER_AXIS_LEFTX));
      pad.left = SDL_GameControllerGetButton(c, SDL_CONTROLLER_BUTTON_DPAD_LEFT) != 0;
      pad.right = SDL_GameControllerGetButton(c, SDL_CONTROLLER_BUTTON_DPAD_RIGHT) != 0;
      pad.stick_y = stick_steer(SDL_GameControllerGetAxis(c, SDL_CONTROLLER_AXIS_LEFTY));
      pad.a = SDL_GameControllerGetButton(c, SDL_CONTROLLER_BUTTON_A) != 0;
      pads_[id] = pad;
      const char* name = SDL_GameControllerName(c);
      messages.push_back(std::string("game controller connected: ") + (name ? name : "(unnamed)"));
      return PadAction::none;
    }
    case SDL_CONTROLLERDEVICEREMOVED: {
      // e.cdevice.which is an instance id here.
      const auto it = pads_.find(e.cdevice.which);
      if (it == pads_.end()) return PadAction::none;
      SDL_GameControllerClose(it->second.controller);
      pads_.erase(it);
      messages.push_back("game controller disconnected");
      return PadAction::none;
    }
    case SDL_CONTROLLERAXISMOTION: {
      const auto it = pads_.find(e.caxis.which);
      if (it == pads_.end()) return PadAction::none;
      // A trigger reads 0 … 32767: the stick's dead zone and rescaling on its positive half.
      if (e.caxis.axis == SDL_CONTROLLER_AXIS_LEFTX) it->second.stick = stick_steer(e.caxis.value);
      if (e.caxis.axis == SDL_CONTROLLER_AXIS_LEFTY) it->second.stick_y = stick_steer(e.caxis.value);
      if (e.caxis.axis == SDL_CONTROLLER_AXIS_TRIGGERLEFT)
        it->second.left_trigger = stick_steer(e.caxis.value);
      if (e.caxis.axis == SDL_CONTROLLER_AXIS_TRIGGERRIGHT)
        it->second.right_trigger = stick_steer(e.caxis.value);
      return PadAction::none;
    }
    case SDL_CONTROLLERBUTTONDOWN:
    case SDL_CONTROLLERBUTTONUP: {
      const auto it = pads_.find(e.cbutton.which);
      if (it == pads_.end()) return PadAction::none;
      const bool down = e.type == SDL_CONTROLLERBUTTONDOWN;
      Pad& pad = it->second;
      switch (e.cbutton.button) {
        case SDL_CONTROLLER_BUTTON_DPAD_LEFT: pad.left = down; return PadAction::none;
        case SDL_CONTROLLER_BUTTON_DPAD_RIGHT: pad.right = down; return PadAction::none;
        case SDL_CONTROLLER_BUTTON_A: pad.a = down; break;  // held: a vehicle's brake; pressed: jump
        default: break;
      }
      if (!down) return PadAction::none;
      switch (e.cbutton.button) {
        case SDL_CONTROLLER_BUTTON_A: return PadAction::jump;
        case SDL_CONTROLLER_BUTTON_B: return PadAction::back;
        case SDL_CONTROLLER_BUTTON_START: return PadAction::pause;
        case SDL_CONTROLLER_BUTTON_BACK: return PadAction::restart;
        case SDL_CONTROLLER_BUTTON_RIGHTSHOULDER: return PadAction::next_level;
        case SDL_CONTROLLER_BUTTON_LEFTSHOULDER: return PadAction::previous_level;
        case SDL_CONTROLLER_BUTTON_DPAD_UP: return PadAction::menu_up;
        case SDL_CONTROLLER_BUTTON_DPAD_DOWN: return PadAction::menu_down;
        default: return PadAction::none;
      }
    }
    default: return PadAction::none;
  }
}

double Gamepads::inflate() const {
  double sum = 0.0;
  for (const auto& [id, pad] : pads_)
    sum += std::max(0.0, pad.right_trigger) - std::max(0.0, pad.left_trigger);
  return std::clamp(sum, -1.0, 1.0);
}

double Gamepads::lean() const {
  double sum = 0.0;
  for (const auto& [id, pad] : pads_) sum -= pad.stick_y;  // SDL's y grows downwards; up leans back
  return std::clamp(sum, -1.0, 1.0);
}

bool Gamepads::brake() const {
  return std::any_of(pads_.begin(), pads_.end(), [](const auto& p) { return p.second.a; });
}

double Gamepads::steer() const {
  double sum = 0.0;
  for (const auto& [id, pad] : pads_) {
    if (pad.left != pad.right)
      sum += pad.right ? 1.0 : -1.0;
    else
      sum += pad.stick;
  }
  return std::clamp(sum, -1.0, 1.0);
}

}  // namespace game
