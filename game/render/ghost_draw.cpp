#include "render/ghost_draw.h"

#include <imgui.h>

#include <algorithm>

namespace game {

void GhostRenderer::draw(Draw& d, const Camera& camera, const Ghost& ghost, double alpha) {
  const std::optional<tire::TireView> t = ghost.player();
  if (!ghost.visible || !t) return;
  ghost.interpolated_positions(alpha, positions_);
  const std::uint32_t n = t->segments;
  if (positions_.size() < 2 * n || n < 3) return;
  tire::Vec2 hub_world;
  for (std::uint32_t i = 0; i < 2 * n; ++i) hub_world += positions_[i];
  const ScreenPoint hub = camera.to_screen(hub_world / static_cast<double>(2 * n));
  outer_.clear();
  inner_.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    outer_.push_back(camera.to_screen(positions_[i]));
    inner_.push_back(camera.to_screen(positions_[n + i]));
  }
  // The tread band and the rim do not overlap, so each is one even shade of translucency.
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    d.quad(outer_[i], outer_[j], inner_[j], inner_[i], kGhostTread);
  }
  d.fan(hub, inner_, kGhostRim);
  d.polyline(outer_, true, 1.5f, kGhostEdge);
  d.flush();
  // Named above its top, so nobody takes it for a second player.
  float top = hub.y;
  for (const ScreenPoint& p : outer_) top = std::min(top, p.y);
  const char* label = "best run";
  const ImVec2 size = ImGui::CalcTextSize(label);
  ImGui::GetBackgroundDrawList()->AddText({hub.x - size.x * 0.5f, top - size.y - 4.0f}, kGhostLabel, label);
}

}  // namespace game
