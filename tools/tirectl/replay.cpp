// tirectl replay: run each replay headless and check what it expects.
#include <iostream>

#include "commands.h"
#include "progress.h"
#include "tire/io/file_io.h"
#include "tire/replay/replay_file.h"

namespace tirectl {

namespace {

constexpr int kPass = 0, kFail = 1, kBadInput = 2;

int check_one(const std::string& file, const ReplayOptions& options) {
  const tire::ReplayLoad load = tire::load_replay_file(file);
  if (!load.replay) {
    for (const std::string& e : load.errors) std::cerr << e << "\n";
    return kBadInput;
  }
  tire::Replay replay = *load.replay;
  const std::string shown = tire::printable(file);
  // The level is read as a level before its digest is looked at: a replay may name any file.
  const tire::ReplayLevel level = tire::load_replay_level(file, replay);
  if (!level.level) {
    for (const std::string& e : level.errors) std::cerr << e << "\n";
    return kBadInput;
  }
  const std::string& sha = level.sha256;
  if (sha != replay.level_sha256) {
    if (!options.allow_level_change && !options.update) {
      std::cerr << shown << ": refused: " << tire::printable(level.path.string())
                << " has changed since this replay was recorded (SHA-256 " << sha.substr(0, 12)
                << "…, recorded on " << replay.level_sha256.substr(0, 12)
                << "…); run with --allow-level-change to run it anyway, or "
                << "--update to record new expectations\n";
      return kFail;
    }
    std::cerr << shown << ": note: the level changed since recording; running it anyway\n";
  }
  // With --update, a replay without checkpoints gets one every 30 ticks: placeholders that the run
  // fills with the real hashes.
  tire::Replay to_run = replay;
  if (options.update && to_run.expect.checkpoints.empty())
    for (std::uint64_t t = 30; t <= replay.ticks; t += 30)
      to_run.expect.checkpoints.push_back({t, "0000000000000000"});
  tire_tools::TickProgress progress("replay " + shown, to_run.ticks, options.progress);
  const tire::ReplayOutcome outcome =
      tire::run_replay(to_run, *level.level, [&](std::uint64_t done) { progress.update(done); });
  progress.finish();

  if (options.update) {
    tire::Replay updated = replay;
    updated.level_sha256 = sha;
    updated.expect.status = outcome.status;
    updated.expect.hash = outcome.hash;
    updated.expect.checkpoints = outcome.checkpoints;
    std::vector<std::string> changes;
    if (replay.level_sha256 != sha) changes.push_back("level_sha256");
    if (replay.expect.status != updated.expect.status) changes.push_back("status → " + outcome.status);
    if (replay.expect.hash != updated.expect.hash) changes.push_back("final hash → " + outcome.hash);
    std::size_t moved = 0;
    for (std::size_t i = 0; i < updated.expect.checkpoints.size(); ++i)
      moved += i >= replay.expect.checkpoints.size() ||
               replay.expect.checkpoints[i].hash != updated.expect.checkpoints[i].hash;
    if (moved) changes.push_back(std::to_string(moved) + " checkpoint hash(es)");
    if (changes.empty()) {
      std::cout << shown << ": up to date\n";
      return kPass;
    }
    std::string error;
    if (!tire::write_file_atomically(file, tire::replay_to_json(updated), error)) {
      std::cerr << shown << ": " << error << "\n";
      return kBadInput;
    }
    std::cout << shown << ": updated:";
    for (const std::string& c : changes) std::cout << " " << c << ";";
    std::cout << "\n";
    return kPass;
  }

  if (outcome.failures.empty()) {
    std::cout << shown << ": ok (" << replay.ticks << " ticks, " << outcome.status << ")\n";
    return kPass;
  }
  std::cout << shown << ": FAILED";
  if (outcome.first_divergent_tick) std::cout << ", first divergent tick " << *outcome.first_divergent_tick;
  std::cout << "\n";
  for (const std::string& f : outcome.failures) std::cout << "  " << f << "\n";
  return kFail;
}

}  // namespace

int replay(const ReplayOptions& options) {
  int worst = kPass;
  for (const std::string& file : options.files) worst = std::max(worst, check_one(file, options));
  return worst;
}

}  // namespace tirectl
