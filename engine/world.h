// The simulated world: tires, static obstacles and the fixed tick that advances them. Knows
// nothing of windows, files or input devices: the game, tirectl and the tests all drive it
// through step().
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rigid_world.h"
#include "solver_config.h"
#include "tire.h"

namespace tire {

// The player's input for one tick.
struct TickInput {
  double steer = 0.0;  // [-1, 1]
  bool jump = false;
};

class World {
 public:
  World(const SolverConfig& config, Vec2 gravity);

  // Adds a tire between ticks. The first tire, or one whose spec says player, becomes the player.
  TireId add_tire(const TireSpec& spec);
  bool remove_tire(TireId id);
  void add_obstacle(const Obstacle& obstacle) { rigid_.add_obstacle(obstacle); }
  std::uint32_t add_prop(const PropSpec& spec) { return rigid_.add_prop(spec); }

  // Advances one fixed tick of config().dt: `input` drives the player.
  void step(const TickInput& input);

  const std::vector<Tire>& tires() const { return tires_; }
  Tire* find_tire(TireId id);
  const Tire* player() const;
  const RigidWorld& rigid() const { return rigid_; }
  RigidWorld& rigid() { return rigid_; }
  const SolverConfig& config() const { return config_; }
  SolverConfig& config() { return config_; }
  Vec2 gravity() const { return gravity_; }
  void set_gravity(Vec2 g) {
    gravity_ = g;
    rigid_.set_gravity(g);
  }

  std::uint64_t tick() const { return tick_; }
  double time() const { return static_cast<double>(tick_) * config_.dt; }

  // Digest of the exact state: tick, every tire's id, particle positions, velocities and grounded
  // flags, and every prop's transform, velocity and path state. Same binary and same inputs give
  // the same hash.
  std::uint64_t state_hash() const;

  // Warnings raised while stepping (a diverged tire that was reset, ...); the caller drains them.
  std::vector<std::string>& warnings() { return warnings_; }

 private:
  void guard_divergence(Tire& t);

  SolverConfig config_;
  Vec2 gravity_;
  RigidWorld rigid_;
  std::vector<Tire> tires_;
  std::optional<TireId> player_;
  TireId next_id_ = 0;
  std::uint64_t tick_ = 0;
  std::vector<std::string> warnings_;
};

}  // namespace tire
