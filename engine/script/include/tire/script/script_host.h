// What a level script sees of the running game and what it can do to it. The World's adapter
// implements it for the game, tirectl and replays; tests use a fake that records calls. Keeping the
// script behind this interface keeps it free of physics: it reads positions and issues commands.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "tire/math/geometry.h"
#include "tire/rigid/bodies.h"
#include "tire/script/script_spec.h"
#include "tire/tire/tire.h"
#include "tire/tire/tire_spec.h"

namespace tire {

class ScriptHost {
 public:
  virtual ~ScriptHost() = default;

  // ---- Clock
  // Ticks completed so far (World::tick()): the simulated time is tick() · dt(). 0 before the
  // first step, 1 after it.
  virtual std::uint64_t tick() const = 0;
  virtual double dt() const = 0;  // fixed tick (s)

  // ---- Tires, by index in [0, tire_count())
  virtual std::optional<TireId> player() const = 0;
  virtual std::size_t tire_count() const = 0;
  virtual TireId tire_id(std::size_t index) const = 0;
  virtual Vec2 tire_centroid(std::size_t index) const = 0;
  // A player vehicle's chassis' centre of mass, which stands for the player's position (the goal,
  // crossings by the player) when the player is a vehicle rather than a tire; nullopt otherwise.
  virtual std::optional<Vec2> player_vehicle_center() const { return std::nullopt; }

  // ---- Props, by index; a name not (or no longer) in the world gives nullopt
  virtual std::optional<std::size_t> find_prop(std::string_view name) const = 0;
  virtual Vec2 prop_position(std::size_t index) const = 0;  // body origin (m)

  // ---- Budgets (run_budgets.h): asked before each firing of a trigger; false drops the firing.
  // The level session counts them against its tick's budget; a host with none allows every one.
  virtual bool take_firing() { return true; }

  // ---- Actions. Names were checked at load against the level's props and the spawned ones; a
  // name whose prop is not in the world at that moment is the host's to ignore.
  virtual void spawn_tire(const TireSpec& spec) = 0;
  virtual void spawn_prop(const PropSpec& spec) = 0;
  virtual void remove_prop(std::string_view name) = 0;
  virtual void set_gravity(Vec2 gravity) = 0;                                   // m/s²
  virtual void apply_impulse_to_player(Vec2 impulse) = 0;                       // N·s, to the whole tire
  virtual void apply_impulse_to_all_tires(Vec2 impulse) = 0;                    // N·s, to each tire
  virtual void apply_impulse_to_prop(std::string_view name, Vec2 impulse) = 0;  // N·s, at its centre of mass
  // `key` is one of the keys SCRIPTING.md lists ("solver.substeps", "player.friction",
  // "tires.max_speed", ...); `value` is within that key's range (integral for the integer keys).
  virtual void set_parameter(std::string_view key, double value) = 0;
  virtual void path_command(std::string_view prop, PathCommand command) = 0;
  virtual void show_message(std::string_view text, double seconds) = 0;
  virtual void set_checkpoint(Vec2 position) = 0;  // m: where the player respawns
  virtual void next_level() = 0;
};

}  // namespace tire
