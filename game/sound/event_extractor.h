// The world → sound events: after each tick, what the tires' contacts did (Tire::tick_contacts, the
// XPBD multipliers of the step as impulses) and what the level's script did become SoundEvents.
//  - An impact is a sharp rise of a tire's normal impulse against one kind of surface: a contact
//    that starts, or a harder hit on one that holds. A rise is followed to its peak (a landing lasts
//    a tick or two) and played there if its size, as a change of the tire's velocity (rise / mass),
//    passes kImpactMinSpeed: steady support (weight × dt a tick) never does. Loudness and pitch
//    follow the rise in N·s.
//  - A grounded, awake tire rolls: pitch from its angular speed. A contact sliding under kinetic
//    friction faster than kSkidMinSpeed skids.
//  - A player vehicle's motor, held while it exists: pitch from its driven wheels' spin, loudness
//    from the throttle (motor_tone.h).
//  - The player's jump, a new checkpoint, a new script message, won and lost.
// No SDL: tested on its own (game/tests/test_sound.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "motor_tone.h"
#include "sound_event.h"
#include "tire/engine.h"

namespace game::sound {

// The thresholds and scales of the extraction, in one place.
struct ExtractorTuning {
  double impact_min_speed = 0.5;  // m/s: a rise below this change of the tire's velocity is silent
  double impact_full = 60.0;      // N·s: a rise this big plays at gain 1 (10 kg stopped from 6 m/s)
  double roll_min_speed = 0.2;    // m/s of tread speed (|ω|·r) below which the tread is silent
  double roll_full_speed = 10.0;  // m/s of tread speed at gain 1
  double skid_min_speed = 0.6;    // m/s of sliding below which there is no skid
  double skid_full_speed = 6.0;   // m/s of sliding at gain 1
  // Stereo: a tire pan_width to the player's right (the middle of the screen, which follows the
  // player) sounds from the right at pan_most; nearer, in proportion. The player's own tire and the
  // game's events sound from the middle.
  double pan_width = 7.0;  // m: about half the view's width (camera.h: 7.5 m high, 16:9)
  double pan_most = 0.8;

  // Impacts: gain = surface gain · strength^impact_gain_power (strength = hit / impact_full, at
  // most 1); pitch = (impact_pitch_soft − impact_pitch_drop · strength) · surface pitch · size
  // pitch, clamped to impact_pitch: harder hits are louder and deeper.
  double impact_gain_power = 0.6;
  double impact_pitch_soft = 1.25;
  double impact_pitch_drop = 0.5;
  double impact_gain_tire = 0.7;    // a tire on a tire thuds softer
  double impact_pitch_prop = 1.3;   // a prop knocks a little higher
  double impact_pitch_tire = 0.85;  // and a tire lower
  double impact_pitch[2] = {0.4, 3.0};
  // Rolling: gain roll_gain at roll_full_speed; pitch roll_pitch_base + roll_pitch_per_omega·|ω|.
  double roll_gain = 0.5;
  double roll_pitch_base = 0.5;
  double roll_pitch_per_omega = 0.1;  // per rad/s
  double roll_pitch[2] = {0.3, 3.0};
  // Skids: gain skid_gain at skid_full_speed; pitch skid_pitch_base + skid_pitch_per_speed·slide.
  double skid_gain = 0.6;
  double skid_pitch_base = 0.85;
  double skid_pitch_per_speed = 0.04;  // per m/s
  double skid_pitch[2] = {0.4, 2.5};
  // The game's events, at pitch 1.
  double jump_gain = 0.7;
  double checkpoint_gain = 0.8;
  double message_gain = 0.5;
  double end_gain = 0.9;  // win and lose
};

class EventExtractor {
 public:
  explicit EventExtractor(ExtractorTuning tuning = {}, MotorTuning motor = {})
      : tuning_(tuning), motor_(motor) {}

  // After a tick of `simulation`, in which the player's input was `input`: appends its events to
  // `out`, the tires' and then the script's (checkpoint, message, won, lost).
  void after_tick(const tire::Simulation& simulation, const tire::TickInput& input,
                  std::vector<SoundEvent>& out);
  // A new world (level load, restart): forget every tire and the script's state.
  void reset();

 private:
  // What a tire's contacts did up to the last tick, per surface.
  struct Rise {
    double before = 0.0;  // the impulse a tick before the rise began (N·s)
    double last = 0.0;    // the last tick's impulse
    bool rising = false;
  };
  struct TireState {
    Rise surfaces[3];  // ground, prop, tire
  };
  void script_events(const tire::Simulation& simulation, std::vector<SoundEvent>& out);
  void impacts(const tire::TireView& t, std::uint64_t tick, std::vector<SoundEvent>& out);
  // Where `t` sounds from (SoundEvent::pan), heard from listener_x_.
  double pan_of(const tire::TireView& t) const;
  void follow(Rise& rise, double impulse, const tire::TireView& t, Surface surface, std::uint64_t tick,
              std::vector<SoundEvent>& out);

  ExtractorTuning tuning_;
  MotorTuning motor_;
  std::optional<double> heard_revs_;  // the player vehicle's motor's revs as heard (smoothed)
  std::unordered_map<tire::TireId, TireState> tires_;
  std::optional<double> listener_x_;  // the player's hub, this tick (none: no player)
  bool player_grounded_ = false;      // before this tick's step: what the jump needs
  std::optional<tire::Vec2> checkpoint_;
  std::vector<tire::ScriptMessage> messages_;
  tire::ScriptStatus status_ = tire::ScriptStatus::running;
};

}  // namespace game::sound
