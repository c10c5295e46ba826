// The smallest program that uses the engine: load a level, roll the player right for two
// seconds, print where it got to and the state hash.
//   minimal LEVEL.json [TICKS]
#include <tire/engine.h>  // the whole public API

#include <charconv>
#include <cstdio>
#include <iostream>
#include <string_view>

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: minimal LEVEL.json [TICKS]\n";
    return 2;
  }
  long ticks = 120;
  if (argc == 3) {
    const std::string_view text = argv[2];
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), ticks);
    if (ec != std::errc{} || end != text.data() + text.size() || ticks < 0) {
      std::cerr << "minimal: TICKS must be a whole number >= 0, got " << text << "\n";
      return 2;
    }
  }

  // Read and validate the level: on failure, one message per problem.
  tire::SimulationLoad load = tire::Simulation::load(argv[1]);
  if (!load.simulation) {
    for (const std::string& error : load.errors) std::cerr << error << "\n";
    return 2;
  }
  tire::Simulation& sim = *load.simulation;

  // Fixed ticks of the level's dt, the player steering right throughout.
  for (long i = 0; i < ticks; ++i) sim.step({.steer = 1.0});

  const std::optional<tire::TireView> player = sim.player() ? sim.tire(*sim.player()) : std::nullopt;
  if (!player) {
    std::cerr << "minimal: the level has no player tire\n";
    return 1;
  }
  std::printf("tick %llu  %s  player centroid (%.6f, %.6f) m  hash %016llx\n",
              static_cast<unsigned long long>(sim.tick()), tire::to_string(sim.status()), player->centroid.x,
              player->centroid.y, static_cast<unsigned long long>(sim.state_hash()));
  return 0;
}
