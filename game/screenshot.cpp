#include "screenshot.h"

#include <filesystem>

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
    const std::string temp = file + ".tmp";
    if (SDL_SaveBMP(surface, temp.c_str()) != 0) {
      error = SDL_GetError();
    } else {
      std::error_code ec;
      std::filesystem::rename(temp, file, ec);
      if (ec) {
        error = "cannot rename " + temp + " to " + file + ": " + ec.message();
        std::filesystem::remove(temp, ec);
      }
    }
  }
  SDL_FreeSurface(surface);
  return error;
}

}  // namespace game
