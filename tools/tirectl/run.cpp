#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "level.h"
#include "state_hash.h"
#include "world.h"

namespace tirectl {

namespace {

nlohmann::ordered_json vec(tire::Vec2 v) { return nlohmann::ordered_json::array({v.x, v.y}); }

nlohmann::ordered_json summary(const tire::World& world) {
  nlohmann::ordered_json tires = nlohmann::ordered_json::array();
  for (const tire::Tire& t : world.tires())
    tires.push_back({{"id", t.id},
                     {"centroid", vec(t.centroid())},
                     {"velocity", vec(t.velocity())},
                     {"area_ratio", t.area_ratio()},
                     {"grounded", t.grounded()}});
  nlohmann::ordered_json props = nlohmann::ordered_json::array();
  const tire::RigidWorld& rigid = world.rigid();
  for (std::uint32_t i = 0; i < rigid.props().size(); ++i) {
    const tire::Prop& p = rigid.props()[i];
    if (!p.alive || p.spec.name.empty()) continue;
    const tire::Pose pose = rigid.current_pose(i);
    props.push_back({{"name", p.spec.name}, {"position", vec(pose.position)}, {"angle", pose.angle}});
  }
  return {{"ticks", world.tick()},
          {"time", world.time()},
          {"status", tire::to_string(world.status())},
          {"tires", tires},
          {"props", props},
          {"hash", tire::to_hex(world.state_hash())}};
}

void trace(const tire::World& world) {
  const tire::Tire* p = world.player();
  if (!p) return;
  const tire::Vec2 c = p->centroid(), v = p->velocity();
  std::fprintf(stderr, "t=%6.2f s  hub (%7.3f, %6.3f) m  speed (%6.2f, %6.2f) m/s  spin %6.2f rad/s  area %5.1f %%  %s\n",
               world.time(), c.x, c.y, v.x, v.y, p->angular_velocity(), 100.0 * p->area_ratio(),
               p->grounded() ? "grounded" : "in the air");
}

}  // namespace

int run(const RunOptions& options) {
  const tire::LevelLoad load = tire::load_level_file(options.level, options.overrides);
  if (!load.level) {
    for (const std::string& error : load.errors) std::cerr << error << "\n";
    return 2;
  }
  tire::World world(load.level->solver, load.level->gravity);
  tire::populate_world(*load.level, world);

  std::vector<long long> jumps = options.jump_at;
  std::sort(jumps.begin(), jumps.end());
  auto next_jump = jumps.begin();
  for (long long tick = 0; tick < options.ticks; ++tick) {
    bool jump = false;
    while (next_jump != jumps.end() && *next_jump == tick) jump = true, ++next_jump;
    while (next_jump != jumps.end() && *next_jump < tick) ++next_jump;
    world.step({options.steer, jump});
    if (options.trace_every > 0 && (tick + 1) % options.trace_every == 0) trace(world);
    for (const std::string& w : world.warnings()) std::cerr << "tirectl: warning: " << w << "\n";
    world.warnings().clear();
  }
  std::cout << summary(world).dump(2) << "\n";
  return 0;
}

}  // namespace tirectl
