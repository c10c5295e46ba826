// The game's sounds, synthesised when the game starts (nothing is downloaded or shipped): a few
// hundred milliseconds of mono float samples each, from sines, sweeps and seeded noise, so the
// same bank comes out of every run. No SDL.
#pragma once

#include <array>
#include <vector>

#include "sound_event.h"

namespace game::sound {

// One synthesised sound.
struct Sample {
  std::vector<float> data;      // mono, in [-1, 1]
  bool loop = false;            // held sounds (roll, skid) loop while they last
  std::vector<float> envelope;  // the peak of each kEnvelopeBlock samples: how loud it is when
};

class SoundBank {
 public:
  static constexpr int kRate = 44100;  // samples per second of every sound
  static constexpr int kEnvelopeBlock = kRate / 100;

  SoundBank();  // synthesises every sound
  const Sample& sample(SoundKind kind) const { return samples_[static_cast<std::size_t>(kind)]; }
  // The seconds a one-shot lasts at playback rate `pitch`.
  double seconds(SoundKind kind, double pitch) const;
  // How loud `kind` is `seconds` into it at playback rate `pitch` (its peak there; 0 past its end).
  double envelope(SoundKind kind, double seconds, double pitch) const;

 private:
  std::array<Sample, 9> samples_;  // one per SoundKind
};

}  // namespace game::sound
