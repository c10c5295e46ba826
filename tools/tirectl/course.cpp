// tirectl course: a folder of levels checked as the game's course (docs/tirectl.md, "course").
// Each level needs a time limit and medals; with --replays, a shipped replay that wins it
// (and the medal that run earns); and at most a share of the levels may be won by holding one
// direction, or nothing, from the first tick to the last.
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.h"
#include "tire/engine.h"
#include "tire/io/file_io.h"

namespace tirectl {

namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

// What a player may hold for a whole level without playing it.
struct Held {
  const char* name;
  double steer;
};
constexpr Held kHeld[] = {{"nothing", 0.0}, {"right", 1.0}, {"left", -1.0}};

struct Ending {
  tire::ScriptStatus status = tire::ScriptStatus::running;
  std::uint64_t ticks = 0;  // when it ended, or the ticks run
};

// Plays `inputs` (sorted by tick) into `level` until it ends or `max_ticks` have run.
Ending play(const std::shared_ptr<const tire::Level>& level, const std::vector<tire::ReplayInput>& inputs,
            std::uint64_t max_ticks) {
  tire::Simulation simulation(level);
  tire::InputFeed feed(inputs);
  for (std::uint64_t tick = 0; tick < max_ticks && simulation.status() == tire::ScriptStatus::running;
       ++tick) {
    simulation.step(feed);
    simulation.take_warnings();
  }
  return {simulation.status(), simulation.end_tick().value_or(simulation.tick())};
}

struct Shipped {
  fs::path file;
  tire::Replay replay;
  fs::path level;  // the level file it names
};

}  // namespace

int course(const CourseOptions& options) {
  std::string error;
  const std::vector<fs::path> levels = tire::level_files(options.levels, error);
  if (!error.empty() || levels.empty()) {
    std::cerr << "tirectl: course: "
              << (error.empty() ? "no levels in " + tire::printable(options.levels) : error) << "\n";
    return 2;
  }
  std::vector<Shipped> shipped;
  if (!options.replays.empty()) {
    for (const fs::path& file : tire::json_files(options.replays, error)) {
      tire::ReplayLoad load = tire::load_replay_file(file);
      if (!load.replay) {
        for (const std::string& e : load.errors) std::cerr << e << "\n";
        return 2;
      }
      shipped.push_back({file, *load.replay, file.parent_path() / load.replay->level});
    }
    if (!error.empty()) {
      std::cerr << "tirectl: course: " << error << "\n";
      return 2;
    }
  }

  ojson report = ojson::array();
  std::size_t held_wins = 0, problems = 0;
  for (const fs::path& file : levels) {
    const tire::LevelOpen load = tire::open_level_file(file);
    if (!load.level) {
      for (const std::string& e : load.errors) std::cerr << e << "\n";
      return 2;
    }
    const std::shared_ptr<const tire::Level>& level = load.level;
    const tire::LevelInfo& info = load.info;
    const double dt = info.dt;
    ojson entry{{"file", file.filename().string()}, {"name", info.name}};
    ojson issues = ojson::array();
    if (!info.time_limit) issues.push_back("no time_limit");
    if (!info.medals) issues.push_back("no medals");
    const std::uint64_t max_ticks = tire::tick_at(info.time_limit.value_or(options.max_seconds), dt);

    ojson won_holding = ojson::array();
    for (const Held& h : kHeld) {
      tire::ReplayInput hold;
      hold.steer = h.steer;
      if (play(level, {hold}, max_ticks).status == tire::ScriptStatus::won) won_holding.push_back(h.name);
    }
    if (!won_holding.empty()) ++held_wins;
    entry["won_holding"] = won_holding;

    if (!options.replays.empty()) {
      ojson wins = ojson::array();
      for (const Shipped& s : shipped) {
        if (!tire::same_file(s.level, file) || s.replay.expect.status != "won") continue;
        const Ending end = play(level, s.replay.inputs, s.replay.ticks);
        ojson w{{"replay", s.file.filename().string()},
                {"status", tire::to_string(end.status)},
                {"time", static_cast<double>(end.ticks) * dt}};
        if (info.medals && end.status == tire::ScriptStatus::won)
          w["medal"] = tire::medal_name(tire::medal_for(*info.medals, end.ticks, dt));
        if (end.status != tire::ScriptStatus::won)
          issues.push_back("the replay " + s.file.filename().string() + " does not win it");
        wins.push_back(w);
      }
      if (wins.empty()) issues.push_back("no shipped replay wins it");
      entry["winning_replays"] = wins;
    }
    if (info.medals)
      entry["medals"] = {
          {"gold", info.medals->gold}, {"silver", info.medals->silver}, {"bronze", info.medals->bronze}};
    problems += issues.size();
    entry["problems"] = issues;
    report.push_back(entry);
  }
  const double share = static_cast<double>(held_wins) / static_cast<double>(levels.size());
  const bool ok = problems == 0 && share <= options.max_held_share;
  const ojson out{{"levels", report},
                  {"won_holding_one_input", held_wins},
                  {"share", share},
                  {"max_share", options.max_held_share},
                  {"ok", ok}};
  std::cout << out.dump(2) << "\n";
  if (share > options.max_held_share)
    std::cerr << "tirectl: course: " << held_wins << " of " << levels.size()
              << " levels are won by holding one input (at most " << options.max_held_share * 100.0
              << " % may be)\n";
  if (problems) std::cerr << "tirectl: course: " << problems << " problem(s), listed under \"problems\"\n";
  return ok ? 0 : 1;
}

}  // namespace tirectl
