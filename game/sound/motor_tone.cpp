#include "motor_tone.h"

#include <algorithm>
#include <cmath>

namespace game::sound {

double motor_revs(double wheel_spin, double motor_speed, const MotorTuning& tuning) {
  if (!(motor_speed > 0.0)) return 0.0;  // a motor that cannot turn stays at idle
  return std::clamp(std::abs(wheel_spin) / motor_speed, 0.0, tuning.max_revs);
}

double motor_pitch(double revs, const MotorTuning& tuning) {
  // std::lerp: exactly idle_pitch at 0 and full_pitch at 1.
  return std::lerp(tuning.idle_pitch, tuning.full_pitch, std::clamp(revs, 0.0, tuning.max_revs));
}

double motor_gain(double throttle, const MotorTuning& tuning) {
  return std::lerp(tuning.idle_gain, tuning.full_gain, std::min(1.0, std::abs(throttle)));
}

double driven_wheel_spin(const tire::Simulation& simulation, const tire::VehicleView& vehicle) {
  const bool any_driven =
      std::any_of(vehicle.wheel_driven.begin(), vehicle.wheel_driven.begin() + vehicle.wheel_count,
                  [](bool d) { return d; });
  double sum = 0.0;
  int count = 0;
  for (std::size_t w = 0; w < vehicle.wheel_count; ++w) {
    if (any_driven && !vehicle.wheel_driven[w]) continue;
    if (const std::optional<tire::TireView> t = simulation.tire(vehicle.wheel_ids[w])) {
      sum += std::abs(t->spin - vehicle.angular_velocity);
      ++count;
    }
  }
  return count ? sum / count : 0.0;
}

std::optional<MotorReading> read_motor(const tire::Simulation& simulation, const MotorTuning& tuning) {
  for (std::size_t i = 0; const std::optional<tire::VehicleView> v = simulation.vehicle_at(i); ++i)
    if (v->player)
      return MotorReading{motor_revs(driven_wheel_spin(simulation, *v), v->motor_speed, tuning), v->throttle};
  return std::nullopt;
}

SoundEvent motor_event(std::uint64_t tick, double revs, double throttle, const MotorTuning& tuning) {
  SoundEvent e;
  e.tick = tick;
  e.kind = SoundKind::motor;
  e.gain = motor_gain(throttle, tuning);
  e.pitch = motor_pitch(revs, tuning);
  return e;  // the player's own: from the middle
}

double smoothed_revs(double heard, double revs, double dt, const MotorTuning& tuning) {
  const double k = dt / (std::max(tuning.smoothing, 0.0) + dt);  // 1 without smoothing
  return heard + k * (revs - heard);
}

}  // namespace game::sound
