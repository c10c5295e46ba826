#include "tire/engine.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "tire/io/level.h"
#include "tire/math/trig.h"
#include "tire/replay/replay.h"
#include "tire/session/level_session.h"
#include "tire/tire/parameters.h"
#include "tire/world/energy.h"
#include "tire/world/overlap.h"

namespace tire {

namespace {

// The level a simulation built in code restarts to: its solver settings and gravity, nothing in it.
std::shared_ptr<const Level> empty_level(const SolverConfig& config, Vec2 gravity) {
  auto level = std::make_shared<Level>();
  level->solver = config;
  level->gravity = gravity;
  return level;
}

}  // namespace

Simulation::Simulation(const SolverConfig& config, Vec2 gravity)
    : level_(empty_level(config, gravity)), session_(std::make_unique<LevelSession>(config, gravity)) {}

Simulation::Simulation(std::shared_ptr<const Level> level)
    : level_(std::move(level)), session_(make_session(*level_)) {}

Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

SimulationLoad Simulation::load(const std::filesystem::path& level_file) {
  LevelLoad load = load_level_file(level_file);
  SimulationLoad out;
  if (!load.level) {
    out.errors = std::move(load.errors);
    return out;
  }
  out.simulation = std::make_unique<Simulation>(std::make_shared<const Level>(std::move(*load.level)));
  return out;
}

TireId Simulation::add_tire(const TireSpec& spec) { return session_->world().add_tire(spec); }
std::optional<TireId> Simulation::spawn_tire(const TireSpec& spec) {
  return session_->world().spawn_tire(spec);
}
PropId Simulation::add_prop(const PropSpec& spec) { return session_->world().add_prop(spec); }
void Simulation::add_obstacle(const Obstacle& obstacle) { session_->world().add_obstacle(obstacle); }
bool Simulation::remove_tire(TireId id) { return session_->world().remove_tire(id); }

void Simulation::step(const TickInput& input) { session_->step(input); }
void Simulation::step(InputFeed& feed) { tire::step(feed, *session_, *level_); }

void Simulation::apply(const ReplayInput& input, TickInput& held) {
  apply_input(input, *session_, *level_, held);
}

std::uint64_t Simulation::tick() const { return session_->world().tick(); }
double Simulation::time() const { return session_->world().time(); }
ScriptStatus Simulation::status() const { return session_->status(); }
EndReason Simulation::end_reason() const { return session_->end_reason(); }
std::optional<std::uint64_t> Simulation::end_tick() const { return session_->end_tick(); }
std::optional<Aabb> Simulation::bounds() const { return session_->bounds(); }
int Simulation::respawns() const { return session_->respawns(); }
std::uint64_t Simulation::state_hash() const { return session_->state_hash(); }
const SolverConfig& Simulation::config() const { return session_->world().config(); }
Vec2 Simulation::gravity() const { return session_->world().gravity(); }
std::optional<TireId> Simulation::player() const { return session_->world().player_id(); }

std::vector<TireId> Simulation::tires() const {
  std::vector<TireId> ids;
  for (const Tire& t : session_->world().tires()) ids.push_back(t.id);
  return ids;
}

std::optional<TireView> Simulation::tire(TireId id) const { return session_->world().tire_view(id); }
std::size_t Simulation::tire_count() const { return session_->world().tires().size(); }
std::optional<TireView> Simulation::tire_at(std::size_t index) const {
  const World& world = session_->world();
  if (index >= world.tires().size()) return std::nullopt;
  return world.view_of(world.tires()[index]);
}
std::size_t Simulation::vehicle_count() const { return session_->world().vehicles().count(); }
std::optional<VehicleView> Simulation::vehicle_at(std::size_t index) const {
  static_assert(kMaxVehicleWheels == VehicleJoints::kMaxWheels);
  const World& world = session_->world();
  const VehicleJoints& joints = world.vehicles();
  if (index >= joints.count()) return std::nullopt;
  const auto v = static_cast<std::uint32_t>(index);
  VehicleView view;
  view.index = index;
  view.chassis = joints.chassis(v);
  view.player = world.player_vehicle() == v;
  const PropState chassis = world.rigid().prop_state(view.chassis);
  view.pose = chassis.pose;
  view.center = chassis.center;
  view.velocity = chassis.velocity;
  view.angular_velocity = chassis.angular_velocity;
  view.wheel_count = joints.wheel_count(v);
  for (std::size_t w = 0; w < view.wheel_count; ++w) {
    view.wheel_ids[w] = world.tires()[joints.wheel_tire(v, w)].id;
    view.wheel_driven[w] = joints.axle(v, w).driven;
  }
  view.motor_speed = joints.drivetrain(v).motor_speed;
  const VehicleControl& control = joints.control(v);
  view.throttle = control.throttle;
  view.lean = control.lean;
  view.brake = control.brake;
  view.head_center = session_->vehicle_head_center(v);
  if (const std::optional<VehicleHead>& head = session_->vehicle_head(v)) view.head_radius = head->radius;
  return view;
}
std::size_t Simulation::prop_count() const { return session_->world().rigid().props().size(); }
std::optional<PropView> Simulation::prop(PropId id) const { return session_->world().prop_view(id); }
std::span<const Obstacle> Simulation::obstacles() const { return session_->world().rigid().obstacles(); }

std::span<const Region> Simulation::regions() const {
  const ScriptRunner* script = session_->script();
  return script ? std::span<const Region>(script->spec().regions) : std::span<const Region>();
}
std::optional<std::size_t> Simulation::goal() const {
  const ScriptRunner* script = session_->script();
  return script ? script->spec().goal : std::nullopt;
}
std::span<const ScriptMessage> Simulation::messages() const { return session_->messages(); }
std::optional<Vec2> Simulation::checkpoint() const { return session_->checkpoint(); }
bool Simulation::next_level_requested() const { return session_->next_level_requested(); }
std::size_t Simulation::asleep_count() const { return session_->world().asleep_count(); }
std::uint64_t Simulation::solver_failures() const { return session_->world().failed_solves(); }

EnergyView Simulation::energy() const {
  const World& world = session_->world();
  const Energy e = world_energy(world);
  return {e.kinetic, e.gravitational, e.elastic, world.energy_in()};
}

TireOverlap Simulation::deepest_overlap() const { return deepest_tire_overlap(session_->world()); }

std::optional<double> Simulation::tire_strain(TireId id) const {
  for (const Tire& t : session_->world().tires()) {
    if (t.id != id) continue;
    double strain = 0.0;
    for (const DistanceConstraint& c : t.distance.constraints()) {
      const double len = length(t.particles.x[c.b] - t.particles.x[c.a]);
      strain = std::max(strain, std::abs(len / c.rest_length - 1.0));
    }
    return strain;
  }
  return std::nullopt;
}

int Simulation::tick_substeps() const { return session_->world().tick_substeps(); }

SolverReport Simulation::solver_report() const {
  const World& world = session_->world();
  SolverReport out;
  out.tick_substeps = tick_substeps();
  out.failed_solves = world.failed_solves();
  out.islands = world.island_work();
  for (const Tire& t : world.tires()) out.touching_particles += t.touching_particles();
  out.tire_pairs = world.tire_pair_count();
  for (const World::BudgetReached& b : world.budgets_reached()) {
    const char* key = tire::parameter(b.budget).key;
    out.budgets_reached.push_back({key, world.parameter(key).value_or(0.0), b.first_tick, b.dropped});
  }
  return out;
}

std::vector<std::string> Simulation::take_warnings() {
  std::vector<std::string> out;
  out.swap(session_->world().warnings());
  return out;
}

bool Simulation::apply_impulse(TireId id, Vec2 impulse) {
  return session_->world().apply_impulse_to_tire(id, impulse);
}

bool Simulation::reset_tire(TireId id) {
  if (!session_->world().find_tire(id)) return false;
  session_->world().reset_tire(id);
  return true;
}

bool Simulation::set_parameter(std::string_view key, double value) {
  return session_->world().set_parameter(key, value);
}

std::optional<double> Simulation::parameter(std::string_view key) const {
  return session_->world().parameter(key);
}

bool Simulation::grab(TireId id, std::uint32_t particle, Vec2 target) {
  return session_->world().grab_particle(id, particle, target);
}
bool Simulation::move_grab(TireId id, Vec2 target) {
  return session_->world().move_grabbed_particle(id, target);
}
bool Simulation::release(TireId id) { return session_->world().release_particle(id); }
std::optional<TireId> Simulation::grab_at(Vec2 point, double radius) { return session_->grab(point, radius); }
void Simulation::move_grab(Vec2 target) { session_->move_grab(target); }
void Simulation::release_grab() { session_->release_grab(); }

void Simulation::set_sleep(bool on) {
  session_->world().config().sleep = on;
  session_->world().wake_all();
}
void Simulation::set_rolling_hold(bool on) {
  session_->world().config().rolling_hold = on;
  session_->world().wake_all();
}
void Simulation::wake_all() { session_->world().wake_all(); }

void Simulation::set_threads(unsigned threads) { session_->world().set_threads(threads); }
unsigned Simulation::threads() const { return session_->world().threads_in_use(); }
void Simulation::set_schedule(StepSchedule schedule) { session_->world().set_schedule(schedule); }

void Simulation::debug_draw(DebugDraw& draw) const {
  session_->world().debug_draw(draw);
  // The drivers' heads: the level session keeps them, not the world. Each is drawn where its
  // chassis is drawn (DebugDraw::prop_pose), as a ring of kHeadPoints and a line to the chassis'
  // centre of mass.
  if (!(draw.flags() & DebugDraw::structure)) return;
  constexpr int kHeadPoints = 24;
  const VehicleJoints& joints = session_->world().vehicles();
  for (std::uint32_t v = 0; v < joints.count(); ++v) {
    const std::optional<VehicleHead>& head = session_->vehicle_head(v);
    if (!head) continue;
    const PropState chassis = session_->world().rigid().prop_state(joints.chassis(v));
    const Pose pose = draw.prop_pose(joints.chassis(v), chassis.pose);
    const Vec2 center = pose.to_world(head->position);
    std::array<Vec2, kHeadPoints> ring;
    for (int k = 0; k < kHeadPoints; ++k) {
      const double a = 2.0 * std::numbers::pi * k / kHeadPoints;
      const CosSin cs = cos_sin(a);
      ring[static_cast<std::size_t>(k)] = center + Vec2{cs.cos, cs.sin} * head->radius;
    }
    draw.polygon(ring, DebugShape::head);
    draw.segment(pose.to_world(chassis.pose.to_local(chassis.center)), center, DebugShape::head);
  }
}

ReplayCheck check_replay(const std::filesystem::path& replay_file) {
  ReplayCheck out;
  ReplayLoad load = load_replay_file(replay_file);
  if (!load.replay) {
    out.errors = std::move(load.errors);
    return out;
  }
  ReplayLevel level = load_replay_level(replay_file, *load.replay);
  if (!level.level) {
    out.errors = std::move(level.errors);
    return out;
  }
  out.ticks = load.replay->ticks;
  if (auto changed = level_changed(level, *load.replay)) {
    out.errors.push_back(std::move(*changed));
    return out;
  }
  ReplayOutcome run = run_replay(*load.replay, *level.level);
  out.status = run.status;
  out.errors = std::move(run.failures);
  out.passed = out.errors.empty();
  return out;
}

}  // namespace tire
