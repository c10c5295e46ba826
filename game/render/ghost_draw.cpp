#include "render/ghost_draw.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/vehicle_draw.h"

namespace game {

float GhostRenderer::draw_tire(Draw& d, const Camera& camera, std::uint32_t n) {
  if (positions_.size() < 2 * n || n < 3) return std::numeric_limits<float>::max();
  tire::Vec2 hub_world;
  for (std::uint32_t i = 0; i < 2 * n; ++i) hub_world += positions_[i];
  const ScreenPoint hub = camera.to_screen(hub_world / static_cast<double>(2 * n));
  hub_x_ = hub.x;
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
  float top = hub.y;
  for (const ScreenPoint& p : outer_) top = std::min(top, p.y);
  return top;
}

float GhostRenderer::draw_vehicle(Draw& d, const Camera& camera, const Ghost& ghost,
                                  const tire::VehicleView& v, double alpha) {
  float top = std::numeric_limits<float>::max();
  // The chassis: its outline filled as faintly as the rim, its edge as the tread's.
  const tire::Pose pose = ghost.interpolated_chassis(alpha);
  if (const std::optional<tire::PropView> c = ghost.chassis()) {
    outer_.clear();
    if (c->shape == tire::PropShape::circle) {
      for (int k = 0; k < 32; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 32;
        outer_.push_back(camera.to_screen(pose.to_world(tire::Vec2{std::cos(a), std::sin(a)} * c->radius)));
      }
    } else {
      for (const tire::Vec2& p : c->vertices) outer_.push_back(camera.to_screen(pose.to_world(p)));
    }
    if (outer_.size() >= 3) {
      d.convex(outer_, kGhostRim);
      d.polyline(outer_, true, 1.5f, kGhostEdge);
      for (const ScreenPoint& p : outer_) top = std::min(top, p.y);
    }
  }
  for (std::size_t w = 0; w < v.wheel_count; ++w) {
    ghost.interpolated_wheel(w, alpha, positions_);
    top = std::min(top, draw_tire(d, camera, static_cast<std::uint32_t>(positions_.size() / 2)));
  }
  if (v.head_center) {
    const tire::Vec2 local = head_local(v.pose, *v.head_center);
    draw_helmet(d, camera, pose, local, v.head_radius, ghost_helmet(), outer_);
    top = std::min(top, camera.to_screen(pose.to_world(local)).y - camera.pixels(v.head_radius));
  }
  return top;
}

void GhostRenderer::draw(Draw& d, const Camera& camera, const Ghost& ghost, double alpha) {
  if (!ghost.visible) return;
  float top = std::numeric_limits<float>::max();
  float x = 0.0f;
  if (const std::optional<tire::TireView> t = ghost.player()) {
    ghost.interpolated_positions(alpha, positions_);
    top = draw_tire(d, camera, t->segments);
    x = hub_x_;
  } else if (const std::optional<tire::VehicleView> v = ghost.vehicle()) {
    top = draw_vehicle(d, camera, ghost, *v, alpha);
    x = camera.to_screen(ghost.interpolated_chassis(alpha).to_world(v->pose.to_local(v->center))).x;
  } else {
    return;
  }
  d.flush();
  if (top == std::numeric_limits<float>::max()) return;
  // Named above its top, so nobody takes it for a second player.
  const char* label = "best run";
  const ImVec2 size = ImGui::CalcTextSize(label);
  ImGui::GetBackgroundDrawList()->AddText({x - size.x * 0.5f, top - size.y - 4.0f}, kGhostLabel, label);
}

}  // namespace game
