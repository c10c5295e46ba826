#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.h"
#include "progress.h"
#include "tire/io/file_io.h"
#include "tire/io/level.h"
#include "tire/math/state_hash.h"
#include "tire/replay/replay.h"
#include "tire/world/energy.h"
#include "tire/world/overlap.h"
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

// The largest rise of a quantity over any stretch of the run, q(t) − min q(s ≤ t), and the tick
// that ended it.
struct Rise {
  double lowest = 0.0;
  double largest = 0.0;
  long long tick = 0;
  void start(double q) { lowest = q; }
  void add(double q, long long at) {
    lowest = std::min(lowest, q);
    if (q - lowest > largest) {
      largest = q - lowest;
      tick = at;
    }
  }
};

// The world's energy tick by tick (tire/world/energy.h) and its largest rise. Steering, jumps,
// scripts and kinematic props do work on the world, so a rise of the total is not by itself a
// fault; the energy less what was brought into the world (World::energy_in: bodies added, commands,
// the tires' controls) rises only by what is not booked: with no kinematic props or grabs at work,
// energy a contact made.
struct EnergyWatch {
  tire::Energy now;
  double brought_in = 0.0;  // World::energy_in
  std::uint64_t last_tick = 0;
  Rise total;
  Rise unexplained;
  void start(const tire::World& world) {
    last_tick = world.tick();
    now = tire::world_energy(world);
    brought_in = world.energy_in();
    total.start(now.total());
    unexplained.start(now.total() - brought_in);
  }
  void add(const tire::World& world) {
    if (world.tick() < last_tick) {  // a restart rebuilt the world: its books start again
      start(world);
      return;
    }
    last_tick = world.tick();
    now = tire::world_energy(world);
    brought_in = world.energy_in();
    const auto tick = static_cast<long long>(world.tick());
    total.add(now.total(), tick);
    unexplained.add(now.total() - brought_in, tick);
  }
  nlohmann::ordered_json to_json() const {
    return {{"kinetic", now.kinetic},
            {"gravitational", now.gravitational},
            {"elastic", now.elastic},
            {"total", now.total()},
            {"largest_rise", total.largest},
            {"largest_rise_tick", total.tick},
            {"energy_in", brought_in},
            {"largest_unexplained_rise", unexplained.largest},
            {"largest_unexplained_rise_tick", unexplained.tick}};
  }
};

nlohmann::ordered_json summary(const tire::LevelSession& session,
                               const std::optional<tire::LevelMedals>& medals, const SubstepTally& tally,
                               const EnergyWatch& energy) {
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
  // Each run budget reached (run_budgets.h): when first, and how much it dropped.
  nlohmann::ordered_json budgets = nlohmann::ordered_json::array();
  for (const tire::World::BudgetReached& b : world.budgets_reached())
    budgets.push_back({{"budget", tire::parameter(b.budget).key},
                       {"limit", static_cast<long long>(*world.parameter(tire::parameter(b.budget).key))},
                       {"first_tick", b.first_tick},
                       {"dropped", b.dropped}});
  const nlohmann::ordered_json substeps = {
      {"level", world.config().substeps}, {"most", tally.most}, {"refined_ticks", tally.refined_ticks}};
  // How the level ended: on which tick, and by what (the goal, the time limit, the bounds...).
  nlohmann::ordered_json end;
  if (const std::optional<std::uint64_t> tick = session.end_tick())
    end = {{"tick", *tick},
           {"time", static_cast<double>(*tick) * world.config().dt},
           {"reason", tire::to_string(session.end_reason())}};
  // The medal a win earns (levels/README.md, "medals"); null for a level without medals.
  nlohmann::ordered_json medal;
  if (medals && session.status() == tire::ScriptStatus::won && session.end_tick())
    medal = tire::medal_name(tire::medal_for(*medals, *session.end_tick(), world.config().dt));
  // The box the player must stay in; an open side (the computed top) is null.
  nlohmann::ordered_json bounds;
  if (const std::optional<tire::Aabb>& b = session.bounds()) {
    const auto side = [](double v) {
      return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
    };
    bounds = {{"min", {side(b->min.x), side(b->min.y)}}, {"max", {side(b->max.x), side(b->max.y)}}};
  }
  // The island solve's work (docs/at-rest.md): all zero when solver.island_tires is 0.
  const tire::IslandContacts::Work& island = world.island_work();
  const nlohmann::ordered_json islands = {{"solved", island.solves},       {"rows", island.rows},
                                          {"passes", island.passes},       {"iterations", island.iterations},
                                          {"unsettled", island.unsettled}, {"breakdowns", island.breakdowns},
                                          {"overflows", island.overflows}, {"failures", island.failures}};
  // How far tires are inside each other at the end (tire/world/overlap.h).
  const tire::TireOverlap deepest = tire::deepest_tire_overlap(world);
  nlohmann::ordered_json overlap = {{"deepest", deepest.depth}, {"tire", nullptr}, {"inside", nullptr}};
  if (deepest.depth > 0.0) {
    overlap["tire"] = deepest.tire;
    overlap["inside"] = deepest.inside;
  }
  return {{"ticks", world.tick()},
          {"time", world.time()},
          {"status", tire::to_string(session.status())},
          {"end", end},
          {"medal", medal},
          {"bounds", bounds},
          {"respawns", session.respawns()},
          {"tires", tires},
          {"props", props},
          {"substeps", substeps},
          {"energy", energy.to_json()},
          {"overlap", overlap},
          {"failed_solves", world.failed_solves()},
          {"islands", islands},
          {"budgets_reached", budgets},
          {"hash", tire::to_hex(session.state_hash())}};
}

