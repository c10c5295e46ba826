// The keys of a level file (levels/README.md, levels/SCRIPTING.md) in one table. Numeric keys of
// the solver, a tire and its compliance take range, unit and default from the parameter table;
// other defaults come from the structs a level reads into (PropSpec{}, Obstacle{}, ...), the one
// place those are written. Ranges of the other keys are written here, once.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>

#include "tire/io/level.h"
#include "tire/io/level_format.h"
#include "tire/tire/parameters.h"

namespace tire {

namespace {

using json = nlohmann::json;

const Range kCoordinate{-LevelLimits::max_coordinate, LevelLimits::max_coordinate};
const Range kVelocity{-1000.0, 1000.0};

// A whole number as a JSON integer ("0", not "0.0"), as a level writes it.
json number(double v) {
  if (std::floor(v) == v && std::fabs(v) < 9.0e15) return static_cast<std::int64_t>(v);
  return v;
}

json vec2(Vec2 v) { return json::array({number(v.x), number(v.y)}); }

// "m/s^2" as the reference page writes it: "m/s²".
std::string page_unit(std::string_view unit) {
  std::string out(unit);
  for (const auto& [ascii, superscript] :
       std::array<std::pair<std::string_view, std::string_view>, 3>{{{"^2", "²"}, {"^3", "³"}, {"^4", "⁴"}}})
    for (std::size_t at = out.find(ascii); at != std::string::npos; at = out.find(ascii))
      out.replace(at, ascii.size(), superscript);
  return out;
}

// A key being written into the table.
struct Key {
  LevelKey k;

