#include "progress/ghost.h"

#include <cmath>
#include <span>

#include "tire/io/file_io.h"

namespace game {

std::string Ghost::load(const std::filesystem::path& file, std::shared_ptr<const tire::Level> level,
                        const std::string& level_sha256) {
  clear();
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return "";
  tire::ReplayLoad load = tire::load_replay_file(file);
  if (!load.replay) {
    std::string why = "cannot read the ghost " + tire::printable(file.string());
    if (!load.errors.empty()) why += ": " + load.errors.front();
    return why;
  }
  if (load.replay->level_sha256 != level_sha256)
    return "ghost dropped: the level changed since " + tire::printable(file.string()) + " was recorded";
  replay_ = std::move(*load.replay);
  level_ = std::move(level);
  file_ = file;
  restart();
  return "";
}

void Ghost::clear() {
  simulation_.reset();
  level_.reset();
  replay_ = {};
  file_.clear();
  tick_ = 0;
}

void Ghost::restart() {
  simulation_ = std::make_unique<tire::Simulation>(level_);
  tick_ = 0;
  next_input_ = 0;
  held_ = {};
  previous_.clear();
  previous_chassis_.reset();
}

void Ghost::remember() {
  previous_.clear();
  previous_chassis_.reset();
  if (const std::optional<tire::TireView> p = player()) {
    previous_.assign(p->positions.begin(), p->positions.end());
  } else if (const std::optional<tire::VehicleView> v = vehicle()) {
    previous_chassis_ = v->pose;
    for (const tire::TireId id : v->wheels())
      if (const std::optional<tire::TireView> w = simulation_->tire(id))
        previous_.insert(previous_.end(), w->positions.begin(), w->positions.end());
  }
}

void Ghost::sync(std::uint64_t tick) {
  if (!simulation_) return;
  if (tick < tick_) restart();
  while (tick_ < tick && tick_ < replay_.ticks) {
    held_.jump = false;
    while (next_input_ < replay_.inputs.size() && replay_.inputs[next_input_].tick == tick_)
      simulation_->apply(replay_.inputs[next_input_++], held_);
    remember();
    simulation_->step(held_);
    ++tick_;
  }
  // Its run is over: it holds still where it finished.
  if (tick > tick_) remember();
}

std::optional<tire::TireView> Ghost::player() const {
  if (!simulation_) return std::nullopt;
  const std::optional<tire::TireId> id = simulation_->player();
  return id ? simulation_->tire(*id) : std::nullopt;
}

namespace {

// `now` blended from `before` (when it has as many points) by `alpha`.
void blend(std::span<const tire::Vec2> before, std::span<const tire::Vec2> now, double alpha,
           std::vector<tire::Vec2>& out) {
  out.resize(now.size());
  const bool blend = before.size() == now.size();
  for (std::size_t i = 0; i < now.size(); ++i)
    out[i] =
        blend ? tire::Vec2{std::lerp(before[i].x, now[i].x, alpha), std::lerp(before[i].y, now[i].y, alpha)}
              : now[i];
}

}  // namespace

void Ghost::interpolated_positions(double alpha, std::vector<tire::Vec2>& out) const {
  const std::optional<tire::TireView> p = player();
  out.clear();
  if (!p) return;
  blend(previous_, p->positions, alpha, out);
}

std::optional<tire::VehicleView> Ghost::vehicle() const {
  if (!simulation_) return std::nullopt;
  for (std::size_t i = 0; std::optional<tire::VehicleView> v = simulation_->vehicle_at(i); ++i)
    if (v->player) return v;
  return std::nullopt;
}

std::optional<tire::PropView> Ghost::chassis() const {
  const std::optional<tire::VehicleView> v = vehicle();
  return v ? simulation_->prop(v->chassis) : std::nullopt;
}

tire::Pose Ghost::interpolated_chassis(double alpha) const {
  const std::optional<tire::VehicleView> v = vehicle();
  if (!v) return {};
  if (!previous_chassis_) return v->pose;
  const tire::Pose& a = *previous_chassis_;
  return tire::Pose::make({std::lerp(a.position.x, v->pose.position.x, alpha),
                           std::lerp(a.position.y, v->pose.position.y, alpha)},
                          std::lerp(a.angle, v->pose.angle, alpha));
}

void Ghost::interpolated_wheel(std::size_t w, double alpha, std::vector<tire::Vec2>& out) const {
  out.clear();
  const std::optional<tire::VehicleView> v = vehicle();
  if (!v || w >= v->wheel_count) return;
  // The wheels' particles lie one after another in previous_, in the vehicle's order.
  std::size_t first = 0;
  std::optional<tire::TireView> wheel;
  for (std::size_t k = 0; k <= w; ++k) {
    if (wheel) first += wheel->positions.size();
    wheel = simulation_->tire(v->wheel_ids[k]);
    if (!wheel) return;
  }
  const std::span<const tire::Vec2> before =
      first + wheel->positions.size() <= previous_.size()
          ? std::span<const tire::Vec2>(previous_).subspan(first, wheel->positions.size())
          : std::span<const tire::Vec2>();
  blend(before, wheel->positions, alpha, out);
}

std::optional<tire::Vec2> Ghost::position() const {
  if (const std::optional<tire::TireView> p = player()) return p->centroid;
  if (const std::optional<tire::VehicleView> v = vehicle()) return v->center;
  return std::nullopt;
}

}  // namespace game
