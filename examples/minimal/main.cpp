// The smallest program that uses the engine: load a level, roll the player right for two
// seconds, print where it got to and the state hash.
//   minimal LEVEL.json [TICKS]
#include <tire/io/level.h>               // load_level_file, make_session
#include <tire/math/state_hash.h>        // to_hex
#include <tire/session/level_session.h>  // LevelSession: the World and the level's script

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
  const tire::LevelLoad load = tire::load_level_file(argv[1]);
  if (!load.level) {
    for (const std::string& error : load.errors) std::cerr << error << "\n";
    return 2;
  }

  // The level ready to play: a World with its solver settings, gravity, obstacles, props and
  // tires, and the level's script (goal, triggers) around it.
  const std::unique_ptr<tire::LevelSession> session = tire::make_session(*load.level);
  const tire::World& world = session->world();

  // Fixed ticks of load.level->solver.dt, the player steering right throughout.
  for (long i = 0; i < ticks; ++i) session->step({.steer = 1.0, .jump = false});

  const tire::Tire* player = world.player();
  if (!player) {
    std::cerr << "minimal: the level has no player tire\n";
    return 1;
  }
  const tire::Vec2 c = player->centroid();
  std::printf("tick %llu  %s  player centroid (%.6f, %.6f) m  hash %s\n",
              static_cast<unsigned long long>(world.tick()), tire::to_string(session->status()), c.x, c.y,
              tire::to_hex(session->state_hash()).c_str());
  return 0;
}
