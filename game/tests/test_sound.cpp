// The game's sound without SDL: the world → sound events (event_extractor.h), what the engine
// exposes for it (Tire::tick_contacts), the voice mixer's limit and limiter, the audio log.
#define CATCH_CONFIG_MAIN
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "internals.h"
#include "sound/audio_log.h"
#include "sound/event_extractor.h"
#include "sound/motor_tone.h"
#include "sound/sound_bank.h"
#include "sound/voice_mixer.h"

using namespace game::sound;
using game::world_of;

namespace {

std::unique_ptr<tire::Simulation> session_of(const std::string& file) {
  tire::LevelLoad load = tire::load_level_file(file);
  if (!load.level) throw std::runtime_error(load.errors.front());
  return std::make_unique<tire::Simulation>(std::make_shared<const tire::Level>(std::move(*load.level)));
}

std::string test_level(const std::string& name) {
  return std::string(TIRE_GAME_TESTS_DIR) + "/levels/" + name;
}
std::string level(const std::string& name) { return std::string(TIRE_LEVELS_DIR) + "/" + name; }

// Steps `session` `ticks` ticks with `input` (its jump at tick `jump_at` only), extracting events.
std::vector<SoundEvent> play(tire::Simulation& session, int ticks, tire::TickInput input = {},
                             int jump_at = -1) {
  EventExtractor extractor;
  std::vector<SoundEvent> events;
  for (int i = 0; i < ticks; ++i) {
    tire::TickInput in = input;
    in.jump = i == jump_at;
    session.step(in);
    extractor.after_tick(session, in, events);
  }
  return events;
}

std::vector<SoundEvent> of_kind(const std::vector<SoundEvent>& events, SoundKind kind) {
  std::vector<SoundEvent> out;
  std::copy_if(events.begin(), events.end(), std::back_inserter(out),
               [&](const SoundEvent& e) { return e.kind == kind; });
  return out;
}

}  // namespace

TEST_CASE("a resting tire's tick contacts report its weight times dt against the ground", "[sound]") {
  auto session = session_of(test_level("resting.json"));
  play(*session, 120);
  const tire::Tire& t = world_of(*session).tires().front();
  const double weight_dt = t.total_mass() * 9.81 * world_of(*session).config().dt;
  CHECK(t.tick_contacts.ground == Approx(weight_dt).epsilon(0.02));
  CHECK(t.tick_contacts.prop == 0.0);
  CHECK(t.tick_contacts.tire == 0.0);
  CHECK(t.tick_contacts.slip_speed < 0.05);
}

TEST_CASE("a tire dropped from 3 m makes a louder first impact than one dropped from 0.3 m", "[sound]") {
  auto high = session_of(test_level("drop-3m.json"));
  auto low = session_of(test_level("drop-0.3m.json"));
  const auto high_events = play(*high, 120);
  const auto high_hits = of_kind(high_events, SoundKind::impact);
  const auto low_hits = of_kind(play(*low, 120), SoundKind::impact);
  REQUIRE(!high_hits.empty());
  REQUIRE(!low_hits.empty());
  INFO("3 m: gain " << high_hits[0].gain << " pitch " << high_hits[0].pitch << " at tick "
                    << high_hits[0].tick);
  INFO("0.3 m: gain " << low_hits[0].gain << " pitch " << low_hits[0].pitch << " at tick "
                      << low_hits[0].tick);
  CHECK(high_hits[0].surface == Surface::ground);
  CHECK(high_hits[0].gain > 1.3 * low_hits[0].gain);
  CHECK(high_hits[0].pitch < low_hits[0].pitch);  // a harder hit is deeper
  // It lands about when free fall says: 3 m takes 0.78 s (47 ticks).
  CHECK(high_hits[0].tick >= 44);
  CHECK(high_hits[0].tick <= 52);
  // A straight landing spreads the tread sideways over the ground: that is no skid.
  CHECK(of_kind(high_events, SoundKind::skid).empty());
}

