#include "play/session_recorder.h"

#include <chrono>
#include <cmath>
#include <ctime>

#include "tire/io/file_io.h"
#include "tire/io/level_format.h"

namespace game {

std::string level_file_sha256(const std::filesystem::path& file) {
  std::string error;
  const auto bytes = tire::read_level_text(file, error);
  return bytes ? tire::sha256_hex(*bytes) : std::string();
}

namespace {
// What the recording names: an unreadable level as 64 zeros (a replay needs 64 hex digits).
std::string level_sha(const std::filesystem::path& file) {
  const std::string sha = level_file_sha256(file);
  return sha.empty() ? std::string(64, '0') : sha;
}
}  // namespace

tire::Replay last_attempt(const tire::Replay& replay) {
  std::size_t start = replay.inputs.size();
  for (std::size_t i = replay.inputs.size(); i-- > 0;)
    if (replay.inputs[i].restart) {
      start = i;
      break;
    }
  if (start == replay.inputs.size()) return replay;  // no restart: the whole recording is one run
  const std::uint64_t from = replay.inputs[start].tick;
  tire::Replay out;
  out.level = replay.level;
  out.level_sha256 = replay.level_sha256;
  out.ticks = replay.ticks - from;
  for (std::size_t i = start + 1; i < replay.inputs.size(); ++i) {
    tire::ReplayInput in = replay.inputs[i];
    in.tick -= from;
    out.inputs.push_back(in);
  }
  // A restart zeroes the held steer, and the recorder records a steer held through it again at the
  // restart's tick: the run needs nothing from before its restart.
  out.expect.status = replay.expect.status;
  out.expect.hash = replay.expect.hash;
  for (const tire::ReplayCheckpoint& c : replay.expect.checkpoints)
    if (c.tick > from) out.expect.checkpoints.push_back({c.tick - from, c.hash});
  for (const tire::ReplayBox& b : replay.expect.boxes)
    if (b.tick > from) {
      tire::ReplayBox moved = b;
      moved.tick -= from;
      out.expect.boxes.push_back(moved);
    }
  return out;
}

void SessionRecorder::begin(const std::filesystem::path& level_file, tire::Vec2 gravity) {
  level_file_ = std::filesystem::absolute(level_file);
  level_sha256_ = level_sha(level_file_);
  // The level path is made relative to the replay file when saved; the recorder holds a placeholder.
  recorder_.emplace(level_file_.string(), level_sha256_);
  steer_ = inflate_ = lean_ = 0.0;
  brake_ = false;
  gravity_ = gravity;
}

void SessionRecorder::input(tire::ReplayInput in) {
  if (!recorder_) return;
  in.tick = recorder_->ticks();
  recorder_->input(in);
}

void SessionRecorder::on_events(std::uint64_t, const std::vector<SessionEvent>& events) {
  for (const SessionEvent& event : events) {
    std::visit(
        [this](const auto& e) {
          using T = std::decay_t<decltype(e)>;
          tire::ReplayInput in;
          if constexpr (std::is_same_v<T, LoadLevelEvent>) {
            const std::filesystem::path file = std::filesystem::absolute(e.path);
            if (recorder_ && file == level_file_ && level_sha(file) == level_sha256_) {
              in.restart = true;  // the same level, restarted: one recording goes on
              input(in);
              steer_ = inflate_ = lean_ = 0.0;
              brake_ = false;
              gravity_ = tire::level_info(*e.level).gravity;
            } else {  // another level, or the file changed: a new recording
              begin(file, tire::level_info(*e.level).gravity);
            }
          } else if constexpr (std::is_same_v<T, SpawnTireEvent>) {
            in.spawn = e.position;
            input(in);
          } else if constexpr (std::is_same_v<T, GrabEvent>) {
            in.grab = e.point;
            in.grab_radius = e.radius;
            input(in);
          } else if constexpr (std::is_same_v<T, MoveGrabEvent>) {
            in.drag = e.target;
            input(in);
          } else if constexpr (std::is_same_v<T, ReleaseGrabEvent>) {
            in.release = true;
            input(in);
          } else if constexpr (std::is_same_v<T, TuneEvent>) {
            // A panel change becomes what apply_tuning (tuning.cpp) does to the World; one the
            // table refuses changed nothing there, so it is not recorded either. Neither is the
            // sleep checkbox (no row of the table) nor the World::wake_all apply_tuning does: a
            // replay's `set` and `gravity` wake nothing unless the engine does it.
            const tire::TunableParameter* p = tire::find_tunable_parameter(e.key);
            if (!p || !p->by_panel || e.key != p->key) return;
            const double value = p->integer ? std::round(e.value) : e.value;
            if (!p->accepts(value)) return;
            if (p->key == "gravity.x" || p->key == "gravity.y") {
              (p->key == "gravity.x" ? gravity_.x : gravity_.y) = value;
              in.gravity = gravity_;
              input(in);
            } else if (p->key == "tires.friction") {
              for (const char* key : {"tires.friction", "tires.kinetic_friction"}) {
                in.set_key = key;
                in.set_value = value;
                input(in);
              }
            } else if (p->by_replay) {
              in.set_key = e.key;
              in.set_value = value;
              input(in);
            }
          }
        },
        event);
  }
}

void SessionRecorder::on_step(std::uint64_t, const tire::TickInput& input_now) {
  tire::ReplayInput in;
  if (input_now.steer != steer_) {
    in.steer = input_now.steer;
    steer_ = input_now.steer;
  }
  if (input_now.inflate != inflate_) {
    in.inflate = input_now.inflate;
    inflate_ = input_now.inflate;
  }
  if (input_now.lean != lean_) {
    in.lean = input_now.lean;
    lean_ = input_now.lean;
  }
  if (input_now.brake != brake_) {
    in.brake = input_now.brake;
    brake_ = input_now.brake;
  }
  in.jump = input_now.jump;
  if (in.steer || in.jump || in.inflate || in.lean || in.brake) input(in);
}

void SessionRecorder::on_stepped(const tire::Simulation& session) {
  if (recorder_) recorder_->after_step(session.state_hash());
}

std::optional<std::string> SessionRecorder::replay_json(const tire::Simulation& session,
                                                        const std::filesystem::path& target,
                                                        bool last_run_only, std::string& error) const {
  if (!recorder_) {
    error = "nothing recorded yet";
    return std::nullopt;
  }
  tire::Replay replay = recorder_->finish(session.status(), session.state_hash());
  if (last_run_only) replay = last_attempt(replay);
  std::error_code ec;
  std::filesystem::create_directories(target.parent_path(), ec);
  // Relative to the replay's folder, as a replay must name its level (tire/replay/replay.h); both
  // are absolute, so the lexical form always exists when the resolved one cannot be had.
  replay.level = std::filesystem::relative(level_file_, target.parent_path(), ec).generic_string();
  if (ec || replay.level.empty())
    replay.level = level_file_.lexically_relative(target.parent_path()).generic_string();
  return tire::replay_to_json(replay);
}

std::string SessionRecorder::save(const tire::Simulation& session, const std::filesystem::path& file,
                                  bool last_run_only) const {
  const std::filesystem::path target = std::filesystem::absolute(file);
  std::string error;
  const std::optional<std::string> json = replay_json(session, target, last_run_only, error);
  if (!json || !tire::write_file_atomically(target, *json, error)) return error;
  return "";
}

std::optional<std::filesystem::path> SessionRecorder::save_new(const tire::Simulation& session,
                                                               const std::filesystem::path& file,
                                                               std::string& error) const {
  // Every name tried is in the same folder, so the level's path inside is right for any of them.
  const std::filesystem::path target = std::filesystem::absolute(file);
  const std::optional<std::string> json = replay_json(session, target, false, error);
  if (!json) return std::nullopt;
  return tire::write_new_file_atomically(target, *json, error);
}

std::filesystem::path SessionRecorder::default_file(const std::filesystem::path& dir) const {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
  return dir / (level_file_.stem().string() + "-" + stamp + ".json");
}

}  // namespace game
