#include "render/vehicle_draw.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace game {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// A band between radii r0 and r1 (as fractions of the helmet's radius) over the angles a0 to a1
// (chassis frame, counter-clockwise from its +x), as quads.
void band(Draw& d, const Camera& camera, const tire::Pose& chassis, tire::Vec2 local, double radius,
          double r0, double r1, double a0, double a1, SDL_Color color) {
  constexpr int kSteps = 8;
  const auto at = [&](double r, double a) {
    return camera.to_screen(chassis.to_world(local + tire::Vec2{std::cos(a), std::sin(a)} * (r * radius)));
  };
  for (int i = 0; i < kSteps; ++i) {
    const double a = a0 + (a1 - a0) * i / kSteps, b = a0 + (a1 - a0) * (i + 1) / kSteps;
    d.quad(at(r1, a), at(r1, b), at(r0, b), at(r0, a), color);
  }
}

}  // namespace

HelmetLook player_helmet() { return {}; }

HelmetLook other_helmet() {
  HelmetLook look;
  look.shell = rgba(70, 120, 200);
  look.edge = rgba(28, 48, 86);
  return look;
}

HelmetLook ghost_helmet() {
  HelmetLook look;
  look.shell = rgba(210, 235, 255, 110);
  look.edge = rgba(235, 248, 255, 170);
  look.visor = rgba(150, 200, 255, 90);
  look.glint = rgba(235, 248, 255, 140);
  look.stripe = rgba(235, 248, 255, 60);
  look.suit = rgba(150, 200, 255, 70);
  return look;
}

void draw_helmet(Draw& d, const Camera& camera, const tire::Pose& chassis, tire::Vec2 local, double radius,
                 const HelmetLook& look, std::vector<ScreenPoint>& ring) {
  const float r_px = camera.pixels(radius);
  if (r_px < 0.5f) return;
  const ScreenPoint c = camera.to_screen(chassis.to_world(local));
  // The driver's body under the helmet, down into the chassis: so the head is someone's, sitting in
  // it, not a ball floating over it.
  const tire::Vec2 hips = local + tire::Vec2{-0.25, -2.3} * radius;
  d.line(camera.to_screen(chassis.to_world(local + tire::Vec2{0.0, -0.5} * radius)),
         camera.to_screen(chassis.to_world(hips)), camera.pixels(1.2 * radius), look.suit);
  const int segments = std::clamp(static_cast<int>(r_px), 12, 40);
  // The shell with a dark rim one and a half pixels wide: a ring of quads, so that a translucent
  // look does not show the rim through the shell.
  ring.clear();
  const float inner = std::max(0.5f, r_px - 1.5f);
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * std::numbers::pi * i / segments;
    ring.push_back(
        {c.x + inner * static_cast<float>(std::cos(a)), c.y + inner * static_cast<float>(std::sin(a))});
  }
  d.fan(c, ring, look.shell);
  for (int i = 0; i < segments; ++i) {
    const ScreenPoint a = ring[static_cast<std::size_t>(i)];
    const ScreenPoint b = ring[static_cast<std::size_t>((i + 1) % segments)];
    const auto out = [&](ScreenPoint p) {
      return ScreenPoint{c.x + (p.x - c.x) * r_px / inner, c.y + (p.y - c.y) * r_px / inner};
    };
    d.quad(a, b, out(b), out(a), look.edge);
  }
  // A stripe over the top, front to back, and the visor at the front (the chassis' +x), looking a
  // little up: both turn with the chassis.
  band(d, camera, chassis, local, radius, 0.62, 0.8, 75.0 * kDegree, 190.0 * kDegree, look.stripe);
  band(d, camera, chassis, local, radius, 0.3, 0.9, -40.0 * kDegree, 60.0 * kDegree, look.visor);
  band(d, camera, chassis, local, radius, 0.7, 0.8, 10.0 * kDegree, 45.0 * kDegree, look.glint);
}

}  // namespace game
