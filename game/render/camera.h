// World (metres, y up) to screen (pixels, y down). The camera follows a target within the level's
// bounds, and its scale follows the window size: about kViewHeight metres are always in view.
#pragma once

#include "tire/math/geometry.h"

namespace tire {
class Simulation;
}  // namespace tire

namespace game {

struct ScreenPoint {
  float x = 0.0f;
  float y = 0.0f;
};

class Camera {
 public:
  static constexpr double kViewHeight = 7.5;  // m visible vertically
  static constexpr double kViewWidth = 12.0;  // m at least visible horizontally

  // The window's drawable size in pixels; sets the scale.
  void resize(int width, int height);
  // Where the camera looks for a player at `position` moving at `velocity`: a little ahead of it,
  // and above it, so that the ground sits in the lower part of the screen and jumps stay in view.
  tire::Vec2 aim(tire::Vec2 position, tire::Vec2 velocity) const;
  // Eases towards `target` (wall-clock seconds since the last frame: rendering only), then keeps
  // the view inside `bounds` (when the bounds are smaller than the view: centred horizontally,
  // resting on their bottom vertically).
  void follow(tire::Vec2 target, const tire::Aabb& bounds, double seconds);
  // Jumps straight to the target.
  void snap(tire::Vec2 target, const tire::Aabb& bounds);
  // Looks at `center` at `scale` pixels per metre, wherever that is: the editor's free view.
  void set_view(tire::Vec2 center, double scale) {
    center_ = center;
    scale_ = scale;
  }

  ScreenPoint to_screen(tire::Vec2 p) const {
    return {static_cast<float>((p.x - center_.x) * scale_ + width_ * 0.5),
            static_cast<float>(height_ * 0.5 - (p.y - center_.y) * scale_)};
  }
  tire::Vec2 to_world(double sx, double sy) const {
    return {center_.x + (sx - width_ * 0.5) / scale_, center_.y + (height_ * 0.5 - sy) / scale_};
  }
  float pixels(double metres) const { return static_cast<float>(metres * scale_); }
  double metres(double pixels) const { return pixels / scale_; }
  double scale() const { return scale_; }  // pixels per metre
  int width() const { return width_; }
  int height() const { return height_; }
  tire::Vec2 center() const { return center_; }
  // What is on screen, in world coordinates.
  tire::Aabb view() const;

 private:
  void clamp(const tire::Aabb& bounds);

  tire::Vec2 center_;
  double scale_ = 80.0;
  int width_ = 1280;
  int height_ = 720;
};

// The union of the level's obstacles, props and regions (and the tires), with a margin: `below`
// under it, `margin` at the sides and more above, where tires jump.
// Where the level's ground is. `floor`: the height below which the level is underground, drawn as
// rock under the ground and as the deep elsewhere (a chasm, past a ledge): the bottom of its widest
// obstacle, or else of its static props (chain terrain); -1e9 without either. `surface`: the top of
// the widest obstacle (the floor without one); an obstacle whose bottom is below it stands on the
// ground, and rock goes on under it, where a platform floats.
struct Underground {
  double floor = -1e9;
  double surface = -1e9;
};
Underground underground(const tire::Simulation& simulation);

constexpr double kBoundsMarginBelow = 0.75;  // m
tire::Aabb level_bounds(const tire::Simulation& simulation, double margin = 1.5,
                        double below = kBoundsMarginBelow);

}  // namespace game
