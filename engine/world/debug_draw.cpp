// World::debug_draw: the one place outside the solver that reads a tire's constraints, contact
// records and broad-phase lists, turning them into DebugDraw's shapes (debug_draw.h).
#include "tire/world/debug_draw.h"

#include <algorithm>

#include "tire/world/world.h"

namespace tire {

namespace {

constexpr unsigned kTireFlags = DebugDraw::structure | DebugDraw::contacts | DebugDraw::velocities |
                                DebugDraw::bounds | DebugDraw::broadphase;

// The world box around a prop's shape at `pose`.
Aabb prop_bounds(const Prop& p, const Pose& pose) { return pose.to_world(p.geometry.local_bounds()); }

void draw_tire(DebugDraw& draw, const Tire& t, const TireView& view, const RigidWorld& rigid) {
  const unsigned flags = draw.flags();
  const std::span<const Vec2> x = draw.tire_positions(view);
  if (x.size() != t.particle_count()) return;  // nothing sensible to draw against
  const std::uint32_t n = t.segments();
  const Vec2 hub = mean(x);  // every particle weighs the same: the centroid (tire.h)

  if (flags & DebugDraw::structure) {
    const auto& constraints = t.distance.constraints();
    for (std::size_t k = t.spokes_first(); k < constraints.size(); ++k)
      draw.segment(x[constraints[k].a], x[constraints[k].b], DebugShape::spoke);
    draw.polygon(x.subspan(n, n), DebugShape::rim);
    draw.polygon(x.first(n), DebugShape::tread);
    for (std::uint32_t i = 0; i < n; ++i) draw.point(x[i], DebugShape::tread);
    for (std::uint32_t i = n; i < 2 * n; ++i) draw.point(x[i], DebugShape::rim);
  }
  if (flags & DebugDraw::contacts)
    t.for_each_contact([&](std::uint32_t i) {
      if (!t.contacts[i].active) return;
      draw.point(x[i], DebugShape::contact);
      draw.vector(x[i], t.contacts[i].normal, DebugShape::contact);
    });
  if (flags & DebugDraw::velocities) draw.vector(hub, t.velocity(), DebugShape::velocity);
  if (flags & DebugDraw::bounds) draw.box(bounds_of(x), DebugShape::tire_bounds);
  if (flags & DebugDraw::broadphase) {
    const auto& obstacles = rigid.obstacles();
    const auto& props = rigid.props();
    for (const std::uint32_t o : t.candidates) {
      if (o >= obstacles.size()) continue;
      const Aabb& b = obstacles[o].box;
      draw.box(b, DebugShape::candidate_obstacle);
      draw.segment(hub, (b.min + b.max) * 0.5, DebugShape::candidate_obstacle);
    }
    for (const std::uint32_t p : t.prop_candidates) {
      if (p >= props.size() || !props[p].alive) continue;
      const Aabb b = prop_bounds(props[p], draw.prop_pose(p, rigid.current_pose(p)));
      draw.box(b, DebugShape::candidate_prop);
      draw.segment(hub, (b.min + b.max) * 0.5, DebugShape::candidate_prop);
    }
    for (const ContactPair& pair : t.pairs)
      if (pair.particle < x.size()) draw.point(x[pair.particle], DebugShape::pair);
  }
}

}  // namespace

std::span<const Vec2> DebugDraw::tire_positions(const TireView& t) { return t.positions; }

void World::debug_draw(DebugDraw& draw) const {
  const unsigned flags = draw.flags();
  if (flags & kTireFlags)
    for (const Tire& t : tires_) draw_tire(draw, t, view_of(t), rigid_);
  if (flags & DebugDraw::bounds) {
    const auto& props = rigid_.props();
    for (std::uint32_t i = 0; i < props.size(); ++i)
      if (props[i].alive)
        draw.box(prop_bounds(props[i], draw.prop_pose(i, rigid_.current_pose(i))), DebugShape::prop_bounds);
    for (const Obstacle& o : rigid_.obstacles()) draw.box(o.box, DebugShape::obstacle_bounds);
  }
}

}  // namespace tire
