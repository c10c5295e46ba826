#include "tire/world/world.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <thread>

#include "tire/math/check.h"
#include "tire/math/reserve_doubling.h"
#include "tire/math/state_hash.h"
#include "tire/tire/parameters.h"
#include "tire/tire/soft_contact.h"
#include "tire/tire/tire_method.h"
#include "tire/tire/tire_solver.h"
#include "tire/world/energy.h"

namespace tire {

namespace {
// Colours of tire pairs that are solved in parallel; pairs beyond go to colour kColors, solved in order.
constexpr std::uint32_t kColors = 64;
}  // namespace

World::World(const SolverConfig& config, Vec2 gravity)
    : config_(config),
      tick_config_(config),
      gravity_(gravity),
      rigid_(gravity),
      threads_(std::max(1u, std::thread::hardware_concurrency())) {
  color_begin_.reserve(66);  // at most 64 colours and the overflow one, plus the end
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

double World::energy_now() const { return world_energy(*this).total(); }

bool World::apply_impulse_to_tire(TireId id, Vec2 impulse) {
  Tire* t = find_tire(id);
  if (!t) return false;
  wake_island_of(*t);
  const double before = tire_energy(*t, gravity_).total();  // only this tire's energy changes
  const Vec2 dv = impulse / t->total_mass();
  for (Vec2& v : t->particles.v) v += dv;
  energy_in_ += tire_energy(*t, gravity_).total() - before;
  return true;
}

bool World::apply_impulse_to_vehicle(std::uint32_t v, Vec2 impulse) {
  if (v >= vehicles_.count()) return false;
  const std::uint32_t c = vehicles_.chassis(v);
  const Prop& chassis = rigid_.props()[c];
  // Box2D's type and mass: the Prop's copies (is_dynamic, inverse_mass) are the last tick's, none
  // before the first (a script's start trigger).
  if (!chassis.alive || chassis.spec.type != PropType::dynamic_body) return false;
  const double chassis_mass = rigid_.prop_state(c).mass;
  if (!(chassis_mass > 0.0)) return false;
  const double before = energy_now();
  double mass = chassis_mass;
  for (std::size_t w = 0; w < vehicles_.wheel_count(v); ++w)
    mass += tires_[vehicles_.wheel_tire(v, w)].total_mass();
  const Vec2 dv = impulse / mass;
  rigid_.apply_impulse_now(c, dv * chassis_mass);
  for (std::size_t w = 0; w < vehicles_.wheel_count(v); ++w) {
    Tire& t = tires_[vehicles_.wheel_tire(v, w)];
    wake_island_of(t);
    for (Vec2& pv : t.particles.v) pv += dv;
  }
  energy_in_ += energy_now() - before;
  return true;
}

void World::set_gravity(Vec2 g) {
  const double before = energy_now();
  set_gravity_unbooked(g);
  energy_in_ += energy_now() - before;
}

void World::set_gravity_unbooked(Vec2 g) {
  gravity_ = g;
  rigid_.set_gravity(g);
  wake_all();
}

namespace {
// Sets a tire parameter on one tire; false for a parameter that only a level file sets (a tire's
// shape is fixed once it is built).
bool set_tire_parameter(Tire& t, ParamId id, double value) {
  TireSpec& s = t.spec;
  TireCompliance c = s.compliance;
  switch (id) {
    case ParamId::tire_friction: s.friction = value; return true;
    case ParamId::tire_kinetic_friction: s.kinetic_friction = value; return true;
    case ParamId::tire_pressure: s.pressure = t.area_constraint.pressure = value; return true;
    case ParamId::tire_material_damping: s.material_damping = value; return true;
    case ParamId::tire_rolling_resistance: s.rolling_resistance = value; return true;
    case ParamId::tire_drive_acceleration: s.drive_acceleration = value; return true;
    case ParamId::tire_jump_speed: s.jump_speed = value; return true;
    case ParamId::tire_max_speed: s.max_speed = value; return true;
    case ParamId::tire_restitution: s.restitution = value; return true;
    case ParamId::tire_inflate_rate: s.inflate_rate = value; return true;
    case ParamId::tire_min_pressure: s.min_pressure = value; return true;
    case ParamId::tire_max_pressure: s.max_pressure = value; return true;
    case ParamId::tire_mass: t.set_mass(value); return true;
    case ParamId::tire_mass_scale: t.set_mass(t.spawn_mass * value); return true;
    case ParamId::tire_compliance_outer: c.outer = value; break;
    case ParamId::tire_compliance_inner: c.inner = value; break;
    case ParamId::tire_compliance_spoke: c.spoke = value; break;
    case ParamId::tire_compliance_pressure: c.pressure = value; break;
    case ParamId::tire_angle:
    case ParamId::tire_angular_velocity:
    case ParamId::tire_outer_radius:
    case ParamId::tire_inner_radius:
    case ParamId::tire_segments:
    case ParamId::solver_dt:
    case ParamId::solver_substeps:
    case ParamId::solver_iterations:
    case ParamId::solver_damping:
    case ParamId::solver_tunnel_clamp:
    case ParamId::solver_ground_normal_y:
    case ParamId::solver_jump_grace:
    case ParamId::solver_divergence_area:
    case ParamId::solver_divergence_speed:
    case ParamId::solver_restitution_threshold:
    case ParamId::solver_tire_neighbours:
    case ParamId::solver_island_tires:
    case ParamId::gravity_x:
    case ParamId::gravity_y:
    case ParamId::budget_tires:
    case ParamId::budget_particles:
    case ParamId::budget_props:
    case ParamId::budget_spawns_per_tick:
    case ParamId::budget_messages:
    case ParamId::budget_message_bytes:
    case ParamId::budget_firings_per_tick: return false;
  }
  t.set_compliance(c);
  return true;
}

std::optional<double> tire_parameter(const Tire& t, ParamId id) {
  const TireSpec& s = t.spec;
  switch (id) {
    case ParamId::tire_angle: return s.angle;
    case ParamId::tire_angular_velocity: return s.angular_velocity;
    case ParamId::tire_outer_radius: return s.outer_radius;
    case ParamId::tire_inner_radius: return s.inner_radius;
    case ParamId::tire_segments: return s.segments;
    case ParamId::tire_mass: return s.mass;
    case ParamId::tire_mass_scale: return s.mass / t.spawn_mass;
    case ParamId::tire_friction: return s.friction;
    case ParamId::tire_kinetic_friction: return s.kinetic_friction;
    case ParamId::tire_pressure: return s.pressure;
    case ParamId::tire_compliance_outer: return s.compliance.outer;
    case ParamId::tire_compliance_inner: return s.compliance.inner;
    case ParamId::tire_compliance_spoke: return s.compliance.spoke;
    case ParamId::tire_compliance_pressure: return s.compliance.pressure;
    case ParamId::tire_material_damping: return s.material_damping;
    case ParamId::tire_rolling_resistance: return s.rolling_resistance;
    case ParamId::tire_drive_acceleration: return s.drive_acceleration;
    case ParamId::tire_jump_speed: return s.jump_speed;
    case ParamId::tire_max_speed: return s.max_speed;
    case ParamId::tire_restitution: return s.restitution;
    case ParamId::tire_inflate_rate: return s.inflate_rate;
    case ParamId::tire_min_pressure: return s.min_pressure;
    case ParamId::tire_max_pressure: return s.max_pressure;
    default: return std::nullopt;
  }
}
}  // namespace

bool World::set_parameter(std::string_view key, double value) {
  const double before = energy_now();
  const bool set = set_parameter_unbooked(key, value);
  energy_in_ += energy_now() - before;  // a pressure or compliance changes the energy the tires hold
  return set;
}

bool World::set_parameter_unbooked(std::string_view key, double value) {
  const Parameter* p = find_parameter(key);
  if (!p || !p->runtime() || !p->accepts(value)) return false;
  wake_all();  // live tuning: no island can tell whether it still rests under the new value
  switch (p->id) {
    case ParamId::solver_substeps: config_.substeps = static_cast<int>(value); return true;
    case ParamId::solver_iterations: config_.iterations = static_cast<int>(value); return true;
    case ParamId::solver_damping: config_.damping = value; return true;
    case ParamId::gravity_x: set_gravity_unbooked({value, gravity_.y}); return true;
    case ParamId::gravity_y: set_gravity_unbooked({gravity_.x, value}); return true;
    default: break;
  }
  if (!p->is_tire()) return false;
  if (key.starts_with("player.")) {
    const Tire* player_tire = player();
    return player_tire && set_tire_parameter(*find_tire(player_tire->id), p->id, value);
  }
  bool known = true;
  for (Tire& t : tires_) known = set_tire_parameter(t, p->id, value) && known;
  if (known) remember_tire_setting(p->id, value);
  return known;
}

void World::remember_tire_setting(ParamId id, double value) {
  const auto end = tire_settings_.begin() + static_cast<std::ptrdiff_t>(tire_setting_count_);
  const auto it =
      std::find_if(tire_settings_.begin(), end, [id](const TireSetting& s) { return s.id == id; });
  if (it != end) {
    std::move(it + 1, end, it);  // keeps the order in which the others were last set
    --tire_setting_count_;
  }
  tire_settings_[tire_setting_count_++] = {id, value};
}

std::optional<double> World::parameter(std::string_view key) const {
  const Parameter* p = find_parameter(key);
  if (!p) return std::nullopt;
  switch (p->id) {
    case ParamId::solver_dt: return config_.dt;
    case ParamId::solver_substeps: return config_.substeps;
    case ParamId::solver_iterations: return config_.iterations;
    case ParamId::solver_damping: return config_.damping;
    case ParamId::solver_tunnel_clamp: return config_.tunnel_clamp;
    case ParamId::solver_ground_normal_y: return config_.ground_normal_y;
    case ParamId::solver_jump_grace: return config_.jump_grace;
    case ParamId::solver_divergence_area: return config_.divergence_area;
    case ParamId::solver_divergence_speed: return config_.divergence_speed;
    case ParamId::solver_restitution_threshold: return config_.restitution_threshold;
    case ParamId::solver_tire_neighbours: return config_.tire_neighbours;
    case ParamId::solver_island_tires: return config_.island_tires;
    case ParamId::gravity_x: return gravity_.x;
    case ParamId::gravity_y: return gravity_.y;
    case ParamId::budget_tires: return budgets_.tires;
    case ParamId::budget_particles: return budgets_.particles;
    case ParamId::budget_props: return budgets_.props;
    case ParamId::budget_spawns_per_tick: return budgets_.spawns_per_tick;
    case ParamId::budget_messages: return budgets_.messages;
    case ParamId::budget_message_bytes: return budgets_.message_bytes;
    case ParamId::budget_firings_per_tick: return budgets_.firings_per_tick;
    default: break;
  }
  const Tire* t = player();
  if (!t && !key.starts_with("player.") && !tires_.empty()) t = &tires_.front();
  return t ? tire_parameter(*t, p->id) : std::nullopt;
}

void World::reset_tire(TireId id, std::optional<Vec2> position) {
  Tire* t = find_tire(id);
  if (!t) return;
  if (position) t->spec.position = *position;
  wake_island_of(*t);
  const double before = tire_energy(*t, gravity_).total();
  t->reset();
  energy_in_ += tire_energy(*t, gravity_).total() - before;
}

bool World::grab_particle(TireId id, std::uint32_t particle, Vec2 target) {
  Tire* t = find_tire(id);
  if (!t || particle >= t->n) return false;
  wake_island_of(*t);
  t->grabbed = true;
  t->grab_particle = particle;
  t->grab_target = target;
  return true;
}

bool World::move_grabbed_particle(TireId id, Vec2 target) {
  Tire* t = find_tire(id);
  if (!t || !t->grabbed) return false;
  t->grab_target = target;
  return true;
}

bool World::release_particle(TireId id) {
  Tire* t = find_tire(id);
  if (!t || !t->grabbed) return false;
  t->grabbed = false;
  return true;
}

TireId World::add_tire(const TireSpec& spec) {
  const TireId id = next_id_++;
  tires_.emplace_back(id, spec, topologies_.of(TireShape::of(spec)));
  for (std::size_t i = 0; i < tire_setting_count_; ++i)
    set_tire_parameter(tires_.back(), tire_settings_[i].id, tire_settings_[i].value);
  if (spec.player || (!player_ && !player_vehicle_)) player_ = id;
  // Room for the contacts between tires, so that stepping never allocates: a tire in a pile
  // touches at most six others, and a pair is counted once.
  const std::size_t pairs = 4 * tires_.size();
  reserve_doubling(tire_pairs_, pairs);
  reserve_doubling(colored_pairs_, pairs);
  reserve_doubling(pair_color_, pairs);
  reserve_doubling(tire_colors_, tires_.size());
  sleep_.reserve(tires_.capacity(), rigid_.props().size());
  reserve_global_solvers();
  energy_in_ += tire_energy(tires_.back(), gravity_).total();
  return id;
}

void World::budget_reached(ParamId budget) {
  for (BudgetReached& r : budgets_reached_)
    if (r.budget == budget) {
      ++r.dropped;
      return;
    }
  budgets_reached_.push_back({budget, tick_, 1});
  const char* key = tire::parameter(budget).key;
  warnings_.push_back(std::string(key) + " (" + std::to_string(static_cast<long long>(*parameter(key))) +
                      ") reached at tick " + std::to_string(tick_) + ": what would pass it is dropped");
}

// A spawn this tick: false, and the budget reported, when the tick has had its spawns.
bool World::take_spawn() {
  if (spawn_tick_ != tick_) spawn_tick_ = tick_, spawns_this_tick_ = 0;
  if (spawns_this_tick_ >= budgets_.spawns_per_tick) {
    budget_reached(ParamId::budget_spawns_per_tick);
    return false;
  }
  ++spawns_this_tick_;
  return true;
}

std::optional<TireId> World::spawn_tire(const TireSpec& spec) {
  std::size_t particles = 0;
  for (const Tire& t : tires_) particles += t.particles.size();
  if (tires_.size() >= static_cast<std::size_t>(budgets_.tires)) {
    budget_reached(ParamId::budget_tires);
    return std::nullopt;
  }
  if (particles + 2 * static_cast<std::size_t>(spec.segments) >
      static_cast<std::size_t>(budgets_.particles)) {
    budget_reached(ParamId::budget_particles);
    return std::nullopt;
  }
  if (!take_spawn()) return std::nullopt;
  return add_tire(spec);
}

std::optional<std::uint32_t> World::spawn_prop(const PropSpec& spec) {
  if (rigid_.props().size() >= static_cast<std::size_t>(budgets_.props)) {
    budget_reached(ParamId::budget_props);
    return std::nullopt;
  }
  if (!take_spawn()) return std::nullopt;
  return add_prop(spec);
}

std::uint32_t World::add_prop(const PropSpec& spec) {
  const double before = energy_now();
  const std::uint32_t i = rigid_.add_prop(spec);
  energy_in_ += energy_now() - before;
  sleep_.reserve(tires_.capacity(), rigid_.props().size());
  return i;
}

std::optional<std::uint32_t> World::add_vehicle(const VehicleSpec& spec) {
  if (config_.method != SolverMethod::global || spec.wheels.empty() ||
      spec.wheels.size() > VehicleJoints::kMaxWheels)
    return std::nullopt;
  PropSpec chassis_spec = spec.chassis;
  chassis_spec.type = PropType::dynamic_body;
  const std::uint32_t chassis = add_prop(chassis_spec);
  const Pose pose = Pose::make(chassis_spec.position, chassis_spec.angle);
  const std::optional<TireId> player = player_;
  std::vector<std::uint32_t> wheels;
  std::vector<AxleSpec> axles;
  std::uint32_t segments = 0;
  const std::size_t first_slot = vehicles_.solver_count();
  for (const WheelSpec& w : spec.wheels) {
    TireSpec tire = w.tire;
    tire.player = false;
    tire.position = pose.to_world(w.axle.point);
    tire.velocity =
        chassis_spec.velocity + perp(tire.position - chassis_spec.position) * chassis_spec.angular_velocity;
    add_tire(tire);
    Tire& t = tires_.back();
    t.wheel = static_cast<std::int32_t>(first_slot + wheels.size());
    t.chassis = static_cast<std::int32_t>(chassis);
    wheels.push_back(static_cast<std::uint32_t>(tires_.size() - 1));
    axles.push_back(w.axle);
    segments = std::max(segments, t.n);
  }
  player_ = player;  // a wheel is not the player
  if (!player_ && !player_vehicle_ && !tires_.empty()) {
    const auto free = std::find_if(tires_.begin(), tires_.end(), [](const Tire& t) { return t.wheel < 0; });
    if (free != tires_.end()) player_ = free->id;
  }
  return vehicles_.add(chassis, wheels, axles, spec.drivetrain, segments);
}

bool World::set_vehicle_control(std::uint32_t v, const VehicleControl& control) {
  if (v >= vehicles_.count()) return false;
  vehicles_.set_control(v, control);
  return true;
}

bool World::set_player_vehicle(std::uint32_t v) {
  if (v >= vehicles_.count()) return false;
  player_vehicle_ = v;
  player_.reset();  // the player is the vehicle, not a tire
  return true;
}

bool World::reset_vehicle(std::uint32_t v, std::optional<Vec2> position) {
  if (v >= vehicles_.count()) return false;
  const double before = energy_now();
  const std::uint32_t chassis = vehicles_.chassis(v);
  const Vec2 at = position.value_or(rigid_.props()[chassis].spec.position);
  rigid_.place_prop(chassis, at, 0.0);
  vehicles_.clear(v);
  const Pose pose = Pose::make(at, 0.0);
  for (std::size_t w = 0; w < vehicles_.wheel_count(v); ++w) {
    Tire& t = tires_[vehicles_.wheel_tire(v, w)];
    wake_island_of(t);
    t.spec.position = pose.to_world(vehicles_.axle(v, w).point);
    t.spec.velocity = {};
    t.spec.angular_velocity = 0.0;
    t.reset();
  }
  energy_in_ += energy_now() - before;
  return true;
}

bool World::remove_tire(TireId id) {
  const auto it = std::find_if(tires_.begin(), tires_.end(), [id](const Tire& t) { return t.id == id; });
  if (it == tires_.end() || it->wheel >= 0) return false;  // a wheel stays on its vehicle
  vehicles_.tire_removed(static_cast<std::uint32_t>(it - tires_.begin()));
  wake_all();  // what rested on it falls; indices shift
  energy_in_ -= tire_energy(*it, gravity_).total();
  tires_.erase(it);
  sleep_.mark_stale();
  if (player_ == id) player_.reset();
  return true;
}

Tire* World::find_tire(TireId id) {
  for (Tire& t : tires_)
    if (t.id == id) return &t;
  return nullptr;
}

const Tire* World::player() const {
  for (const Tire& t : tires_)
    if (player_ && t.id == *player_) return &t;
  return nullptr;
}

std::optional<TireView> World::tire_view(TireId id) const {
  for (const Tire& t : tires_)
    if (t.id == id) return view_of(t);
  return std::nullopt;
}

TireView World::view_of(const Tire& t) const {
  const RigidMotion m = t.rigid_motion();
  TireView v;
  v.id = t.id;
  v.player = player_ && *player_ == t.id;
  v.asleep = t.asleep;
  v.grounded = t.grounded();
  v.may_jump = t.touched_ground_within(config_.jump_grace);
  v.centroid = m.centroid;
  v.velocity = m.velocity;
  v.spin = m.omega;
  v.area_ratio = t.area_ratio();
  v.pressure = t.spec.pressure;
  v.outer_radius = t.spec.outer_radius;
  v.inner_radius = t.spec.inner_radius;
  v.mass = t.total_mass();
  v.segments = t.n;
  v.positions = t.particles.x;
  v.contacts = t.tick_contacts;
  if (t.grabbed) v.grab = TireGrab{t.grab_particle, t.grab_target};
  return v;
}

std::optional<PropView> World::prop_view(PropId id) const {
  const auto& props = rigid_.props();
  if (id >= props.size()) return std::nullopt;
  const Prop& p = props[id];
  PropView v;
  v.id = id;
  v.type = p.spec.type;
  v.shape = p.spec.shape;
  v.alive = p.alive;
  v.name = p.spec.name;
  if (p.alive) v.state = rigid_.prop_state(id);
  const PropGeometry& g = p.geometry;
  v.vertices = g.vertices;
  v.normals = g.normals;
  v.radius = g.radius;
  v.thickness = g.thickness;
  v.loop = g.loop;
  v.local_bounds = g.local_bounds();
  v.path = p.spec.path.waypoints;
  return v;
}

// One tick, as Macklin et al. 2019, "Small Steps in Physics Simulation", Algorithm 1 writes it:
// collision detection once per tick, then n substeps of h = Δt/n, each of which predicts the
// positions, solves them and updates the velocities from them. Each tire's share of a phase is in
// tire/tire_solver.cpp (begin_substep, solve_iteration, end_substep, one tire each); the world adds
// the props around the substeps and the contacts between tires within them.
void World::step(const TickInput& input) {
  TIRE_ASSERT(config_.substeps >= 1 && config_.iterations >= 1, "fewer than one substep or iteration a tick");
  TIRE_ASSERT(config_.dt > 0.0 && std::isfinite(config_.dt), "the tick is not a positive length of time");
  std::optional<std::uint32_t> held;  // the player while a key is held: its island stays awake
  if (player_vehicle_) {
    VehicleControl c;
    c.throttle = std::clamp(input.steer, -1.0, 1.0);
    c.lean = std::clamp(input.lean, -1.0, 1.0);
    c.brake = input.brake;
    vehicles_.set_control(*player_vehicle_, c);
  } else if (player_) {
    if (Tire* p = find_tire(*player_)) {
      p->control.steer = input.steer;
      p->control.jump = input.jump;
      p->control.inflate = input.inflate;
      if (input.steer != 0.0 || input.jump || input.inflate != 0.0) {
        held = index_of(*p);
        sleep_.wake(tires_, *held, rigid_);
      }
    }
  }

  // Once per tick, before the substeps (the paper detects collisions once per frame, not per
  // substep): Box2D's props read and kinematic ones steered; the sleeping islands that something
  // moving may reach woken; each awake tire's broad phase against obstacles and props, and its
  // jump; the broad phase between tires (a lone tire skips it), its pairs coloured for the
  // parallel solve.
  // The method (tire_method.h) says whether Box2D steps with the substeps (rigid_world.h: each of
  // its steps is then h) and whether the tick takes the refinement's substeps
  // (SolverConfig::refine_turn).
  // A vehicle sleeps as one island, its chassis and its wheels (SleepIslands::settle joins them), and
  // wakes whole: while its motor or lean is at work (a brake alone lets it rest: it holds), when its
  // control changes (a brake let go), and when its chassis moves (Box2D woke it: a blow, a respawn).
  for (std::uint32_t v = 0; v < vehicles_.count(); ++v) {
    const VehicleControl& c = vehicles_.control(v);
    const bool driven = c.throttle != 0.0 || c.lean != 0.0;
    const bool changed = vehicles_.take_control_change(v);
    const bool wake = driven || changed || rigid_.prop_state(vehicles_.chassis(v)).awake;  // Box2D's, now
    for (std::size_t w = 0; w < vehicles_.wheel_count(v); ++w) {
      Tire& t = tires_[vehicles_.wheel_tire(v, w)];
      t.driven = driven;
      if (wake && t.asleep) wake_island_of(t);
    }
  }
  const TireMethod& method = tire_method(config_.method);
  if (!method.refines_substeps()) refine_ = 1;
  tick_config_ = config_;
  tick_config_.substeps = config_.substeps * refine_;
  const double h = config_.dt / tick_config_.substeps;
  const bool substep_motion = method.steps_props_with_substeps();
  const bool rigid_substeps = substep_motion && !rigid_.props().empty();
  rigid_.begin_tick(rigid_substeps ? h : config_.dt, substep_motion);
  if (!config_.sleep && sleep_.asleep_count() > 0) wake_all();  // sleeping was turned off
  wake_for_props();
  if (sleep_.stale()) sleep_.refresh(tires_);
  sweep_tires([&](Tire& t) { begin_tick(t, tick_config_, rigid_); });
  sleep_.clear_woken();
  find_tire_pairs();
  color_pairs();
  // A method that couples tires in its solves takes each tire's neighbours (tire_neighbours.h)
  // instead of solving the pairs after each iteration.
  const bool neighbours = method.couples_tires_in_solve() && !tire_pairs_.empty();
  if (neighbours) {
    neighbours_.set_pairs(tires_.size(), sleep_.awake(), tire_pairs_);
    island_.set_islands(tires_, sleep_.awake(), tire_pairs_,
                        static_cast<std::size_t>(std::max(0, config_.island_tires)), rigid_);
  }

  SubstepContext ctx{h,        0.0,
                     gravity_, &tick_config_,
                     &rigid_,  !tire_pairs_.empty(),
                     &global_, neighbours ? &neighbours_ : nullptr};
  if (vehicles_.count() > 0) ctx.vehicles = &vehicles_;
  // (The fused schedule runs a substep's prediction and first iteration in one sweep; with the
  // contacts between tires in the tires' solves, the tires take their turns by colour, each after
  // every prediction, and with Box2D stepping between substeps: the plain loop.)
  if (schedule_ == StepSchedule::fused && !neighbours && !rigid_substeps) {
    fused_substeps(ctx);  // the loop below in fewer sweeps over the tires, to the same bits: see there
  } else {
    for (int s = 0; s < tick_config_.substeps; ++s) {
      ctx.time = s * h;
      if (rigid_substeps && s > 0) {  // Box2D steps the last substep's pushes, then is read again
        rigid_.end_tick(h);
        rigid_.begin_tick(h, substep_motion, ctx.time);
      }
      // Predict: v ← v + h f_ext/m;  x_prev ← x;  x ← x + h v.
      predict(ctx);
      // Solve positions: constraints and contacts (the paper takes one iteration a substep).
      for (int it = 0; it < config_.iterations; ++it) solve_positions(ctx, it);
      // Update velocities: v ← (x − x_prev)/h; then the velocity-level pass (friction, damping).
      update_velocities(ctx);
    }
  }

  // After the substeps: the impulses the tires gave props go to Box2D, which steps them (the last
  // substep, when it steps with the substeps); a tire that diverged is reset.
  rigid_.end_tick(rigid_substeps ? h : config_.dt);
  energy_in_ += vehicles_.take_work();
  for (const std::uint32_t i : sleep_.awake()) {
    note_failed_solves(tires_[i]);
    guard_divergence(tires_[i]);
    energy_in_ += tires_[i].control_work;
    tires_[i].control_work = 0.0;
  }
  if (method.refines_substeps()) update_refinement();
  if (config_.sleep) sleep_.settle(tires_, tire_pairs_, rigid_, tick_config_, held);
  if (sleep_.stale()) sleep_.refresh(tires_);
  sleep_.hold_props_near_awake_tires(tires_, rigid_);
  ++tick_;
}

// Doubles the substeps while a solve turns a constraint too far for its linearisation, halves them
// back once none turns far (SolverConfig::refine_turn); the decision is the tick's, for every tire,
// as Box2D and the contacts between tires step with the substeps.
void World::update_refinement() {
  // Two look-aheads ask for substeps, each as a demand (1/s): a substep of h is short enough while
  // demand · h ≤ 1.
  // - Rolling: a tire on the ground turns by |ω| h a substep, to be kept within refine_roll of a
  //   segment's angle 2π/N (SolverConfig::refine_roll); and so does a tire in the air within reach
  //   of an obstacle or a prop this tick (its broad phase found one), before it lands on it
  //   spinning: at one substep, a tire landing at 12.5 rad/s turned its ring by 0.13 rad in the
  //   landing tick's one linear step, its landing particles stuck, and held 990 J in its springs
  //   for that tick.
  // - A blow between two tires of an island: its turn vh/R kept within refine_turn (below).
  double turn = 0.0;
  double demand = 0.0;
  const bool roll = config_.refine_roll > 0.0;
  for (const std::uint32_t i : sleep_.awake()) {
    const Tire& t = tires_[i];
    turn = std::max(turn, t.newton_turn);
    const bool near = !t.candidates.empty() || !t.prop_candidates.empty();
    if (roll && (t.touched_ground_within(config_.jump_grace) || near)) {
      const double segment = 2.0 * std::numbers::pi / static_cast<double>(t.n);
      demand = std::max(demand, std::abs(t.angular_velocity()) / (config_.refine_roll * segment));
    }
  }
  if (turn > config_.refine_turn)
    refine_ *= 2;
  else if (turn < config_.settle_turn)
    refine_ = std::max(1, refine_ / 2);
  // An island's contacts move its tires by one linear step a substep (island_contacts.h), which
  // holds while it turns them a little; a blow that stops a tire closing at v turns it by about
  // vh/R in one substep, read by the step as a move along its tangents, off its ring. So the tick
  // after one in which two tires of an island close fast takes the substeps that keep that turn
  // within refine_turn, before the blow rather than after it: a blow at 10 m/s at one substep,
  // refined only afterwards, left the striking tire's ring 2.8 % over its area and the pair's energy
  // up 4.7 times (at 6–12 m/s, up to 12 times).
  for (const TirePair& p : tire_pairs_) {
    if (!island_.solves(p.a) || !island_.solves(p.b)) continue;
    const Tire& a = tires_[p.a];
    const Tire& b = tires_[p.b];
    const Vec2 d = b.centroid() - a.centroid();
    const double distance = length(d);
    if (!(distance > 0.0)) continue;
    const double closing = dot(a.velocity() - b.velocity(), d) / distance;
    demand = std::max(demand,
                      closing / (std::min(a.spec.outer_radius, b.spec.outer_radius) * config_.refine_turn));
  }
  // - A vehicle's motor or brake at work: its row turns the wheel against the chassis by one
  //   linear step a substep (vehicle_joints.h), which holds while that turn is within refine_turn.
  //   Unrefined, a car whose wheels spun at 40 rad/s in the air, its motor on, stepped down to one
  //   substep and left 4.2 kJ in its wheels' rings for a tick.
  for (std::uint32_t v = 0; v < vehicles_.count(); ++v) {
    const VehicleControl& c = vehicles_.control(v);
    if (c.throttle == 0.0 && !c.brake) continue;
    const Prop& chassis = rigid_.props()[vehicles_.chassis(v)];
    for (std::size_t w = 0; w < vehicles_.wheel_count(v); ++w) {
      const Tire& t = tires_[vehicles_.wheel_tire(v, w)];
      if (!t.asleep)
        demand = std::max(demand, std::abs(t.angular_velocity() - chassis.omega) / config_.refine_turn);
    }
  }
  const int most = std::max(1, config_.max_refine);
  while (refine_ < most && demand * config_.dt / (config_.substeps * refine_) > 1.0) refine_ *= 2;
  refine_ = std::min(refine_, most);
}

void World::find_tire_pairs() {
  tire_pairs_.clear();
  if (tires_.size() < 2) return;  // a lone tire has no pairs
  // Two wheels of one vehicle hang apart on its axles: never a pair (their broad phase may overlap).
  const auto same_vehicle = [&](const TirePair& p) {
    return tires_[p.a].chassis >= 0 && tires_[p.a].chassis == tires_[p.b].chassis;
  };
  for (;;) {
    pair_finder_.find(tires_, sleep_.awake(), config_.dt, length(gravity_),
                      static_cast<std::uint32_t>(std::max(1, config_.tire_neighbours)), tire_pairs_);
    if (vehicles_.count() > 0) std::erase_if(tire_pairs_, same_vehicle);
    if (sleep_.asleep_count() == 0) return;
    // An awake tire that may reach a sleeping one this tick wakes its island, whose tires then
    // begin their tick and join the broad phase (and may reach another island: again).
    for (const std::uint32_t i : sleep_.awake())
      sleep_.overlapping(pair_finder_.bounds(i), [&](std::uint32_t j) { sleep_.wake(tires_, j, rigid_); });
    if (sleep_.woken().empty()) return;
    for (const std::uint32_t j : sleep_.woken()) begin_tick(tires_[j], tick_config_, rigid_);
    sleep_.clear_woken();
    sleep_.refresh(tires_);
  }
}

void World::wake_for_props() {
  if (sleep_.asleep_count() == 0) {
    seen_removals_ = rigid_.removals();
    return;
  }
  const auto& props = rigid_.props();
  for (std::uint32_t p = 0; p < props.size(); ++p)
    if (rigid_.moving(p))
      sleep_.overlapping(rigid_.swept_bounds(p, config_.dt).expanded(kTirePairSkin),
                         [&](std::uint32_t j) { sleep_.wake(tires_, j, rigid_); });
  if (rigid_.removals() != seen_removals_) {
    seen_removals_ = rigid_.removals();
    for (std::uint32_t i = 0; i < tires_.size(); ++i) {
      if (!tires_[i].asleep) continue;
      for (const std::uint32_t p : tires_[i].prop_candidates)
        if (!props[p].alive) {
          sleep_.wake(tires_, i, rigid_);
          break;
        }
    }
  }
}

// Predict (begin_substep): v ← v + h f_ext/m (gravity, and steering's torque about the hub), the
// anti-tunneling clamp, x_prev ← x, x ← x + h v; then the narrow phase along each particle's path
// and every λ ← 0.
void World::predict(const SubstepContext& ctx) {
  // The vehicles first, on the velocities the last substep left (their gravity follows, as the tires').
  if (ctx.vehicles) vehicles_.begin_substep(tires_, rigid_, ctx);
  rigid_.begin_substep(ctx.time, ctx.h);
  sweep_tires([&](Tire& t) { begin_substep(t, ctx); });
}

// One iteration of the position solve: each tire's constraints and its contacts with obstacles and
// props (solve_iteration); the impulses those contacts owe dynamic props handed over, so that a
// pushed crate gives way in the next; then the contacts between tires.
void World::solve_positions(const SubstepContext& ctx, int iteration) {
  const bool last = iteration + 1 == config_.iterations;
  if (ctx.vehicles) vehicles_.load_wheels(tires_, ctx);  // each wheel loaded with its joints' forces
  if (ctx.neighbours) {
    if (island_.any()) solve_islands(ctx, last);
    solve_by_tire_colour(ctx, last);
    if (ctx.vehicles) vehicles_.solve(tires_, rigid_, ctx, last);
    hand_over_impulses();
    return;
  }
  sweep_tires([&](Tire& t) { solve_iteration(t, ctx, last); });
  if (ctx.vehicles) vehicles_.solve(tires_, rigid_, ctx, last);
  hand_over_impulses();
  solve_tire_pairs();
}

// The islands of tires in contact that are solved as one problem (island_contacts.h), a group at a
// time: the group's contacts found where its tires are predicted, each tire solved alone (in
// parallel) by the solver that keeps its system, then the contacts between them together (its
// per-tire parts in parallel too).
void World::solve_islands(const SubstepContext& ctx, bool last) {
  SubstepContext alone = ctx;
  alone.neighbours = nullptr;
  alone.island = &island_;
  for (std::size_t g = 0; g < island_.groups(); ++g) {
    island_.find(tires_, g, ctx.h);
    const std::span<const std::uint32_t> tires = island_.group_tires(g);
    if (!island_.solves(tires.front())) continue;  // its contacts did not fit: block Gauss–Seidel
    for_tires(tires.size(), [&](std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k) solve_iteration(tires_[tires[k]], alone, last);
    });
    island_.solve(tires_, g, ctx, parallel_pool());
  }
}

// A method that couples tires in its solves, with tires in contact: block Gauss–Seidel between
// tires (tire_neighbours.h), for the tires no island solve takes.
// A colour at a time, its tires solved in parallel against their neighbours' treads as the colours
// before left them; then the pushes they owe the neighbours, in tire order.
//
// Only summing the pushes is serial (in tire order); capturing the treads and handing the pushes out
// run on the threads, tire by tire (TireNeighbours::capture_tire, apply_reaction).
void World::solve_by_tire_colour(const SubstepContext& ctx, bool last) {
  neighbours_.begin_capture(tires_, ctx.h);
  const std::span<const std::uint32_t> members = neighbours_.members();
  for_tires(members.size(), [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k)
      if (!island_.solves(members[k])) neighbours_.capture_tire(tires_[members[k]], members[k]);
  });
  for (std::size_t c = 0; c < neighbours_.colours(); ++c) {
    const std::span<const std::uint32_t> tires = neighbours_.tires_of_colour(c);
    const bool more = c + 1 < neighbours_.colours();  // a later colour reads the treads
    for_tires(tires.size(), [&](std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k) {
        if (island_.solves(tires[k])) continue;
        solve_iteration(tires_[tires[k]], ctx, last);
        if (more) neighbours_.capture_tire(tires_[tires[k]], tires[k]);
      }
    });
    const std::span<const std::uint32_t> owed = neighbours_.gather_reactions(tires_);
    for_tires(owed.size(), [&](std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k) {
        const std::uint32_t i = owed[k];
        if (neighbours_.apply_reaction(tires_[i], i, config_.tunnel_clamp, ctx.h, c) && more)
          neighbours_.capture_tire(tires_[i], i);
      }
    });
  }
}

