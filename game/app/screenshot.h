// Saves what the renderer has drawn (before it is presented) as a BMP file: made in memory, then
// written by tire::write_file_atomically (atomic; a symbolic link written through, the mode of an
// existing file kept; a directory, FIFO or device refused).
#pragma once

#include <SDL.h>

#include <string>

namespace game {

// Returns "" on success, otherwise what went wrong.
std::string save_screenshot(SDL_Renderer* renderer, const std::string& file);

}  // namespace game