TEST_CASE("a tire resting 5 s makes no impact sound after it settles", "[sound]") {
  auto session = session_of(test_level("resting.json"));
  const auto events = play(*session, 360);
  REQUIRE(!world_of(*session).tires().front().asleep);  // sleeping is off: simulated throughout
  for (const SoundEvent& e : of_kind(events, SoundKind::impact)) {
    INFO("impact at tick " << e.tick << " gain " << e.gain);
    CHECK(e.tick <= 60);
  }
  CHECK(of_kind(events, SoundKind::roll).empty());
  CHECK(of_kind(events, SoundKind::skid).empty());
}

TEST_CASE("a tire landing on another makes a tire impact", "[sound]") {
  auto session = session_of(test_level("resting.json"));
  tire::TireSpec spec = world_of(*session).tires().front().spec;
  spec.player = false;
  spec.position = {0.0, 2.6};
  world_of(*session).add_tire(spec);
  const auto hits = of_kind(play(*session, 120), SoundKind::impact);
  CHECK(
      std::any_of(hits.begin(), hits.end(), [](const SoundEvent& e) { return e.surface == Surface::tire; }));
}

TEST_CASE("a rolling tire's tread sound rises in pitch as it speeds up, and the jump sounds", "[sound]") {
  auto session = session_of(level("01-first-roll.json"));
  tire::TickInput right;
  right.steer = 1.0;
  const auto events = play(*session, 240, right, 100);
  const auto rolls = of_kind(events, SoundKind::roll);
  REQUIRE(rolls.size() > 100);
  CHECK(rolls.back().pitch > rolls.front().pitch);
  CHECK(rolls.back().gain > rolls.front().gain);
  const auto jumps = of_kind(events, SoundKind::jump);
  REQUIRE(jumps.size() == 1);
  CHECK(jumps[0].tick == 101);
  CHECK(of_kind(events, SoundKind::message).size() == 1);  // the level's opening message
}

TEST_CASE("a tire to the player's right sounds from the right, the player's own from the middle", "[sound]") {
  // resting.json's tire is the player's; a second one 6 m to its right, spinning on the ground,
  // rolls and skids there: pan 0.8 × 6/7 = 0.69 while it stays there.
  auto session = session_of(test_level("resting.json"));
  REQUIRE(world_of(*session).player() != nullptr);
  const double player_x = world_of(*session).player()->centroid().x;
  tire::TireSpec spec = world_of(*session).tires().front().spec;
  spec.player = false;
  spec.position = {player_x + 6.0, spec.position.y};
  spec.angular_velocity = -20.0;
  const tire::TireId other = world_of(*session).add_tire(spec);
  const ExtractorTuning tuning;
  bool heard = false;
  for (const SoundEvent& e : play(*session, 30)) {
    if (e.tire < 0) {
      CHECK(e.pan == 0.0);  // the game's events
      continue;
    }
    if (e.tire == static_cast<std::int64_t>(other)) {
      heard = true;
      CHECK(e.pan > 0.0);
      CHECK(e.pan <= tuning.pan_most);
    } else {
      CHECK(e.pan == 0.0);  // the player's own tire
    }
  }
  CHECK(heard);
}

TEST_CASE("a voice panned left is louder on the left, and as loud in all as in the middle", "[sound]") {
  const SoundBank bank;
  const auto channel_power = [&](double pan) {
    VoiceMixer mixer(bank);
    mixer.set_volume(0.5);
    SoundEvent e{1, SoundKind::roll, Surface::ground, 7, 0.5, 1.0};
    e.pan = pan;
    mixer.play(e);
    mixer.end_tick(1.0 / 60.0);
    std::vector<float> out(2 * 4096);
    mixer.render(out.data(), out.size() / 2);
    std::pair<double, double> power{0.0, 0.0};
    for (std::size_t i = 0; i < out.size(); i += 2) {
      power.first += static_cast<double>(out[i]) * out[i];
      power.second += static_cast<double>(out[i + 1]) * out[i + 1];
    }
    return power;
  };
  const auto middle = channel_power(0.0), left = channel_power(-0.8), right = channel_power(0.8);
  CHECK(middle.first == Approx(middle.second));
  CHECK(left.first > 10.0 * left.second);
  CHECK(right.second > 10.0 * right.first);
  // Equal power: below the limiter's knee, the two channels add up to what the middle gives.
  CHECK(left.first + left.second == Approx(middle.first + middle.second).epsilon(0.01));
}

