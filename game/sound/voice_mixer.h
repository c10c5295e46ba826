// The voices: each sound event becomes a voice (a one-shot that rings out, or a held sound renewed
// every tick), and only the kMaxVoices loudest are mixed; the rest are dropped (silent, still
// aging, so a quieter voice may come back when louder ones have faded). The choice is made once a
// tick on the game's thread (end_tick), from the events and the sounds' envelopes alone, so it is
// the same on every run whatever the audio device does; render() then mixes the chosen voices on
// the audio thread, through a soft limiter that keeps every sample inside [-1, 1]. The caller holds
// the audio lock around play/end_tick (SDL_LockAudioDevice; audio_output.h). No SDL.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sound_bank.h"
#include "sound_event.h"

namespace game::sound {

// How many voices are mixed at once; the quieter rest are dropped.
constexpr std::size_t kMaxVoices = 8;
// How many voices are kept at all (ringing one-shots and held sounds); beyond it the quietest new
// one-shot is dropped at once.
constexpr std::size_t kVoicePool = 256;
// A voice at gain 1 contributes this much: two full voices reach full scale before the limiter.
constexpr double kVoiceHeadroom = 0.5;
// The limiter is linear below this and bends smoothly towards 1 above it.
constexpr float kLimiterKnee = 0.6f;

// What a tick's choice came to.
struct MixStats {
  std::size_t playing = 0;  // voices mixed (≤ kMaxVoices)
  std::size_t wanted = 0;   // voices that would sound if there were no limit
};

// The soft limiter: x below the knee as it is, above it bent towards ±1, never reaching it.
float soft_limit(float x);

class VoiceMixer {
 public:
  explicit VoiceMixer(const SoundBank& bank);

  // The device's sample rate (the bank's sounds are resampled to it).
  void set_output_rate(int rate) { step_scale_ = static_cast<double>(SoundBank::kRate) / rate; }
  void set_volume(double volume);  // [0, 1]
  double volume() const { return volume_; }
  void set_muted(bool muted) { muted_ = muted; }
  bool muted() const { return muted_; }

  // Game thread, under the audio lock.
  void play(const SoundEvent& event);
  // Ages the one-shots by `dt`, ends the held sounds not renewed this tick, and picks the voices
  // to mix.
  MixStats end_tick(double dt);
  // Ends the held sounds (a new level: its tires, and their ids, are new); one-shots ring out, so a
  // win's jingle is not cut by the next level.
  void end_held() {
    std::erase_if(voices_, [](const Voice& v) { return is_held(v.kind); });
  }
  std::size_t voices() const { return voices_.size(); }

  // Audio thread: mixes the chosen voices into `out` (stereo, `frames` frames of a left and a right
  // sample; overwritten). Never allocates.
  void render(float* out, std::size_t frames);

 private:
  struct Voice {
    SoundKind kind = SoundKind::impact;
    std::int64_t key = -1;  // a held sound's tire; −1 for one-shots
    double gain = 0.0;
    double pitch = 1.0;
    float left = 1.0f;  // its pan's gains, equal power: 1 and 1 in the middle
    float right = 1.0f;
    double age = 0.0;       // s since it started (one-shots)
    double position = 0.0;  // in the sample (samples at the bank's rate)
    double loudness = 0.0;  // gain × its envelope now, as end_tick last saw it
    float level = 0.0f;     // the gain render applies now, ramping towards the target
    bool selected = false;
    bool started = false;   // selected at least once
    bool renewed = true;    // a held sound's record arrived this tick
    bool finished = false;  // its sample ran out (render)
  };
  double loudness(const Voice& v) const;
  static void set_pan(Voice& v, double pan);

  const SoundBank& bank_;
  std::vector<Voice> voices_;
  std::vector<std::size_t> order_;  // end_tick's scratch
  double step_scale_ = 1.0;
  double volume_ = 1.0;
  bool muted_ = false;
};

}  // namespace game::sound
