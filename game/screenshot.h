// Saves what the renderer has drawn (before it is presented) as a BMP file, atomically: written to
// a temporary file beside it, then renamed over it.
#pragma once

#include <SDL.h>

#include <string>

namespace game {

// Returns "" on success, otherwise what went wrong.
std::string save_screenshot(SDL_Renderer* renderer, const std::string& file);

}  // namespace game
