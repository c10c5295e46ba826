// The parameter table: every scalar number of the solver and of a tire that a level, a script's
// `set` action, a replay's `set` input or the game's tuning panel may give, in one place: its key,
// unit, range, whether it is an integer, its default and who may set it.
//
// Everything that reads or sets such a number takes it from here: the level reader (ranges of the
// solver's and the tires' keys), the script reader (the keys and ranges of `set`), the replay reader
// (`set` inputs), World::set_parameter (refuses a value outside the range), the game's tuning panel
// (its keys; its sliders stay inside these ranges) and levels/schema.json (generated from this
// table: `tirectl schema --write levels/schema.json`; a test fails while they differ).
// Programs outside the engine (the game, tirectl) read its rows and the material presets through
// the installed tire/io/level_format.h (tunable_parameters(), material_presets()), made from them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "tire/math/geometry.h"
#include "tire/math/numbers.h"
#include "tire/tire/run_budgets.h"
#include "tire/tire/solver_config.h"
#include "tire/tire/tire_spec.h"

namespace tire {

// A new world's gravity (m/s²) when the level gives none.
inline constexpr Vec2 kDefaultGravity{0.0, -9.81};

// Who may set a parameter (bit flags).
enum Setter : unsigned {
  by_level = 1u << 0,   // a level file: "solver.X" at /solver/X, "tires.X" in every tire object
  by_script = 1u << 1,  // a level script's `set` action
  by_replay = 1u << 2,  // a replay's `set` input
  by_panel = 1u << 3,   // the game's tuning panel
};
// Set while the world runs, through World::set_parameter.
inline constexpr unsigned kRuntimeSetters = by_script | by_replay | by_panel;

// One per row of the table, in its order.
enum class ParamId : std::uint8_t {
  solver_dt,
  solver_substeps,
  solver_iterations,
  solver_damping,
  solver_tunnel_clamp,
  solver_ground_normal_y,
  solver_jump_grace,
  solver_divergence_area,
  solver_divergence_speed,
  solver_restitution_threshold,
  solver_tire_neighbours,
  solver_island_tires,
  gravity_x,
  gravity_y,
  tire_angle,
  tire_angular_velocity,
  tire_outer_radius,
  tire_inner_radius,
  tire_segments,
  tire_mass,
  tire_mass_scale,
  tire_friction,
  tire_kinetic_friction,
  tire_pressure,
  tire_compliance_outer,
  tire_compliance_inner,
  tire_compliance_spoke,
  tire_compliance_pressure,
  tire_material_damping,
  tire_rolling_resistance,
  tire_drive_acceleration,
  tire_jump_speed,
  tire_max_speed,
  tire_restitution,
  tire_inflate_rate,
  tire_min_pressure,
  tire_max_pressure,
  budget_tires,
  budget_particles,
  budget_props,
  budget_spawns_per_tick,
  budget_messages,
  budget_message_bytes,
  budget_firings_per_tick,
};

struct Parameter {
  ParamId id;
  // As written in scripts, replays and the panel: "solver.substeps", "tires.compliance.outer",
  // "gravity.x". A "tires." key sets every tire; "player." + the rest sets the player's tire only.
  const char* key;
  // As messages print it after the range: "m/s^2", "(fraction of the rest area)"; "" for none.
  const char* unit;
  Range range;
  bool integer;
  double default_value;  // taken from TireSpec{} / SolverConfig{}: those structs are the one place
  unsigned setters;      // Setter bits
  // For the schema and the docs; "{range}" stands where the range goes.
  const char* description;
  // The key whose value is the default instead of default_value ("tires.kinetic_friction": the
  // tire's friction); nullptr for a fixed default.
  const char* default_follows = nullptr;

