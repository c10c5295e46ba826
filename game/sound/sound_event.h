// What the game plays, as the simulation and the level's script produce it: one record a tick per
// hit, per rolling or sliding tire and per game event. The mixer turns these into voices; the
// audio log (--audio-log) writes them as JSON lines. No SDL.
#pragma once

#include <cstdint>
#include <string_view>

namespace game::sound {

enum class SoundKind : std::uint8_t {
  impact,      // a tire hit something (one-shot)
  roll,        // a grounded tire's tread turning (held while it lasts: one record a tick)
  skid,        // a contact sliding under kinetic friction (held while it lasts)
  jump,        // the player jumped
  checkpoint,  // the script set a new checkpoint
  message,     // the script put a message on screen
  win,
  lose,
  motor,  // the player vehicle's motor (held while there is one: one record a tick; motor_tone.h)
};

// What an impact hit.
enum class Surface : std::uint8_t { none, ground, prop, tire };

// Held sounds last while a record arrives every tick; the rest play once.
constexpr bool is_held(SoundKind k) {
  return k == SoundKind::roll || k == SoundKind::skid || k == SoundKind::motor;
}

std::string_view kind_name(SoundKind kind);
std::string_view surface_name(Surface surface);

struct SoundEvent {
  std::uint64_t tick = 0;  // Simulation::tick() after the step that made it
  SoundKind kind = SoundKind::impact;
  Surface surface = Surface::none;
  std::int64_t tire = -1;  // the tire's id, or −1 for a game event and the motor
  double gain = 0.0;       // [0, 1]
  double pitch = 1.0;      // playback rate: 1 as synthesised, 2 an octave up
  double pan = 0.0;        // [-1, 1], left to right: where the tire is from the player (0 for game events)
};

}  // namespace game::sound
