#include "play/game_session.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <type_traits>
#include <utility>

namespace game {

namespace {
// a at t = 0, b at t = 1, exactly (std::lerp: a + (b − a)·1 can miss b by a rounding).
tire::Vec2 lerp(tire::Vec2 a, tire::Vec2 b, double t) {
  return {std::lerp(a.x, b.x, t), std::lerp(a.y, b.y, t)};
}
}  // namespace

void GameSession::start(std::string path, std::shared_ptr<const tire::Level> level) {
  simulation_ = std::make_unique<tire::Simulation>(level);
  info_ = tire::level_info(*level);
  level_ = std::move(level);
  path_ = std::move(path);
  tuning_ = Tuning::from_simulation(*simulation_);
  tuned_ = false;
  previous_x_.clear();
  previous_poses_.clear();
  ++generation_;
}

void GameSession::queue(SessionEvent event) {
  if (std::holds_alternative<MoveGrabEvent>(event) && !queue_.empty() &&
      std::holds_alternative<MoveGrabEvent>(queue_.back())) {
    queue_.back() = std::move(event);
    return;
  }
  queue_.push_back(std::move(event));
}

void GameSession::flush() {
  if (queue_.empty()) return;
  // The observer sees each batch as applied; a level load starts a new world, so split there.
  std::vector<SessionEvent> batch;
  for (SessionEvent& e : queue_) {
    const bool load = std::holds_alternative<LoadLevelEvent>(e);
    if (load && !batch.empty()) {
      if (observer_) observer_->on_events(simulation_->tick(), batch);
      batch.clear();
    }
    const std::uint64_t tick = simulation_ ? simulation_->tick() : 0;
    apply(e);
    batch.push_back(std::move(e));
    if (load) {
      if (observer_) observer_->on_events(tick, batch);
      batch.clear();
    }
  }
  if (!batch.empty() && observer_) observer_->on_events(simulation_->tick(), batch);
  queue_.clear();
}

void GameSession::apply(const SessionEvent& event) {
  std::visit(
      [this](const auto& e) {
        using T = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<T, LoadLevelEvent>) {
          start(e.path, e.level);
        } else if constexpr (std::is_same_v<T, SpawnTireEvent>) {
          tire::TireSpec spec;
          spec.position = e.position;
          spec.player = false;
          simulation_->spawn_tire(spec);  // within the level's budgets
        } else if constexpr (std::is_same_v<T, GrabEvent>) {
          simulation_->grab_at(e.point, e.radius);
        } else if constexpr (std::is_same_v<T, MoveGrabEvent>) {
          simulation_->move_grab(e.target);
        } else if constexpr (std::is_same_v<T, ReleaseGrabEvent>) {
          simulation_->release_grab();
        } else if constexpr (std::is_same_v<T, TuneEvent>) {
          // Wakes the world when the change is made (tuning.h).
          if (apply_tuning(*simulation_, e.key, e.value)) {
            tuning_.set(e.key, e.value);
            tuned_ = true;
          }
        }
      },
      event);
}

void GameSession::step(const tire::TickInput& input) {
  flush();
  for (std::size_t i = 0; const std::optional<tire::TireView> t = simulation_->tire_at(i); ++i)
    previous_x_[t->id].assign(t->positions.begin(), t->positions.end());  // reuses capacity
  if (previous_x_.size() > 2 * simulation_->tire_count() + 16)
    std::erase_if(previous_x_, [this](const auto& entry) { return !simulation_->tire(entry.first); });
  const std::size_t props = simulation_->prop_count();
  previous_poses_.resize(props);
  for (std::uint32_t i = 0; i < props; ++i)
    if (const std::optional<tire::PropView> p = simulation_->prop(i); p && p->alive)
      previous_poses_[i] = p->state.pose;
  if (observer_) observer_->on_step(simulation_->tick(), input);
  simulation_->step(input);
  if (observer_) observer_->on_stepped(*simulation_);
}

void GameSession::interpolated_positions(const tire::TireView& t, double alpha,
                                         std::vector<tire::Vec2>& out) const {
  interpolated_positions(t.id, t.positions, alpha, out);
}

void GameSession::interpolated_positions(tire::TireId id, std::span<const tire::Vec2> now, double alpha,
                                         std::vector<tire::Vec2>& out) const {
  out.resize(now.size());
  const auto it = previous_x_.find(id);
  if (it == previous_x_.end() || it->second.size() != now.size()) {
    std::copy(now.begin(), now.end(), out.begin());
    return;
  }
  const std::vector<tire::Vec2>& before = it->second;
  for (std::size_t i = 0; i < now.size(); ++i) out[i] = lerp(before[i], now[i], alpha);
}

tire::Vec2 GameSession::interpolated_centroid(const tire::TireView& t, double alpha) const {
  const tire::Vec2 now = t.centroid;
  const auto it = previous_x_.find(t.id);
  if (it == previous_x_.end() || it->second.empty() || it->second.size() != t.positions.size()) return now;
  tire::Vec2 sum;
  for (const tire::Vec2& p : it->second) sum += p;
  const tire::Vec2 before = sum / static_cast<double>(it->second.size());
  return lerp(before, now, alpha);
}

tire::Pose GameSession::interpolated_pose(std::uint32_t prop, double alpha) const {
  const std::optional<tire::PropView> view = simulation_->prop(prop);
  const tire::Pose now = view ? view->state.pose : tire::Pose{};
  if (prop >= previous_poses_.size()) return now;
  const tire::Pose& before = previous_poses_[prop];
  return tire::Pose::make(lerp(before.position, now.position, alpha),
                          std::lerp(before.angle, now.angle, alpha));
}

std::vector<std::string> GameSession::take_warnings() {
  std::vector<std::string> out;
  if (simulation_) out = simulation_->take_warnings();
  return out;
}

}  // namespace game
