// The tuning panel (F2): sliders and the sleep checkbox over a copy of the session's Tuning, and
// toggles for the debug overlays. It changes nothing itself: it returns the key = value changes for the
// session to apply (as TuneEvents, so that a replay can record them).
#pragma once

#include <vector>

#include "input/session_input.h"
#include "play/tuning.h"
#include "render/renderer.h"

namespace game {

// The sound's settings, which the panel sets directly: they are no part of the simulation, and a
// replay does not record them.
struct SoundSettings {
  double volume = 0.8;  // [0, 1]
  bool muted = false;   // M
};

// `current` is the tuning in force, `level_defaults` what the level started with (for "Reset").
std::vector<TuneEvent> draw_tuning_panel(const Tuning& current, const Tuning& level_defaults,
                                         DebugOptions& debug, SoundSettings& sound, bool* open);

}  // namespace game