// Update velocities (end_substep): v ← (x − x_prev)/h, then the velocity-level pass: kinetic
// friction, material and deviation damping, rolling resistance, the speed cap. Friction's impulses
// on dynamic props are handed over.
void World::update_velocities(const SubstepContext& ctx) {
  sweep_tires([&](Tire& t) { end_substep(t, ctx); });
  hand_over_impulses();
  // Kinetic friction's reactions between tires, for their next prediction (every tire is solved).
  if (ctx.neighbours) neighbours_.apply_reactions(tires_, config_.tunnel_clamp, ctx.h, neighbours_.colours());
}

// The fused schedule (StepSchedule::fused): step()'s substeps with the tire phases that follow each
// other run in one sweep over the tires, so that a big scene, memory-bound, reads each tire's data
// once per substep instead of three times. It gives the plain schedule's bits because:
// - a sweep runs each tire's phases in the plain order on the same data, and a tire phase touches
//   only its own tire (props are read only; the impulses owed to them wait in the tire), so whether
//   other tires' phases run in between makes no difference;
// - nothing else happens between two phases fused on a tire. Between a prediction and its first
//   iteration, the plain schedule does nothing either. Between a velocity pass and the next
//   prediction it hands friction's impulses to the props, and a prop free to move feels them at
//   once (its velocity changes, and with it the predicted pose the next narrow phase reads): so
//   that pair is fused only when no prop takes impulses (no live dynamic prop: no contact owes one,
//   and the hand-over is empty). Otherwise the velocity pass keeps its own sweep, and its hand-over
//   its place. (tests/test_step_schedule.cpp has the case that tells: a crate lying on a tire.)
void World::fused_substeps(SubstepContext ctx) {
  const bool carry_velocity_pass = !rigid_.takes_impulses();
  SubstepContext previous = ctx;
  for (int s = 0; s < tick_config_.substeps; ++s) {
    ctx.time = s * ctx.h;
    const bool velocity_pass_here = s > 0 && carry_velocity_pass;
    if (s > 0 && !carry_velocity_pass) update_velocities(previous);
    rigid_.begin_substep(ctx.time, ctx.h);
    sweep_tires([&](Tire& t) {
      if (velocity_pass_here) end_substep(t, previous);  // the previous substep's update velocities
      begin_substep(t, ctx);                             // predict
      solve_iteration(t, ctx, config_.iterations == 1);  // solve positions, first iteration
    });
    hand_over_impulses();
    solve_tire_pairs();
    for (int it = 1; it < config_.iterations; ++it) solve_positions(ctx, it);
    previous = ctx;
  }
  update_velocities(previous);  // the last substep's
}

