#include "render/debug_draw_sdl.h"

#include <algorithm>
#include <cmath>

#include "render/renderer.h"

namespace game {

namespace {

using tire::DebugShape;

constexpr SDL_Color kTread = rgba(255, 255, 255, 220);
constexpr SDL_Color kTreadParticle = rgba(255, 255, 255);
constexpr SDL_Color kRim = rgba(0, 200, 255);
constexpr SDL_Color kSpoke = rgba(120, 220, 255, 200);
constexpr SDL_Color kContact = rgba(255, 40, 40);
constexpr SDL_Color kVelocity = rgba(255, 220, 0);
constexpr SDL_Color kBounds = rgba(60, 230, 90);
constexpr SDL_Color kCandidateObstacle = rgba(255, 140, 0);
constexpr SDL_Color kCandidateProp = rgba(230, 0, 230);  // and the narrow-phase pairs
constexpr SDL_Color kHead = rgba(255, 70, 200, 230);     // a driver's head: the circle the level watches

// Seconds of travel a velocity arrow shows, and metres a unit normal is drawn long.
constexpr double kVelocityArrowSeconds = 0.25;
constexpr double kNormalArrowMetres = 0.25;

void arrow(Draw& d, ScreenPoint a, ScreenPoint b, float width, SDL_Color c) {
  d.line(a, b, width, c);
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float len = std::sqrt(dx * dx + dy * dy);
  if (len < 4.0f) return;
  const float ux = dx / len, uy = dy / len, head = std::min(10.0f, len * 0.4f);
  d.triangle(b, {b.x - ux * head - uy * head * 0.5f, b.y - uy * head + ux * head * 0.5f},
             {b.x - ux * head + uy * head * 0.5f, b.y - uy * head - ux * head * 0.5f}, c);
}

}  // namespace

unsigned debug_flags(const DebugOptions& o) {
  unsigned flags = 0;
  if (o.structure) flags |= tire::DebugDraw::structure;
  if (o.contacts) flags |= tire::DebugDraw::contacts;
  if (o.velocities) flags |= tire::DebugDraw::velocities;
  if (o.aabbs) flags |= tire::DebugDraw::bounds;
  if (o.broadphase) flags |= tire::DebugDraw::broadphase;
  return flags;
}

SDL_Color SdlDebugDraw::color(SDL_Color c, DebugShape kind) const {
  // Every kind but these three is reported for one tire (debug_draw.cpp's draw_tire).
  const bool of_tire =
      kind != DebugShape::prop_bounds && kind != DebugShape::obstacle_bounds && kind != DebugShape::head;
  return asleep_ && of_tire ? asleep_shade(c) : c;
}

void SdlDebugDraw::segment(tire::Vec2 a, tire::Vec2 b, DebugShape kind) {
  SDL_Color c = kSpoke;
  if (kind == DebugShape::candidate_obstacle)
    c = kCandidateObstacle;
  else if (kind == DebugShape::candidate_prop)
    c = kCandidateProp;
  else if (kind == DebugShape::head)
    c = kHead;
  d_.line(camera_.to_screen(a), camera_.to_screen(b), 1.0f, color(c, kind));
}

void SdlDebugDraw::polygon(std::span<const tire::Vec2> points, DebugShape kind) {
  points_.clear();
  for (const tire::Vec2& p : points) points_.push_back(camera_.to_screen(p));
  const SDL_Color c = kind == DebugShape::rim ? kRim : kind == DebugShape::head ? kHead : kTread;
  d_.polyline(points_, true, 1.5f, color(c, kind));
}

void SdlDebugDraw::point(tire::Vec2 p, DebugShape kind) {
  const ScreenPoint s = camera_.to_screen(p);
  switch (kind) {
    case DebugShape::contact: d_.circle(s, 3.5f, color(kContact, kind), 8); break;
    case DebugShape::pair: d_.circle(s, 3.0f, color(kCandidateProp, kind), 6); break;
    case DebugShape::rim: d_.circle(s, 2.0f, color(kRim, kind), 6); break;
    default: d_.circle(s, 2.0f, color(kTreadParticle, kind), 6); break;
  }
}

void SdlDebugDraw::vector(tire::Vec2 at, tire::Vec2 v, DebugShape kind) {
  if (kind == DebugShape::velocity)
    arrow(d_, camera_.to_screen(at), camera_.to_screen(at + v * kVelocityArrowSeconds), 3.0f,
          color(kVelocity, kind));
  else
    arrow(d_, camera_.to_screen(at), camera_.to_screen(at + v * kNormalArrowMetres), 2.0f,
          color(kContact, kind));
}

void SdlDebugDraw::box(const tire::Aabb& b, DebugShape kind) {
  const ScreenPoint min = camera_.to_screen(b.min), max = camera_.to_screen(b.max);
  switch (kind) {
    case DebugShape::candidate_obstacle:
      d_.rect_outline(min, max, 3.0f, color(kCandidateObstacle, kind));
      break;
    case DebugShape::candidate_prop: d_.rect_outline(min, max, 3.0f, color(kCandidateProp, kind)); break;
    default: d_.rect_outline(min, max, 1.5f, color(kBounds, kind)); break;
  }
}

std::span<const tire::Vec2> SdlDebugDraw::tire_positions(const tire::TireView& t) {
  asleep_ = t.asleep;
  session_.interpolated_positions(t.id, t.positions, alpha_, positions_);
  return positions_;
}

tire::Pose SdlDebugDraw::prop_pose(std::uint32_t prop, const tire::Pose& /*now*/) {
  return session_.interpolated_pose(prop, alpha_);
}

}  // namespace game
