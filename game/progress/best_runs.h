// Progress and the ghost together, as the app sees them: a level starting loads its ghost, each tick
// moves the ghost along, a finished level is recorded (and a new best run kept as the level's ghost),
// and the menu and the exit summary read the records. Off with --no-progress (or when there is no
// data folder): then nothing is read or written.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "play/session_recorder.h"
#include "progress/ghost.h"
#include "progress/progress.h"

namespace game {

// What a finished level came to, for the end screen.
struct RunResult {
  bool won = false;
  double time = 0.0;
  std::uint64_t ticks = 0;
  bool new_best = false;                  // a win faster than the best so far, and saved as the new best
  bool saved = false;                     // the progress file was written with this run
  std::string note;                       // "New best time!" or "best 9.85 s"
  tire::Medal medal = tire::Medal::none;  // what the win earned, when the level has medals
};

class BestRuns {
 public:
  // Reads the progress in `dir` (nullopt: off). Returns the warnings to show (a damaged file).
  std::vector<std::string> open(std::optional<std::filesystem::path> dir, std::filesystem::path levels_dir);
  bool enabled() const { return enabled_; }

  // A level (re)started from `level_path`: its ghost loads (or starts over, on a restart).
  void level_started(const std::string& level_path, std::shared_ptr<const tire::Level> level,
                     std::vector<std::string>& messages);
  // The player's world has run `tick` ticks: the ghost catches up.
  void ticked(std::uint64_t tick) { ghost_.sync(tick); }
  // The level was won or lost after `ticks` (`time` s). A new best keeps the run (the recording
  // since the last restart) as the level's ghost. `record`: false for a level that is not the file
  // on disk (an unsaved edit), which is not recorded.
  RunResult finished(bool won, double time, std::uint64_t ticks, bool record, const SessionRecorder& recorder,
                     const tire::Simulation& session, std::vector<std::string>& messages);

  // How many times the progress or a ghost was written (or a damaged file set aside) so far: the
  // browser build copies the data folder to the page's IndexedDB when it changes.
  std::uint64_t writes() const { return writes_; }

  // The menu's note for a level file: "best 9.85 s", "not won yet" or "" (with "on an earlier
  // version" or "not won since it changed" once the file has changed since its record).
  std::string note(const std::filesystem::path& level_file) const;
  // The HUD's time to beat: the best ("best 9.85 s, silver") and, in a level with `medals`, the
  // next medal's time ("gold within 7.00 s"; gold's before any medal); "" for neither. A record of
  // an earlier version of the level is no time to beat.
  std::string target(const std::filesystem::path& level_file,
                     const std::optional<tire::LevelMedals>& medals) const;
  Ghost& ghost() { return ghost_; }
  const Ghost& ghost() const { return ghost_; }
  // For the exit summary: the progress file, this level's record and the menu's note, the last run,
  // and the ghost (loaded, visible, its tick and position).
  nlohmann::json summary(const std::string& level_path) const;

 private:
  // Level `level_file`'s record and whether it is of the file as it is now (nullptr: none).
  std::pair<const LevelRecord*, bool> record_of(const std::filesystem::path& level_file) const;
  // The SHA-256 of a level file's bytes, read again only when its size or time of change moves
  // (the menu asks for every level each frame).
  const std::string& file_sha256(const std::filesystem::path& level_file) const;
  struct FileHash {
    std::filesystem::file_time_type changed;
    std::uintmax_t size = 0;
    std::string sha256;
  };

  bool enabled_ = false;
  std::filesystem::path levels_dir_;
  Progress progress_;
  Ghost ghost_;
  std::string key_, sha_;                    // the level the ghost was loaded for
  std::string level_sha256_;                 // the current level's file, as it was started
  std::optional<tire::LevelMedals> medals_;  // the current level's
  double dt_ = 0.0;                          // and its tick
  std::optional<RunResult> last_;
  std::uint64_t writes_ = 0;
  mutable std::map<std::string, FileHash> file_hashes_;
};

}  // namespace game
