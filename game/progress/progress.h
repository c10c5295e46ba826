// The player's progress: for each level, whether it was won and the best time, kept in
// progress.json in the user's data folder ($XDG_DATA_HOME/soft-tire/, else
// $HOME/.local/share/soft-tire/). A level is keyed by its file's path relative to the levels
// folder ("01-first-roll.json"; a level from elsewhere by its absolute path), so that renaming a
// level inside the file keeps its record and two levels of the same name do not share one. A record
// holds the SHA-256 of the level file it was made on: once the file changes, its times are of an
// earlier version of the level, shown as such, and the next finished run starts a new record.
//
//   { "format": "soft-tire-progress/1",
//     "levels": { "01-first-roll.json": { "won": true, "best_time": 9.85, "best_ticks": 591,
//                                         "medal": "gold", "level_sha256": "3f0c…" } } }
//
// The file is written atomically (tire::write_file_atomically). A damaged one (not JSON, cut short,
// wrong types) is reported, renamed to progress.json.damaged, and the game starts with none.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tire/io/level_medals.h"

namespace game {

inline constexpr const char* kProgressFormat = "soft-tire-progress/1";
inline constexpr const char* kProgressFile = "progress.json";
inline constexpr const char* kDamagedSuffix = ".damaged";
// Bigger than any progress file could honestly be (a record is under 100 bytes).
inline constexpr std::uintmax_t kMaxProgressBytes = 16u << 20;

struct LevelRecord {
  bool won = false;
  double best_time = 0.0;                 // s of simulated time, when won
  std::uint64_t best_ticks = 0;           // the same in ticks
  tire::Medal medal = tire::Medal::none;  // the best medal a win earned (levels/README.md, "medals")
  std::string level_sha256;               // the level file's, lowercase hex; "" in a record from before
};

// Whether `record` was made on the level file whose bytes hash to `level_sha256` (a record that
// does not say which file it was made on is not).
bool of_version(const LevelRecord& record, const std::string& level_sha256);

// The data folder from the environment: $XDG_DATA_HOME/soft-tire (when set and absolute), else
// $HOME/.local/share/soft-tire; nullopt when neither is set.
std::optional<std::filesystem::path> data_dir_from_env();

// "" when `dir` can be the data folder, else why not: a part of it that exists and is not a folder
// ("XDG_DATA_HOME=/some/file"), named, so that nothing is promised that cannot be saved there.
std::string unusable_data_dir(const std::filesystem::path& dir);

// The key of `level_file` in the progress file: its path relative to `levels_dir`, or its absolute
// path when it is not inside it.
std::string level_key(const std::filesystem::path& levels_dir, const std::filesystem::path& level_file);

// "best 9.85 s" for a won level ("best 9.85 s, gold" with a medal), "not won yet" for one played but
// not won, "" for none. A record of an earlier version of the level (`earlier`) says so: "best 9.85 s
// on an earlier version", "not won since it changed".
std::string format_record(const LevelRecord* record, bool earlier = false);
inline constexpr const char* kEarlierVersion = " on an earlier version";

class Progress {
 public:
  // Reads DIR/progress.json (none there: no progress yet). A damaged file is set aside; the
  // returned warnings say which file and what was wrong.
  std::vector<std::string> load(const std::filesystem::path& dir);
  // Parses the file's text; nullopt with `error` set when it is damaged.
  static std::optional<std::map<std::string, LevelRecord>> parse(const std::string& text, std::string& error);
  std::string to_json() const;

  const LevelRecord* find(const std::string& key) const;
  // A finished run of level `key` (its file's bytes hashing to `level_sha256`), and the medal it
  // earned; true when it is a win faster than the best so far on this version of the level (or the
  // first win on it). The record keeps the best medal won; a record of another version starts over.
  bool record(const std::string& key, const std::string& level_sha256, bool won, double time,
              std::uint64_t ticks, tire::Medal medal = tire::Medal::none);
  // Puts level `key`'s record back as it was before record() (nullopt: none): after a save that
  // failed, what the game shows stays what the file holds.
  void restore(const std::string& key, const std::optional<LevelRecord>& before);
  // Writes the file atomically; "" or why not.
  std::string save() const;

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path file() const { return dir_ / kProgressFile; }
  // Where level `key`'s best run is kept as a replay: DIR/ghosts/<key, without .json, made safe>.json
  std::filesystem::path ghost_file(const std::string& key) const;

 private:
  std::filesystem::path dir_;
  std::map<std::string, LevelRecord> levels_;
};

}  // namespace game
