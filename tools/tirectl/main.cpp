// tirectl: the headless command line over the engine (docs/tirectl.md).
#include <CLI/CLI.hpp>
#include <iostream>

#include "cli_numbers.h"
#include "commands.h"
#include "tradeoff.h"

int main(int argc, char** argv) {
  using tire_tools::integer_in;
  using tire_tools::number_in;
  CLI::App app{"tirectl: run, validate and measure soft-tire levels without a window"};
  app.require_subcommand(1);

  tirectl::RunOptions run;
  CLI::App* run_cmd = app.add_subcommand("run", "Step a level headless and print its final state as JSON");
  run_cmd->add_option("level", run.level, "Level file (JSON)")->required();
  run_cmd->add_option("--ticks", run.ticks, "Fixed ticks to step")->transform(integer_in({0, 1e8}));
  run_cmd->add_option("--set", run.overrides,
                      "Override a numeric key by dotted path, e.g. solver.substeps=16");
  // A replay given with --input drives the player: --steer, --lean, --brake and --jump-at would be
  // ignored, so they
  // exclude it (CLI11: "--input excludes --steer", exit 2).
  CLI::Option* input_opt =
      run_cmd->add_option("--input", run.input, "Drive the player with the inputs of this replay file");
  run_cmd->add_option("--steer", run.steer, "Player steering in [-1, 1] for the whole run")
      ->check(number_in({-1, 1}))
      ->excludes(input_opt);
  run_cmd->add_option("--lean", run.lean, "A player vehicle's lean in [-1, 1] for the whole run")
      ->check(number_in({-1, 1}))
      ->excludes(input_opt);
  run_cmd->add_flag("--brake", run.brake, "Hold a player vehicle's brakes for the whole run")
      ->excludes(input_opt);
  run_cmd->add_option("--jump-at", run.jump_at, "Ask the player to jump at this tick (repeatable)")
      ->transform(integer_in({0, 1e8}))
      ->excludes(input_opt);
  run_cmd
      ->add_option("--trace", run.trace_every,
                   "Every N ticks, print a readable line about the player on stderr")
      ->transform(integer_in({1, 1e8}));
  run_cmd->add_option("--record", run.record, "Record the run as a replay file (written atomically)");
  run_cmd->add_flag("!--no-progress", run.progress, "No progress line on stderr (shown only on a terminal)");

  tirectl::ReplayOptions replay;
  CLI::App* replay_cmd = app.add_subcommand(
      "replay", "Run replays headless and check their expectations (exit 0 pass, 1 fail, 2 bad input)");
  replay_cmd->add_option("files", replay.files, "Replay files (JSON)")->required();
  replay_cmd->add_flag("--update", replay.update,
                       "Rewrite each replay's expectations from this run, saying what changed");
  replay_cmd->add_flag("--allow-level-change", replay.allow_level_change,
                       "Run a replay even if its level's content changed since it was recorded");
  replay_cmd->add_flag("!--no-progress", replay.progress,
                       "No progress line on stderr (shown only on a terminal)");

  std::vector<std::string> validate_files;
  CLI::App* validate_cmd = app.add_subcommand("validate", "Check level files; one line per problem");
  validate_cmd->add_option("files", validate_files, "Level files (JSON)")->required();

  tirectl::CourseOptions course;
  CLI::App* course_cmd = app.add_subcommand(
      "course",
      "Check a folder of levels as a course: goals, time limits, medals, winning replays, one-key wins");
  course_cmd->add_option("levels", course.levels, "The levels' folder")->capture_default_str();
  course_cmd->add_option("--replays", course.replays,
                         "A folder of replays: each level needs one that wins it");
  course_cmd
      ->add_option("--max-held-share", course.max_held_share,
                   "The largest share of levels that holding right, left or nothing may win")
      ->check(number_in({0, 1}))
      ->capture_default_str();

  tirectl::SchemaOptions schema;
  CLI::App* schema_cmd = app.add_subcommand(
      "schema", "Print levels/schema.json as the parameter table generates it; --check or --write the file");
  schema_cmd->add_option("file", schema.file, "The committed schema, whose hand-written parts are kept")
      ->capture_default_str();
  CLI::Option* check_flag = schema_cmd->add_flag(
      "--check", schema.check, "Exit 1, saying where, when the file differs from the generated schema");
  schema_cmd->add_flag("--write", schema.write, "Rewrite the file from the parameter table")
      ->excludes(check_flag);

  tirectl::BenchOptions bench;
  CLI::App* bench_cmd = app.add_subcommand("bench", "Time the performance scenes; CSV on stdout");
  bench_cmd->add_option("--scene", bench.scenes, "Only these scenes (repeatable; default all)");
  bench_cmd->add_option("--threads", bench.threads, "Threads to step with (default: the hardware's)")
      ->transform(integer_in({1, 256}));
  // --steps fixes the count, --seconds a budget the count follows: given both, one would be ignored.
  CLI::Option* steps_opt =
      bench_cmd
          ->add_option("--steps", bench.steps,
                       "Timed steps per scene (default: as many as --seconds allow, at least 30)")
          ->transform(integer_in({1, 1e7}));
  bench_cmd->add_option("--seconds", bench.seconds, "Timing budget per scene")
      ->check(number_in({0, 3600}))
      ->excludes(steps_opt);
  bench_cmd->add_option("--warmup", bench.warmup, "Untimed steps before timing")
      ->transform(integer_in({0, 1e6}));
  bench_cmd
      ->add_option("--settle", bench.settle,
                   "A *-settled scene's most untimed ticks before the warm-up, stepped until its count of "
                   "sleeping tires holds for 60 ticks")
      ->transform(integer_in({0, 1e6}))
      ->capture_default_str();
  bench_cmd
      ->add_option("--report-every", bench.report_every,
                   "Every N timed steps, print the recent median and p99, RSS and heap in use to stderr")
      ->transform(integer_in({1, 1e7}));
  bench_cmd
      ->add_option("--schedule", bench.schedule,
                   "World::step's phase order: fused (the default) or plain (Small Steps' Algorithm 1 "
                   "a phase at a time; the same results, for timing what the fusion saves)")
      ->check(CLI::IsMember({"fused", "plain"}))
      ->capture_default_str();

  tirectl::TradeoffOptions tradeoff;
  CLI::App* tradeoff_cmd = tirectl::add_tradeoff_command(app, tradeoff);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    if (*run_cmd) return tirectl::run(run);
    if (*validate_cmd) return tirectl::validate(validate_files);
    if (*course_cmd) return tirectl::course(course);
    if (*replay_cmd) return tirectl::replay(replay);
    if (*schema_cmd) return tirectl::schema(schema);
    if (*bench_cmd) return tirectl::bench(bench);
    if (*tradeoff_cmd) return tirectl::tradeoff(tradeoff);
  } catch (const std::exception& e) {
    std::cerr << "tirectl: " << e.what() << "\n";
    return 2;
  }
  return 2;
}
