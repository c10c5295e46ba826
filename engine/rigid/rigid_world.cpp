#include "tire/rigid/rigid_world.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

namespace tire {

namespace {

// Fixture user data: which list, and the index in it.
constexpr std::uintptr_t kPropTag = std::uintptr_t{1} << 31;

// Box2D's own solver settings for the props (its recommended values).
constexpr int kBox2dVelocityIterations = 8;
constexpr int kBox2dPositionIterations = 3;

b2Vec2 to_b2(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }
Vec2 from_b2(b2Vec2 v) { return {v.x, v.y}; }

class CollectFixtures final : public b2QueryCallback {
 public:
  CollectFixtures(std::vector<std::uint32_t>& obstacles, std::vector<std::uint32_t>& props)
      : obstacles_(obstacles), props_(props) {}
  bool ReportFixture(b2Fixture* fixture) override {
    const std::uintptr_t tag = fixture->GetUserData().pointer;
    if (tag & kPropTag)
      props_.push_back(static_cast<std::uint32_t>(tag & ~kPropTag));
    else
      obstacles_.push_back(static_cast<std::uint32_t>(tag));
    return true;  // every candidate
  }

 private:
  std::vector<std::uint32_t>& obstacles_;
  std::vector<std::uint32_t>& props_;
};

// Restitution acts only on the approach velocity the bodies had before the tires pushed them
// (issue 33). Box2D gives a contact the bounce −e·v_rel for the relative normal velocity v_rel it
// finds at the start of its step (b2ContactSolver's velocity bias, Catto's sequential impulses),
// and that velocity includes the impulses the tires handed a prop just before: a crate or a ball
// pushed into the ground it lies on would be bounced back up by that ground, the push taken as an
// impact. Measured before: a tire rolling into level 07's pit onto the ball (restitution 0.3) left
// at 27 m/s, tire and ball going from 1160 to 4092 J. So before Box2D solves a contact of a pushed
// prop, its restitution is scaled so that the bounce is e times the approach the bodies had
// without the push: e_eff = e · max(0, −v_before) / −v_now at the point that approaches fastest.
// A prop pushed into its support is then held by it, not bounced; a prop that was already falling
// onto it still bounces from its own speed.
class RestitutionRule final : public b2ContactListener {
 public:
  const std::vector<Prop>* props = nullptr;

  void PreSolve(b2Contact* contact, const b2Manifold*) override {
    contact->ResetRestitution();
    const float restitution = contact->GetRestitution();
    if (restitution <= 0.0f || !props) return;
    const Prop* a = pushed_prop(contact->GetFixtureA());
    const Prop* b = pushed_prop(contact->GetFixtureB());
    if (!a && !b) return;
    b2WorldManifold manifold;
    contact->GetWorldManifold(&manifold);
    const Vec2 normal = from_b2(manifold.normal);  // from A to B
    const b2Body& body_a = *contact->GetFixtureA()->GetBody();
    const b2Body& body_b = *contact->GetFixtureB()->GetBody();
    double approach_now = 0.0, approach_before = 0.0;
    for (int k = 0; k < contact->GetManifold()->pointCount; ++k) {
      const Vec2 point = from_b2(manifold.points[k]);
      const double now =
          -dot(normal, velocity_at(body_b, nullptr, point) - velocity_at(body_a, nullptr, point));
      if (now <= approach_now) continue;
      approach_now = now;
      approach_before = -dot(normal, velocity_at(body_b, b, point) - velocity_at(body_a, a, point));
    }
    if (approach_now <= 0.0) return;
    const double share = std::clamp(approach_before / approach_now, 0.0, 1.0);
    contact->SetRestitution(static_cast<float>(restitution * share));
  }

