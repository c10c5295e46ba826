// Draws the world: sky, obstacles, props, chain terrain, the goal flag, the tires (filled, with a
// tread that shows them roll) and, on request, the debug overlays, in which sleeping tires are darker.
// Positions are interpolated between the last two ticks by `alpha`.
#pragma once

#include <cstdint>
#include <vector>

#include "play/game_session.h"
#include "render/camera.h"
#include "render/draw.h"

namespace game {

// F3 turns the debug drawing on; the tuning panel picks what it shows.
struct DebugOptions {
  bool enabled = false;
  bool structure = true;    // inner ring and spokes
  bool contacts = true;     // active contacts and their normals
  bool velocities = true;   // hub velocity arrows
  bool aabbs = false;       // bounding boxes of tires and props
  bool broadphase = false;  // what each tire's broad phase returned this tick, and its narrow-phase pairs
  bool regions = true;      // the script's regions, named
};

// How a small tire looks in its texture (renderer.cpp draws it into an image once per look).
struct TireLook {
  double inner_ratio = 0.6;     // rim radius / tread radius
  double radius_pixels = 16.0;  // the tread's radius in the image, for features sized in pixels
  SDL_Color rim{176, 182, 194, 255};
  int tread_blocks = 14;  // alternating dark and light blocks round the tread
};
// The colour at (x, y) in units of the tread radius from the hub (y down), for |(x, y)| <= 1.
SDL_Color tire_texel(double x, double y, const TireLook& look);
// A size × size RGBA32 picture of the tire, its tread one texel inside the edge.
void tire_image(const TireLook& look, int size, std::vector<std::uint32_t>& rgba_pixels);

class WorldRenderer {
 public:
  WorldRenderer() = default;
  ~WorldRenderer();
  WorldRenderer(const WorldRenderer&) = delete;
  WorldRenderer& operator=(const WorldRenderer&) = delete;
  // Frees the textures; call before the SDL_Renderer they were made with is destroyed.
  void release();

  // A tire is drawn through as few of its particles as keep its drawn tread segments at least this
  // long on screen (px).
  static constexpr float kMinSegmentPixels = 6.0f;

  // Where the level's ground is (camera.h): below its floor, rock under the ground, the deep elsewhere.
  void set_underground(const Underground& u) { floor_ = u.floor, surface_ = u.surface; }
  void draw(Draw& draw, const Camera& camera, const GameSession& session, double alpha,
            const DebugOptions& debug);
  // The grab line from the grabbed tire to the mouse.
  void draw_grab(Draw& draw, const Camera& camera, const GameSession& session, double alpha);

 private:
  void draw_background(Draw& d, const Camera& camera);
  void draw_obstacles(Draw& d, const Camera& camera, const tire::Simulation& simulation);
  void draw_props(Draw& d, const Camera& camera, const GameSession& session, double alpha);
  void draw_goal(Draw& d, const Camera& camera, const tire::Simulation& simulation);
  // `shaded`: in asleep_shade() (draw.h), as the debug view draws a sleeping tire.
  void draw_tire(Draw& d, const Camera& camera, const GameSession& session, const tire::TireView& t,
                 double alpha, bool is_player, bool shaded);
  // Each vehicle's driver's head, a helmet (the debug view adds the circle the engine reports).
  void draw_heads(Draw& d, const Camera& camera, const GameSession& session, double alpha);
  void draw_debug(Draw& d, const Camera& camera, const GameSession& session, double alpha,
                  const DebugOptions& debug);

  // Small tires are drawn as one textured fan each, batched per texture.
  struct TireTexture {
    int size = 0;   // px, a power of two
    int ratio = 0;  // rim / tread radius, in fiftieths
    bool player = false;
    SDL_Texture* texture = nullptr;
    std::vector<SDL_Vertex> vertices;
  };
  TireTexture* tire_texture(SDL_Renderer* renderer, const tire::TireView& t, float radius_px, bool is_player);

  double floor_ = -1e9;
  double surface_ = -1e9;
  std::vector<TireTexture> tire_textures_;
  std::vector<SDL_FPoint> uv_;  // texture coordinates of a reduced tire's drawn points
  std::uint32_t uv_segments_ = 0, uv_step_ = 0;
  float uv_radius_ = 0.0f;
  std::vector<tire::Vec2> positions_;
  std::vector<ScreenPoint> outer_, inner_, band_;
  std::vector<ScreenPoint> shape_;
};

}  // namespace game
