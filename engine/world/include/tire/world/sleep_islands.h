// Sleeping (issue 14): a world costs what moves in it. Bodies that touch form islands: tires
// through their broad-phase pairs, a tire and a dynamic prop through the tire's broad phase (its
// prop candidates), props with each other through Box2D's touching contacts. An island whose
// bodies have all been still (every particle of a tire, a prop's centre and outline, slower than
// SolverConfig::sleep_speed) for sleep_time sleeps: its tires are skipped by every phase of the
// step (no prediction, constraints, contacts or broad phase of their own), its props are put to
// sleep in Box2D. It wakes whole (World::step says when: never missed).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "tire/math/geometry.h"
#include "tire/rigid/rigid_world.h"
#include "tire/tire/soft_contact.h"
#include "tire/tire/solver_config.h"
#include "tire/tire/tire.h"

namespace tire {

class SleepIslands {
 public:
  // Room for `tires` tires and `props` props, so that a tick never allocates (allocates).
  void reserve(std::size_t tires, std::size_t props);

  // The awake tires' indices, ascending (current after refresh()); how many sleep (always current).
  std::span<const std::uint32_t> awake() const { return awake_; }
  std::size_t asleep_count() const { return asleep_; }
  // Whether a tire fell asleep, woke, came or went since the last refresh().
  bool stale() const { return stale_; }
  void mark_stale() { stale_ = true; }
  // The awake list and the index of sleeping tires' bounds, rebuilt: only when stale.
  void refresh(const std::vector<Tire>& tires);

  // f(i) for each sleeping tire i (as of the last refresh) whose bounds overlap `box`.
  template <typename F>
  void overlapping(const Aabb& box, F&& f) const;

  // Wakes the island tire i sleeps in: its tires (each awake for at least sleep_time again) and
  // the props put to sleep with it. False when tire i was awake. The woken tires are listed in
  // woken() until clear_woken().
  bool wake(std::vector<Tire>& tires, std::uint32_t i, RigidWorld& rigid);
  void wake_all(std::vector<Tire>& tires, RigidWorld& rigid);
  std::span<const std::uint32_t> woken() const { return woken_; }
  void clear_woken() { woken_.clear(); }

  // The end of a tick: each awake tire's stillness counted over dt, then each island of awake
  // bodies whose bodies have all been still for sleep_time put to sleep, except the one holding
  // `keep_awake` (the player while a key is held). `config`: the tick's (its substeps are the ones
  // the tick took): a tire's stillness is read from its motion over the last substep.
  void settle(std::vector<Tire>& tires, std::span<const TirePair> pairs, RigidWorld& rigid,
              const SolverConfig& config, std::optional<std::uint32_t> keep_awake);
  // Every tick, sleeping on or off: Box2D does not see tires, so a prop lying on an awake tire looks
  // at rest to it and would be put to sleep between the tire's pushes; it may sleep on its own only
  // while no awake tire is near it. Reads awake(): refresh() first.
  void hold_props_near_awake_tires(const std::vector<Tire>& tires, RigidWorld& rigid);

 private:
  std::uint32_t find(std::uint32_t node);
  void join(std::uint32_t a, std::uint32_t b);
  // The dynamic props near tires `members` into props_, each once.
  void gather_props(const std::vector<Tire>& tires, std::span<const std::uint32_t> members,
                    const RigidWorld& rigid);

  struct Entry {
    double min_x;
    std::uint32_t index;
  };
  std::vector<std::uint32_t> awake_;
  std::vector<Entry> sleeping_;  // sleeping tires by the left edge of their bounds
  std::vector<Aabb> bounds_;     // per tire: its bounds when it fell asleep
  double widest_ = 0.0;          // the widest sleeping tire's bounds (m)
  std::size_t asleep_ = 0;
  bool stale_ = true;
  std::vector<std::uint32_t> woken_;
  // settle()'s scratch: union–find over tires (index i) and props (tires.size() + prop index).
  std::vector<std::uint32_t> parent_;
  std::vector<double> still_;           // per root: the least still_time of its tires
  std::vector<std::uint8_t> blocked_;   // per root: holds keep_awake
  std::vector<std::uint64_t> members_;  // (root << 32 | tire) for the awake tires, sorted
  std::vector<std::uint32_t> island_;   // one island's tires
  std::vector<std::uint32_t> props_;    // one island's props
  std::vector<std::uint8_t> picked_;    // per prop: in props_ (gather_props' scratch)
  std::vector<std::uint8_t> near_;      // per prop: an awake tire is near it
};

template <typename F>
void SleepIslands::overlapping(const Aabb& box, F&& f) const {
  const double from = box.min.x - widest_;
  auto it = std::lower_bound(sleeping_.begin(), sleeping_.end(), from,
                             [](const Entry& e, double x) { return e.min_x < x; });
  for (; it != sleeping_.end() && it->min_x <= box.max.x; ++it)
    if (bounds_[it->index].overlaps(box)) f(it->index);
}

}  // namespace tire
