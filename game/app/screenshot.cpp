#include "app/screenshot.h"

#include <cstdint>
#include <vector>

#include "tire/io/file_io.h"

namespace game {

std::string save_screenshot(SDL_Renderer* renderer, const std::string& file) {
  int w = 0, h = 0;
  if (SDL_GetRendererOutputSize(renderer, &w, &h) != 0) return SDL_GetError();
  SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormat(0, w, h, 24, SDL_PIXELFORMAT_BGR24);
  if (!surface) return SDL_GetError();
  std::string error;
  if (SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_BGR24, surface->pixels, surface->pitch) != 0) {
    error = SDL_GetError();
  } else {
    // The BMP is made in memory, then written like every other output (tire::write_file_atomically).
    // Room for any header SDL writes (at most 138 bytes) and rows of 3 bytes a pixel padded to 4.
    std::vector<std::uint8_t> bmp(1024 + static_cast<std::size_t>(h) * (static_cast<std::size_t>(w) * 3 + 3));
    SDL_RWops* out = SDL_RWFromMem(bmp.data(), static_cast<int>(bmp.size()));
    if (!out || SDL_SaveBMP_RW(surface, out, 0) != 0) {
      error = SDL_GetError();
    } else {
      const Sint64 size = SDL_RWtell(out);
      if (size <= 0 || static_cast<std::size_t>(size) > bmp.size()) {
        error = "the BMP did not fit in memory";
      } else {
        const std::string_view bytes(reinterpret_cast<const char*>(bmp.data()),
                                     static_cast<std::size_t>(size));
        tire::write_file_atomically(file, bytes, error);  // sets `error` when it fails
      }
    }
    if (out) SDL_RWclose(out);
  }
  SDL_FreeSurface(surface);
  return error;
}

}  // namespace game
