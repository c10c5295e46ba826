// Scripted key presses for automation: `--press right:0-300 --press space:120`. A spec is a key
// name and a frame ("space:120": pressed on frame 120, released on frame 121) or an inclusive frame
// range ("right:0-300": held from frame 0 through frame 300, released on frame 301). Key names are
// SDL's (case-insensitive: left, right, up, space, return, escape, f1, a, ...) plus the aliases
// enter, esc, period/dot (.) and comma (,). Modifiers go before the key, joined by "+":
// "ctrl+s:30", "ctrl+shift+z:40" (ctrl, shift, alt).
#pragma once

#include <SDL.h>

#include <optional>
#include <string>
#include <vector>

namespace game {

struct KeyPress {
  SDL_Scancode key = SDL_SCANCODE_UNKNOWN;
  Uint16 mod = KMOD_NONE;  // modifiers held with it
  long long first = 0;     // frame the key goes down
  long long last = 0;      // last frame it is held (it goes up on last + 1)
};

// Parses one spec; on failure returns nullopt and sets `error`.
std::optional<KeyPress> parse_key_press(const std::string& spec, std::string& error);

// A key event the script makes on a frame.
struct ScriptedKey {
  SDL_Scancode key;
  bool down;
  Uint16 mod = KMOD_NONE;
};

class KeyScript {
 public:
  void add(const KeyPress& press) { presses_.push_back(press); }
  bool empty() const { return presses_.empty(); }
  // The key-down and key-up events of `frame`, ups first.
  std::vector<ScriptedKey> events_at(long long frame) const;

 private:
  std::vector<KeyPress> presses_;
};

}  // namespace game
