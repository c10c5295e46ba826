// Records every session as a replay (tire/replay/replay_file.h): attached to the GameSession as its
// observer, it turns each input the simulation receives into a replay input, at the replay's own
// tick count. A restart of the same level is a "restart" input; loading another level (or a changed
// file) starts a new recording. F5 saves the current one.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "input/session_input.h"
#include "tire/replay/replay_file.h"

namespace game {

// The SHA-256 of a level file's bytes (what a replay records), or "" when it cannot be read.
std::string level_file_sha256(const std::filesystem::path& file);

// The part of a recording after its last restart, as a replay of its own from tick 0: the run that
// ended the recording (the recorder keeps one recording across restarts of a level).
tire::Replay last_attempt(const tire::Replay& replay);

class SessionRecorder final : public SessionObserver {
 public:
  // Starts recording `level_file` (a session's first level, which is not loaded by an event).
  void begin(const std::filesystem::path& level_file, tire::Vec2 gravity);

  void on_events(std::uint64_t tick, const std::vector<SessionEvent>& events) override;
  void on_step(std::uint64_t tick, const tire::TickInput& input) override;
  void on_stepped(const tire::Simulation& session) override;

  // Writes the recording so far (atomically) to `file`; the level path inside is relative to it.
  // `last_run_only`: only what followed the last restart (last_attempt). Returns an error text, or
  // "" when saved.
  std::string save(const tire::Simulation& session, const std::filesystem::path& file,
                   bool last_run_only = false) const;
  // As save, but never over an existing file (F5): `file` when free, else the first free one of
  // <stem>-2.json, <stem>-3.json, ... (tire::write_new_file_atomically). Returns the file written,
  // or nullopt with `error` set.
  std::optional<std::filesystem::path> save_new(const tire::Simulation& session,
                                                const std::filesystem::path& file, std::string& error) const;
  // A file name the player can find: <dir>/<level name>-<YYYYmmdd-HHMMSS>.json (save_new numbers
  // a second save in the same second).
  std::filesystem::path default_file(const std::filesystem::path& dir) const;

  std::uint64_t ticks() const { return recorder_ ? recorder_->ticks() : 0; }

 private:
  void input(tire::ReplayInput in);
  // The recording as replay JSON to be written at `target` (absolute; its folder is made), the
  // level named relative to it.
  std::optional<std::string> replay_json(const tire::Simulation& session, const std::filesystem::path& target,
                                         bool last_run_only, std::string& error) const;

  std::optional<tire::ReplayRecorder> recorder_;
  std::filesystem::path level_file_;  // absolute
  std::string level_sha256_;
  double steer_ = 0.0;
  double inflate_ = 0.0;
  double lean_ = 0.0;
  bool brake_ = false;
  tire::Vec2 gravity_;
};

}  // namespace game
