// tire-game [LEVEL] [--levels-dir DIR] [--frames N] [--press SPEC]... [--screenshot FILE] [--record FILE]
//           [--edit FILE] [--replay FILE] [--pad SPEC]... [--no-progress] [--volume V] [--audio-log FILE]
//
// The same program runs in the browser (docs/web.md): there the page's query string is
// the command line (game/web/shell.html), and the browser's main loop calls App::frame() once per
// animation frame instead of App::run()'s loop.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "app/app.h"
#include "app/replay_check.h"
#include "cli_numbers.h"
#include "progress/progress.h"

#ifdef __EMSCRIPTEN__
#include <emscripten.h>

#include "web/web_page.h"

namespace {

// One animation frame of the page; at the end, the exit summary goes into the page. What the frame
// wrote to the data folder (a best time, a ghost) is copied to the page's IndexedDB.
void browser_frame(void* arg) {
  static std::uint64_t persisted_writes = 0;
  auto* app = static_cast<game::App*>(arg);
  game::web::follow_canvas_size(app->window());
  const bool running = app->frame();
  if (app->data_writes() != persisted_writes) {
    persisted_writes = app->data_writes();
    game::web::persist_data();
  }
  if (running) return;
  emscripten_cancel_main_loop();
  const int code = app->finish();
  game::web::publish_summary(app->summary(), code);
}

}  // namespace
#endif

#ifndef TIRE_LEVELS_DIR
#define TIRE_LEVELS_DIR "levels"
#endif

int main(int argc, char** argv) {
  CLI::App cli{
      "Soft tire: roll a deformable XPBD tire through a level.\n"
      "Keys: arrows/A/D steer, Space/Up/W jump, Shift inflate, Down/S deflate, R restart, P pause,\n"
      ". step, N/B next/previous level,\n"
      "Esc level menu, F1 help, F2 tuning panel, F3 debug drawing, E the level editor, G the ghost,\n"
      "M mute. Mouse: click spawns a tire, drag grabs one.\n"
      "Gamepad: left stick/d-pad steer, A jump, triggers inflate/deflate, Start pause, Back restart,\n"
      "shoulders next/previous level.\n"
      "A car (levels 13-15): Right/Left throttle and reverse, Space brake, Up/W lean back, Down/S lean\n"
      "forward; pad: left stick throttle and lean, A brake.\n"
      "Progress and ghosts: $XDG_DATA_HOME/soft-tire/ (else ~/.local/share/soft-tire/).",
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
  std::vector<std::string> pads;
  cli.add_option(
      "--pad", pads,
      "scripted virtual game controller: AXIS=VALUE:FRAMES or BUTTON:FRAMES, e.g. leftx=1:0-899, a:140");
  bool no_progress = false;
  cli.add_flag("--no-progress", no_progress,
               "neither read nor write the progress file and the ghosts (for scripted runs)");
  std::string replay;
  cli.add_option("--replay", replay,
                 "run the replay FILE headless (no window) and print the result as one line of JSON; "
                 "exit 0 pass, 1 fail, 2 unreadable");
  double volume = 0.8;
  cli.add_option("--volume", volume, "sound volume, 0 (silent) to 1")
      ->transform(tire_tools::number_in({0, 1}))
      ->capture_default_str();
  std::string audio_log;
  cli.add_option("--audio-log", audio_log,
                 "write every sound event to FILE as one line of JSON (tick, kind, gain, pitch), streamed");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
#ifdef __EMSCRIPTEN__
    game::web::publish_summary("", code == 0 ? 0 : 2);
#endif
    return code == 0 ? 0 : 2;
  }

  if (!replay.empty()) {
    const game::ReplayCheck check = game::check_replay_file(replay);
    std::cout << check.json << std::endl;
#ifdef __EMSCRIPTEN__
    game::web::publish_summary(check.json, check.exit_code);
#endif
    return check.exit_code;
  }

  game::GameOptions options;
  options.levels_dir = levels_dir;
  options.level = level.empty() ? options.levels_dir / "01-first-roll.json" : std::filesystem::path(level);
  if (frames >= 0) options.frames = frames;
  options.screenshot = screenshot;
  options.record = record;
  options.edit = edit;
  options.sound.volume = volume;
  options.sound.log_file = audio_log;
  // A bad --press or --pad: the message, and exit 2 (in the page too).
  const auto bad_spec = [](const std::string& error) {
    std::cerr << "tire-game: " << error << "\n";
#ifdef __EMSCRIPTEN__
    game::web::publish_summary("", 2);
#endif
    return 2;
  };
  for (const std::string& spec : presses) {
    std::string error;
    const auto press = game::parse_key_press(spec, error);
    if (!press) return bad_spec(error);
    options.keys.add(*press);
  }
  for (const std::string& spec : pads) {
    std::string error;
    const auto press = game::parse_pad_press(spec, error);
    if (!press) return bad_spec(error);
    options.pads.push_back(*press);
  }
  if (!no_progress) options.data_dir = game::data_dir_from_env();
#ifdef __EMSCRIPTEN__
  // The page lives on after main returns: the app with it.
  static std::unique_ptr<game::App> app;
  app = std::make_unique<game::App>(std::move(options));
  if (const std::optional<int> failed = app->start()) {
    game::web::publish_summary("", *failed);
    return *failed;
  }
  emscripten_set_main_loop_arg(browser_frame, app.get(), 0, true);
  return 0;
#else
  game::App app(std::move(options));
  return app.run();
#endif
}
