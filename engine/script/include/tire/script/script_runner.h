// Runs a level's script: once per tick, after the physics step, it looks at the world through a
// ScriptHost, fires the triggers whose condition holds and runs their actions. Its state (status,
// counters, what has fired, who is inside which region) is part of the simulation state hash.
//
// Order within one update (levels/SCRIPTING.md "When things happen"):
//   1. nothing, once the level is won or lost: the script has stopped;
//   2. the goal: the player's centroid inside the goal region wins;
//   3. every trigger except counter triggers, in file order, each looking at the world as the
//      actions of the triggers before it left it; a trigger runs its actions in list order;
//   4. counter triggers whose counter an action changed to their value, in file order, repeated
//      while their own actions make more of them due (at most kMaxCounterSweeps times per tick);
//   5. the time limit: reaching it while still running loses.
// An action that wins or loses ends the pass once its trigger's remaining actions have run.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tire/math/state_hash.h"
#include "tire/script/script_host.h"
#include "tire/script/script_spec.h"
#include "tire/script/script_status.h"

namespace tire {

struct CounterValue {
  std::string name;
  int value = 0;
};

class ScriptRunner {
 public:
  // Region triggers keep the sorted ids of the tires inside; this many are reserved at
  // construction so that update() does not allocate until a level has more tires than that.
  static constexpr std::size_t kReservedTires = 64;
  // Bound on chained counter triggers in one tick (a counter trigger changing a counter that
  // another one watches); those still due fire on the next tick.
  static constexpr int kMaxCounterSweeps = 16;

  explicit ScriptRunner(ScriptSpec spec);

  // Call once per tick after the physics step (and, so that level-start actions apply before
  // any physics, once after loading at tick 0).
  void update(ScriptHost& host);

  ScriptStatus status() const { return status_; }
  EndReason end_reason() const { return end_reason_; }                     // none while running
  const std::vector<CounterValue>& counters() const { return counters_; }  // in name order
  std::optional<int> counter(std::string_view name) const;
  const ScriptSpec& spec() const { return spec_; }

  // Everything that affects what the script will do next.
  void hash_into(StateHash& hash) const;

 private:
  struct TriggerState {
    std::uint64_t fires = 0;     // times the trigger has fired
    bool pending = false;        // counter triggers: an action changed the counter to the value
    bool prop_inside = false;    // prop_enter: the prop was inside at the previous look
    std::vector<TireId> inside;  // enter/leave: ids of the watched tires inside, ascending
  };

  void evaluate(std::size_t trigger, ScriptHost& host);
  std::size_t count_crossings(TriggerState& state, const RegionCrossing& crossing, const ScriptHost& host);
  void sweep_counter_triggers(ScriptHost& host);
  void fire(std::size_t trigger, ScriptHost& host);
  void run(const Action& action, ScriptHost& host);
  void change_counter(const ChangeCounter& change);
  bool player_inside(const Region& region, const ScriptHost& host) const;
  // The id a player vehicle crosses regions under: no tire's (ids count up from 0).
  static constexpr TireId kPlayerVehicle = ~TireId{0};
  void finish(ScriptStatus status, EndReason reason);

  ScriptSpec spec_;
  ScriptStatus status_ = ScriptStatus::running;
  EndReason end_reason_ = EndReason::none;  // follows from the state hashed: not hashed itself
  std::vector<CounterValue> counters_;
  std::vector<TriggerState> triggers_;  // parallel to spec_.triggers
  std::vector<TireId> scratch_;         // the tires inside a region this tick, before it is swapped in
};

}  // namespace tire