void World::hand_over_impulses() {
  for (const std::uint32_t i : sleep_.awake()) apply_prop_impulses(tires_[i], rigid_);
}

// The contacts between tires, a colour at a time; a colour's pairs share no tire, so they are solved
// in parallel. The colours go in the same order whatever the thread count.
void World::solve_tire_pairs() {
  for (std::size_t c = 0; c + 1 < color_begin_.size(); ++c) {
    const TirePair* first = colored_pairs_.data() + color_begin_[c];
    auto solve = [&](std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k)
        solve_tire_contact(tires_[first[k].a], tires_[first[k].b], config_.ground_normal_y);
    };
    const std::size_t count = color_begin_[c + 1] - color_begin_[c];
    if (c < kColors)
      for_tires(count, solve);
    else
      solve(0, count);  // the overflow colour: its pairs may share a tire
  }
}

namespace {
// Below this many tires a tick is too short to be worth waking threads for; below this many items
// (tires, or tire pairs of one colour) neither is a phase.
constexpr std::size_t kParallelMinTires = 32;
constexpr std::size_t kParallelMinItems = 4;
}  // namespace

unsigned World::threads_in_use() const { return tires_.size() >= kParallelMinTires ? threads_ : 1u; }

void World::set_threads(unsigned threads) {
  threads_ = std::max(1u, threads);
  pool_.reset();
  reserve_global_solvers();
}

