// Progress on stderr for the long runs of the command-line tools: one line, rewritten in place,
// only when stderr is a terminal. A pipe, a file and the test suite see nothing of it. The wall
// clock is read here for the display alone; nothing read from it reaches a simulation.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>

namespace tire_tools {

// The line itself: written after a carriage return and padded over what it replaces, so that a
// shorter text leaves nothing of a longer one behind.
class TerminalLine {
 public:
  // `wanted`: false for --no-progress. Inactive also when stderr is not a terminal.
  explicit TerminalLine(bool wanted) : active_(wanted && isatty(STDERR_FILENO) == 1) {}
  TerminalLine(const TerminalLine&) = delete;
  TerminalLine& operator=(const TerminalLine&) = delete;
  ~TerminalLine() { clear(); }

  bool active() const { return active_; }
  void show(const std::string& text) {
    if (!active_) return;
    const int pad = static_cast<int>(shown_ > text.size() ? shown_ - text.size() : 0);
    std::fprintf(stderr, "\r%s%*s", text.c_str(), pad, "");
    std::fflush(stderr);
    shown_ = text.size();
  }
  // A line that stays (the progress line is redrawn by the next show).
  void note(const std::string& text) {
    if (!active_) return;
    clear();
    std::fprintf(stderr, "%s\n", text.c_str());
  }
  // Erases the line, before anything else is written to stderr or at the end.
  void clear() {
    if (!active_ || shown_ == 0) return;
    std::fprintf(stderr, "\r%*s\r", static_cast<int>(shown_), "");
    std::fflush(stderr);
    shown_ = 0;
  }

 private:
  bool active_;
  std::size_t shown_ = 0;  // characters on the line now
};

// "run: 42% (2100000 / 5000000 ticks, 61000 ticks/s, 48 s left)": `done` of `total` ticks in
// `seconds` of wall time.
inline std::string tick_progress_text(const std::string& what, std::uint64_t done, std::uint64_t total,
                                      double seconds) {
  const double fraction = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
  std::string text = what + ": " + std::to_string(static_cast<int>(100.0 * fraction)) + "% (" +
                     std::to_string(done) + " / " + std::to_string(total) + " ticks";
  if (seconds > 0.0 && done > 0) {
    const double rate = static_cast<double>(done) / seconds;
    text += ", " + std::to_string(static_cast<std::uint64_t>(rate + 0.5)) + " ticks/s";
    const double left = static_cast<double>(total - done) / rate;
    if (left >= 120.0)
      text += ", " + std::to_string(static_cast<std::uint64_t>(left / 60.0 + 0.5)) + " min left";
    else
      text += ", " + std::to_string(static_cast<std::uint64_t>(left + 0.5)) + " s left";
  }
  return text + ")";
}

// A loop of `total` ticks: update(done) after each; the line shows at the start and then about
// every `interval` seconds, and is erased by finish() (or at the end of its scope).
class TickProgress {
 public:
  using Clock = std::chrono::steady_clock;

  TickProgress(std::string what, std::uint64_t total, bool wanted, double interval = 2.0)
      : line_(wanted), what_(std::move(what)), total_(total), interval_(interval) {
    if (!line_.active()) return;
    start_ = last_ = Clock::now();
    line_.show(tick_progress_text(what_, 0, total_, 0.0));
  }
  void update(std::uint64_t done) {
    // The clock every 64 ticks: a sleeping level steps a million ticks a second.
    if (!line_.active() || done % 64 != 0) return;
    const Clock::time_point now = Clock::now();
    if (std::chrono::duration<double>(now - last_).count() < interval_) return;
    last_ = now;
    line_.show(tick_progress_text(what_, done, total_, std::chrono::duration<double>(now - start_).count()));
  }
  // Erases the line before other output on stderr; the next update past the interval redraws it.
  void clear() { line_.clear(); }
  void finish() { line_.clear(); }

 private:
  TerminalLine line_;
  std::string what_;
  std::uint64_t total_;
  double interval_;
  Clock::time_point start_, last_;
};

}  // namespace tire_tools
