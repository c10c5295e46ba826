#include "input/key_script.h"

#include <cctype>

#include "input/frame_range.h"

namespace game {

namespace {

SDL_Scancode scancode_of(const std::string& given) {
  std::string name;
  for (const char c : given) name.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  struct Alias {
    const char* alias;
    const char* sdl;
  };
  static constexpr Alias kAliases[] = {
      {"enter", "return"}, {"esc", "escape"}, {"period", "."}, {"dot", "."}, {"comma", ","}};
  for (const Alias& a : kAliases)
    if (name == a.alias) return SDL_GetScancodeFromName(a.sdl);
  return SDL_GetScancodeFromName(name.c_str());
}

}  // namespace

std::optional<KeyPress> parse_key_press(const std::string& spec, std::string& error) {
  const auto colon = spec.rfind(':');
  if (colon == std::string::npos || colon == 0) {
    error = "--press " + spec + ": expected KEY:FRAME or KEY:FIRST-LAST, e.g. right:0-300 or space:120";
    return std::nullopt;
  }
  KeyPress press;
  std::string name = spec.substr(0, colon);
  // Modifiers: "ctrl+", "shift+", "alt+" before the key.
  for (std::size_t plus = name.find('+'); plus != std::string::npos && plus + 1 < name.size();
       plus = name.find('+')) {
    std::string mod = name.substr(0, plus);
    for (char& c : mod) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (mod == "ctrl")
      press.mod = static_cast<Uint16>(press.mod | KMOD_LCTRL);
    else if (mod == "shift")
      press.mod = static_cast<Uint16>(press.mod | KMOD_LSHIFT);
    else if (mod == "alt")
      press.mod = static_cast<Uint16>(press.mod | KMOD_LALT);
    else {
      error = "--press " + spec + ": unknown modifier \"" + mod + "\" (ctrl, shift or alt)";
      return std::nullopt;
    }
    name = name.substr(plus + 1);
  }
  press.key = scancode_of(name);
  if (press.key == SDL_SCANCODE_UNKNOWN) {
    error = "--press " + spec + ": unknown key \"" + name +
            "\" (use SDL key names: left, right, up, space, r, p, ...)";
    return std::nullopt;
  }
  const std::string frames = spec.substr(colon + 1);
  const std::optional<FrameRange> range = parse_frame_range(frames);
  if (!range) {
    error =
        "--press " + spec + ": \"" + frames + "\" is not a frame or an increasing frame range (FIRST-LAST)";
    return std::nullopt;
  }
  press.first = range->first;
  press.last = range->last;
  return press;
}

std::vector<ScriptedKey> KeyScript::events_at(long long frame) const {
  std::vector<ScriptedKey> out;
  for (const KeyPress& p : presses_)
    if (p.last + 1 == frame) out.push_back({p.key, false, p.mod});
  for (const KeyPress& p : presses_)
    if (p.first == frame) out.push_back({p.key, true, p.mod});
  return out;
}

}  // namespace game
