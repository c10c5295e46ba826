#include "tire/script/script_runner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tire {

namespace {

// std::visit over a set of lambdas.
template <typename... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <typename... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

// Relative tolerance of tick_at: absorbs the rounding of seconds/dt, far below one tick.
constexpr double kTickTolerance = 1e-9;

}  // namespace

const char* to_string(ScriptStatus status) {
  switch (status) {
    case ScriptStatus::running: return "running";
    case ScriptStatus::won: return "won";
    case ScriptStatus::lost: return "lost";
  }
  return "running";
}

const char* to_string(EndReason reason) {
  switch (reason) {
    case EndReason::none: return "none";
    case EndReason::goal: return "goal";
    case EndReason::win_action: return "win_action";
    case EndReason::lose_action: return "lose_action";
    case EndReason::time_limit: return "time_limit";
    case EndReason::out_of_bounds: return "out_of_bounds";
    case EndReason::head_hit: return "head_hit";
  }
  return "none";
}

std::uint64_t tick_at(double seconds, double dt) {
  const double ticks = seconds / dt;
  const double n = std::ceil(ticks - kTickTolerance * std::max(1.0, ticks));
  if (!(n > 0.0)) return 0;
  // Beyond any reachable tick (an unlimited "every" after ~10^19 firings): never.
  if (n >= 1.8e19) return std::numeric_limits<std::uint64_t>::max();
  return static_cast<std::uint64_t>(n);
}

ScriptRunner::ScriptRunner(ScriptSpec spec) : spec_(std::move(spec)) {
  counters_.reserve(spec_.counters.size());
  for (const Counter& c : spec_.counters) counters_.push_back({c.name, c.initial});
  triggers_.resize(spec_.triggers.size());
  for (std::size_t i = 0; i < triggers_.size(); ++i)
    if (std::holds_alternative<RegionCrossing>(spec_.triggers[i].when))
      triggers_[i].inside.reserve(kReservedTires);
  scratch_.reserve(kReservedTires);
}

std::optional<int> ScriptRunner::counter(std::string_view name) const {
  for (const CounterValue& c : counters_)
    if (c.name == name) return c.value;
  return std::nullopt;
}

void ScriptRunner::update(ScriptHost& host) {
  if (status_ != ScriptStatus::running) return;

  if (spec_.goal && player_inside(spec_.regions[*spec_.goal], host)) {
    finish(ScriptStatus::won, EndReason::goal);
    return;
  }
  for (std::size_t i = 0; i < spec_.triggers.size() && status_ == ScriptStatus::running; ++i)
    evaluate(i, host);
  sweep_counter_triggers(host);
  if (status_ == ScriptStatus::running && spec_.time_limit &&
      host.tick() >= tick_at(*spec_.time_limit, host.dt()))
    finish(ScriptStatus::lost, EndReason::time_limit);
}

void ScriptRunner::evaluate(std::size_t i, ScriptHost& host) {
  const Trigger& trigger = spec_.triggers[i];
  TriggerState& state = triggers_[i];
  if (trigger.once && state.fires > 0) return;
  const std::uint64_t now = host.tick();
  const double dt = host.dt();

  // How many times the trigger fires now: region crossings fire once per crossing tire.
  const std::size_t firings = std::visit(
      Overloaded{
          [&](const AtStart&) -> std::size_t { return state.fires == 0 ? 1 : 0; },
          [&](const AtTime& t) -> std::size_t {
            return state.fires == 0 && now >= tick_at(t.at, dt) ? 1 : 0;
          },
          [&](const Every& e) -> std::size_t {
            if (e.count && state.fires >= static_cast<std::uint64_t>(*e.count)) return 0;
            // The k-th firing's time is computed afresh, not accumulated, so it does not drift.
            const double due = e.start + static_cast<double>(state.fires) * e.period;
            return now >= tick_at(due, dt) ? 1 : 0;
          },
          [&](const RegionCrossing& c) -> std::size_t { return count_crossings(state, c, host); },
          [&](const PropEnters& p) -> std::size_t {
            const auto prop = host.find_prop(p.prop);
            const bool inside = prop && spec_.regions[p.region].contains(host.prop_position(*prop));
            const bool entered = inside && !state.prop_inside;
            state.prop_inside = inside;
            return entered ? 1 : 0;
          },
          [&](const CounterReaches&) -> std::size_t { return 0; },  // fired by sweep_counter_triggers
      },
      trigger.when);

  for (std::size_t k = 0; k < firings && status_ == ScriptStatus::running; ++k) {
    if (trigger.once && state.fires > 0) break;
    fire(i, host);
  }
}