 private:
  const Prop* pushed_prop(b2Fixture* f) const {
    const std::uintptr_t tag = f->GetUserData().pointer;
    if (!(tag & kPropTag)) return nullptr;
    const Prop& p = (*props)[tag & ~kPropTag];
    return p.pushed ? &p : nullptr;
  }
  // The velocity of the body's material point at `point`: as Box2D has it, or, for a pushed prop,
  // as it was before the push.
  static Vec2 velocity_at(const b2Body& body, const Prop* pushed, Vec2 point) {
    const Vec2 r = point - from_b2(body.GetWorldCenter());
    if (pushed) return pushed->velocity_before_push + perp(r) * pushed->omega_before_push;
    return from_b2(body.GetLinearVelocity()) + perp(r) * static_cast<double>(body.GetAngularVelocity());
  }
};

b2BodyType body_type(PropType t) {
  switch (t) {
    case PropType::dynamic_body: return b2_dynamicBody;
    case PropType::kinematic_body: return b2_kinematicBody;
    case PropType::static_body: break;
  }
  return b2_staticBody;
}

}  // namespace

Pose Prop::pose_at(double t) const {
  // The centre of mass moves with `velocity`, the body turns about it with `omega`.
  const Pose turned = Pose::make({}, start_pose.angle + omega * (t - start_time) - untravelled_angle);
  return Pose::make(center_at(t) - turned.rotate(local_center), turned.angle);
}

RigidWorld::RigidWorld(Vec2 gravity)
    : restitution_rule_(std::make_unique<RestitutionRule>()),
      world_(std::make_unique<b2World>(to_b2(gravity))),
      gravity_(gravity) {
  world_->SetContactListener(restitution_rule_.get());
  b2BodyDef def;
  def.type = b2_staticBody;
  ground_ = world_->CreateBody(&def);
}

RigidWorld::~RigidWorld() = default;
RigidWorld::RigidWorld(RigidWorld&&) noexcept = default;
RigidWorld& RigidWorld::operator=(RigidWorld&&) noexcept = default;

std::uint32_t RigidWorld::add_obstacle(const Obstacle& obstacle) {
  const auto index = static_cast<std::uint32_t>(obstacles_.size());
  obstacles_.push_back(obstacle);
  const Vec2 half = (obstacle.box.max - obstacle.box.min) * 0.5;
  const Vec2 center = (obstacle.box.max + obstacle.box.min) * 0.5;
  b2PolygonShape shape;
  shape.SetAsBox(static_cast<float>(half.x), static_cast<float>(half.y), to_b2(center), 0.0f);
  b2FixtureDef fixture;
  fixture.shape = &shape;
  fixture.friction = static_cast<float>(obstacle.friction);
  fixture.userData.pointer = index;
  ground_->CreateFixture(&fixture);
  return index;
}

std::uint32_t RigidWorld::add_prop(const PropSpec& spec) {
  const auto index = static_cast<std::uint32_t>(props_.size());
  Prop prop;
  prop.spec = spec;
  prop.geometry = PropGeometry::from_spec(spec);

  b2BodyDef def;
  def.type = body_type(spec.type);
  def.position = to_b2(spec.position);
  def.angle = static_cast<float>(spec.angle);
  def.linearVelocity = to_b2(spec.velocity);
  def.angularVelocity = static_cast<float>(spec.angular_velocity);
  b2Body* body = world_->CreateBody(&def);

  b2FixtureDef fixture;
  fixture.density = static_cast<float>(spec.density);
  fixture.friction = static_cast<float>(spec.friction);
  fixture.restitution = static_cast<float>(spec.restitution);
  fixture.userData.pointer = kPropTag | index;
  b2PolygonShape polygon;
  b2CircleShape circle;
  b2ChainShape chain;
  std::vector<b2Vec2> points;
  for (const Vec2& p : prop.geometry.vertices) points.push_back(to_b2(p));
  // Box2D's chains are one-sided too, but solid on the left of their direction (their normals
  // point right, as a counter-clockwise polygon's do); ours are solid on the right. Same side:
  // reverse the points.
  if (spec.shape == PropShape::chain) std::reverse(points.begin(), points.end());
  switch (spec.shape) {
    case PropShape::box:
    case PropShape::polygon:
      polygon.Set(points.data(), static_cast<int32>(points.size()));
      fixture.shape = &polygon;
      break;
    case PropShape::circle:
      circle.m_radius = static_cast<float>(spec.radius);
      fixture.shape = &circle;
      break;
    case PropShape::chain:
      if (spec.loop)
        chain.CreateLoop(points.data(), static_cast<int32>(points.size()));
      else
        chain.CreateChain(points.data(), static_cast<int32>(points.size()), points.front(), points.back());
      fixture.shape = &chain;
      break;
  }
  body->CreateFixture(&fixture);
  if (spec.type != PropType::static_body) ++moving_props_;
  if (spec.type == PropType::dynamic_body) ++dynamic_props_;
  props_.push_back(std::move(prop));
  bodies_.push_back(body);
  group_.reserve(props_.size());
  grouped_.push_back(0);
  return index;
}

Pose RigidWorld::current_pose(std::uint32_t i) const {
  const b2Body& b = *bodies_[i];
  return Pose::make(from_b2(b.GetPosition()), b.GetAngle());
}

Vec2 RigidWorld::current_velocity(std::uint32_t i) const { return from_b2(bodies_[i]->GetLinearVelocity()); }

PropState RigidWorld::prop_state(std::uint32_t i) const {
  const b2Body& b = *bodies_[i];
  PropState s;
  s.pose = Pose::make(from_b2(b.GetPosition()), b.GetAngle());
  s.center = from_b2(b.GetWorldCenter());
  s.velocity = from_b2(b.GetLinearVelocity());
  s.angular_velocity = b.GetAngularVelocity();
  s.mass = b.GetMass();
  // GetInertia is about the body origin; the parallel-axis theorem gives it about the centre.
  s.inertia = static_cast<double>(b.GetInertia()) - s.mass * length_squared(from_b2(b.GetLocalCenter()));
  s.awake = b.IsAwake();
  return s;
}

std::optional<std::uint32_t> RigidWorld::find_prop(std::string_view name) const {
  for (std::uint32_t i = 0; i < props_.size(); ++i)
    if (props_[i].alive && props_[i].spec.name == name) return i;
  return std::nullopt;
}

bool RigidWorld::remove_prop(std::string_view name) {
  const auto i = find_prop(name);
  if (!i) return false;
  Prop& p = props_[*i];
  world_->DestroyBody(bodies_[*i]);
  bodies_[*i] = nullptr;
  p.alive = false;
  ++removals_;
  if (p.spec.type != PropType::static_body) --moving_props_;
  if (p.spec.type == PropType::dynamic_body) --dynamic_props_;
  return true;
}

namespace {

// Moves `next` one waypoint on in `direction`, at the ends doing what the path's mode says.
void advance_waypoint(Prop& p) {
  KinematicPath& path = p.spec.path;
  const auto n = static_cast<std::ptrdiff_t>(path.waypoints.size());
  const auto next = static_cast<std::ptrdiff_t>(p.next_waypoint) + p.direction;
  if (next >= 0 && next < n) {
    p.next_waypoint = static_cast<std::size_t>(next);
    return;
  }
  switch (path.mode) {
    case PathMode::loop: p.next_waypoint = static_cast<std::size_t>((next + n) % n); break;
    case PathMode::ping_pong:
      p.direction = -p.direction;
      if (n > 1)
        p.next_waypoint =
            static_cast<std::size_t>(static_cast<std::ptrdiff_t>(p.next_waypoint) + p.direction);
      break;
    case PathMode::once: path.running = false; break;
  }
}

}  // namespace

bool RigidWorld::path_command(std::string_view name, PathCommand command) {
  const auto i = find_prop(name);
  if (!i || props_[*i].spec.type != PropType::kinematic_body) return false;
  Prop& p = props_[*i];
  switch (command) {
    case PathCommand::start: p.spec.path.running = true; break;
    case PathCommand::stop: p.spec.path.running = false; break;
    case PathCommand::reverse:
      // Between waypoints next − direction and next: turn round towards the one it came from.
      p.direction = -p.direction;
      if (!p.spec.path.waypoints.empty()) advance_waypoint(p);
      break;
  }
  return true;
}

void RigidWorld::set_gravity(Vec2 gravity) {
  world_->SetGravity(to_b2(gravity));
  gravity_ = gravity;
}

void RigidWorld::place_prop(std::uint32_t i, Vec2 position, double angle) {
  if (i >= props_.size() || !props_[i].alive) return;
  b2Body& b = *bodies_[i];
  b.SetTransform(to_b2(position), static_cast<float>(angle));
  b.SetLinearVelocity(b2Vec2(0.0f, 0.0f));
  b.SetAngularVelocity(0.0f);
  b.SetAwake(true);
}

void RigidWorld::apply_impulse_now(std::string_view name, Vec2 impulse) {
  if (const auto i = find_prop(name)) apply_impulse_now(*i, impulse);
}

void RigidWorld::apply_impulse_now(std::uint32_t i, Vec2 impulse) {
  if (i >= props_.size() || !props_[i].alive || props_[i].spec.type != PropType::dynamic_body) return;
  bodies_[i]->ApplyLinearImpulseToCenter(to_b2(impulse), true);
}

void RigidWorld::query(const Aabb& region, std::vector<std::uint32_t>& obstacles,
                       std::vector<std::uint32_t>& props) const {
  obstacles.clear();
  props.clear();
  // Widen by a float ulp's worth so rounding to float never drops a touching shape.
  const double scale = std::max(
      {std::abs(region.min.x), std::abs(region.min.y), std::abs(region.max.x), std::abs(region.max.y)});
  const Aabb r = region.expanded(1e-3 + 1e-6 * scale);
  b2AABB aabb;
  aabb.lowerBound = to_b2(r.min);
  aabb.upperBound = to_b2(r.max);
  CollectFixtures collect(obstacles, props);
  world_->QueryAABB(&collect, aabb);
  std::sort(obstacles.begin(), obstacles.end());
  // Box2D gives a chain one proxy per edge, and answers each edge's: once per prop.
  std::sort(props.begin(), props.end());
  props.erase(std::unique(props.begin(), props.end()), props.end());
}

void RigidWorld::steer_along_path(std::uint32_t i, double dt) {
  Prop& p = props_[i];
  const KinematicPath& path = p.spec.path;
  if (path.waypoints.empty()) return;
  Vec2 velocity;
  if (path.running) {
    // Head for the next waypoint at the path's speed, arriving exactly rather than overshooting.
    const Vec2 to_target = path.waypoints[p.next_waypoint] - from_b2(bodies_[i]->GetPosition());
    const double distance = length(to_target);
    if (distance <= path.speed * dt) {
      velocity = to_target / dt;
      advance_waypoint(p);
    } else {
      velocity = to_target * (path.speed / distance);
    }
  }
  bodies_[i]->SetLinearVelocity(to_b2(velocity));
}

void RigidWorld::begin_tick(double dt, bool substep_motion, double time) {
  substep_motion_ = substep_motion;
  for (std::uint32_t i = 0; i < props_.size(); ++i) {
    Prop& p = props_[i];
    if (!p.alive) continue;
    if (p.spec.type == PropType::kinematic_body) {
      steer_along_path(i, dt);
      bodies_[i]->SetAngularVelocity(static_cast<float>(p.spec.angular_velocity));
    }
    const b2Body& b = *bodies_[i];
    p.start_time = time;
    p.start_pose = Pose::make(from_b2(b.GetPosition()), b.GetAngle());
    p.local_center = from_b2(b.GetLocalCenter());
    p.start_center = from_b2(b.GetWorldCenter());
    p.velocity = from_b2(b.GetLinearVelocity());
    p.omega = b.GetAngularVelocity();
    const bool dynamic = b.GetType() == b2_dynamicBody && b.GetMass() > 0.0f;
    p.inverse_mass = dynamic ? 1.0 / b.GetMass() : 0.0;
    // GetInertia is about the body origin; the parallel-axis theorem gives it about the centre.
    const double inertia = dynamic ? b.GetInertia() - b.GetMass() * length_squared(p.local_center) : 0.0;
    p.inverse_inertia = inertia > 0.0 ? 1.0 / inertia : 0.0;
    p.impulse = {};
    p.angular_impulse = 0.0;
    p.untravelled = {};
    p.untravelled_angle = 0.0;
    p.support_count = 0;
    p.airborne = false;
    p.awake = dynamic && b.IsAwake();
    if (!dynamic) continue;
    p.airborne = substep_motion && b.IsAwake();
    for (const b2ContactEdge* edge = b.GetContactList(); edge && p.support_count < Prop::kMaxSupports;
         edge = edge->next) {
      const b2Contact* contact = edge->contact;
      if (contact->IsTouching()) p.airborne = false;
      if (!contact->IsTouching() || edge->other->GetType() == b2_dynamicBody) continue;
      b2WorldManifold manifold;
      contact->GetWorldManifold(&manifold);
      // Box2D's normal points from fixture A to fixture B; the support's normal points into us.
      const Vec2 normal = from_b2(manifold.normal);
      p.supports[p.support_count++] = contact->GetFixtureA()->GetBody() == &b ? -normal : normal;
    }
  }
}

void RigidWorld::begin_substep(double time, double h) {
  if (!substep_motion_) return;
  for (Prop& p : props_) {
    if (!p.alive || !p.airborne) continue;
    // v ← v + h g, travelled from this substep on.
    const Vec2 dv = gravity_ * h;
    p.velocity += dv;
    p.untravelled += dv * (time - p.start_time);
  }
}

void RigidWorld::add_impulse(std::uint32_t i, Vec2 impulse, Vec2 point, double t, double since) {
  Prop& p = props_[i];
  if (!p.is_dynamic()) return;
  const double moment = cross(point - p.center_at(t), impulse);
  p.impulse += impulse;
  p.angular_impulse += moment;
  // A free body gives way at once: the rest of the tick sees its new velocity. One resting on
  // something is moved by Box2D alone, which weighs the push against its support's contact and
  // friction; within the tick it stays on its course.
  if (p.support_count > 0) return;
  const Vec2 dv = impulse * p.inverse_mass;
  const double dw = moment * p.inverse_inertia;
  p.velocity += dv;
  p.omega += dw;
  if (!substep_motion_) return;
  p.untravelled += dv * (since - p.start_time);
  p.untravelled_angle += dw * (since - p.start_time);
}

void RigidWorld::add_angular_impulse(std::uint32_t i, double angular, double since) {
  Prop& p = props_[i];
  if (!p.is_dynamic()) return;
  p.angular_impulse += angular;
  if (p.support_count > 0) return;  // as add_impulse: Box2D weighs it against the support
  const double dw = angular * p.inverse_inertia;
  p.omega += dw;
  if (substep_motion_) p.untravelled_angle += dw * (since - p.start_time);
}

void RigidWorld::end_tick(double dt) {
  for (std::uint32_t i = 0; i < props_.size(); ++i) {
    Prop& p = props_[i];
    p.pushed = false;
    if (!p.alive || !p.is_dynamic()) continue;
    if (p.untravelled != Vec2{} || p.untravelled_angle != 0.0) {
      // Box2D's step ends at its start plus dt times the final velocity (gravity and the pushes in
      // it): started this much short, it ends where the substeps left the prop.
      const double angle = p.start_pose.angle - p.untravelled_angle;
      const Vec2 center = p.start_center - p.untravelled;
      const Vec2 origin = center - Pose::make({}, angle).rotate(p.local_center);
      bodies_[i]->SetTransform(to_b2(origin), static_cast<float>(angle));
      bodies_[i]->SetAwake(true);  // Box2D may have put a prop lying on a tire to sleep
    }
    if (p.impulse == Vec2{} && p.angular_impulse == 0.0) continue;
    p.pushed = true;
    p.velocity_before_push = from_b2(bodies_[i]->GetLinearVelocity());
    p.omega_before_push = bodies_[i]->GetAngularVelocity();
    bodies_[i]->ApplyLinearImpulseToCenter(to_b2(p.impulse), true);
    bodies_[i]->ApplyAngularImpulse(static_cast<float>(p.angular_impulse), true);
  }
  static_cast<RestitutionRule&>(*restitution_rule_).props = &props_;
  if (needs_stepping())
    world_->Step(static_cast<float>(dt), kBox2dVelocityIterations, kBox2dPositionIterations);
}

bool RigidWorld::moving(std::uint32_t i) const {
  const Prop& p = props_[i];
  if (!p.alive) return false;
  if (p.spec.type == PropType::kinematic_body) return p.velocity != Vec2{} || p.omega != 0.0;
  return p.awake;
}

Aabb RigidWorld::swept_bounds(std::uint32_t i, double dt) const {
  const Prop& p = props_[i];
  const Aabb local = p.geometry.local_bounds();
  const double reach = length(local.max - local.min) * 0.5;
  const double travel = (length(p.velocity) + std::abs(p.omega) * reach) * dt;
  return p.start_pose.to_world(local).expanded(travel);
}

void RigidWorld::gather_group(std::span<const std::uint32_t> props) {
  group_.clear();
  const auto visit = [&](std::uint32_t i) {
    if (!props_[i].alive || grouped_[i] || bodies_[i]->GetType() != b2_dynamicBody) return;
    grouped_[i] = 1;
    group_.push_back(i);
  };
  for (const std::uint32_t i : props) visit(i);
  for (std::size_t k = 0; k < group_.size(); ++k)
    for (const b2ContactEdge* e = bodies_[group_[k]]->GetContactList(); e; e = e->next) {
      if (!e->contact->IsTouching() || e->other->GetType() != b2_dynamicBody) continue;
      b2Fixture* f = e->other->GetFixtureList();
      if (f && (f->GetUserData().pointer & kPropTag))
        visit(static_cast<std::uint32_t>(f->GetUserData().pointer & ~kPropTag));
    }
  for (const std::uint32_t i : group_) grouped_[i] = 0;
}

bool RigidWorld::group_still(std::span<const std::uint32_t> props, double speed) {
  gather_group(props);
  for (const std::uint32_t i : group_) {
    const b2Body& b = *bodies_[i];
    const Aabb local = props_[i].geometry.local_bounds();
    const double reach = length(local.max - local.min) * 0.5;
    if (length(from_b2(b.GetLinearVelocity())) + std::abs(b.GetAngularVelocity()) * reach >= speed)
      return false;
  }
  return true;
}

void RigidWorld::sleep_group(std::span<const std::uint32_t> props) {
  gather_group(props);
  for (const std::uint32_t i : group_) bodies_[i]->SetAwake(false);
}

void RigidWorld::wake_group(std::span<const std::uint32_t> props) {
  gather_group(props);
  for (const std::uint32_t i : group_) bodies_[i]->SetAwake(true);
}

void RigidWorld::set_sleeping_allowed(std::uint32_t i, bool allowed) {
  b2Body* b = bodies_[i];
  if (b && b->IsSleepingAllowed() != allowed) b->SetSleepingAllowed(allowed);
}

void RigidWorld::hash_into(StateHash& h) const {
  for (std::uint32_t i = 0; i < props_.size(); ++i) {
    const Prop& p = props_[i];
    h.add(p.alive);
    if (!p.alive) continue;
    const b2Body& b = *bodies_[i];
    h.add(b.GetPosition());
    h.add(b.GetAngle());
    h.add(b.GetLinearVelocity());
    h.add(b.GetAngularVelocity());
    h.add(std::uint64_t{p.next_waypoint});
    h.add(p.direction);
    h.add(p.spec.path.running);
  }
}

}  // namespace tire