TEST_CASE("a tire set spinning on the ground skids until it grips", "[sound]") {
  auto session = session_of(test_level("resting.json"));
  world_of(*session).reset_tire(0);
  tire::Tire& t = *world_of(*session).find_tire(0);
  const tire::RigidMotion m = t.rigid_motion();
  for (std::size_t i = 0; i < t.particles.size(); ++i)
    t.particles.v[i] += tire::perp(t.particles.x[i] - m.centroid) * -30.0;
  const auto skids = of_kind(play(*session, 60), SoundKind::skid);
  REQUIRE(!skids.empty());
  CHECK(skids.front().tick <= 3);
  CHECK(skids.front().gain > 0.3);
}

TEST_CASE("level 01 played to its flag ends with the win sound", "[sound]") {
  auto session = session_of(level("01-first-roll.json"));
  tire::TickInput right;
  right.steer = 1.0;
  const auto events = play(*session, 900, right);
  REQUIRE(session->status() == tire::ScriptStatus::won);
  CHECK(of_kind(events, SoundKind::win).size() == 1);
  CHECK(of_kind(events, SoundKind::lose).empty());
}

TEST_CASE("a level lost on its time limit ends with the lose sound", "[sound]") {
  tire::LevelLoad load = tire::load_level_file(test_level("resting.json"));
  REQUIRE(load.level);
  load.level->script.time_limit = 0.5;  // a level file's "time_limit": 0.5
  auto session = std::make_unique<tire::Simulation>(std::make_shared<const tire::Level>(*load.level));
  const auto events = play(*session, 60);
  REQUIRE(session->status() == tire::ScriptStatus::lost);
  const auto lose = of_kind(events, SoundKind::lose);
  REQUIRE(lose.size() == 1);
  CHECK(lose[0].tick == 30);  // 0.5 s of 1/60 s ticks
  CHECK(lose[0].gain > 0.0);
  CHECK(of_kind(events, SoundKind::win).empty());
}

TEST_CASE("a new checkpoint sounds once", "[sound]") {
  auto session = session_of(test_level("resting.json"));
  EventExtractor extractor;
  std::vector<SoundEvent> events;
  for (int tick = 0; tick < 5; ++tick) {
    if (tick == 2)  // what the script's checkpoint action does
      tire::SimulationInternals::session(*session).set_checkpoint({1.0, 1.0});
    session->step({});
    extractor.after_tick(*session, {}, events);
  }
  const auto checkpoints = of_kind(events, SoundKind::checkpoint);
  REQUIRE(checkpoints.size() == 1);
  CHECK(checkpoints[0].tick == 3);
}

TEST_CASE("the mixer plays only the loudest kMaxVoices of 300 loud impacts", "[sound]") {
  const SoundBank bank;
  VoiceMixer mixer(bank);
  for (int i = 0; i < 300; ++i)
    mixer.play({1, SoundKind::impact, Surface::ground, i, 0.5 + 0.5 * (i % 100) / 100.0, 1.0});
  const MixStats stats = mixer.end_tick(1.0 / 60.0);
  CHECK(stats.playing == kMaxVoices);
  CHECK(stats.wanted == kVoicePool);  // the pool keeps the loudest kVoicePool; the rest were dropped at once
  // Held sounds renewed every tick compete with them, the limit holds for as long as they ring.
  for (int tick = 0; tick < 60; ++tick) {
    for (int i = 0; i < 50; ++i) mixer.play({2, SoundKind::roll, Surface::ground, i, 0.4, 1.0});
    CHECK(mixer.end_tick(1.0 / 60.0).playing <= kMaxVoices);
  }
}

TEST_CASE("300 loud events mixed stay inside [-1, 1]", "[sound]") {
  const SoundBank bank;
  VoiceMixer mixer(bank);
  mixer.set_volume(1.0);
  std::vector<float> out(4096);
  float peak = 0.0f;
  for (int tick = 0; tick < 30; ++tick) {
    for (int i = 0; i < 300; ++i) {
      const auto kind = static_cast<SoundKind>(i % 8);
      mixer.play({static_cast<std::uint64_t>(tick), kind, Surface::ground, i, 1.0, 0.5 + (i % 7) * 0.25});
    }
    mixer.end_tick(1.0 / 60.0);
    mixer.render(out.data(), out.size() / 2);
    for (const float x : out) {
      REQUIRE(std::isfinite(x));
      REQUIRE(std::abs(x) < 1.0f);
      peak = std::max(peak, std::abs(x));
    }
  }
  CHECK(peak > 0.5f);  // loud: the limiter had work to do
}

