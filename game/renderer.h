// Draws the world: sky, obstacles, props, chain terrain, the goal flag, the tires (filled, with a
// tread that shows them roll) and, on request, the debug overlays. Positions are interpolated
// between the last two ticks by `alpha`.
#pragma once

#include <vector>

#include "camera.h"
#include "draw.h"
#include "game_session.h"

namespace game {

// F3 turns the debug drawing on; the tuning panel picks what it shows.
struct DebugOptions {
  bool enabled = false;
  bool structure = true;   // inner ring and spokes
  bool contacts = true;    // active contacts and their normals
  bool velocities = true;  // hub velocity arrows
  bool aabbs = false;      // bounding boxes of tires and props
  bool broadphase = false; // what each tire's broad phase returned this tick, and its narrow-phase pairs
  bool regions = true;     // the script's regions, named
};

class WorldRenderer {
 public:
  // Below this height (m) the level is underground: drawn as rock rather than sky.
  void set_floor(double y) { floor_ = y; }
  void draw(Draw& draw, const Camera& camera, const GameSession& session, double alpha, const DebugOptions& debug);
  // The grab line from the grabbed tire to the mouse.
  void draw_grab(Draw& draw, const Camera& camera, const GameSession& session, double alpha);

 private:
  void draw_background(Draw& d, const Camera& camera);
  void draw_obstacles(Draw& d, const Camera& camera, const tire::World& world);
  void draw_props(Draw& d, const Camera& camera, const GameSession& session, double alpha);
  void draw_goal(Draw& d, const Camera& camera, const tire::World& world);
  void draw_tire(Draw& d, const Camera& camera, const GameSession& session, const tire::Tire& t, double alpha,
                 bool is_player);
  void draw_debug(Draw& d, const Camera& camera, const GameSession& session, double alpha, const DebugOptions& debug);

  double floor_ = -1e9;
  std::vector<tire::Vec2> positions_;
  std::vector<ScreenPoint> outer_, inner_, band_;
  std::vector<ScreenPoint> shape_;
};

}  // namespace game
