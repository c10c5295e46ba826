// Watches the level file: poll() looks at its modification time at most once per interval and
// says when it changed since the last look. The caller reloads and validates.
#pragma once

#include <filesystem>
#include <optional>

namespace game {

class HotReload {
 public:
  explicit HotReload(double interval_seconds = 1.0) : interval_(interval_seconds) {}

  // Starts watching `file` from its current state.
  void watch(const std::filesystem::path& file);
  // `now` in seconds (any monotonic wall clock: this never reaches the simulation). True once per
  // change of the file's modification time (or size); a file that disappears is not a change.
  bool poll(double now);

 private:
  struct Stamp {
    std::filesystem::file_time_type time;
    std::uintmax_t size = 0;
    bool operator==(const Stamp&) const = default;
  };
  static std::optional<Stamp> stamp(const std::filesystem::path& file);

  std::filesystem::path file_;
  std::optional<Stamp> last_;
  double interval_;
  double next_poll_ = 0.0;
};

}  // namespace game