void trace(const tire::World& world, const EnergyWatch& energy) {
  const tire::Tire* p = world.player();
  if (!p) return;
  const tire::Vec2 c = p->centroid(), v = p->velocity();
  std::fprintf(
      stderr,
      "t=%6.2f s  hub (%7.3f, %6.3f) m  speed (%6.2f, %6.2f) m/s  spin %6.2f rad/s  area %5.1f %%  %s%s  "
      "%d substeps  energy %.1f J  brought in %.1f J\n",
      world.time(), c.x, c.y, v.x, v.y, p->angular_velocity(), 100.0 * p->area_ratio(),
      p->grounded() ? "grounded" : "in the air", p->asleep ? ", asleep" : "", world.tick_substeps(),
      energy.now.total(), energy.brought_in);
}

}  // namespace

int run(const RunOptions& options) {
  // An output is never written over an input, nor onto what is not a regular file: refused before
  // the run, not after it.
  if (!options.record.empty()) {
    using tire::printable;
    if (tire::same_file(options.record, options.level)) {
      std::cerr << "tirectl: --record " << printable(options.record) << " is the level being run ("
                << printable(options.level) << "); refusing to write the replay over it\n";
      return 2;
    }
    if (!options.input.empty() && tire::same_file(options.record, options.input)) {
      std::cerr << "tirectl: --record " << printable(options.record) << " is the replay --input "
                << printable(options.input)
                << " the run reads; refusing to write over it (tirectl replay --update rewrites a replay)\n";
      return 2;
    }
    if (const std::string error = tire::check_output_file(options.record); !error.empty()) {
      std::cerr << "tirectl: --record: " << error << "\n";
      return 2;
    }
  }
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
  tire_tools::TickProgress progress("run", static_cast<std::uint64_t>(options.ticks), options.progress);
  tire::InputFeed feed(inputs, recorder ? &*recorder : nullptr);
  SubstepTally tally;
  EnergyWatch energy;
  energy.start(session->world());
  for (long long tick = 0; tick < options.ticks; ++tick) {
    feed.step(*session, *load.level);
    if (recorder) recorder->after_step(*session);
    tire::World& world = session->world();
    tally.add(world);
    energy.add(world);
    if (options.trace_every > 0 && (tick + 1) % options.trace_every == 0) {
      progress.clear();
      trace(world, energy);
    }
    if (!world.warnings().empty()) progress.clear();
    for (const std::string& w : world.warnings()) std::cerr << "tirectl: warning: " << w << "\n";
    world.warnings().clear();
    progress.update(static_cast<std::uint64_t>(tick + 1));
  }
  progress.finish();
  if (recorder) {
    std::string error;
    if (!tire::write_file_atomically(options.record, tire::replay_to_json(recorder->finish(*session)),
                                     error)) {
      std::cerr << "tirectl: " << error << "\n";
      return 2;
    }
  }
  std::cout << summary(*session, load.level->medals, tally, energy).dump(2) << "\n";
  return 0;
}

}  // namespace tirectl
