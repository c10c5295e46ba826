#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.h"
#include "tire/io/file_io.h"
#include "tire/io/level.h"
#include "tire/math/state_hash.h"
#include "tire/replay/replay.h"
#include "tire/world/world.h"

namespace tirectl {

namespace {

nlohmann::ordered_json vec(tire::Vec2 v) { return nlohmann::ordered_json::array({v.x, v.y}); }

// The substeps the ticks took: the level's, and what the global method's refinement added
// (SolverConfig::refine_turn).
struct SubstepTally {
  int most = 0;
  long long refined_ticks = 0;  // ticks that took more than the level's substeps
  void add(const tire::World& world) {
    most = std::max(most, world.tick_substeps());
    if (world.tick_substeps() > world.config().substeps) ++refined_ticks;
  }
};

nlohmann::ordered_json summary(const tire::LevelSession& session, const SubstepTally& tally) {
  const tire::World& world = session.world();
  nlohmann::ordered_json tires = nlohmann::ordered_json::array();
  for (const tire::Tire& t : world.tires())
    tires.push_back({{"id", t.id},
                     {"centroid", vec(t.centroid())},
                     {"velocity", vec(t.velocity())},
                     {"area_ratio", t.area_ratio()},
                     {"grounded", t.grounded()},
                     {"asleep", t.asleep}});
  nlohmann::ordered_json props = nlohmann::ordered_json::array();
  const tire::RigidWorld& rigid = world.rigid();
  for (std::uint32_t i = 0; i < rigid.props().size(); ++i) {
    const tire::Prop& p = rigid.props()[i];
    if (!p.alive || p.spec.name.empty()) continue;
    const tire::Pose pose = rigid.current_pose(i);
    props.push_back({{"name", p.spec.name}, {"position", vec(pose.position)}, {"angle", pose.angle}});
  }
  const nlohmann::ordered_json substeps = {
      {"level", world.config().substeps}, {"most", tally.most}, {"refined_ticks", tally.refined_ticks}};
  return {{"ticks", world.tick()},
          {"time", world.time()},
          {"status", tire::to_string(session.status())},
          {"tires", tires},
          {"props", props},
          {"substeps", substeps},
          {"hash", tire::to_hex(session.state_hash())}};
}

void trace(const tire::World& world) {
  const tire::Tire* p = world.player();
  if (!p) return;
  const tire::Vec2 c = p->centroid(), v = p->velocity();
  std::fprintf(
      stderr,
      "t=%6.2f s  hub (%7.3f, %6.3f) m  speed (%6.2f, %6.2f) m/s  spin %6.2f rad/s  area %5.1f %%  %s%s  "
      "%d substeps\n",
      world.time(), c.x, c.y, v.x, v.y, p->angular_velocity(), 100.0 * p->area_ratio(),
      p->grounded() ? "grounded" : "in the air", p->asleep ? ", asleep" : "", world.tick_substeps());
}

}  // namespace

int run(const RunOptions& options) {
  const tire::LevelLoad load = tire::load_level_file(options.level, options.overrides);
  if (!load.level) {
    for (const std::string& error : load.errors) std::cerr << error << "\n";
    return 2;
  }
  // The inputs: a replay's, or those of --steer and --jump-at.
  std::vector<tire::ReplayInput> inputs;
  if (!options.input.empty()) {
    const tire::ReplayLoad replay = tire::load_replay_file(options.input);
    if (!replay.replay) {
      for (const std::string& error : replay.errors) std::cerr << error << "\n";
      return 2;
    }
    inputs = replay.replay->inputs;
  } else {
    tire::ReplayInput hold;
    hold.steer = options.steer;
    inputs.push_back(hold);
    std::vector<long long> jumps = options.jump_at;
    std::sort(jumps.begin(), jumps.end());
    jumps.erase(std::unique(jumps.begin(), jumps.end()), jumps.end());
    for (const long long tick : jumps)
      if (tick < options.ticks) {
        tire::ReplayInput jump;
        jump.tick = static_cast<std::uint64_t>(tick);
        jump.jump = true;
        inputs.push_back(jump);
      }
    std::stable_sort(inputs.begin(), inputs.end(),
                     [](const auto& a, const auto& b) { return a.tick < b.tick; });
  }

  std::optional<tire::ReplayRecorder> recorder;
  if (!options.record.empty()) {
    const std::filesystem::path out = std::filesystem::absolute(options.record);
    const std::filesystem::path level = std::filesystem::absolute(options.level);
    std::string error;
    const auto bytes = tire::read_file(level, tire::LevelLimits::max_file_bytes, error);
    recorder.emplace(std::filesystem::relative(level, out.parent_path()).generic_string(),
                     tire::sha256_hex(*bytes));
  }

  std::unique_ptr<tire::LevelSession> session = tire::make_session(*load.level);
  double steer = 0.0;
  std::size_t next = 0;
  SubstepTally tally;
  for (long long tick = 0; tick < options.ticks; ++tick) {
    bool jump = false;
    while (next < inputs.size() && inputs[next].tick == static_cast<std::uint64_t>(tick)) {
      if (recorder) recorder->input(inputs[next]);
      tire::apply_input(inputs[next++], *session, *load.level, steer, jump);
    }
    session->step({steer, jump});
    if (recorder) recorder->after_step(*session);
    tire::World& world = session->world();
    tally.add(world);
    if (options.trace_every > 0 && (tick + 1) % options.trace_every == 0) trace(world);
    for (const std::string& w : world.warnings()) std::cerr << "tirectl: warning: " << w << "\n";
    world.warnings().clear();
  }
  if (recorder) {
    std::string error;
    if (!tire::write_file_atomically(options.record, tire::replay_to_json(recorder->finish(*session)),
                                     error)) {
      std::cerr << "tirectl: " << error << "\n";
      return 2;
    }
  }
  std::cout << summary(*session, tally).dump(2) << "\n";
  return 0;
}

}  // namespace tirectl
