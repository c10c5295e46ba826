#include "progress/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "tire/io/file_io.h"

namespace game {

namespace {

const char* type_name(const nlohmann::json& j) { return j.type_name(); }

}  // namespace

std::optional<std::filesystem::path> data_dir_from_env() {
  const char* xdg = std::getenv("XDG_DATA_HOME");
  if (xdg && *xdg && std::filesystem::path(xdg).is_absolute())
    return std::filesystem::path(xdg) / "soft-tire";
  const char* home = std::getenv("HOME");
  if (home && *home) return std::filesystem::path(home) / ".local" / "share" / "soft-tire";
  return std::nullopt;
}

std::string unusable_data_dir(const std::filesystem::path& dir) {
  // The nearest part of the path that exists must be a folder (the rest is made when saving).
  for (std::filesystem::path p = dir; !p.empty(); p = p.parent_path()) {
    std::error_code ec;
    const std::filesystem::file_status st = std::filesystem::status(p, ec);
    if (st.type() == std::filesystem::file_type::not_found) {
      if (p == p.parent_path()) break;
      continue;
    }
    if (ec) return "cannot look at " + tire::printable(p.string()) + ": " + ec.message();
    if (!std::filesystem::is_directory(st)) return tire::printable(p.string()) + " is not a folder";
    return "";
  }
  return "";
}

std::string level_key(const std::filesystem::path& levels_dir, const std::filesystem::path& level_file) {
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::weakly_canonical(level_file, ec);
  const std::filesystem::path dir = std::filesystem::weakly_canonical(levels_dir, ec);
  const std::filesystem::path rel = file.lexically_relative(dir);
  if (!rel.empty() && *rel.begin() != "..") return rel.generic_string();
  return file.generic_string();
}

bool of_version(const LevelRecord& record, const std::string& level_sha256) {
  return !record.level_sha256.empty() && record.level_sha256 == level_sha256;
}

std::string format_record(const LevelRecord* record, bool earlier) {
  if (!record) return "";
  if (!record->won) return earlier ? "not won since it changed" : "not won yet";
  char text[64];
  std::snprintf(text, sizeof text, "best %.2f s", record->best_time);
  std::string out = text;
  if (record->medal != tire::Medal::none) out += ", " + std::string(tire::medal_name(record->medal));
  return earlier ? out + kEarlierVersion : out;
}

std::optional<std::map<std::string, LevelRecord>> Progress::parse(const std::string& text,
                                                                  std::string& error) {
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded()) {
    error = "not valid JSON (cut short or damaged)";
    return std::nullopt;
  }
  if (!doc.is_object()) {
    error = std::string("/: must be an object, got ") + type_name(doc);
    return std::nullopt;
  }
  const auto format = doc.find("format");
  if (format == doc.end() || !format->is_string() || format->get<std::string>() != kProgressFormat) {
    error = std::string("/format: must be \"") + kProgressFormat + "\"";
    return std::nullopt;
  }
  const auto levels = doc.find("levels");
  if (levels == doc.end() || !levels->is_object()) {
    error = "/levels: must be an object of level records";
    return std::nullopt;
  }
  std::map<std::string, LevelRecord> out;
  for (const auto& [key, entry] : levels->items()) {
    const std::string path = "/levels/" + key;
    if (!entry.is_object()) {
      error = path + ": must be an object, got " + type_name(entry);
      return std::nullopt;
    }
    LevelRecord r;
    const auto won = entry.find("won");
    if (won == entry.end() || !won->is_boolean()) {
      error = path + "/won: must be true or false";
      return std::nullopt;
    }
    r.won = won->get<bool>();
    if (r.won) {
      const auto time = entry.find("best_time");
      if (time == entry.end() || !time->is_number() || !std::isfinite(time->get<double>()) ||
          time->get<double>() < 0.0) {
        error = path + "/best_time: must be a time in seconds (a number >= 0)";
        return std::nullopt;
      }
      r.best_time = time->get<double>();
      const auto ticks = entry.find("best_ticks");
      if (ticks == entry.end() || !ticks->is_number_unsigned()) {
        error = path + "/best_ticks: must be an integer >= 0";
        return std::nullopt;
      }
      r.best_ticks = ticks->get<std::uint64_t>();
      if (const auto medal = entry.find("medal"); medal != entry.end()) {
        const std::optional<tire::Medal> m =
            medal->is_string() ? tire::medal_from_name(medal->get<std::string>()) : std::nullopt;
        if (!m) {
          error = path + "/medal: must be \"gold\", \"silver\", \"bronze\" or \"none\"";
          return std::nullopt;
        }
        r.medal = *m;
      }
    }
    if (const auto sha = entry.find("level_sha256"); sha != entry.end()) {
      if (!sha->is_string() || !tire::is_lowercase_hex(sha->get<std::string>(), 64)) {
        error = path + "/level_sha256: must be 64 lowercase hex digits";
        return std::nullopt;
      }
      r.level_sha256 = sha->get<std::string>();
    }
    out[key] = r;
  }
  return out;
}

