#include "tire/session/level_session.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "session_script_host.h"
#include "tire/math/state_hash.h"
#include "tire/rigid/prop_geometry.h"
#include "tire/rigid/rigid_world.h"

namespace tire {

LevelSession::LevelSession(const SolverConfig& config, Vec2 gravity) : world_(config, gravity) {}
LevelSession::~LevelSession() = default;
LevelSession::LevelSession(LevelSession&&) noexcept = default;
LevelSession& LevelSession::operator=(LevelSession&&) noexcept = default;

void LevelSession::set_script(const ScriptSpec& spec) {
  const bool empty = spec.regions.empty() && spec.triggers.empty() && spec.counters.empty() && !spec.goal &&
                     !spec.time_limit;
  script_ = empty ? nullptr : std::make_unique<ScriptRunner>(spec);
  has_checkpoints_ = false;
  for (const Trigger& t : spec.triggers)
    for (const Action& a : t.actions)
      has_checkpoints_ = has_checkpoints_ || std::holds_alternative<SetCheckpoint>(a);
  if (script_) {
    SessionScriptHost host(*this);
    script_->update(host);
    note_end();
  }
}

ScriptStatus LevelSession::status() const {
  if (out_of_bounds_ || head_hit_) return ScriptStatus::lost;
  return script_ ? script_->status() : ScriptStatus::running;
}

EndReason LevelSession::end_reason() const {
  if (out_of_bounds_) return EndReason::out_of_bounds;
  if (head_hit_) return EndReason::head_hit;
  return script_ ? script_->end_reason() : EndReason::none;
}

void LevelSession::note_end() {
  if (!end_tick_ && status() != ScriptStatus::running) end_tick_ = world_.tick();
}

void LevelSession::check_bounds() {
  if (!bounds_ || status() != ScriptStatus::running) return;
  const std::optional<Vec2> player = player_position();
  if (!player) return;
  const Vec2 c = *player;
  const Aabb& b = *bounds_;
  if (c.x >= b.min.x && c.x <= b.max.x && c.y >= b.min.y && c.y <= b.max.y) return;
  if (has_checkpoints_) {
    respawn_player();
    ++respawns_;
    return;
  }
  out_of_bounds_ = true;
}

void LevelSession::step(const TickInput& input) {
  world_.step(input);
  const std::uint64_t now = world_.tick();
  std::erase_if(messages_, [&](const ScriptMessage& m) {
    if (m.until_tick > now) return false;
    message_bytes_ -= m.text.size();
    return true;
  });
  // The script has stopped once the level is over; so it has when the bounds ended it.
  if (script_ && !out_of_bounds_ && !head_hit_) {
    SessionScriptHost host(*this);
    script_->update(host);
  }
  check_bounds();
  check_head();
  note_end();
}

void LevelSession::show_message(std::string_view text, double seconds) {
  const RunBudgets& budgets = world_.budgets();
  if (messages_.size() >= static_cast<std::size_t>(budgets.messages)) {
    world_.budget_reached(ParamId::budget_messages);
    return;
  }
  if (message_bytes_ + text.size() > static_cast<std::size_t>(budgets.message_bytes)) {
    world_.budget_reached(ParamId::budget_message_bytes);
    return;
  }
  const auto ticks = static_cast<std::uint64_t>(std::ceil(seconds / world_.config().dt));
  messages_.push_back({std::string(text), world_.tick() + ticks});
  message_bytes_ += text.size();
}

bool LevelSession::take_firing() {
  if (firing_tick_ != world_.tick()) firing_tick_ = world_.tick(), firings_ = 0;
  if (firings_ >= world_.budgets().firings_per_tick) {
    world_.budget_reached(ParamId::budget_firings_per_tick);
    return false;
  }
  ++firings_;
  return true;
}

void LevelSession::respawn_player() {
  if (const auto v = world_.player_vehicle())
    world_.reset_vehicle(*v, checkpoint_);
  else if (const Tire* p = world_.player())
    world_.reset_tire(p->id, checkpoint_);
}

std::optional<Vec2> LevelSession::player_position() const {
  if (const auto v = world_.player_vehicle())
    return world_.rigid().prop_state(world_.vehicles().chassis(*v)).center;
  if (const Tire* p = world_.player()) return p->centroid();
  return std::nullopt;
}

void LevelSession::set_vehicle_head(std::uint32_t v, const VehicleHead& head) {
  if (heads_.size() <= v) heads_.resize(v + 1);
  heads_[v] = head;
}

const std::optional<VehicleHead>& LevelSession::vehicle_head(std::uint32_t v) const {
  static const std::optional<VehicleHead> none;
  return v < heads_.size() ? heads_[v] : none;
}

std::optional<Vec2> LevelSession::vehicle_head_center(std::uint32_t v) const {
  const std::optional<VehicleHead>& head = vehicle_head(v);
  if (!head || v >= world_.vehicles().count()) return std::nullopt;
  return world_.rigid().current_pose(world_.vehicles().chassis(v)).to_world(head->position);
}

void LevelSession::check_head() {
  if (status() != ScriptStatus::running) return;
  const auto v = world_.player_vehicle();
  if (!v) return;
  const std::optional<Vec2> center = vehicle_head_center(*v);
  if (!center) return;
  const double radius = vehicle_head(*v)->radius;
  const RigidWorld& rigid = world_.rigid();
  rigid.query(Aabb{*center, *center}.expanded(radius), near_obstacles_, near_props_);
  bool hit = false;
  for (const std::uint32_t o : near_obstacles_) {
    const Aabb& box = rigid.obstacles()[o].box;
    const Vec2 nearest{std::clamp(center->x, box.min.x, box.max.x),
                       std::clamp(center->y, box.min.y, box.max.y)};
    hit = hit || length_squared(nearest - *center) <= radius * radius;
  }
  for (const std::uint32_t i : near_props_) {
    const Prop& p = rigid.props()[i];
    if (!p.alive || p.spec.type == PropType::dynamic_body) continue;  // the ground is static or kinematic
    hit = hit || circle_touches(p.geometry, rigid.current_pose(i).to_local(*center), radius);
  }
  if (!hit) return;
  head_hit_ = true;
  show_message("the driver's head hit the ground", 3.0);
}

std::optional<TireId> LevelSession::grab(Vec2 point, double radius) {
  release_grab();
  // The nearest tread particle within `radius`; failing that, the tire whose hub is under the
  // point, by its nearest tread particle.
  const Tire* chosen = nullptr;
  std::uint32_t particle = 0;
  double best = radius * radius;
  for (const Tire& t : world_.tires())
    for (std::uint32_t i = 0; i < t.n; ++i)
      if (const double d2 = length_squared(t.particles.x[i] - point); d2 < best)
        best = d2, chosen = &t, particle = i;
  if (!chosen) {
    for (const Tire& t : world_.tires()) {
      if (length(t.centroid() - point) >= t.spec.outer_radius) continue;
      chosen = &t;
      double nearest = 1e300;
      for (std::uint32_t i = 0; i < t.n; ++i)
        if (const double d2 = length_squared(t.particles.x[i] - point); d2 < nearest)
          nearest = d2, particle = i;
      break;
    }
  }
  if (!chosen) return std::nullopt;
  grabbed_ = chosen->id;
  world_.grab_particle(*grabbed_, particle, point);
  return grabbed_;
}

void LevelSession::move_grab(Vec2 target) {
  if (grabbed_) world_.move_grabbed_particle(*grabbed_, target);
}

void LevelSession::release_grab() {
  if (grabbed_) world_.release_particle(*grabbed_);
  grabbed_.reset();
}

std::uint64_t LevelSession::state_hash() const {
  StateHash h;
  world_.hash_into(h);
  if (script_) script_->hash_into(h);
  // Only once it happens, so that the digest of every run that never left the bounds stays what it
  // was before bounds existed (the replays' recorded hashes).
  if (out_of_bounds_) h.add(std::uint8_t{1});
  if (head_hit_) h.add(std::uint8_t{2});
  return h.digest();
}

}  // namespace tire
