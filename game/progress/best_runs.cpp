#include "progress/best_runs.h"

#include <cstdio>

#include "tire/io/file_io.h"

namespace game {

std::vector<std::string> BestRuns::open(std::optional<std::filesystem::path> dir,
                                        std::filesystem::path levels_dir) {
  levels_dir_ = std::move(levels_dir);
  enabled_ = dir.has_value();
  if (!enabled_) return {};
  // A data folder that cannot be one (XDG_DATA_HOME naming a file) is said now; each finished level
  // says again that it was not saved.
  std::vector<std::string> warnings = progress_.load(*dir);
  if (!warnings.empty()) ++writes_;  // a damaged file was set aside (renamed)
  if (const std::string why = unusable_data_dir(*dir); !why.empty())
    warnings.push_back("progress and best runs cannot be kept in " + tire::printable(dir->string()) + ": " +
                       why + "; nothing will be saved");
  return warnings;
}

void BestRuns::level_started(const std::string& level_path, std::shared_ptr<const tire::Level> level,
                             std::vector<std::string>& messages) {
  last_.reset();
  const tire::LevelInfo info = level ? tire::level_info(*level) : tire::LevelInfo{};
  medals_ = info.medals;
  dt_ = info.dt;
  if (!enabled_) return;
  const std::string key = level_key(levels_dir_, level_path);
  const std::string sha = level_file_sha256(level_path);
  level_sha256_ = sha;
  if (key == key_ && sha == sha_) {
    ghost_.sync(0);  // a restart: the ghost starts over with the player
    return;
  }
  key_ = key;
  sha_ = sha;
  const bool visible = ghost_.visible;
  if (const std::string why = ghost_.load(progress_.ghost_file(key), std::move(level), sha); !why.empty())
    messages.push_back(why);
  ghost_.visible = visible;
}

RunResult BestRuns::finished(bool won, double time, std::uint64_t ticks, bool record,
                             const SessionRecorder& recorder, const tire::Simulation& session,
                             std::vector<std::string>& messages) {
  RunResult r;
  r.won = won;
  r.time = time;
  r.ticks = ticks;
  if (won && medals_) r.medal = tire::medal_for(*medals_, ticks, dt_);
  if (!enabled_ || !record) {
    last_ = r;
    return r;
  }
  const std::string key = key_;
  const LevelRecord* known = progress_.find(key);
  const std::optional<LevelRecord> before = known ? std::optional<LevelRecord>(*known) : std::nullopt;
  const bool faster = progress_.record(key, level_sha256_, won, time, ticks, r.medal);
  ++writes_;
  if (const std::string err = progress_.save(); !err.empty()) {
    // Not saved: the record goes back to what the file holds, and no new best is claimed.
    progress_.restore(key, before);
    messages.push_back("cannot save the progress to " + tire::printable(progress_.file().string()) + ": " +
                       err + (faster ? "; this best time is not kept" : ""));
    if (won)
      r.note =
          faster ? "best time not saved: the progress file cannot be written"
                 : format_record(before ? &*before : nullptr, before && !of_version(*before, level_sha256_));
    last_ = r;
    return r;
  }
  r.saved = true;
  r.new_best = faster;
  if (won) {
    r.note = r.new_best ? "New best time!" : format_record(progress_.find(key));
    // The run is the ghost when it is the best, or when there is no (valid) ghost of this level.
    if (r.new_best || !ghost_.loaded()) {
      const std::filesystem::path file = progress_.ghost_file(key);
      if (const std::string err = recorder.save(session, file, true); !err.empty())
        messages.push_back("cannot save the ghost " + tire::printable(file.string()) + ": " + err);
      else
        sha_.clear();  // the next start of this level loads the new ghost
    }
  }
  last_ = r;
  return r;
}

const std::string& BestRuns::file_sha256(const std::filesystem::path& level_file) const {
  FileHash& known = file_hashes_[level_file.string()];
  std::error_code ec;
  const std::filesystem::file_time_type changed = std::filesystem::last_write_time(level_file, ec);
  const std::uintmax_t size = ec ? 0 : std::filesystem::file_size(level_file, ec);
  if (ec || known.sha256.empty() || changed != known.changed || size != known.size)
    known = {changed, size, level_file_sha256(level_file)};
  return known.sha256;
}

std::pair<const LevelRecord*, bool> BestRuns::record_of(const std::filesystem::path& level_file) const {
  const LevelRecord* r = enabled_ ? progress_.find(level_key(levels_dir_, level_file)) : nullptr;
  return {r, r && of_version(*r, file_sha256(level_file))};
}

std::string BestRuns::note(const std::filesystem::path& level_file) const {
  const auto [r, current] = record_of(level_file);
  return format_record(r, !current);
}

std::string BestRuns::target(const std::filesystem::path& level_file,
                             const std::optional<tire::LevelMedals>& medals) const {
  auto [r, current] = record_of(level_file);
  if (!current) r = nullptr;
  std::string out = r && r->won ? format_record(r) : "";
  const tire::Medal have = r && r->won ? r->medal : tire::Medal::none;
  const tire::Medal next = have == tire::Medal::none ? tire::Medal::gold : tire::next_medal(have);
  if (medals && next != tire::Medal::none) {
    char text[64];
    std::snprintf(text, sizeof text, "%s within %.2f s", std::string(tire::medal_name(next)).c_str(),
                  *tire::medal_time(*medals, next));
    out += (out.empty() ? "" : "  -  ") + std::string(text);
  }
  return out;
}

nlohmann::json BestRuns::summary(const std::string& level_path) const {
  nlohmann::json out{{"enabled", enabled_}};
  if (!enabled_) return out;
  const std::string key = level_key(levels_dir_, level_path);
  out["file"] = progress_.file().string();
  out["level"] = key;
  const auto [r, current] = record_of(level_path);
  out["won"] = r && r->won;
  out["of_this_version"] = current;
  out["best_time"] = r && r->won ? nlohmann::json(r->best_time) : nlohmann::json(nullptr);
  out["menu"] = format_record(r, !current);  // note()'s, without looking the record up again
  if (last_)
    out["run"] = {
        {"won", last_->won}, {"time", last_->time}, {"new_best", last_->new_best}, {"saved", last_->saved}};
  nlohmann::json g{{"loaded", ghost_.loaded()}, {"visible", ghost_.visible}};
  if (ghost_.loaded()) {
    g["file"] = ghost_.file().string();
    g["tick"] = ghost_.tick();
    g["ticks"] = ghost_.ticks();
    if (const std::optional<tire::Vec2> c = ghost_.position()) g["position"] = {c->x, c->y};
  }
  out["ghost"] = g;
  return out;
}

}  // namespace game
