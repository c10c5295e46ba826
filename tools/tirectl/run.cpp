#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.h"
#include "progress.h"
#include "tire/engine.h"
#include "tire/io/file_io.h"
#include "tire/math/numbers.h"

namespace tirectl {

namespace {

nlohmann::ordered_json vec(tire::Vec2 v) { return nlohmann::ordered_json::array({v.x, v.y}); }

// The substeps the ticks took: the level's, and what the global method's refinement added
// (SolverConfig::refine_turn).
struct SubstepTally {
  int most = 0;
  long long refined_ticks = 0;  // ticks that took more than the level's substeps
  void add(const tire::Simulation& simulation) {
    const int substeps = simulation.tick_substeps();
    most = std::max(most, substeps);
    if (substeps > simulation.config().substeps) ++refined_ticks;
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

// The world's energy tick by tick (Simulation::energy) and its largest rise. Steering, jumps,
// scripts and kinematic props do work on the world, so a rise of the total is not by itself a
// fault; the energy less what was brought into the world (EnergyView::brought_in: bodies added,
// commands, the tires' controls) rises only by what is not booked: with no kinematic props or grabs
// at work, energy a contact made.
struct EnergyWatch {
  tire::EnergyView now;
  double brought_in = 0.0;  // EnergyView::brought_in
  std::uint64_t last_tick = 0;
  Rise total;
  Rise unexplained;
  void start(const tire::Simulation& simulation) {
    last_tick = simulation.tick();
    now = simulation.energy();
    brought_in = now.brought_in;
    total.start(now.total());
    unexplained.start(now.total() - brought_in);
  }
  void add(const tire::Simulation& simulation) {
    if (simulation.tick() < last_tick) {  // a restart rebuilt the world: its books start again
      start(simulation);
      return;
    }
    last_tick = simulation.tick();
    now = simulation.energy();
    brought_in = now.brought_in;
    const auto tick = static_cast<long long>(simulation.tick());
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

// The player vehicle, if the player is one.
std::optional<tire::VehicleView> player_vehicle(const tire::Simulation& simulation) {
  for (std::size_t i = 0; const std::optional<tire::VehicleView> v = simulation.vehicle_at(i); ++i)
    if (v->player) return v;
  return std::nullopt;
}

nlohmann::ordered_json vehicle_json(const tire::VehicleView& v) {
  return {{"index", v.index},          {"player", v.player},
          {"position", vec(v.center)}, {"velocity", vec(v.velocity)},
          {"angle", v.pose.angle},     {"angular_velocity", v.angular_velocity}};
}

nlohmann::ordered_json summary(const tire::Simulation& simulation,
                               const std::optional<tire::LevelMedals>& medals, const SubstepTally& tally,
                               const EnergyWatch& energy) {
  const double dt = simulation.config().dt;
  nlohmann::ordered_json tires = nlohmann::ordered_json::array();
  for (const tire::TireId id : simulation.tires()) {
    const tire::TireView t = *simulation.tire(id);
    tires.push_back({{"id", t.id},
                     {"centroid", vec(t.centroid)},
                     {"velocity", vec(t.velocity)},
                     {"area_ratio", t.area_ratio},
                     {"grounded", t.grounded},
                     {"asleep", t.asleep}});
  }
  nlohmann::ordered_json props = nlohmann::ordered_json::array();
  for (tire::PropId i = 0; i < simulation.prop_count(); ++i) {
    const tire::PropView p = *simulation.prop(i);
    if (!p.alive || p.name.empty()) continue;
    props.push_back(
        {{"name", p.name}, {"position", vec(p.state.pose.position)}, {"angle", p.state.pose.angle}});
  }
  // Each vehicle's chassis: its centre of mass, velocity and angle.
  nlohmann::ordered_json vehicles = nlohmann::ordered_json::array();
  for (std::size_t i = 0; const std::optional<tire::VehicleView> v = simulation.vehicle_at(i); ++i)
    vehicles.push_back(vehicle_json(*v));
  const tire::SolverReport report = simulation.solver_report();
  // Each run budget reached (levels/README.md, "budgets"): when first, and how much it dropped.
  nlohmann::ordered_json budgets = nlohmann::ordered_json::array();
  for (const tire::SolverReport::Budget& b : report.budgets_reached)
    budgets.push_back({{"budget", b.key},
                       {"limit", static_cast<long long>(b.limit)},
                       {"first_tick", b.first_tick},
                       {"dropped", b.dropped}});
  const nlohmann::ordered_json substeps = {
      {"level", simulation.config().substeps}, {"most", tally.most}, {"refined_ticks", tally.refined_ticks}};
  // How the level ended: on which tick, and by what (the goal, the time limit, the bounds...).
  nlohmann::ordered_json end;
  if (const std::optional<std::uint64_t> tick = simulation.end_tick())
    end = {{"tick", *tick},
           {"time", static_cast<double>(*tick) * dt},
           {"reason", tire::to_string(simulation.end_reason())}};
  // The medal a win earns (levels/README.md, "medals"); null for a level without medals.
  nlohmann::ordered_json medal;
  if (medals && simulation.status() == tire::ScriptStatus::won && simulation.end_tick())
    medal = tire::medal_name(tire::medal_for(*medals, *simulation.end_tick(), dt));
  // The box the player must stay in; an open side (the computed top) is null.
  nlohmann::ordered_json bounds;
  if (const std::optional<tire::Aabb> b = simulation.bounds()) {
    const auto side = [](double v) {
      return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
    };
    bounds = {{"min", {side(b->min.x), side(b->min.y)}}, {"max", {side(b->max.x), side(b->max.y)}}};
  }
  // The island solve's work (docs/at-rest.md): all zero when solver.island_tires is 0.
  const tire::IslandWork& island = report.islands;
  const nlohmann::ordered_json islands = {{"solved", island.solves},       {"rows", island.rows},
                                          {"passes", island.passes},       {"iterations", island.iterations},
                                          {"unsettled", island.unsettled}, {"breakdowns", island.breakdowns},
                                          {"overflows", island.overflows}, {"failures", island.failures}};
  // How far tires are inside each other at the end.
  const tire::TireOverlap deepest = simulation.deepest_overlap();
  nlohmann::ordered_json overlap = {{"deepest", deepest.depth}, {"tire", nullptr}, {"inside", nullptr}};
  if (deepest.depth > 0.0) {
    overlap["tire"] = deepest.tire;
    overlap["inside"] = deepest.inside;
  }
  return {{"ticks", simulation.tick()},
          {"time", simulation.time()},
          {"status", tire::to_string(simulation.status())},
          {"end", end},
          {"medal", medal},
          {"bounds", bounds},
          {"respawns", simulation.respawns()},
          {"tires", tires},
          {"props", props},
          {"vehicles", vehicles},
          {"substeps", substeps},
          {"energy", energy.to_json()},
          {"overlap", overlap},
          {"failed_solves", report.failed_solves},
          {"islands", islands},
          {"budgets_reached", budgets},
          {"hash", tire::to_hex(simulation.state_hash())}};
}

void trace(const tire::Simulation& simulation, const EnergyWatch& energy) {
  if (const std::optional<tire::VehicleView> v = player_vehicle(simulation)) {
    std::fprintf(stderr,
                 "t=%6.2f s  chassis (%7.3f, %6.3f) m  speed (%6.2f, %6.2f) m/s  angle %6.3f rad  spin %6.2f "
                 "rad/s  throttle %5.2f  lean %5.2f%s  %d substeps  energy %.1f J  brought in %.1f J\n",
                 simulation.time(), v->center.x, v->center.y, v->velocity.x, v->velocity.y, v->pose.angle,
                 v->angular_velocity, v->throttle, v->lean, v->brake ? "  braking" : "",
                 simulation.tick_substeps(), energy.now.total(), energy.brought_in);
    return;
  }
  const std::optional<tire::TireId> id = simulation.player();
  if (!id) return;
  const tire::TireView p = *simulation.tire(*id);
  const tire::Vec2 c = p.centroid, v = p.velocity;
  std::fprintf(
      stderr,
      "t=%6.2f s  hub (%7.3f, %6.3f) m  speed (%6.2f, %6.2f) m/s  spin %6.2f rad/s  area %5.1f %%  %s%s  "
      "%d substeps  energy %.1f J  brought in %.1f J\n",
      simulation.time(), c.x, c.y, v.x, v.y, p.spin, 100.0 * p.area_ratio,
      p.grounded ? "grounded" : "in the air", p.asleep ? ", asleep" : "", simulation.tick_substeps(),
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
  const tire::LevelOpen load = tire::open_level_file(options.level, options.overrides);
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
    if (options.lean != 0.0) hold.lean = options.lean;
    if (options.brake) hold.brake = true;
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
    recorder.emplace(std::filesystem::relative(level, out.parent_path()).generic_string(), load.sha256);
  }

  tire::Simulation simulation(load.level);
  tire_tools::TickProgress progress("run", static_cast<std::uint64_t>(options.ticks), options.progress);
  tire::InputFeed feed(inputs, recorder ? &*recorder : nullptr);
  SubstepTally tally;
  EnergyWatch energy;
  energy.start(simulation);
  for (long long tick = 0; tick < options.ticks; ++tick) {
    simulation.step(feed);
    if (recorder) recorder->after_step(simulation.state_hash());
    tally.add(simulation);
    energy.add(simulation);
    if (options.trace_every > 0 && (tick + 1) % options.trace_every == 0) {
      progress.clear();
      trace(simulation, energy);
    }
    const std::vector<std::string> warnings = simulation.take_warnings();
    if (!warnings.empty()) progress.clear();
    for (const std::string& w : warnings) std::cerr << "tirectl: warning: " << w << "\n";
    progress.update(static_cast<std::uint64_t>(tick + 1));
  }
  progress.finish();
  if (recorder) {
    std::string error;
    if (!tire::write_file_atomically(
            options.record,
            tire::replay_to_json(recorder->finish(simulation.status(), simulation.state_hash())), error)) {
      std::cerr << "tirectl: " << error << "\n";
      return 2;
    }
  }
  std::cout << summary(simulation, load.info.medals, tally, energy).dump(2) << "\n";
  return 0;
}

}  // namespace tirectl
