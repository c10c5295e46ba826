// The player vehicle's motor: a continuous tone, held while a player vehicle exists, whose pitch
// follows its driven wheels' spin relative to the chassis (what the motor turns at: its revs, as
// in a fixed gear) and whose loudness follows the throttle. Pure functions of what the façade shows
// (tire::VehicleView, tire::TireView): the sound reads the simulation and never feeds it. No SDL.
#pragma once

#include <optional>

#include "sound_event.h"
#include "tire/engine.h"

namespace game::sound {

// The motor tone's fundamental at playback rate 1 (SoundBank's motor sample: whole periods of it).
constexpr double kMotorHz = 60.0;

struct MotorTuning {
  // Revs: the driven wheels' mean |spin − the chassis' spin| over the vehicle's motor_speed (its
  // spin at full throttle), clamped to [0, max_revs]: a wheel spun faster by a slope revs higher.
  double max_revs = 1.25;
  double idle_pitch = 1.0;  // at 0 revs: kMotorHz
  double full_pitch = 4.0;  // at 1 rev (full speed): 4 × kMotorHz
  double idle_gain = 0.15;  // throttle 0: ticking over
  double full_gain = 0.45;  // full throttle, either way
};

// The revs of a motor whose driven wheels turn at `wheel_spin` (rad/s, relative to the chassis,
// mean of their magnitudes) and whose full-throttle spin is `motor_speed` (rad/s).
double motor_revs(double wheel_spin, double motor_speed, const MotorTuning& tuning = {});
// The playback rate at `revs`: idle_pitch at 0, rising in proportion (full_pitch at 1).
double motor_pitch(double revs, const MotorTuning& tuning = {});
// The gain at `throttle` in [-1, 1]: idle_gain at 0, full_gain at ±1, in proportion.
double motor_gain(double throttle, const MotorTuning& tuning = {});

// The mean |spin relative to the chassis| of `vehicle`'s driven wheels (all its wheels when none
// is driven), as `simulation` shows them now.
double driven_wheel_spin(const tire::Simulation& simulation, const tire::VehicleView& vehicle);

// The motor's record for this tick: the player vehicle's, or nullopt when there is none.
std::optional<SoundEvent> motor_event(const tire::Simulation& simulation, const MotorTuning& tuning = {});

}  // namespace game::sound
