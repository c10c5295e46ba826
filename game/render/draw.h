// Filled shapes and thick lines on an SDL_Renderer, in screen pixels, through SDL_RenderGeometry.
// Vertices are batched per call; nothing here knows about the world.
#pragma once

#include <SDL.h>

#include <vector>

#include "render/camera.h"

namespace game {

class Draw {
 public:
  explicit Draw(SDL_Renderer* renderer) : renderer_(renderer) {}

  SDL_Renderer* renderer() const { return renderer_; }

  void triangle(ScreenPoint a, ScreenPoint b, ScreenPoint c, SDL_Color color);
  void quad(ScreenPoint a, ScreenPoint b, ScreenPoint c, ScreenPoint d, SDL_Color color);  // a-b-c-d in order
  // A convex polygon as a fan from its first point.
  void convex(const std::vector<ScreenPoint>& points, SDL_Color color);
  // A fan from `hub` over a closed ring of points (any star-shaped outline).
  void fan(ScreenPoint hub, const std::vector<ScreenPoint>& ring, SDL_Color color);
  void rect(ScreenPoint min, ScreenPoint max, SDL_Color color);  // any two opposite corners
  void circle(ScreenPoint center, float radius, SDL_Color color, int segments = 24);
  void line(ScreenPoint a, ScreenPoint b, float width, SDL_Color color);
  void polyline(const std::vector<ScreenPoint>& points, bool closed, float width, SDL_Color color);
  void rect_outline(ScreenPoint min, ScreenPoint max, float width, SDL_Color color);
  // Sends the batched vertices to the renderer. Called by the other methods when the batch grows
  // and must be called before anything else draws (ImGui, SDL_RenderPresent).
  void flush();
  // Two-colour vertical gradient over the whole target, or over the box from `min` (top left) to
  // `max` (bottom right).
  void vertical_gradient(int width, int height, SDL_Color top, SDL_Color bottom);
  void vertical_gradient(ScreenPoint min, ScreenPoint max, SDL_Color top, SDL_Color bottom);

 private:
  void vertex(ScreenPoint p, SDL_Color c);

  SDL_Renderer* renderer_;
  std::vector<SDL_Vertex> vertices_;
  bool translucent_ = false;  // a vertex of the batch has alpha below 255
  std::vector<ScreenPoint> scratch_;
};

constexpr SDL_Color rgba(int r, int g, int b, int a = 255) {
  return {static_cast<Uint8>(r), static_cast<Uint8>(g), static_cast<Uint8>(b), static_cast<Uint8>(a)};
}

// `c` with its red, green and blue times f (in [0, 1]), alpha kept.
constexpr SDL_Color darker(SDL_Color c, float f = 0.6f) {
  return rgba(static_cast<int>(c.r * f), static_cast<int>(c.g * f), static_cast<int>(c.b * f), c.a);
}

// The debug view (F3) draws a sleeping tire, and what the engine reports about it, in this shade of
// the colours an awake one has.
constexpr float kAsleepShade = 0.55f;
constexpr SDL_Color asleep_shade(SDL_Color c) { return darker(c, kAsleepShade); }

}  // namespace game
