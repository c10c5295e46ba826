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
}

void Ghost::sync(std::uint64_t tick) {
  if (!simulation_) return;
  if (tick < tick_) restart();
  while (tick_ < tick && tick_ < replay_.ticks) {
    held_.jump = false;
    while (next_input_ < replay_.inputs.size() && replay_.inputs[next_input_].tick == tick_)
      simulation_->apply(replay_.inputs[next_input_++], held_);
    if (const std::optional<tire::TireView> p = player())
      previous_.assign(p->positions.begin(), p->positions.end());
    simulation_->step(held_);
    ++tick_;
  }
  // Its run is over: it holds still where it finished.
  if (tick > tick_)
    if (const std::optional<tire::TireView> p = player())
      previous_.assign(p->positions.begin(), p->positions.end());
}

std::optional<tire::TireView> Ghost::player() const {
  if (!simulation_) return std::nullopt;
  const std::optional<tire::TireId> id = simulation_->player();
  return id ? simulation_->tire(*id) : std::nullopt;
}

void Ghost::interpolated_positions(double alpha, std::vector<tire::Vec2>& out) const {
  const std::optional<tire::TireView> p = player();
  out.clear();
  if (!p) return;
  const std::span<const tire::Vec2> now = p->positions;
  out.resize(now.size());
  const bool blend = previous_.size() == now.size();
  for (std::size_t i = 0; i < now.size(); ++i)
    out[i] = blend ? tire::Vec2{std::lerp(previous_[i].x, now[i].x, alpha),
                                std::lerp(previous_[i].y, now[i].y, alpha)}
                   : now[i];
}

}  // namespace game
