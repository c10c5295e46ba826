#include "world.h"

#include <algorithm>

#include "state_hash.h"
#include "tire_solver.h"

namespace tire {

World::World(const SolverConfig& config, Vec2 gravity) : config_(config), gravity_(gravity), rigid_(gravity) {}

TireId World::add_tire(const TireSpec& spec) {
  const TireId id = next_id_++;
  tires_.emplace_back(id, spec);
  if (spec.player || !player_) player_ = id;
  return id;
}

bool World::remove_tire(TireId id) {
  const auto it = std::find_if(tires_.begin(), tires_.end(), [id](const Tire& t) { return t.id == id; });
  if (it == tires_.end()) return false;
  tires_.erase(it);
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

void World::step(const TickInput& input) {
  if (player_) {
    if (Tire* p = find_tire(*player_)) {
      p->control.steer = input.steer;
      p->control.jump = input.jump;
    }
  }
  rigid_.begin_tick(config_.dt);
  for (Tire& t : tires_) begin_tick(t, config_, rigid_);
  const double h = config_.dt / config_.substeps;
  SubstepContext ctx{h, 0.0, gravity_, &config_, &rigid_};
  for (int s = 0; s < config_.substeps; ++s) {
    ctx.time = s * h;
    for (Tire& t : tires_) substep(t, ctx);
  }
  rigid_.end_tick(config_.dt);
  for (Tire& t : tires_) guard_divergence(t);
  ++tick_;
}

void World::guard_divergence(Tire& t) {
  if (t.is_finite() && t.max_abs_coordinate() <= config_.divergence_limit) return;
  warnings_.push_back("tick " + std::to_string(tick_) + ": tire " + std::to_string(t.id) +
                      " diverged (NaN, Inf or beyond " + std::to_string(config_.divergence_limit) +
                      " m); reset to its spawn state");
  t.reset();
}

std::uint64_t World::state_hash() const {
  StateHash h;
  h.add(tick_);
  for (const Tire& t : tires_) {
    h.add(t.id);
    h.add_bytes(t.particles.x.data(), t.particles.x.size() * sizeof(Vec2));
    h.add_bytes(t.particles.v.data(), t.particles.v.size() * sizeof(Vec2));
    h.add_bytes(t.grounded_flags.data(), t.grounded_flags.size());
  }
  rigid_.hash_into(h);
  return h.digest();
}

}  // namespace tire
