// The text on top of the world, all drawn with ImGui: the HUD (what a player needs: the level, the
// time or the countdown of its time limit, the time to beat, speed, in the air), under it with F3 the
// numbers for developers (frame rate, physics time, tick, tires and how many sleep), the help
// overlay (F1), the script's messages, the level's validation errors after a failed hot reload, and
// the world's warnings.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

struct ImFont;

namespace tire {
class Simulation;
}

namespace game {

struct HudInfo {
  std::string_view level;            // views the level's name: the HUD copies nothing each frame
  double time = 0.0;                 // s of simulated time
  std::optional<double> time_limit;  // s: the level's, shown as a countdown
  std::string_view target;           // the time to beat ("best 9.85 s"); "" for none
  double speed = 0.0;                // player hub speed (m/s)
  bool grounded = false;
  bool paused = false;
  bool over = false;  // the level has ended: the tire's speed and air are no longer the player's
};

// What F3 adds under the HUD.
struct DevInfo {
  bool shown = false;  // F3
  std::uint64_t tick = 0;
  double fps = 0.0;
  double physics_ms = 0.0;  // wall time spent in Simulation::step per frame (smoothed)
  int steps_last_frame = 0;
  std::size_t tires = 0;
  std::size_t asleep = 0;           // tires asleep (Simulation::asleep_count)
  std::uint64_t failed_solves = 0;  // Simulation::solver_failures
};

// Seconds left of a time limit, never below 0.
double time_left(double limit, double time);
// The HUD's clock line into `out` (cut to fit, terminated): "time left   12.3 s" with a limit,
// "time       12.34 s" without.
void format_clock_line(std::span<char> out, double time, std::optional<double> limit);

void draw_hud(const HudInfo& info, const DevInfo& dev);
// The HUD's line on sleeping, "asleep      12 / 300" (tires asleep / tires), written into `out`
// (cut to fit, terminated); false, leaving `out` alone, when there are no tires or no room.
bool format_asleep_line(std::span<char> out, std::size_t asleep, std::size_t tires);
void draw_help(bool* open);
void draw_script_messages(const tire::Simulation& simulation, ImFont* big);
// A red window listing why the level file failed to reload (the last good level keeps playing).
void draw_level_errors(const std::string& file, const std::vector<std::string>& errors);
// Recent warnings (a diverged tire that was reset, a failed screenshot ...).
void draw_warnings(const std::vector<std::string>& warnings);

}  // namespace game
