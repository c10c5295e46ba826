#include "tire/io/level_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "tire/io/level.h"
#include "tire/rigid/prop_geometry.h"

namespace tire {

namespace {

struct Extent {
  Aabb box = Aabb::none();
  void add(Vec2 p) {
    if (std::isfinite(p.x) && std::isfinite(p.y)) box.include(p);  // not: a region the reader refused
  }
  void add(const Aabb& b) {
    add(b.min);
    add(b.max);
  }
};

// A prop's box in its own frame, read from its spec alone (the level reader calls this on levels
// it has not finished checking, so a spec's shape may be incomplete: what is missing adds nothing).
std::optional<Aabb> local_box(const PropSpec& p) {
  switch (p.shape) {
    case PropShape::box: return Aabb{p.size * -0.5, p.size * 0.5};
    case PropShape::circle: return Aabb{{-p.radius, -p.radius}, {p.radius, p.radius}};
    case PropShape::polygon:
    case PropShape::chain: {
      if (p.points.empty()) return std::nullopt;
      const Aabb b = bounds_of(p.points);
      return p.shape == PropShape::chain ? b.expanded(p.thickness) : b;
    }
  }
  return std::nullopt;
}

void add_prop(Extent& e, const PropSpec& p) {
  const std::optional<Aabb> local = local_box(p);
  if (!local) return;
  e.add(Pose::make(p.position, p.angle).to_world(*local));
  // A kinematic prop's origin visits its waypoints (turning, if it spins: its box's diagonal).
  const double reach = std::max(length(local->min), length(local->max));
  for (const Vec2& w : p.path.waypoints) e.add(Aabb{w, w}.expanded(reach));
}

void add_tire(Extent& e, const TireSpec& t) { e.add(Aabb{t.position, t.position}.expanded(t.outer_radius)); }

}  // namespace

Aabb level_extent(const Level& level) {
  Extent e;
  for (const Obstacle& o : level.obstacles) e.add(o.box);
  for (const PropSpec& p : level.props) add_prop(e, p);
  for (const Region& r : level.script.regions) e.add(r.box);
  for (const TireSpec& t : level.tires) add_tire(e, t);
  for (const LevelVehicle& v : level.vehicles) {
    add_prop(e, v.spec.chassis);
    const Pose pose = Pose::make(v.spec.chassis.position, v.spec.chassis.angle);
    for (const WheelSpec& w : v.spec.wheels)
      e.add(Aabb{pose.to_world(w.axle.point), pose.to_world(w.axle.point)}.expanded(w.tire.outer_radius));
  }
  for (const Trigger& trigger : level.script.triggers)
    for (const Action& action : trigger.actions) {
      if (const auto* s = std::get_if<SpawnTire>(&action)) add_tire(e, s->tire);
      if (const auto* s = std::get_if<SpawnProp>(&action)) add_prop(e, s->prop);
      if (const auto* c = std::get_if<SetCheckpoint>(&action)) e.add(c->position);
    }
  return e.box.holds_nothing() ? Aabb{} : e.box;
}

Aabb resolve_bounds(const LevelBounds& bounds, const Aabb& extent) {
  const Aabb computed{{extent.min.x - bounds.margin, extent.min.y - bounds.margin},
                      {extent.max.x + bounds.margin, std::numeric_limits<double>::infinity()}};
  return {bounds.min.value_or(computed.min), bounds.max.value_or(computed.max)};
}

}  // namespace tire