std::vector<std::string> Progress::load(const std::filesystem::path& dir) {
  dir_ = dir;
  levels_.clear();
  const std::filesystem::path f = file();
  std::error_code ec;
  if (!std::filesystem::exists(f, ec)) return {};
  std::string error;
  const std::optional<std::string> text = tire::read_file(f, kMaxProgressBytes, error);
  std::optional<std::map<std::string, LevelRecord>> parsed;
  if (text) parsed = parse(*text, error);
  if (parsed) {
    levels_ = std::move(*parsed);
    return {};
  }
  std::vector<std::string> warnings;
  std::filesystem::path aside = f;
  aside += kDamagedSuffix;
  std::filesystem::rename(f, aside, ec);
  warnings.push_back("progress file " + tire::printable(f.string()) + " is damaged: " + error + "; " +
                     (ec ? "could not set it aside (" + ec.message() + ")"
                         : "set aside as " + tire::printable(aside.string())) +
                     "; starting with no progress");
  return warnings;
}

std::string Progress::to_json() const {
  nlohmann::json levels = nlohmann::json::object();
  for (const auto& [key, r] : levels_) {
    nlohmann::json entry{{"won", r.won}};
    if (r.won) {
      entry["best_time"] = r.best_time;
      entry["best_ticks"] = r.best_ticks;
      if (r.medal != tire::Medal::none) entry["medal"] = tire::medal_name(r.medal);
    }
    if (!r.level_sha256.empty()) entry["level_sha256"] = r.level_sha256;
    levels[key] = entry;
  }
  return nlohmann::json{{"format", kProgressFormat}, {"levels", levels}}.dump(2) + "\n";
}

const LevelRecord* Progress::find(const std::string& key) const {
  const auto it = levels_.find(key);
  return it == levels_.end() ? nullptr : &it->second;
}

bool Progress::record(const std::string& key, const std::string& level_sha256, bool won, double time,
                      std::uint64_t ticks, tire::Medal medal) {
  LevelRecord& r = levels_[key];
  if (!of_version(r, level_sha256)) r = LevelRecord{.level_sha256 = level_sha256};  // the level changed
  if (!won) return false;
  const bool best = !r.won || time < r.best_time;
  if (best) {
    r.won = true;
    r.best_time = time;
    r.best_ticks = ticks;
  }
  r.medal = std::max(r.medal, medal);
  return best;
}

void Progress::restore(const std::string& key, const std::optional<LevelRecord>& before) {
  if (before)
    levels_[key] = *before;
  else
    levels_.erase(key);
}

std::string Progress::save() const {
  if (dir_.empty()) return "no data folder";
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) return "cannot make " + tire::printable(dir_.string()) + ": " + ec.message();
  std::string error;
  if (!tire::write_file_atomically(file(), to_json(), error)) return error;
  return "";
}

std::filesystem::path Progress::ghost_file(const std::string& key) const {
  std::string name = key;
  if (name.size() > 5 && name.ends_with(".json")) name.resize(name.size() - 5);
  for (char& c : name) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_' || c == '.';
    if (!safe) c = '_';
  }
  return dir_ / "ghosts" / (name + ".json");
}

}  // namespace game