void World::reserve_global_solvers() {
  if (!tire_method(config_.method).needs_solver_pool() || tires_.empty()) return;
  std::uint32_t segments = 0;
  for (const Tire& t : tires_) segments = std::max(segments, t.n);
  global_.reserve(threads_, segments);
  neighbours_.reserve(tires_, 4 * tires_.size());
  island_.reserve(static_cast<std::size_t>(std::max(0, config_.island_tires)), segments, tires_.size());
}

template <typename F>
void World::sweep_tires(F&& fn) {
  const std::span<const std::uint32_t> awake = sleep_.awake();
  for_tires(awake.size(), [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k) {
      if (k + 1 < e) tires_[awake[k + 1]].prefetch();  // memory-bound in big scenes: load the next one early
      fn(tires_[awake[k]]);
    }
  });
}

WorkerPool* World::parallel_pool() {
  if (threads_ <= 1 || tires_.size() < kParallelMinTires) return nullptr;
  if (!pool_) pool_ = std::make_unique<WorkerPool>(threads_);
  return pool_.get();
}

template <typename F>
void World::for_tires(std::size_t n, F&& fn) {
  WorkerPool* pool = n >= kParallelMinItems ? parallel_pool() : nullptr;
  if (pool != nullptr)
    pool->parallel_for(n, fn);
  else
    fn(std::size_t{0}, n);
}

