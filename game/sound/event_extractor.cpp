#include "event_extractor.h"

#include <algorithm>
#include <cmath>

namespace game::sound {

std::string_view kind_name(SoundKind kind) {
  switch (kind) {
    case SoundKind::impact: return "impact";
    case SoundKind::roll: return "roll";
    case SoundKind::skid: return "skid";
    case SoundKind::jump: return "jump";
    case SoundKind::checkpoint: return "checkpoint";
    case SoundKind::message: return "message";
    case SoundKind::win: return "win";
    case SoundKind::lose: return "lose";
    case SoundKind::motor: return "motor";
  }
  return "?";
}

std::string_view surface_name(Surface surface) {
  switch (surface) {
    case Surface::none: return "none";
    case Surface::ground: return "ground";
    case Surface::prop: return "prop";
    case Surface::tire: return "tire";
  }
  return "?";
}

namespace {

// A smaller tire sounds higher: pitch scales with 1/√r about the usual 0.5 m.
double size_pitch(const tire::TireView& t) { return std::sqrt(0.5 / std::max(t.outer_radius, 0.01)); }

}  // namespace

void EventExtractor::follow(Rise& rise, double impulse, const tire::TireView& t, Surface surface,
                            std::uint64_t tick, std::vector<SoundEvent>& out) {
  if (!rise.rising && impulse > rise.last) {
    rise.rising = true;
    rise.before = rise.last;
  } else if (rise.rising && impulse <= rise.last) {
    // The rise peaked last tick: its size is the hit.
    rise.rising = false;
    const double hit = rise.last - rise.before;  // N·s
    if (hit >= tuning_.impact_min_speed * t.mass) {
      const ExtractorTuning& k = tuning_;
      const double strength = std::min(1.0, hit / k.impact_full);
      const double surface_gain = surface == Surface::tire ? k.impact_gain_tire : 1.0;
      const double surface_pitch = surface == Surface::prop   ? k.impact_pitch_prop
                                   : surface == Surface::tire ? k.impact_pitch_tire
                                                              : 1.0;
      SoundEvent e;
      e.tick = tick;
      e.kind = SoundKind::impact;
      e.surface = surface;
      e.tire = t.id;
      e.pan = pan_of(t);
      e.gain = surface_gain * std::pow(strength, k.impact_gain_power);
      e.pitch =
          std::clamp((k.impact_pitch_soft - k.impact_pitch_drop * strength) * surface_pitch * size_pitch(t),
                     k.impact_pitch[0], k.impact_pitch[1]);
      out.push_back(e);
    }
  }
  rise.last = impulse;
}

double EventExtractor::pan_of(const tire::TireView& t) const {
  if (!listener_x_) return 0.0;
  const double side = (t.centroid.x - *listener_x_) / tuning_.pan_width;
  return tuning_.pan_most * std::clamp(side, -1.0, 1.0);
}

void EventExtractor::impacts(const tire::TireView& t, std::uint64_t tick, std::vector<SoundEvent>& out) {
  TireState& s = tires_[t.id];
  const tire::TickContacts& c = t.contacts;
  follow(s.surfaces[0], c.ground, t, Surface::ground, tick, out);
  follow(s.surfaces[1], c.prop, t, Surface::prop, tick, out);
  follow(s.surfaces[2], c.tire, t, Surface::tire, tick, out);
}

void EventExtractor::after_tick(const tire::Simulation& simulation, const tire::TickInput& input,
                                std::vector<SoundEvent>& out) {
  const std::uint64_t tick = simulation.tick();
  const std::optional<tire::TireId> player_id = simulation.player();
  const std::optional<tire::TireView> player = player_id ? simulation.tire(*player_id) : std::nullopt;
  const std::optional<MotorReading> motor = read_motor(simulation, motor_);
  listener_x_ = player ? std::optional<double>(player->centroid.x) : std::nullopt;
  // A player vehicle: the view follows its centre of mass, and so does the listener.
  if (!player)
    for (std::size_t i = 0; const std::optional<tire::VehicleView> v = simulation.vehicle_at(i); ++i)
      if (v->player) listener_x_ = v->center.x;
  for (std::size_t i = 0; const std::optional<tire::TireView> view = simulation.tire_at(i); ++i) {
    const tire::TireView& t = *view;
    if (t.asleep) continue;  // not simulated: silent, and its figures are those it fell asleep with
    impacts(t, tick, out);
    const double pitch_scale = size_pitch(t);
    if (t.may_jump) {
      const double omega = std::abs(t.spin);
      const double tread_speed = omega * t.outer_radius;
      if (tread_speed >= tuning_.roll_min_speed) {
        SoundEvent e{tick, SoundKind::roll, Surface::ground, t.id};
        e.pan = pan_of(t);
        e.gain = tuning_.roll_gain * std::min(1.0, tread_speed / tuning_.roll_full_speed);
        e.pitch = std::clamp((tuning_.roll_pitch_base + tuning_.roll_pitch_per_omega * omega) * pitch_scale,
                             tuning_.roll_pitch[0], tuning_.roll_pitch[1]);
        out.push_back(e);
      }
    }
    if (const double slip = t.contacts.slip_speed; slip >= tuning_.skid_min_speed) {
      SoundEvent e{tick, SoundKind::skid, Surface::ground, t.id};
      e.pan = pan_of(t);
      e.gain = tuning_.skid_gain * std::min(1.0, slip / tuning_.skid_full_speed);
      e.pitch = std::clamp((tuning_.skid_pitch_base + tuning_.skid_pitch_per_speed * slip) * pitch_scale,
                           tuning_.skid_pitch[0], tuning_.skid_pitch[1]);
      out.push_back(e);
    }
  }
  // Forget tires that are gone, now and then (ids are never reused).
  if (tires_.size() > 2 * simulation.tire_count() + 16)
    std::erase_if(tires_, [&](const auto& entry) { return !simulation.tire(entry.first); });
  if (input.jump && player_grounded_ && player)
    out.push_back({tick, SoundKind::jump, Surface::none, -1, tuning_.jump_gain, 1.0});
  player_grounded_ = player && player->may_jump;
  if (motor) {
    // A new motor is heard at its revs at once; then they follow the wheels' smoothly.
    heard_revs_ =
        heard_revs_ ? smoothed_revs(*heard_revs_, motor->revs, simulation.config().dt, motor_) : motor->revs;
    out.push_back(motor_event(tick, *heard_revs_, motor->throttle, motor_));
  } else {
    heard_revs_.reset();
  }
  script_events(simulation, out);
}

void EventExtractor::script_events(const tire::Simulation& simulation, std::vector<SoundEvent>& out) {
  const std::uint64_t tick = simulation.tick();
  if (simulation.checkpoint() && simulation.checkpoint() != checkpoint_)
    out.push_back({tick, SoundKind::checkpoint, Surface::none, -1, tuning_.checkpoint_gain, 1.0});
  checkpoint_ = simulation.checkpoint();
  for (const tire::ScriptMessage& m : simulation.messages()) {
    const bool seen = std::any_of(messages_.begin(), messages_.end(), [&](const tire::ScriptMessage& o) {
      return o.text == m.text && o.until_tick == m.until_tick;
    });
    if (!seen) out.push_back({tick, SoundKind::message, Surface::none, -1, tuning_.message_gain, 1.0});
  }
  messages_.assign(simulation.messages().begin(), simulation.messages().end());
  const tire::ScriptStatus status = simulation.status();
  if (status != status_ && status == tire::ScriptStatus::won)
    out.push_back({tick, SoundKind::win, Surface::none, -1, tuning_.end_gain, 1.0});
  if (status != status_ && status == tire::ScriptStatus::lost)
    out.push_back({tick, SoundKind::lose, Surface::none, -1, tuning_.end_gain, 1.0});
  status_ = status;
}

void EventExtractor::reset() {
  tires_.clear();
  heard_revs_.reset();
  player_grounded_ = false;
  checkpoint_.reset();
  messages_.clear();
  status_ = tire::ScriptStatus::running;
}

}  // namespace game::sound
