// The tuning panel (F2): sliders and the sleep checkbox over a copy of the session's Tuning, and
// toggles for the debug overlays. It changes nothing itself: it returns the key = value changes for the
// session to apply (as TuneEvents, so that a replay can record them).
#pragma once

#include <vector>

#include "renderer.h"
#include "session_input.h"
#include "tuning.h"

namespace game {

// `current` is the tuning in force, `level_defaults` what the level started with (for "Reset").
std::vector<TuneEvent> draw_tuning_panel(const Tuning& current, const Tuning& level_defaults,
                                         DebugOptions& debug, bool* open);

}  // namespace game