TEST_CASE("the soft limiter is linear below its knee and never reaches full scale", "[sound]") {
  CHECK(soft_limit(0.3f) == 0.3f);
  CHECK(soft_limit(-0.5f) == -0.5f);
  CHECK(soft_limit(1.0f) < 1.0f);
  CHECK(soft_limit(100.0f) <= 1.0f);
  CHECK(soft_limit(-100.0f) >= -1.0f);
  CHECK(soft_limit(0.9f) > soft_limit(0.8f));
}

TEST_CASE("muted, the mixer renders silence, and its volume scales what it renders", "[sound]") {
  const SoundBank bank;
  const auto rms = [&](double volume, bool muted) {
    VoiceMixer mixer(bank);
    mixer.set_volume(volume);
    mixer.set_muted(muted);
    mixer.play({1, SoundKind::win, Surface::none, -1, 0.5, 1.0});
    mixer.end_tick(1.0 / 60.0);
    std::vector<float> out(8192);
    mixer.render(out.data(), out.size() / 2);
    double sum = 0.0;
    for (const float x : out) sum += static_cast<double>(x) * x;
    return std::sqrt(sum / static_cast<double>(out.size()));
  };
  CHECK(rms(1.0, true) == 0.0);
  CHECK(rms(0.0, false) == 0.0);
  CHECK(rms(1.0, false) > 0.01);
  CHECK(rms(0.5, false) == Approx(0.5 * rms(1.0, false)).epsilon(0.05));
}

TEST_CASE("every sound is synthesised inside [-1, 1] and the held ones loop", "[sound]") {
  const SoundBank bank;
  for (int k = 0; k <= static_cast<int>(SoundKind::motor); ++k) {
    const auto kind = static_cast<SoundKind>(k);
    const Sample& s = bank.sample(kind);
    INFO(kind_name(kind));
    CHECK(s.data.size() > 1000);
    CHECK(s.loop == is_held(kind));
    CHECK(std::all_of(s.data.begin(), s.data.end(), [](float x) { return std::abs(x) <= 1.0f; }));
    CHECK(bank.envelope(kind, 0.01, 1.0) > 0.0);
  }
}

TEST_CASE("the audio log writes one JSON line per event, held sounds when they start or change", "[sound]") {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "tire-sound-log-test.jsonl";
  {
    AudioLog log;
    std::string error;
    REQUIRE(log.open(file.string(), error));
    log.write({5, SoundKind::impact, Surface::prop, 3, 0.75, 1.1, -0.25});
    for (std::uint64_t tick = 6; tick < 10; ++tick)
      log.write({tick, SoundKind::roll, Surface::ground, 0, 0.3, 1.0});
    log.write({10, SoundKind::roll, Surface::ground, 0, 0.3, 1.5});  // pitch moved: a line
    log.write_mix(10, {2, 2});
    log.write_mix(11, {2, 2});  // unchanged: none
    CHECK(log.close().empty());
  }
  std::ifstream in(file);
  std::vector<nlohmann::json> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  std::filesystem::remove(file);
  REQUIRE(lines.size() == 4);
  CHECK(lines[0] == nlohmann::json{{"tick", 5},
                                   {"kind", "impact"},
                                   {"surface", "prop"},
                                   {"tire", 3},
                                   {"gain", 0.75},
                                   {"pitch", 1.1},
                                   {"pan", -0.25}});
  CHECK(lines[1]["kind"] == "roll");
  CHECK(lines[1]["tick"] == 6);
  CHECK(lines[2]["pitch"] == 1.5);
  CHECK(lines[2]["pan"] == 0.0);
  CHECK(lines[3] == nlohmann::json{{"tick", 10}, {"kind", "mix"}, {"playing", 2}, {"wanted", 2}});
}