  constexpr bool may(Setter s) const { return (setters & s) != 0; }
  constexpr bool runtime() const { return (setters & kRuntimeSetters) != 0; }
  constexpr bool is_tire() const { return std::string_view(key).starts_with("tires."); }
  constexpr bool is_budget() const { return std::string_view(key).starts_with("budgets."); }
  // The key within its level object: "substeps", "outer" (of tires.compliance.outer), "x". The
  // tail of `key`, so it ends where `key` does.
  constexpr const char* field() const { return key + std::string_view(key).rfind('.') + 1; }
  // The value is finite, in the range, and whole when the parameter is an integer.
  constexpr bool accepts(double v) const {
    return range.contains(v) && (!integer || static_cast<double>(static_cast<long long>(v)) == v);
  }
};

namespace parameter_table {
inline constexpr TireSpec kTire{};
inline constexpr SolverConfig kSolver{};
inline constexpr RunBudgets kBudgets{};
inline constexpr Range kFriction{0.0, 10.0};
inline constexpr Range kCompliance{0.0, 1.0};
inline constexpr Range kGravity{-1000.0, 1000.0};
inline constexpr unsigned kLevelOnly = by_level;
inline constexpr unsigned kEverywhere = by_level | by_script | by_replay | by_panel;
inline constexpr unsigned kNotPanel = by_level | by_script | by_replay;
inline constexpr unsigned kNotScript = by_level | by_replay | by_panel;
}  // namespace parameter_table

// The table. Ranges keep every value the world can step: no zero mass or scale (inverse masses),
// no more substeps than a tick can afford, finite everything.
inline constexpr std::array kParameters = [] {
  using namespace parameter_table;
  using P = ParamId;
  // One row a line or two, as a table reads: clang-format would put every field on a line of its own.
  // clang-format off
  return std::array<Parameter, 44>{{
      {P::solver_dt, "solver.dt", "s", {1e-4, 0.1}, false, kSolver.dt, kLevelOnly,
       "The fixed tick (s), in {range}; default 1/60."},
      {P::solver_substeps, "solver.substeps", "", {1, 256}, true, kSolver.substeps, kEverywhere,
       "Substeps per tick, in {range}: each is solved with h = dt/substeps; more makes stiff tires accurate."},
      {P::solver_iterations, "solver.iterations", "", {1, 64}, true, kSolver.iterations, kEverywhere,
       "Constraint sweeps per substep, in {range}."},
      {P::solver_damping, "solver.damping", "1/s", {0, 1000}, false, kSolver.damping, kEverywhere,
       "Decay rate of each tire's non-rigid motion (1/s), in {range}; 0 is none."},
      {P::solver_tunnel_clamp, "solver.tunnel_clamp", "segments per substep", {0.1, 10}, false, kSolver.tunnel_clamp,
       kLevelOnly, "Anti-tunneling clamp (rest tread-segment lengths per substep), in {range}."},
      {P::solver_ground_normal_y, "solver.ground_normal_y", "", {0, 1}, false, kSolver.ground_normal_y, kLevelOnly,
       "A contact is ground (for jumping) when its normal's y is at least this, in {range}; 0.5 accepts up to 60°."},
      {P::solver_jump_grace, "solver.jump_grace", "s", {0, 1}, false, kSolver.jump_grace, kLevelOnly,
       "A jump is honoured when the tread touched ground at most this long ago (s), in {range}."},
      {P::solver_divergence_area, "solver.divergence_area", "(times the rest area)", {2, 1000}, false,
       kSolver.divergence_area, kLevelOnly,
       "A tire whose area passes this many times its rest area (or minus it) has diverged and is reset, in {range}."},
      {P::solver_divergence_speed, "solver.divergence_speed", "m/s", {10, 1e6}, false, kSolver.divergence_speed,
       kLevelOnly, "A tire with a particle faster than this (m/s) has diverged and is reset, in {range}."},
      {P::solver_restitution_threshold, "solver.restitution_threshold", "m/s", {0, 100}, false,
       kSolver.restitution_threshold, kLevelOnly,
       "A tire bounces by its restitution only off a landing faster than this (m/s), in {range}."},
      // At most the Gauss–Seidel contacts' parallel colours (world.cpp): a tire with more pairs
      // than colours has its extra pairs solved on one thread.
      {P::solver_tire_neighbours, "solver.tire_neighbours", "tires", {1, 64}, true, kSolver.tire_neighbours,
       kLevelOnly,
       "The most tires one tire is in contact with in a tick, in {range}: one with more candidates keeps its nearest."},
      {P::solver_island_tires, "solver.island_tires", "tires", {0, 1024}, true, kSolver.island_tires, kLevelOnly,
       "Islands of tires in contact of up to this many tires, in {range}, have their contacts solved as one "
       "problem (piles do not creep); 0 solves every island tire by tire."},
      // The level's "gravity" [x, y], a script's set_gravity and a replay's gravity input take
      // each component in this range too.
      {P::gravity_x, "gravity.x", "m/s^2", kGravity, false, kDefaultGravity.x, by_panel,
       "Horizontal gravity (m/s²), in {range}."},
      {P::gravity_y, "gravity.y", "m/s^2", kGravity, false, kDefaultGravity.y, by_panel,
       "Vertical gravity (m/s²), in {range}; -9.81 is Earth's."},
      {P::tire_angle, "tires.angle", "rad", {-100, 100}, false, kTire.angle, kLevelOnly,
       "Rotation (rad) from the pose with a tread segment flat at the bottom, in {range}."},
      {P::tire_angular_velocity, "tires.angular_velocity", "rad/s", {-1000, 1000}, false, kTire.angular_velocity,
       kLevelOnly, "Initial spin (rad/s, counter-clockwise positive), in {range}."},
      {P::tire_outer_radius, "tires.outer_radius", "m", {0.01, 100}, false, kTire.outer_radius, kLevelOnly,
       "Radius of the tread (m), in {range}."},
      {P::tire_inner_radius, "tires.inner_radius", "m", {0.005, 100}, false, kTire.inner_radius, kLevelOnly,
       "Radius of the rim (m), in {range} and less than outer_radius."},
      {P::tire_segments, "tires.segments", "", {6, 256}, true, kTire.segments, kLevelOnly,
       "Particles per ring, in {range}."},
      // At least a gram: a particle's inverse mass is 2·segments / mass, which overflows to infinity
      // below about 1e-300 kg (a tire of 1e-310 kg diverged on its first tick). The lightest tire the
      // tests make (0.01 kg, against a 10 kg box) is ten times above it.
      {P::tire_mass, "tires.mass", "kg", {1e-3, 1e6}, false, kTire.mass, by_level | by_replay,
       "Mass of the whole tire (kg), in {range}, shared equally by its 2·segments particles."},
      // Bounded away from 0: each particle's inverse mass is 2·segments / (spawn mass · scale), and
      // any scale below about 1e-300 makes it infinite as surely as 0 does. 0.01 is ten times below
      // the panel's smallest; 10, the panel's largest, keeps a level's heaviest tire (10⁶ kg) within 10⁷ kg.
      {P::tire_mass_scale, "tires.mass_scale", "(times the tire's spawn mass)", {0.01, 10}, false, 1.0,
       by_replay | by_panel, "Each tire's mass as a multiple of the mass it was built with, in {range}."},
      {P::tire_friction, "tires.friction", "", kFriction, false, kTire.friction, kEverywhere,
       "Static friction coefficient, in {range}; mixed with a surface's as √(μ₁μ₂)."},
      {P::tire_kinetic_friction, "tires.kinetic_friction", "", kFriction, false, kTire.kinetic_friction, kNotPanel,
       "Kinetic friction coefficient once sliding, in {range}; defaults to this tire's friction.", "tires.friction"},
      {P::tire_pressure, "tires.pressure", "(fraction of the rest area)", {0.1, 4}, false, kTire.pressure, kEverywhere,
       "Target area of the air as a fraction of the rest area, in {range}; above 1 inflates."},
      {P::tire_compliance_outer, "tires.compliance.outer", "m/N", kCompliance, false, kTire.compliance.outer,
       kNotScript, "Compliance of the tread segments (m/N), in {range}."},
      {P::tire_compliance_inner, "tires.compliance.inner", "m/N", kCompliance, false, kTire.compliance.inner,
       kNotScript, "Compliance of the rim segments (m/N), in {range}."},
      {P::tire_compliance_spoke, "tires.compliance.spoke", "m/N", kCompliance, false, kTire.compliance.spoke,
       kNotScript, "Compliance of the spokes, the sidewall (m/N), in {range}."},
      {P::tire_compliance_pressure, "tires.compliance.pressure", "m^4/J", kCompliance, false,
       kTire.compliance.pressure, kNotScript,
       "Compliance of the air (m⁴/J), in {range}: an area change ΔA takes a 2D pressure ΔA/α."},
      {P::tire_material_damping, "tires.material_damping", "s", {0, 1}, false, kTire.material_damping, kEverywhere,
       "Kelvin–Voigt damping time τ (s), in {range}; takes energy out of bounces, 0 is elastic."},
      {P::tire_rolling_resistance, "tires.rolling_resistance", "", {0, 1}, false, kTire.rolling_resistance, kNotPanel,
       "Rolling resistance coefficient C_rr, in {range}: a moment C_rr·N·R against rolling (cars ≈ 0.01)."},
      {P::tire_drive_acceleration, "tires.drive_acceleration", "m/s^2", {0, 1000}, false, kTire.drive_acceleration,
       kNotPanel, "Tangential acceleration of the tread at full steer (m/s²), in {range}."},
      {P::tire_jump_speed, "tires.jump_speed", "m/s", {0, 100}, false, kTire.jump_speed, kNotPanel,
       "Upward speed a jump adds when grounded (m/s), in {range}."},
      {P::tire_max_speed, "tires.max_speed", "m/s", {0, 1000, true}, false, kTire.max_speed, kNotPanel,
       "Cap on the hub's horizontal speed and on the steered tread speed (m/s), in {range}."},
      {P::tire_restitution, "tires.restitution", "", {0, 1}, false, kTire.restitution, kEverywhere,
       "A landing tire leaves the surface at this fraction of its landing speed, in {range}; 0 leaves it to the material."},
      {P::tire_inflate_rate, "tires.inflate_rate", "(of the rest area per second)", {0, 10}, false,
       kTire.inflate_rate, kNotPanel, "How fast inflating or deflating moves the pressure (per second), in {range}."},
      {P::tire_min_pressure, "tires.min_pressure", "(fraction of the rest area)", {0.1, 4}, false,
       kTire.min_pressure, kNotPanel, "Deflating stops at this pressure, in {range}."},
      {P::tire_max_pressure, "tires.max_pressure", "(fraction of the rest area)", {0.1, 4}, false,
       kTire.max_pressure, kNotPanel, "Inflating stops at this pressure, in {range}."},
      // Run-time budgets (run_budgets.h): the default is the most; a level may only lower one.
      {P::budget_tires, "budgets.tires", "", {1, kBudgets.tires}, true, kBudgets.tires, kLevelOnly,
       "Tires alive at once, the level's own with those added while it runs, in {range}."},
      {P::budget_particles, "budgets.particles", "", {12, kBudgets.particles}, true, kBudgets.particles, kLevelOnly,
       "Particles of the tires alive at once (2 x segments a tire), in {range}."},
      {P::budget_props, "budgets.props", "", {1, kBudgets.props}, true, kBudgets.props, kLevelOnly,
       "Props over the run, the level's own with those its script adds, in {range}."},
      {P::budget_spawns_per_tick, "budgets.spawns_per_tick", "", {0, kBudgets.spawns_per_tick}, true,
       kBudgets.spawns_per_tick, kLevelOnly,
       "Tires and props added in one tick, by the script, a replay or the player, in {range}."},
      {P::budget_messages, "budgets.messages", "", {0, kBudgets.messages}, true, kBudgets.messages, kLevelOnly,
       "Script messages on screen at once, in {range}."},
      {P::budget_message_bytes, "budgets.message_bytes", "bytes", {0, kBudgets.message_bytes}, true,
       kBudgets.message_bytes, kLevelOnly, "Text of the messages on screen at once, together (bytes), in {range}."},
      {P::budget_firings_per_tick, "budgets.firings_per_tick", "", {1, kBudgets.firings_per_tick}, true,
       kBudgets.firings_per_tick, kLevelOnly, "Trigger firings in one tick, in {range}."},
  }};
  // clang-format on
}();

// Material presets: named starting points for a tire's material. A level's tire names one
// ("material": "balloon"), as do the tuning panel and the editor; any key the tire also gives
// overrides the preset's. "standard" is TireSpec{}'s own. docs/soft-tire.md has what each measures.
// Each is stable loaded to five times its weight at 1 and 2 substeps (tests/test_materials.cpp).
struct Material {
  const char* name;
  const char* description;
  TireCompliance compliance;
  double material_damping;
  double friction;
  double kinetic_friction;
  double rolling_resistance;
  double restitution;
  double pressure;  // the air's target area ratio at rest: above 1 it carries load (tire_spec.h)

