// The game's tire::DebugDraw: the engine walks the world (Simulation::debug_draw) and this draws
// each shape it reports on the screen, in the colour and width its kind has always had, and what it
// reports about a sleeping tire in the darker shade of that colour (asleep_shade, draw.h). Tires
// are drawn where the renderer draws them, blended between the last two ticks by `alpha`.
#pragma once

#include <vector>

#include "play/game_session.h"
#include "render/camera.h"
#include "render/draw.h"
#include "tire/world/debug_draw.h"

namespace game {

struct DebugOptions;

// The engine's flags for what the options ask to see (regions are the game's own: not World state).
unsigned debug_flags(const DebugOptions& options);

class SdlDebugDraw final : public tire::DebugDraw {
 public:
  // `positions` and `points` are the caller's buffers, kept from frame to frame so that drawing
  // allocates only while they grow.
  SdlDebugDraw(Draw& draw, const Camera& camera, const GameSession& session, double alpha,
               std::vector<tire::Vec2>& positions, std::vector<ScreenPoint>& points)
      : d_(draw), camera_(camera), session_(session), alpha_(alpha), positions_(positions), points_(points) {}

  void segment(tire::Vec2 a, tire::Vec2 b, tire::DebugShape kind) override;
  void polygon(std::span<const tire::Vec2> points, tire::DebugShape kind) override;
  void point(tire::Vec2 p, tire::DebugShape kind) override;
  void vector(tire::Vec2 at, tire::Vec2 v, tire::DebugShape kind) override;
  void box(const tire::Aabb& box, tire::DebugShape kind) override;

  std::span<const tire::Vec2> tire_positions(const tire::TireView& t) override;
  tire::Pose prop_pose(std::uint32_t prop, const tire::Pose& now) override;

 private:
  Draw& d_;
  const Camera& camera_;
  const GameSession& session_;
  double alpha_;
  std::vector<tire::Vec2>& positions_;
  std::vector<ScreenPoint>& points_;
  // Whether the tire whose shapes come now is asleep: the engine's debug_draw asks tire_positions()
  // for a tire before reporting its shapes.
  bool asleep_ = false;
  SDL_Color color(SDL_Color c, tire::DebugShape kind) const;
};

}  // namespace game