std::size_t ScriptRunner::count_crossings(TriggerState& state, const RegionCrossing& crossing,
                                          const ScriptHost& host) {
  const Region& region = spec_.regions[crossing.region];
  const std::optional<TireId> player = host.player();
  scratch_.clear();
  for (std::size_t t = 0, n = host.tire_count(); t < n; ++t) {
    const TireId id = host.tire_id(t);
    if (crossing.who == Who::player && (!player || id != *player)) continue;
    if (region.contains(host.tire_centroid(t))) scratch_.push_back(id);
  }
  // A player vehicle crosses as the player, by its chassis' centre of mass.
  if (const std::optional<Vec2> vehicle = host.player_vehicle_center(); vehicle && region.contains(*vehicle))
    scratch_.push_back(kPlayerVehicle);
  std::sort(scratch_.begin(), scratch_.end());

  // Both lists are ascending: walk them together. A tire that appears inside (spawned there, or
  // inside at the level start) enters; one that disappears while inside leaves.
  std::size_t entered = 0, left = 0;
  auto now_it = scratch_.begin();
  auto before_it = state.inside.begin();
  while (now_it != scratch_.end() || before_it != state.inside.end()) {
    if (before_it == state.inside.end() || (now_it != scratch_.end() && *now_it < *before_it)) {
      ++entered, ++now_it;
    } else if (now_it == scratch_.end() || *before_it < *now_it) {
      ++left, ++before_it;
    } else {
      ++now_it, ++before_it;
    }
  }
  std::swap(state.inside, scratch_);
  return crossing.entering ? entered : left;
}

void ScriptRunner::sweep_counter_triggers(ScriptHost& host) {
  for (int sweep = 0; sweep < kMaxCounterSweeps; ++sweep) {
    bool fired_any = false;
    for (std::size_t i = 0; i < spec_.triggers.size(); ++i) {
      if (status_ != ScriptStatus::running) return;
      TriggerState& state = triggers_[i];
      if (!state.pending) continue;
      state.pending = false;
      if (spec_.triggers[i].once && state.fires > 0) continue;
      fire(i, host);
      fired_any = true;
    }
    if (!fired_any) return;
  }
}

void ScriptRunner::fire(std::size_t i, ScriptHost& host) {
  if (!host.take_firing()) return;  // past the tick's budget of firings: dropped
  ++triggers_[i].fires;
  for (const Action& action : spec_.triggers[i].actions) run(action, host);
}

void ScriptRunner::run(const Action& action, ScriptHost& host) {
  std::visit(Overloaded{
                 [&](const SpawnTire& a) { host.spawn_tire(a.tire); },
                 [&](const SpawnProp& a) { host.spawn_prop(a.prop); },
                 [&](const RemoveProp& a) { host.remove_prop(a.prop); },
                 [&](const SetGravity& a) { host.set_gravity(a.gravity); },
                 [&](const ApplyImpulse& a) {
                   switch (a.target) {
                     case ImpulseTarget::player: host.apply_impulse_to_player(a.impulse); break;
                     case ImpulseTarget::all_tires: host.apply_impulse_to_all_tires(a.impulse); break;
                     case ImpulseTarget::prop: host.apply_impulse_to_prop(a.prop, a.impulse); break;
                   }
                 },
                 [&](const SetParameter& a) { host.set_parameter(a.key, a.value); },
                 [&](const ControlPath& a) { host.path_command(a.prop, a.command); },
                 [&](const ShowMessage& a) { host.show_message(a.text, a.seconds); },
                 [&](const SetCheckpoint& a) { host.set_checkpoint(a.position); },
                 [&](const ChangeCounter& a) { change_counter(a); },
                 [&](const Win&) { finish(ScriptStatus::won, EndReason::win_action); },
                 [&](const Lose&) { finish(ScriptStatus::lost, EndReason::lose_action); },
                 [&](const NextLevel&) { host.next_level(); },
             },
             action);
}

void ScriptRunner::change_counter(const ChangeCounter& change) {
  CounterValue& counter = counters_[change.counter];
  const std::int64_t limit = ScriptLimits::max_counter_value;
  const std::int64_t wanted = change.set ? change.amount : std::int64_t{counter.value} + change.amount;
  const int value = static_cast<int>(std::clamp(wanted, -limit, limit));  // saturates, never wraps
  if (value == counter.value) return;  // not a change: nothing reaches anything
  counter.value = value;
  for (std::size_t i = 0; i < spec_.triggers.size(); ++i) {
    const auto* reaches = std::get_if<CounterReaches>(&spec_.triggers[i].when);
    if (reaches && reaches->counter == change.counter && reaches->value == value) triggers_[i].pending = true;
  }
}

bool ScriptRunner::player_inside(const Region& region, const ScriptHost& host) const {
  if (const std::optional<Vec2> vehicle = host.player_vehicle_center()) return region.contains(*vehicle);
  const std::optional<TireId> player = host.player();
  if (!player) return false;
  for (std::size_t t = 0, n = host.tire_count(); t < n; ++t)
    if (host.tire_id(t) == *player) return region.contains(host.tire_centroid(t));
  return false;
}

void ScriptRunner::finish(ScriptStatus status, EndReason reason) {
  if (status_ != ScriptStatus::running) return;  // the first verdict stands
  status_ = status;
  end_reason_ = reason;
}

void ScriptRunner::hash_into(StateHash& hash) const {
  hash.add(static_cast<std::uint8_t>(status_));
  for (const CounterValue& c : counters_) hash.add(std::int32_t{c.value});
  for (const TriggerState& t : triggers_) {
    hash.add(t.fires);
    hash.add(static_cast<std::uint8_t>((t.pending ? 1 : 0) | (t.prop_inside ? 2 : 0)));
    hash.add(static_cast<std::uint64_t>(t.inside.size()));
    for (const TireId id : t.inside) hash.add(id);
  }
}

}  // namespace tire