  // The preset's value of a tire parameter it sets; nothing for one it leaves to TireSpec's
  // default (the editor shows a preset's values as an unset key's default).
  constexpr std::optional<double> value_of(ParamId id) const {
    switch (id) {
      case ParamId::tire_compliance_outer: return compliance.outer;
      case ParamId::tire_compliance_inner: return compliance.inner;
      case ParamId::tire_compliance_spoke: return compliance.spoke;
      case ParamId::tire_compliance_pressure: return compliance.pressure;
      case ParamId::tire_material_damping: return material_damping;
      case ParamId::tire_friction: return friction;
      case ParamId::tire_kinetic_friction: return kinetic_friction;
      case ParamId::tire_rolling_resistance: return rolling_resistance;
      case ParamId::tire_restitution: return restitution;
      case ParamId::tire_pressure: return pressure;
      default: return std::nullopt;
    }
  }
  constexpr void apply_to(TireSpec& t) const {
    t.compliance = compliance;
    t.material_damping = material_damping;
    t.friction = friction;
    t.kinetic_friction = kinetic_friction;
    t.rolling_resistance = rolling_resistance;
    t.restitution = restitution;
    t.pressure = pressure;
  }
};

inline constexpr std::array kMaterials = [] {
  using parameter_table::kTire;
  // One preset a line or two, as a table reads.
  // clang-format off
  return std::array<Material, 7>{{
      {"standard", "the default: a stiff tire that hardly deforms (it sags 0.1 mm)",
       kTire.compliance, kTire.material_damping, kTire.friction, kTire.kinetic_friction, kTire.rolling_resistance,
       kTire.restitution, kTire.pressure},
      {"soft", "a soft road tire on its air: sags 6 % of its radius, 8 % deflated, 3 % inflated",
       {1e-5, 1e-6, 1e-3, 3e-4}, 5e-3, 0.9, 0.9, 0.01, 0.0, 1.1},
      {"slick", "a racing slick: a stiffer sidewall and more air than soft, more grip, rolls easily",
       {1e-5, 1e-6, 3e-4, 3e-4}, 5e-3, 1.2, 1.0, 0.006, 0.0, 1.15},
      {"balloon", "a balloon tire: a soft sidewall on soft air, sags 7 % and squashes a third landing",
       {1e-5, 1e-6, 1e-3, 1e-3}, 1e-2, 0.8, 0.7, 0.02, 0.0, 1.05},
      {"offroad", "a knobbly off-road tire: soft, grips hard, rolls heavily",
       {1e-5, 1e-6, 1e-3, 3e-4}, 8e-3, 1.4, 1.1, 0.03, 0.0, 1.1},
      {"rubber_ball", "a rubber ball: firm and bouncy, rebounds to 70 % of its drop",
       {1e-5, 1e-6, 1e-4, 1e-3}, 1e-3, 0.8, 0.7, 0.005, 0.84, 1.0},
      {"cart_wheel", "a hard cart wheel: hardly deforms, rolls as a polygon, slides easily",
       {1e-6, 1e-7, 1e-6, 1e-5}, 5e-3, 0.6, 0.5, 0.02, 0.0, 1.0},
  }};
  // clang-format on
}();

// The preset a name names, or nullptr.
constexpr const Material* find_material(std::string_view name) {
  for (const Material& m : kMaterials)
    if (name == m.name) return &m;
  return nullptr;
}

// The whole table, in order.
constexpr std::span<const Parameter> parameters() { return kParameters; }
constexpr const Parameter& parameter(ParamId id) { return kParameters[static_cast<std::size_t>(id)]; }

// The row a key names, or nullptr: "player.X" names the tire row "tires.X".
const Parameter* find_parameter(std::string_view key);

// The table's own consistency, checked when it compiles.
namespace parameter_table {
constexpr bool consistent() {
  for (std::size_t i = 0; i < kParameters.size(); ++i) {
    const Parameter& p = kParameters[i];
    if (static_cast<std::size_t>(p.id) != i) return false;                          // ids in table order
    if (p.default_follows == nullptr && !p.accepts(p.default_value)) return false;  // defaults in range
    if (std::string_view(p.description).find("{range}") == std::string_view::npos) return false;
    if (p.integer && (p.range.min_open || p.range.max_open)) return false;  // integer ranges are closed
    for (std::size_t j = 0; j < i; ++j)
      if (std::string_view(kParameters[j].key) == p.key) return false;  // keys unique
  }
  return parameter(ParamId::gravity_x).range == parameter(ParamId::gravity_y).range;  // one component range
}
static_assert(consistent(), "the parameter table: ids in order, defaults in range, unique keys");
}  // namespace parameter_table

}  // namespace tire
