// tire-game [LEVEL] [--levels-dir DIR] [--frames N] [--press SPEC]... [--screenshot FILE] [--record FILE]
//           [--edit FILE]
#include <CLI/CLI.hpp>
#include <iostream>

#include "app.h"
#include "cli_numbers.h"

#ifndef TIRE_LEVELS_DIR
#define TIRE_LEVELS_DIR "levels"
#endif

int main(int argc, char** argv) {
  CLI::App cli{
      "Soft tire: roll a deformable XPBD tire through a level.\n"
      "Keys: arrows/A/D steer, Space/Up/W jump, R restart, P pause, . step, N/B next/previous level,\n"
      "Esc level menu, F1 help, F2 tuning panel, F3 debug drawing, E the level editor. Mouse: click spawns a "
      "tire, drag grabs one.",
      "tire-game"};
  std::string level;
  std::string levels_dir = TIRE_LEVELS_DIR;
  long long frames = -1;
  std::vector<std::string> presses;
  std::string screenshot;
  cli.add_option("level", level, "level file (default: LEVELS_DIR/01-first-roll.json)");
  cli.add_option("--levels-dir", levels_dir, "directory the level menu and next/previous level list")
      ->capture_default_str();
  cli.add_option("--frames", frames, "run exactly N frames (one tick each) and exit; for tests")
      ->transform(tire_tools::integer_in({0, 1e12}));
  cli.add_option("--press", presses,
                 "scripted key press KEY:FRAME or KEY:FIRST-LAST, e.g. right:0-300, space:120");
  cli.add_option("--screenshot", screenshot, "save the last frame to FILE (BMP)");
  std::string edit;
  cli.add_option(
      "--edit", edit,
      "open the level editor on FILE (a new level when it does not exist); E plays it, E again edits");
  std::string record;
  cli.add_option("--record", record,
                 "save a replay of the session to FILE on exit (tirectl replay checks it)");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? 0 : 2;
  }

  game::GameOptions options;
  options.levels_dir = levels_dir;
  options.level = level.empty() ? options.levels_dir / "01-first-roll.json" : std::filesystem::path(level);
  if (frames >= 0) options.frames = frames;
  options.screenshot = screenshot;
  options.record = record;
  options.edit = edit;
  for (const std::string& spec : presses) {
    std::string error;
    const auto press = game::parse_key_press(spec, error);
    if (!press) {
      std::cerr << "tire-game: " << error << "\n";
      return 2;
    }
    options.keys.add(*press);
  }
  game::App app(std::move(options));
  return app.run();
}
