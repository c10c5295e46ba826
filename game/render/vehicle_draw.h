// A vehicle's own parts that are neither a prop nor a tire: its driver's head, drawn as a helmet
// whose visor looks along the chassis' +x (its front), on a body sitting in the chassis, so that it
// turns with the chassis. The game's
// renderer, its debug overlay and the ghost all draw it from here.
#pragma once

#include <vector>

#include "render/camera.h"
#include "render/draw.h"
#include "tire/math/geometry.h"

namespace game {

// How a helmet looks: the shell, its rim and the visor. The ghost's is all translucent.
struct HelmetLook {
  SDL_Color shell{214, 64, 52, 255};
  SDL_Color edge{96, 28, 24, 255};
  SDL_Color visor{34, 44, 64, 255};
  SDL_Color glint{170, 200, 235, 255};  // a highlight on the visor
  SDL_Color stripe{250, 246, 236, 255};
  SDL_Color suit{44, 58, 96, 255};  // the driver's body under the helmet
};
// The player's helmet; another vehicle's, blue; the ghost's, pale and see-through.
HelmetLook player_helmet();
HelmetLook other_helmet();
HelmetLook ghost_helmet();

// The head's centre in the chassis' frame, from the world centre the engine reports and the
// chassis' pose then: drawn on a chassis pose blended between ticks, it stays where it belongs.
inline tire::Vec2 head_local(const tire::Pose& chassis, tire::Vec2 head_world) {
  return chassis.to_local(head_world);
}

// Draws a helmet of `radius` (m) at `local` in the frame `chassis`. `ring` is the caller's scratch.
void draw_helmet(Draw& d, const Camera& camera, const tire::Pose& chassis, tire::Vec2 local, double radius,
                 const HelmetLook& look, std::vector<ScreenPoint>& ring);

}  // namespace game
