// The player vehicle's motor: a continuous tone, held while a player vehicle exists, whose pitch
// follows its driven wheels' spin relative to the chassis (what the motor turns at: its revs, as
// in a fixed gear) and whose loudness follows the throttle. Pure functions of what the façade shows
// (tire::VehicleView, tire::TireView): the sound reads the simulation and never feeds it. No SDL.
#pragma once

#include <cstdint>
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
  // The revs heard follow the wheels' with this time constant (s): a soft wheel's spin wobbles by a
  // few per cent from tick to tick, which would warble the tone.
  double smoothing = 0.05;
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

// What the player vehicle's motor does now: its revs and throttle; nullopt when there is none.
struct MotorReading {
  double revs = 0.0;
  double throttle = 0.0;
};
std::optional<MotorReading> read_motor(const tire::Simulation& simulation, const MotorTuning& tuning = {});

// The motor's record for tick `tick`, at `revs` (as heard: smoothed) and `throttle`.
SoundEvent motor_event(std::uint64_t tick, double revs, double throttle, const MotorTuning& tuning = {});

// The revs heard after one tick of `dt` s: `heard` moved towards `revs` by the smoothing.
double smoothed_revs(double heard, double revs, double dt, const MotorTuning& tuning = {});

}  // namespace game::sound
