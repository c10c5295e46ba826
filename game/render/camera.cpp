#include "render/camera.h"

#include <algorithm>
#include <cmath>

#include "tire/engine.h"

namespace game {

void Camera::resize(int width, int height) {
  width_ = std::max(width, 1);
  height_ = std::max(height, 1);
  scale_ = std::min(height_ / kViewHeight, width_ / kViewWidth);
}

tire::Aabb Camera::view() const {
  const double hw = width_ * 0.5 / scale_;
  const double hh = height_ * 0.5 / scale_;
  return {{center_.x - hw, center_.y - hh}, {center_.x + hw, center_.y + hh}};
}

tire::Vec2 Camera::aim(tire::Vec2 position, tire::Vec2 velocity) const {
  const double hh = height_ * 0.5 / scale_;
  return {position.x + std::clamp(velocity.x * 0.3, -2.0, 2.0), position.y + 0.35 * hh};
}

void Camera::follow(tire::Vec2 target, const tire::Aabb& bounds, double seconds) {
  // Critically damped-ish easing: closes ~1 − e^(−6 t) of the gap.
  const double k = 1.0 - std::exp(-6.0 * std::clamp(seconds, 0.0, 0.25));
  center_ += (target - center_) * k;
  // Never lose the player: a target outside the level's bounds (flung high, fallen off) grows them.
  tire::Aabb b = bounds;
  const double hh = height_ * 0.5 / scale_;
  b.min = {std::min(b.min.x, target.x - 1.0), std::min(b.min.y, target.y - hh)};
  b.max = {std::max(b.max.x, target.x + 1.0), std::max(b.max.y, target.y + hh)};
  clamp(b);
}

void Camera::snap(tire::Vec2 target, const tire::Aabb& bounds) {
  center_ = target;
  clamp(bounds);
}

void Camera::clamp(const tire::Aabb& bounds) {
  const double hw = width_ * 0.5 / scale_;
  const double hh = height_ * 0.5 / scale_;
  // Compared as the clamp's own bounds: a level exactly one view across can round to lo > hi.
  const double lo_x = bounds.min.x + hw, hi_x = bounds.max.x - hw;
  center_.x = lo_x <= hi_x ? std::clamp(center_.x, lo_x, hi_x) : 0.5 * (bounds.min.x + bounds.max.x);
  const double lo_y = bounds.min.y + hh, hi_y = bounds.max.y - hh;
  center_.y = lo_y <= hi_y ? std::clamp(center_.y, lo_y, hi_y) : lo_y;
}

Underground underground(const tire::Simulation& simulation) {
  double widest = -1.0;
  Underground out;
  for (const tire::Obstacle& o : simulation.obstacles())
    if (const double w = o.box.max.x - o.box.min.x; w > widest) widest = w, out = {o.box.min.y, o.box.max.y};
  if (widest > 0.0) return out;
  double height = -1e9;
  bool any = false;
  for (tire::PropId i = 0; i < simulation.prop_count(); ++i) {
    const std::optional<tire::PropView> p = simulation.prop(i);
    if (!p || !p->alive || p->type != tire::PropType::static_body) continue;
    for (const tire::Vec2& v : p->vertices) {
      const double y = p->state.pose.to_world(v).y - p->thickness;
      height = any ? std::min(height, y) : y;
      any = true;
    }
  }
  return {height, height};
}

tire::Aabb level_bounds(const tire::Simulation& simulation, double margin, double below) {
  tire::Aabb box = tire::Aabb::none();
  for (const tire::Obstacle& o : simulation.obstacles()) {
    box.include(o.box.min);
    box.include(o.box.max);
  }
  for (tire::PropId i = 0; i < simulation.prop_count(); ++i) {
    const std::optional<tire::PropView> p = simulation.prop(i);
    if (!p || !p->alive) continue;
    const tire::Aabb& local = p->local_bounds;
    for (const tire::Vec2 c :
         {local.min, local.max, tire::Vec2{local.min.x, local.max.y}, tire::Vec2{local.max.x, local.min.y}})
      box.include(p->state.pose.to_world(c));
    for (const tire::Vec2& w : p->path) {
      box.include(w + local.min);
      box.include(w + local.max);
    }
  }
  for (const tire::Region& r : simulation.regions()) {
    box.include(r.box.min);
    box.include(r.box.max);
  }
  for (std::size_t i = 0; const std::optional<tire::TireView> t = simulation.tire_at(i); ++i) {
    const double r = t->outer_radius;
    box.include(t->centroid - tire::Vec2{r, r});
    box.include(t->centroid + tire::Vec2{r, r});
  }
  if (box.holds_nothing()) return {{-10, -2}, {10, 8}};
  box.min -= tire::Vec2{margin, below};
  box.max += tire::Vec2{margin, margin + 3.0};
  return box;
}

}  // namespace game