TEST_CASE("a failed audio log write is reported with the file and the reason, never lost in silence",
          "[sound]") {
  AudioLog log;
  std::string error;
  CHECK_FALSE(log.open("/nonexistent-folder/log.jsonl", error));
  CHECK(error == "cannot write the audio log /nonexistent-folder/log.jsonl: No such file or directory");
  if (!std::filesystem::exists("/dev/full")) return;
  // A full device takes the buffered lines and refuses them at the flush.
  REQUIRE(log.open("/dev/full", error));
  log.write({5, SoundKind::impact, Surface::prop, 3, 0.75, 1.1, -0.25});
  CHECK(log.close() == "cannot write the audio log /dev/full: No space left on device");
  // More lines than a buffer holds: refused at a write, and nothing more is tried.
  REQUIRE(log.open("/dev/full", error));
  for (std::uint64_t tick = 0; tick < 2000; ++tick)
    log.write({tick, SoundKind::jump, Surface::none, -1, 1.0, 1.0});
  CHECK(log.error() == "cannot write the audio log /dev/full: No space left on device");
  CHECK(log.close() == log.error());
}

// ---- The motor ---------------------------------------------------------------------------------------

namespace {

std::string vehicle_level(const std::string& name) {
  return std::string(TIRE_LEVELS_DIR) + "/../tests/levels/" + name;
}

// The frequency of the left channel of `frames` rendered stereo frames at `rate`, from its zero
// crossings (the motor's wave crosses zero exactly twice a period), skipping the first 20 ms in
// which the voice's gain ramps up.
double rendered_frequency(VoiceMixer& mixer, int rate, std::size_t frames) {
  std::vector<float> out(2 * frames);
  mixer.render(out.data(), frames);
  const std::size_t skip = static_cast<std::size_t>(rate / 50);
  std::size_t crossings = 0, first = 0, last = 0;
  for (std::size_t i = skip + 1; i < frames; ++i) {
    const float a = out[2 * (i - 1)], b = out[2 * i];
    if ((a < 0.0f && b >= 0.0f) || (a >= 0.0f && b < 0.0f)) {
      if (crossings == 0) first = i;
      last = i;
      ++crossings;
    }
  }
  if (crossings < 3) return 0.0;
  // (crossings − 1) half periods between the first crossing and the last.
  return 0.5 * static_cast<double>(crossings - 1) * rate / static_cast<double>(last - first);
}

}  // namespace

TEST_CASE("the motor's pitch follows the driven wheels' revs and its loudness the throttle", "[sound]") {
  const MotorTuning k;
  CHECK(motor_revs(0.0, 40.0) == 0.0);
  CHECK(motor_revs(20.0, 40.0) == 0.5);
  CHECK(motor_revs(-20.0, 40.0) == 0.5);  // reverse revs as high
  CHECK(motor_revs(400.0, 40.0) == k.max_revs);
  CHECK(motor_revs(10.0, 0.0) == 0.0);  // a motor without speed idles
  CHECK(motor_pitch(0.0) == k.idle_pitch);
  CHECK(motor_pitch(1.0) == k.full_pitch);
  CHECK(motor_pitch(0.5) == Approx(0.5 * (k.idle_pitch + k.full_pitch)));
  CHECK(motor_pitch(0.25) < motor_pitch(0.75));
  CHECK(motor_pitch(-1.0) == k.idle_pitch);
  CHECK(motor_gain(0.0) == k.idle_gain);
  CHECK(motor_gain(1.0) == k.full_gain);
  CHECK(motor_gain(-1.0) == k.full_gain);
  CHECK(motor_gain(0.5) == Approx(0.5 * (k.idle_gain + k.full_gain)));
  // The revs heard follow the wheels' over about MotorTuning::smoothing: a quarter of the way in a
  // tick of 1/60 s, all of it within a second, never past it; without smoothing at once.
  const double dt = 1.0 / 60.0;
  CHECK(smoothed_revs(0.0, 1.0, dt) == Approx(dt / (k.smoothing + dt)));
  double heard = 0.0;
  for (int i = 0; i < 60; ++i) heard = smoothed_revs(heard, 1.0, dt);
  CHECK(heard > 0.999);
  CHECK(heard <= 1.0);
  MotorTuning sharp;
  sharp.smoothing = 0.0;
  CHECK(smoothed_revs(0.2, 0.7, dt, sharp) == 0.7);
}

