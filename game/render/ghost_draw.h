// Draws the ghost's player, a tire or a vehicle (its chassis' outline, its wheels and the driver's
// helmet): translucent, so the player's own and the level show through.
#pragma once

#include <cstdint>
#include <limits>
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
  // The tire whose `n` tread and `n` rim particles are in positions_; returns its top (screen y).
  float draw_tire(Draw& d, const Camera& camera, std::uint32_t n);
  float draw_vehicle(Draw& d, const Camera& camera, const Ghost& ghost, const tire::VehicleView& v,
                     double alpha);

  std::vector<tire::Vec2> positions_;
  std::vector<ScreenPoint> outer_, inner_;
  float hub_x_ = 0.0f;  // the last tire drawn's hub on screen
};

}  // namespace game