void World::color_pairs() {
  // Greedy colouring in pair order: each pair takes the lowest colour neither tire uses yet. A tire
  // with 64 neighbours or more sends its extra pairs to a last colour of their own.
  tire_colors_.assign(tires_.size(), 0);
  pair_color_.resize(tire_pairs_.size());
  std::uint32_t color_count = 0;
  for (std::size_t k = 0; k < tire_pairs_.size(); ++k) {
    const TirePair p = tire_pairs_[k];
    const std::uint64_t used = tire_colors_[p.a] | tire_colors_[p.b];
    const auto c = static_cast<std::uint32_t>(std::countr_one(used));  // 64 when all are taken
    if (c < kColors) {
      tire_colors_[p.a] |= std::uint64_t{1} << c;
      tire_colors_[p.b] |= std::uint64_t{1} << c;
    }
    pair_color_[k] = static_cast<std::uint8_t>(c);
    color_count = std::max(color_count, c + 1);
  }
  // Counting sort by colour, keeping pair order within a colour.
  color_begin_.assign(color_count + 1, 0);
  for (const std::uint8_t c : pair_color_) ++color_begin_[c + 1u];
  for (std::uint32_t c = 0; c < color_count; ++c) color_begin_[c + 1] += color_begin_[c];
  colored_pairs_.resize(tire_pairs_.size());
  for (std::size_t k = 0; k < tire_pairs_.size(); ++k)
    colored_pairs_[color_begin_[pair_color_[k]]++] = tire_pairs_[k];
  // The scatter moved each start to the next colour's start: shift back.
  for (std::uint32_t c = color_count; c > 0; --c) color_begin_[c] = color_begin_[c - 1];
  color_begin_[0] = 0;
  TIRE_ASSERT(color_begin_.back() == tire_pairs_.size(), "the colours do not hold every tire pair");
  TIRE_ASSERT(colors_share_no_tire(),
              "two pairs of one parallel colour share a tire: solving them would race");
}

