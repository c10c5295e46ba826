// The smallest program that uses the engine: load a level, roll the player right for two
// seconds, print where it got to and the state hash.
//   minimal LEVEL.json [TICKS]
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include <tire/io/level.h>        // load_level_file, populate_world
#include <tire/math/state_hash.h> // to_hex
#include <tire/world/world.h>     // World, TickInput

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: minimal LEVEL.json [TICKS]\n";
    return 2;
  }
  const long ticks = argc == 3 ? std::strtol(argv[2], nullptr, 10) : 120;

  // Read and validate the level: on failure, one message per problem.
  const tire::LevelLoad load = tire::load_level_file(argv[1]);
  if (!load.level) {
    for (const std::string& error : load.errors) std::cerr << error << "\n";
    return 2;
  }

  // A world with the level's solver settings and gravity, then its obstacles, props and tires.
  tire::World world(load.level->solver, load.level->gravity);
  tire::populate_world(*load.level, world);

  // Fixed ticks of load.level->solver.dt, the player steering right throughout.
  for (long i = 0; i < ticks; ++i) world.step({.steer = 1.0, .jump = false});

  const tire::Tire* player = world.player();
  if (!player) {
    std::cerr << "minimal: the level has no player tire\n";
    return 1;
  }
  const tire::Vec2 c = player->centroid();
  std::printf("tick %llu  player centroid (%.6f, %.6f) m  hash %s\n",
              static_cast<unsigned long long>(world.tick()), c.x, c.y,
              tire::to_hex(world.state_hash()).c_str());
  return 0;
}
