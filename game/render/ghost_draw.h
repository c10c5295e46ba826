// Draws the ghost's player tire: translucent, so the player's own tire and the level show through.
#pragma once

#include <vector>

#include "progress/ghost.h"
#include "render/camera.h"
#include "render/draw.h"

namespace game {

// The ghost's colours: a pale blue tread band and rim, both mostly transparent.
constexpr SDL_Color kGhostTread = rgba(210, 235, 255, 120);
constexpr SDL_Color kGhostRim = rgba(150, 200, 255, 70);
constexpr SDL_Color kGhostEdge = rgba(235, 248, 255, 170);
constexpr unsigned kGhostLabel = 0xC8FFFFFFu;  // ImGui's ABGR: white, mostly opaque

class GhostRenderer {
 public:
  void draw(Draw& d, const Camera& camera, const Ghost& ghost, double alpha);

 private:
  std::vector<tire::Vec2> positions_;
  std::vector<ScreenPoint> outer_, inner_;
};

}  // namespace game