bool World::colors_share_no_tire() {
  std::fill(tire_colors_.begin(), tire_colors_.end(), std::uint64_t{0});
  for (std::uint32_t c = 0; c + 1 < color_begin_.size() && c < kColors; ++c) {
    const std::uint64_t bit = std::uint64_t{1} << c;
    for (std::uint32_t k = color_begin_[c]; k < color_begin_[c + 1]; ++k) {
      const TirePair p = colored_pairs_[k];
      if (p.a == p.b || ((tire_colors_[p.a] | tire_colors_[p.b]) & bit) != 0) return false;
      tire_colors_[p.a] |= bit;
      tire_colors_[p.b] |= bit;
    }
  }
  return true;
}

void World::note_failed_solves(const Tire& t) {
  const std::uint32_t failed = t.global_work.failed_solves;
  if (failed == 0) return;
  failed_solves_ += failed;
  warnings_.push_back("tick " + std::to_string(tick_) + ": tire " + std::to_string(t.id) + ": " +
                      std::to_string(failed) + " global solve(s) failed (not finite); its step was skipped");
}

void World::guard_divergence(Tire& t) {
  std::string what;
  if (!t.is_finite() || t.max_abs_coordinate() > config_.divergence_limit) {
    what = "NaN, Inf or beyond " + std::to_string(config_.divergence_limit) + " m";
  } else if (const double ratio = t.area_ratio(); std::abs(ratio) > config_.divergence_area) {
    what = "its area " + std::to_string(ratio) + " times its rest area, past solver.divergence_area";
  } else {
    double fastest2 = 0.0;
    for (const Vec2& v : t.particles.v) fastest2 = std::max(fastest2, length_squared(v));
    if (!(fastest2 > config_.divergence_speed * config_.divergence_speed)) return;
    what = "a particle at " + std::to_string(std::sqrt(fastest2)) + " m/s, past solver.divergence_speed";
  }
  warnings_.push_back("tick " + std::to_string(tick_) + ": tire " + std::to_string(t.id) + " diverged (" +
                      what + "); reset to its spawn state");
  t.reset();
}

