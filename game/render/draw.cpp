#include "render/draw.h"

#include <cmath>
#include <numbers>

namespace game {

void Draw::vertex(ScreenPoint p, SDL_Color c) {
  SDL_Vertex v{};
  v.position = {p.x, p.y};
  v.color = c;
  translucent_ = translucent_ || c.a != 255;
  vertices_.push_back(v);
}

void Draw::flush() {
  if (vertices_.empty()) return;
  // An opaque batch needs no blending, which a software renderer does pixel by pixel.
  if (!translucent_) SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_NONE);
  SDL_RenderGeometry(renderer_, nullptr, vertices_.data(), static_cast<int>(vertices_.size()), nullptr, 0);
  if (!translucent_) SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_BLEND);
  vertices_.clear();
  translucent_ = false;
}

void Draw::triangle(ScreenPoint a, ScreenPoint b, ScreenPoint c, SDL_Color color) {
  vertex(a, color);
  vertex(b, color);
  vertex(c, color);
  if (vertices_.size() > 30000) flush();
}

void Draw::quad(ScreenPoint a, ScreenPoint b, ScreenPoint c, ScreenPoint d, SDL_Color color) {
  triangle(a, b, c, color);
  triangle(a, c, d, color);
}

void Draw::convex(const std::vector<ScreenPoint>& points, SDL_Color color) {
  for (std::size_t i = 1; i + 1 < points.size(); ++i) triangle(points[0], points[i], points[i + 1], color);
}

void Draw::fan(ScreenPoint hub, const std::vector<ScreenPoint>& ring, SDL_Color color) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) triangle(hub, ring[i], ring[(i + 1) % n], color);
}

void Draw::rect(ScreenPoint a, ScreenPoint b, SDL_Color color) { quad(a, {b.x, a.y}, b, {a.x, b.y}, color); }

void Draw::circle(ScreenPoint c, float radius, SDL_Color color, int segments) {
  scratch_.clear();
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * std::numbers::pi * i / segments;
    scratch_.push_back(
        {c.x + radius * static_cast<float>(std::cos(a)), c.y + radius * static_cast<float>(std::sin(a))});
  }
  fan(c, scratch_, color);
}

void Draw::line(ScreenPoint a, ScreenPoint b, float width, SDL_Color color) {
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float len = std::sqrt(dx * dx + dy * dy);
  if (len <= 0.0f) return;
  const float nx = -dy / len * width * 0.5f, ny = dx / len * width * 0.5f;
  quad({a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}, color);
}

void Draw::polyline(const std::vector<ScreenPoint>& points, bool closed, float width, SDL_Color color) {
  const std::size_t n = points.size();
  if (n < 2) return;
  for (std::size_t i = 0; i + 1 < n; ++i) line(points[i], points[i + 1], width, color);
  if (closed) line(points[n - 1], points[0], width, color);
  // Round the joints so thick lines do not show notches.
  if (width > 2.5f)
    for (const ScreenPoint& p : points) circle(p, width * 0.5f, color, 10);
}

void Draw::rect_outline(ScreenPoint a, ScreenPoint b, float width, SDL_Color color) {
  // As polyline() draws the closed outline, without building a vector for it every frame.
  const ScreenPoint corners[4] = {a, {b.x, a.y}, b, {a.x, b.y}};
  for (int i = 0; i < 4; ++i) line(corners[i], corners[(i + 1) % 4], width, color);
  if (width > 2.5f)
    for (const ScreenPoint& p : corners) circle(p, width * 0.5f, color, 10);
}

void Draw::vertical_gradient(int width, int height, SDL_Color top, SDL_Color bottom) {
  vertical_gradient({0, 0}, {static_cast<float>(width), static_cast<float>(height)}, top, bottom);
}

void Draw::vertical_gradient(ScreenPoint min, ScreenPoint max, SDL_Color top, SDL_Color bottom) {
  vertex(min, top);
  vertex({max.x, min.y}, top);
  vertex(max, bottom);
  vertex(min, top);
  vertex(max, bottom);
  vertex({min.x, max.y}, bottom);
}

}  // namespace game