  Key(const char* name, KeyType type, const char* description) {
    k.key = name;
    k.type = type;
    k.description = description;
  }
  Key& range(Range r, const char* unit = "") {
    k.range = r;
    k.unit = unit;
    return *this;
  }
  Key& by_default(json v) {
    k.default_value = std::move(v);
    return *this;
  }
  Key& required() {
    k.required = true;
    return *this;
  }
  Key& choices(std::vector<std::string> names) {
    k.choices = std::move(names);
    return *this;
  }
  Key& shapes(std::vector<std::string> names) {
    k.shapes = std::move(names);
    return *this;
  }
  Key& nested(LevelObject object) {
    k.nested = object;
    return *this;
  }
  Key& points(std::initializer_list<LevelKey::PointCount> counts) {
    k.point_counts = counts;
    return *this;
  }
};

// A key read through a row of the parameter table: its range, unit and default are the row's.
// `description` says "{range}" where the range goes.
Key from_row(ParamId id, const char* description) {
  const Parameter& p = parameter(id);
  Key key(p.field(), p.integer ? KeyType::integer : KeyType::number, description);
  key.k.range = p.range;
  key.k.unit = page_unit(p.unit);
  if (!p.default_follows) key.k.default_value = number(p.default_value);  // else it follows another key
  key.k.parameter = p.key;
  return key;
}

// A choice's default: the name of a struct's enum value, the choices being in the enum's order.
template <typename Enum>
json choice_default(const std::vector<std::string>& choices, Enum value) {
  return choices.at(static_cast<std::size_t>(value));
}

// The description with "{range}" replaced by the range and "{max}" by its whole maximum.
void expand(LevelKey& key) {
  const std::size_t at = key.description.find("{max}");
  if (at != std::string::npos)
    key.description.replace(at, 5, std::to_string(static_cast<std::uint64_t>(key.range.max)));
  key.description = described(key.description.c_str(), key.range);
}

std::vector<LevelKey> table(std::initializer_list<Key> keys) {
  std::vector<LevelKey> out;
  for (const Key& key : keys) {
    out.push_back(key.k);
    expand(out.back());
  }
  return out;
}

std::vector<LevelKey> root_keys() {
  using T = KeyType;
  const Level level;
  const Parameter& gravity = parameter(ParamId::gravity_x);  // gravity.y's range is the same
  Key gravity_key = Key("gravity", T::vec2, "each in {range}")
                        .range(gravity.range, page_unit(gravity.unit).c_str())
                        .by_default(vec2(level.gravity));
  gravity_key.k.parameter = gravity.key;  // each component read through gravity.x's row
  return table({
      Key("$schema", T::string, "ignored: lets an editor find the schema")
          .range({0, static_cast<double>(LevelLimits::max_string_bytes)}),
      Key("name", T::string, "up to {max} characters; shown in the game").range({0, 200}).required(),
      Key("description", T::string, "up to {max} characters; what the level teaches")
          .range({0, 2000})
          .by_default(level.description),
      gravity_key,
      Key("solver", T::object, "the solver's settings").nested(LevelObject::solver),
      Key("budgets", T::object, "what the level may add while it runs, lower than the defaults")
          .nested(LevelObject::budgets),
      Key("tires", T::array, "at most {max}; tires[0] is the player unless one says \"player\": true")
          .range({0, static_cast<double>(LevelLimits::max_tires)})
          .nested(LevelObject::tire),
      Key("obstacles", T::array, "static axis-aligned boxes, at most {max}")
          .range({0, static_cast<double>(LevelLimits::max_obstacles)})
          .nested(LevelObject::obstacle),
      Key("props", T::array, "rigid bodies simulated by Box2D, at most {max}")
          .range({0, static_cast<double>(LevelLimits::max_props)})
          .nested(LevelObject::prop),
      Key("vehicles", T::array,
          "at most {max}; chassis on wheels; one may be the player (then no tire is); needs the global "
          "solver method")
          .range({0, static_cast<double>(LevelLimits::max_vehicles)})
          .nested(LevelObject::vehicle),
      Key("bounds", T::object,
          "the box the player must stay in; leaving it loses, or respawns at the last checkpoint")
          .nested(LevelObject::bounds),
      Key("medals", T::object, "the times to win within for a gold, silver or bronze medal")
          .nested(LevelObject::medals),
      Key("regions", T::array, "named boxes the script watches, at most {max}")
          .range({0, static_cast<double>(ScriptLimits::max_regions)})
          .nested(LevelObject::region),
      Key("goal", T::string, "the name of a region: the player's centroid inside it wins")
          .range({0, static_cast<double>(ScriptLimits::max_name_length)}),
      Key("time_limit", T::number, "{range}: reaching it while the level is still running loses")
          .range({0.0, ScriptLimits::max_seconds, true}, "s"),
      Key("counters", T::object, "counter name → initial value; at most {max} counters")
          .range({0, static_cast<double>(ScriptLimits::max_counters)}),
      Key("triggers", T::array, "at most {max}; they fire in this order")
          .range({0, static_cast<double>(ScriptLimits::max_triggers)}),
  });
}

std::vector<LevelKey> solver_keys() {
  using T = KeyType;
  using P = ParamId;
  const SolverConfig solver;
  std::vector<std::string> methods;
  for (const SolverMethod m : kSolverMethods) methods.emplace_back(method_name(m));
  return table({
      from_row(P::solver_dt, "{range}: the fixed tick"),
      from_row(P::solver_substeps, "{range}: the tick is solved in substeps of h = dt/substeps"),
      from_row(P::solver_iterations, "{range}: constraint sweeps per substep"),
      from_row(P::solver_damping, "{range}: decay rate of each tire's non-rigid motion; 0 is none"),
      from_row(P::solver_tunnel_clamp,
               "{range}: a particle travels at most this many rest tread-segment lengths per substep"),
      from_row(P::solver_ground_normal_y,
               "{range}: a contact counts as ground (for jumping) when its normal's y is at least this"),
      from_row(
          P::solver_jump_grace,
          "{range}: a jump is honoured when the tread touched ground at most this long ago (coyote time)"),
      from_row(
          P::solver_divergence_area,
          "{range}: a tire whose area passes this many times its rest area (or minus it) has diverged and "
          "is reset"),
      from_row(P::solver_divergence_speed,
               "{range}: a tire with a particle faster than this has diverged and is reset"),
      from_row(P::solver_restitution_threshold,
               "{range}: a tire bounces by its restitution only off a landing faster than this"),
      from_row(
          P::solver_tire_neighbours,
          "{range}: the most tires one tire is in contact with in a tick; one with more candidates keeps "
          "its nearest"),
      from_row(P::solver_island_tires,
               "{range}: islands of tires in contact of up to this many tires have their contacts solved as "
               "one problem, so that piles do not creep; 0 solves every island tire by tire"),
      Key("method", T::choice,
          "\"gauss-seidel\": each constraint on its own; \"global\": each tire solved as one system")
          .choices(methods)
          .by_default(method_name(solver.method)),
      Key("sleep", T::boolean, "resting tires sleep; false simulates every body every tick")
          .by_default(solver.sleep),
      Key("rolling_hold", T::boolean,
          "the global method holds a lone tire's roll where rolling resistance stopped it, up to "
          "C_rr N R: it stays put on a slope gentler than its rolling_resistance")
          .by_default(solver.rolling_hold),
  });
}

std::vector<LevelKey> tire_keys() {
  using T = KeyType;
  using P = ParamId;
  const TireSpec tire;
  const std::vector<std::string> spokes{"radial", "cross"};  // SpokePattern's order
  std::vector<std::string> materials;
  for (const Material& m : kMaterials) materials.emplace_back(m.name);
  return table({
      Key("position", T::vec2, "where the hub starts; each in {range}").range(kCoordinate, "m").required(),
      Key("material", T::choice,
          "a preset of compliance, pressure, material_damping, friction, kinetic_friction, "
          "rolling_resistance "
          "and restitution, as a starting point: the tire's own keys override it")
          .choices(materials)
          .by_default(materials.front()),
      Key("velocity", T::vec2, "each in {range}").range(kVelocity, "m/s").by_default(vec2(tire.velocity)),
      from_row(P::tire_angle, "{range}: rotation from the pose with a tread segment flat at the bottom"),
      from_row(P::tire_angular_velocity, "{range}, counter-clockwise positive"),
      from_row(P::tire_outer_radius, "{range}: the tread"),
      from_row(P::tire_inner_radius, "{range} and less than outer_radius: the rim"),
      from_row(P::tire_segments, "{range}: particles per ring"),
      from_row(P::tire_mass, "{range}: the whole tire, shared equally by its 2·segments particles"),
      from_row(P::tire_friction, "{range}: static friction coefficient; mixed with a surface's as √(μ₁μ₂)"),
      from_row(P::tire_kinetic_friction, "{range}: once sliding; defaults to friction"),
      from_row(P::tire_pressure, "{range}: the air's target area as a fraction of the rest area"),
      Key("compliance", T::object, "XPBD compliances (inverse stiffness)").nested(LevelObject::compliance),
      Key("spokes", T::choice,
          "\"radial\": rim particle i to tread particle i only; \"cross\": also to i±1, resisting shear")
          .choices(spokes)
          .by_default(choice_default(spokes, tire.spokes)),
      from_row(P::tire_material_damping, "{range}: Kelvin–Voigt damping time τ; 0 is perfectly elastic"),
      from_row(P::tire_rolling_resistance,
               "{range}: coefficient C_rr of the moment C_rr·N·R that opposes rolling on the ground"),
      Key("player", T::boolean, "at most one tire").by_default(tire.player),
      from_row(P::tire_drive_acceleration, "{range}: tangential acceleration of the tread at full steer"),
      from_row(P::tire_jump_speed, "{range}: upward speed a jump adds (only when grounded)"),
      from_row(P::tire_max_speed,
               "{range}: cap on the hub's horizontal speed and on the speed steering drives the tread to"),
      from_row(P::tire_restitution,
               "{range}: a landing tire leaves the surface at this fraction of its landing speed; 0 leaves "
               "the bounce to its compliances and material_damping"),
      from_row(P::tire_inflate_rate,
               "{range}: how fast inflating or deflating moves the pressure, per second"),
      from_row(P::tire_min_pressure, "{range}: deflating stops here"),
      from_row(P::tire_max_pressure, "{range}: inflating stops here"),
  });
}

std::vector<LevelKey> compliance_keys() {
  using P = ParamId;
  return table({
      from_row(P::tire_compliance_outer, "{range}: stiffens the tread segments"),
      from_row(P::tire_compliance_inner, "{range}: stiffens the rim segments"),
      from_row(P::tire_compliance_spoke, "{range}: stiffens the spokes (sidewall)"),
      from_row(P::tire_compliance_pressure,
               "{range}: stiffens the air; an area change ΔA takes a 2D pressure ΔA/α"),
  });
}

std::vector<LevelKey> obstacle_keys() {
  using T = KeyType;
  const Obstacle obstacle;
  return table({
      Key("min", T::vec2, "lower-left corner, each in {range}").range(kCoordinate, "m").required(),
      Key("max", T::vec2, "upper-right corner, greater than min on both axes")
          .range(kCoordinate, "m")
          .required(),
      // A surface's friction takes the range of a tire's: the two are mixed.
      Key("friction", T::number, "{range}: mixed with the tire's as √(μ_tire · μ_obstacle)")
          .range(parameter_table::kFriction)
          .by_default(obstacle.friction),
  });
}

std::vector<LevelKey> prop_keys() {
  using T = KeyType;
  const PropSpec prop;
  const std::vector<std::string> shapes{"box", "circle", "polygon", "chain"};  // PropShape's order
  const std::vector<std::string> types{"static", "dynamic", "kinematic"};      // PropType's order
  // A prop turns and spins within the ranges a tire does.
  const Range angle = parameter(ParamId::tire_angle).range;
  const Range spin = parameter(ParamId::tire_angular_velocity).range;
  const LevelKey::PointCount polygon{"polygon", 3, 8};  // at most 8: Box2D's limit
  const LevelKey::PointCount chain{"chain", 2, 100000};
  const std::string points_description =
      "polygon and chain only, relative to position, each in {range}; polygon: " +
      std::to_string(polygon.min) + " to " + std::to_string(polygon.max) +
      ", convex, counter-clockwise; chain: " + std::to_string(chain.min) + " to " +
      std::to_string(chain.max) + " (3 if loop)";
  return table({
      Key("name", T::string,
          "up to {max} characters, unique among the props; scripts refer to the prop by it")
          .range({0, static_cast<double>(ScriptLimits::max_prop_name_length)})
          .by_default(prop.name),
      Key("shape", T::choice, "\"box\", \"circle\", \"polygon\" or \"chain\"").choices(shapes).required(),
      Key("type", T::choice, "\"static\", \"dynamic\" or \"kinematic\"; a chain can only be static")
          .choices(types)
          .by_default(choice_default(types, prop.type)),
      Key("position", T::vec2, "the body's origin, each in {range}; points are relative to it")
          .range(kCoordinate, "m")
          .by_default(vec2(prop.position)),
      Key("angle", T::number, "{range}: the body's rotation, counter-clockwise")
          .range(angle, "rad")
          .by_default(prop.angle),
      Key("size", T::vec2, "box only, each in {range}: full width and height")
          .range({kMinPropLength, 2.0 * LevelLimits::max_coordinate}, "m")
          .required()
          .shapes({"box"}),
      Key("radius", T::number, "circle only, {range}")
          .range({kMinPropLength, 1000.0}, "m")
          .required()
          .shapes({"circle"}),
      Key("points", T::points, points_description.c_str())
          .range(kCoordinate, "m")
          .required()
          .shapes({"polygon", "chain"})
          .points({polygon, chain}),
      Key("loop", T::boolean, "chain only: the last point joins the first")
          .by_default(prop.loop)
          .shapes({"chain"}),
      Key("thickness", T::number,
          "chain only, {range}: how far behind its line a particle still counts as inside")
          .range({kMinPropLength, 100.0}, "m")
          .by_default(prop.thickness)
          .shapes({"chain"}),
      Key("density", T::number, "{range}: a dynamic prop's mass is density × area")
          .range({0.0, 1e5, true}, "kg/m²")
          .by_default(prop.density),
      Key("friction", T::number, "{range}: mixed with the tire's as √(μ_tire · μ_prop)")
          .range(parameter_table::kFriction)
          .by_default(prop.friction),
      Key("restitution", T::number, "{range}: bounciness against other props and obstacles")
          .range({0.0, 1.0})
          .by_default(prop.restitution),
      Key("velocity", T::vec2,
          "each in {range}: a dynamic prop's initial velocity, a kinematic prop's if no path")
          .range(kVelocity, "m/s")
          .by_default(vec2(prop.velocity)),
      Key("angular_velocity", T::number,
          "{range}: a dynamic prop's initial spin, a kinematic prop's constant spin")
          .range(spin, "rad/s")
          .by_default(prop.angular_velocity),
      Key("path", T::object, "kinematic props only: the path it follows").nested(LevelObject::path),
  });
}

std::vector<LevelKey> path_keys() {
  using T = KeyType;
  const KinematicPath path;
  const std::vector<std::string> modes{"once", "loop", "ping_pong"};  // PathMode's order
  constexpr std::size_t kWaypoints = 1000;
  const std::string waypoints_description =
      "1 to " + std::to_string(kWaypoints) + " world positions (not relative to position), each in {range}";
  return table({
      Key("waypoints", T::points, waypoints_description.c_str())
          .range(kCoordinate, "m")
          .required()
          .points({{"", 1, kWaypoints}}),
      Key("speed", T::number, "{range}: speed along the path")
          .range({0.0, 1000.0, true}, "m/s")
          .by_default(path.speed),
      Key("mode", T::choice,
          "\"once\": stop at the last waypoint; \"loop\": back to the first; \"ping_pong\": back and forth")
          .choices(modes)
          .by_default(choice_default(modes, path.mode)),
      Key("running", T::boolean, "moving from the start; false waits for a script's start")
          .by_default(path.running),
  });
}

std::vector<LevelKey> region_keys() {
  using T = KeyType;
  return table({
      Key("name", T::string, "1 to {max} characters, unique among the regions")
          .range({1, static_cast<double>(ScriptLimits::max_name_length)})
          .required(),
      Key("min", T::vec2, "lower-left corner, each in {range}").range(kCoordinate, "m").required(),
      Key("max", T::vec2, "upper-right corner, greater than min on both axes")
          .range(kCoordinate, "m")
          .required(),
  });
}

std::vector<LevelKey> budget_keys() {
  using P = ParamId;
  return table({
      from_row(P::budget_tires,
               "{range}: tires alive at once, the level's own with those added while it runs"),
      from_row(P::budget_particles,
               "{range}: the particles of the tires alive at once (2 x segments a tire)"),
      from_row(P::budget_props, "{range}: props over the run, the level's own with those its script adds"),
      from_row(P::budget_spawns_per_tick,
               "{range}: tires and props added in one tick (script, replay, player)"),
      from_row(P::budget_messages, "{range}: script messages on screen at once"),
      from_row(P::budget_message_bytes, "{range}: the text of the messages on screen at once, together"),
      from_row(P::budget_firings_per_tick, "{range}: trigger firings in one tick"),
  });
}

std::vector<LevelKey> bounds_keys() {
  using T = KeyType;
  const LevelBounds bounds;
  return table({
      Key("min", T::vec2, "lower-left corner, each in {range}; default: the level's geometry less margin")
          .range(kCoordinate, "m"),
      Key("max", T::vec2,
          "upper-right corner, greater than min on both axes; default: right of the geometry by margin, no "
          "top")
          .range(kCoordinate, "m"),
      Key("margin", T::number, "{range}: how far below and beside the level's geometry a computed side lies")
          .range({0.0, 1000.0}, "m")
          .by_default(bounds.margin),
  });
}

std::vector<LevelKey> medals_keys() {
  using T = KeyType;
  const Range seconds{0.0, ScriptLimits::max_seconds, true};
  return table({
      Key("gold", T::number, "{range}: a win within this time earns gold; less than silver")
          .range(seconds, "s")
          .required(),
      Key("silver", T::number, "{range}: a win within this time earns silver; less than bronze")
          .range(seconds, "s")
          .required(),
      Key("bronze", T::number, "{range}: a win within this time earns bronze; at most the time limit")
          .range(seconds, "s")
          .required(),
  });
}

// The rows of `keys` named by `names`, in that order: an object that takes another's keys takes
// the same rows (their ranges, defaults and parameters), not a copy of their rules.
std::vector<LevelKey> rows_of(const std::vector<LevelKey>& keys,
                              std::initializer_list<std::string_view> names) {
  std::vector<LevelKey> out;
  for (const std::string_view name : names)
    for (const LevelKey& k : keys)
      if (k.key == name) out.push_back(k);
  return out;
}

std::vector<LevelKey> vehicle_keys() {
  using T = KeyType;
  const Drivetrain d;
  const LevelVehicle vehicle;
  const Range torque{0.0, 1e5};
  return table({
      Key("player", T::boolean, "the player drives it; at most one player among the tires and vehicles")
          .by_default(vehicle.player),
      Key("chassis", T::object, "the body the wheels hang from: a dynamic box, circle or polygon")
          .required()
          .nested(LevelObject::chassis),
      Key("wheels", T::array, "2 to {max}: tires on axles of the chassis")
          .range({2, static_cast<double>(VehicleJoints::kMaxWheels)})
          .required()
          .nested(LevelObject::wheel),
      Key("motor_torque", T::number, "{range}: most torque a driven wheel's motor gives")
          .range(torque, "N·m")
          .by_default(number(d.motor_torque)),
      Key("motor_speed", T::number, "{range}: a driven wheel's spin relative to the chassis at full throttle")
          .range({0.0, 1000.0}, "rad/s")
          .by_default(number(d.motor_speed)),
      Key("brake_torque", T::number, "{range}: most torque each wheel's brake holds")
          .range(torque, "N·m")
          .by_default(number(d.brake_torque)),
      Key("lean_torque", T::number, "{range}: torque on the chassis at full lean")
          .range(torque, "N·m")
          .by_default(number(d.lean_torque)),
      Key("head", T::object,
          "the driver's head: a player vehicle's touching the ground or a static or kinematic prop loses the "
          "level")
          .nested(LevelObject::head),
  });
}

std::vector<LevelKey> chassis_keys() {
  std::vector<LevelKey> keys =
      rows_of(prop_keys(), {"shape", "position", "angle", "size", "radius", "points", "density", "friction",
                            "restitution", "velocity", "angular_velocity"});
  for (LevelKey& k : keys) {
    if (k.key == "shape") {
      k.choices.pop_back();  // no chain: a chassis has mass
      k.description = "\"box\", \"circle\" or \"polygon\"";
    }
    if (k.key == "points") {
      std::erase_if(k.shapes, [](const std::string& s) { return s == "chain"; });
      std::erase_if(k.point_counts, [](const LevelKey::PointCount& c) { return c.shape == "chain"; });
      const LevelKey::PointCount& polygon = k.point_counts.front();
      k.description = "polygon only, relative to position, each in " + range_for_docs(k.range) + "; " +
                      std::to_string(polygon.min) + " to " + std::to_string(polygon.max) +
                      ", convex, counter-clockwise";
    }
  }
  return keys;
}

std::vector<LevelKey> wheel_keys() {
  using T = KeyType;
  const AxleSpec axle;
  std::vector<LevelKey> keys = table({
      Key("axle", T::vec2, "where the wheel's hub hangs, in the chassis' frame, each in {range}")
          .range({-100.0, 100.0}, "m")
          .required(),
      Key("axis", T::vec2, "the suspension's direction in the chassis' frame: a unit vector, each in {range}")
          .range({-1.0, 1.0})
          .by_default(vec2(axle.axis)),
      Key("stiffness", T::number, "{range}: the suspension's spring along the axis; 0 is a rigid axle")
          .range({0.0, 1e7}, "N/m")
          .by_default(number(axle.stiffness)),
      Key("damping", T::number, "{range}: the suspension's damper")
          .range({0.0, 1e6}, "N·s/m")
          .by_default(number(axle.damping)),
      Key("travel", T::number,
          "{range}: the most a sprung hub moves along the axis either side of its axle point; 0 is no limit")
          .range({0.0, 10.0}, "m")
          .by_default(number(axle.travel)),
      Key("driven", T::boolean, "the motor turns this wheel").by_default(axle.driven),
  });
  for (LevelKey& k :
       rows_of(tire_keys(), {"material", "angle", "outer_radius", "inner_radius", "segments", "mass",
                             "friction", "kinetic_friction", "pressure", "compliance", "spokes",
                             "material_damping", "rolling_resistance", "restitution"}))
    keys.push_back(std::move(k));
  return keys;
}

std::vector<LevelKey> head_keys() {
  using T = KeyType;
  return table({
      Key("position", T::vec2, "its centre in the chassis' frame, each in {range}")
          .range({-100.0, 100.0}, "m")
          .required(),
      Key("radius", T::number, "{range}").range({kMinPropLength, 10.0}, "m").required(),
  });
}

const std::array<std::vector<LevelKey>, kLevelObjects>& all_keys() {
  // Built once, in LevelObject's order.
  static const std::array<std::vector<LevelKey>, kLevelObjects> keys{
      root_keys(),   solver_keys(),  tire_keys(),    compliance_keys(), obstacle_keys(),
      prop_keys(),   path_keys(),    region_keys(),  budget_keys(),     bounds_keys(),
      medals_keys(), vehicle_keys(), chassis_keys(), wheel_keys(),      head_keys()};
  return keys;
}

}  // namespace

std::span<const LevelKey> level_keys(LevelObject object) {
  return all_keys().at(static_cast<std::size_t>(object));
}

const LevelKey* find_level_key(LevelObject object, std::string_view key) {
  for (const LevelKey& k : level_keys(object))
    if (k.key == key) return &k;
  return nullptr;
}

bool applies_to_shape(const LevelKey& key, std::string_view shape) {
  return key.shapes.empty() || std::find(key.shapes.begin(), key.shapes.end(), shape) != key.shapes.end();
}

const LevelKey::PointCount* point_count(const LevelKey& key, std::string_view shape) {
  for (const LevelKey::PointCount& c : key.point_counts)
    if (c.shape.empty() || c.shape == shape) return &c;
  return nullptr;
}

}  // namespace tire