void World::wake_all() {
  sleep_.wake_all(tires_, rigid_);
  sleep_.clear_woken();
}

void World::wake_tire(TireId id) {
  if (Tire* t = find_tire(id)) wake_island_of(*t);
  sleep_.clear_woken();
}

std::uint64_t World::state_hash() const {
  StateHash h;
  hash_into(h);
  return h.digest();
}

void World::hash_into(StateHash& h) const {
  h.add(tick_);
  vehicles_.hash_into(h);  // nothing without vehicles: the hashes of levels without them stay
  for (const Tire& t : tires_) {
    h.add(t.id);
    h.add_bytes(t.particles.x.data(), t.particles.x.size() * sizeof(Vec2));
    h.add_bytes(t.particles.v.data(), t.particles.v.size() * sizeof(Vec2));
    h.add_bytes(t.grounded_flags.data(), t.grounded_flags.size());
    h.add(t.air_time);
    h.add(t.late_push.velocity);
    h.add(t.late_push.spin);
    h.add(t.late_push.centre);
    if (t.spin_as_built) h.add(t.spin_as_built);              // only until its first prediction
    if (config_.rolling_hold) h.add(t.rolling_held);          // what the next solve holds (SolverConfig)
    for (std::uint32_t i = 0; i < t.particle_count(); ++i) {  // friction anchors, where any
      if (t.anchor_on[i] == Tire::kNoAnchor) continue;
      h.add(i);
      h.add(t.anchor_on[i]);
      h.add(t.friction_anchor[i]);
    }
    if (config_.sleep) {  // the sleep state, where sleeping is on (sleep_islands.h)
      h.add(t.asleep);
      h.add(t.still_time);
      h.add(t.still_anchor);
      h.add_bytes(t.still_shape.data(), t.still_shape.size() * sizeof(Vec2));
      h.add(t.island);
    }
  }
  rigid_.hash_into(h);
}

}  // namespace tire