TEST_CASE("the mixer plays the motor's tone at kMotorHz times its pitch, at any output rate", "[sound]") {
  const SoundBank bank;
  for (const int rate : {44100, 48000}) {
    for (const double pitch : {1.0, 1.7, 2.5, 4.0}) {
      VoiceMixer mixer(bank);
      mixer.set_output_rate(rate);
      mixer.set_volume(1.0);
      mixer.play({1, SoundKind::motor, Surface::none, -1, 0.4, pitch});
      mixer.end_tick(1.0 / 60.0);
      INFO("rate " << rate << ", pitch " << pitch);
      CHECK(rendered_frequency(mixer, rate, static_cast<std::size_t>(rate)) ==
            Approx(kMotorHz * pitch).epsilon(0.005));
    }
  }
  // Mixed with impacts, the motor still sounds: the mix is louder than the impacts alone.
  const auto rms = [&](bool with_motor) {
    VoiceMixer mixer(bank);
    mixer.play({1, SoundKind::impact, Surface::ground, 0, 0.8, 1.0});
    if (with_motor) mixer.play({1, SoundKind::motor, Surface::none, -1, 0.4, 2.0});
    CHECK(mixer.end_tick(1.0 / 60.0).playing == (with_motor ? 2u : 1u));
    std::vector<float> out(2 * 8192);
    mixer.render(out.data(), 8192);
    double sum = 0.0;
    for (const float x : out) sum += static_cast<double>(x) * x;
    return std::sqrt(sum / static_cast<double>(out.size()));
  };
  CHECK(rms(true) > 1.1 * rms(false));
}

TEST_CASE("a player vehicle's motor idles at rest and revs up at full throttle, and a tire player has none",
          "[sound]") {
  auto car = session_of(vehicle_level("vehicle-car.json"));
  EventExtractor extractor;
  std::vector<SoundEvent> events;
  // Settled, at rest: the motor ticks over at idle.
  for (int i = 0; i < 60; ++i) {
    car->step({});
    events.clear();
    extractor.after_tick(*car, {}, events);
  }
  auto motor = of_kind(events, SoundKind::motor);
  REQUIRE(motor.size() == 1);
  const MotorTuning k;
  CHECK(motor[0].gain == k.idle_gain);
  CHECK(motor[0].pitch == Approx(k.idle_pitch).margin(0.05));
  CHECK(motor[0].pan == 0.0);
  // Full throttle for a second: louder, and higher as the wheels spin up.
  double last_pitch = motor[0].pitch;
  for (int i = 0; i < 60; ++i) {
    car->step({1.0});
    events.clear();
    extractor.after_tick(*car, {1.0}, events);
    const double before = motor[0].pitch;
    motor = of_kind(events, SoundKind::motor);
    REQUIRE(motor.size() == 1);
    CHECK(std::abs(motor[0].pitch - before) < 0.03);  // no warble from the soft wheel's wobble
    if (i % 20 == 19) {
      CHECK(motor[0].pitch > last_pitch);
      last_pitch = motor[0].pitch;
    }
  }
  CHECK(motor[0].gain == Approx(k.full_gain));
  // The pitch is the driven (rear) wheel's revs: after a second, about 8 rad/s of its 40.
  const tire::VehicleView v = *car->vehicle_at(0);
  const double spin = car->tire(v.wheel_ids[0])->spin - v.angular_velocity;
  // (the revs follow the wheels within MotorTuning::smoothing: a few hundredths behind)
  CHECK(last_pitch == Approx(motor_pitch(motor_revs(spin, v.motor_speed))).epsilon(0.03));
  CHECK(last_pitch > 1.3 * k.idle_pitch);
  // Level 01's player is a tire: no motor.
  auto tire = session_of(level("01-first-roll.json"));
  CHECK(of_kind(play(*tire, 60, {1.0}), SoundKind::motor).empty());
}

TEST_CASE("listening to a vehicle changes nothing in its world", "[sound]") {
  auto heard = session_of(vehicle_level("vehicle-car.json"));
  auto unheard = session_of(vehicle_level("vehicle-car.json"));
  play(*heard, 120, {1.0, false, 0.0, 0.5});
  for (int i = 0; i < 120; ++i) unheard->step({1.0, false, 0.0, 0.5});
  CHECK(heard->state_hash() == unheard->state_hash());
}
