#include "sound_bank.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "motor_tone.h"

namespace game::sound {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// A small seeded noise source (xorshift32): the same noise every run.
class Noise {
 public:
  explicit Noise(std::uint32_t seed) : state_(seed) {}
  double next() {  // uniform in [-1, 1)
    state_ ^= state_ << 13;
    state_ ^= state_ >> 17;
    state_ ^= state_ << 5;
    return static_cast<double>(state_) / 2147483648.0 - 1.0;
  }

 private:
  std::uint32_t state_;
};

std::vector<float> samples_for(double seconds) {
  return std::vector<float>(static_cast<std::size_t>(seconds * SoundBank::kRate), 0.0f);
}

double time_of(std::size_t i) { return static_cast<double>(i) / SoundBank::kRate; }

// A thud: a sine falling from 120 to 50 Hz with a quick decay, and a burst of low-passed noise.
std::vector<float> thud() {
  std::vector<float> s = samples_for(0.35);
  Noise noise(1);
  double phase = 0.0, low = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double t = time_of(i);
    phase += kTwoPi * (50.0 + 70.0 * std::exp(-t / 0.04)) / SoundBank::kRate;
    low += 0.15 * (noise.next() - low);
    const double attack = std::min(1.0, t / 0.002);
    s[i] = static_cast<float>(
        attack * (0.8 * std::sin(phase) * std::exp(-t / 0.09) + 1.2 * low * std::exp(-t / 0.02)));
  }
  return s;
}

// The tread: band-limited noise beaten by the tread blocks passing (a loop of 0.5 s whose ends
// meet: the beat has a whole number of periods, and the noise is cross-faded over its seam).
std::vector<float> tread() {
  std::vector<float> s = samples_for(0.5);
  Noise noise(2);
  double low = 0.0, band = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double t = time_of(i);
    low += 0.2 * (noise.next() - low);
    band += 0.05 * (low - band);
    const double blocks = 0.55 + 0.45 * std::sin(kTwoPi * 24.0 * t);
    s[i] = static_cast<float>(2.5 * (low - band) * blocks);
  }
  const std::size_t fade = s.size() / 10;
  for (std::size_t i = 0; i < fade; ++i) {  // the end fades into the start
    const double a = static_cast<double>(i) / static_cast<double>(fade);
    const std::size_t j = s.size() - fade + i;
    s[i] = static_cast<float>(a * s[i] + (1.0 - a) * s[j]);
  }
  s.resize(s.size() - fade);
  return s;
}

// The skid: a squeal, two wavering tones over hissing noise (a loop of whole periods).
std::vector<float> skid() {
  std::vector<float> s = samples_for(0.5);
  Noise noise(3);
  double previous = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double t = time_of(i);
    const double wobble = 0.004 * std::sin(kTwoPi * 6.0 * t);
    const double white = noise.next();
    const double hiss = white - previous;  // a first difference: high-passed
    previous = white;
    s[i] = static_cast<float>(0.35 * std::sin(kTwoPi * 900.0 * (t + wobble)) +
                              0.2 * std::sin(kTwoPi * 1350.0 * (t + wobble)) + 0.15 * hiss);
  }
  return s;
}

// The motor: a buzz at kMotorHz, its odd and even overtones over a fundamental that a slower beat
// (every second period, the cylinders firing in turn) swells, as a loop of whole periods. The
// wave is sin φ (1 + 3a − 4a sin²φ + 2b cos φ) · (beat > 0), so it crosses zero exactly twice a
// period: the pitch shows as the rate of its zero crossings (test_sound.cpp).
std::vector<float> motor() {
  constexpr int kPeriods = 60;
  const auto period = static_cast<std::size_t>(SoundBank::kRate / kMotorHz);  // 735 samples, exactly
  std::vector<float> s(kPeriods * period + 1);  // the last sample is the first: the loop closes
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double phase = kTwoPi * static_cast<double>(i) / static_cast<double>(period);
    const double wave = std::sin(phase) + 0.3 * std::sin(3.0 * phase) + 0.2 * std::sin(2.0 * phase);
    const double beat = 0.8 + 0.2 * std::cos(0.5 * phase);
    s[i] = static_cast<float>(0.55 * wave * beat);
  }
  return s;
}

// A tone sweeping from f0 to f1 (exponentially) with an exponential decay.
std::vector<float> sweep(double seconds, double f0, double f1, double decay, double overtone) {
  std::vector<float> s = samples_for(seconds);
  double phase = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double t = time_of(i);
    phase += kTwoPi * f0 * std::pow(f1 / f0, t / seconds) / SoundBank::kRate;
    const double attack = std::min(1.0, t / 0.004);
    s[i] = static_cast<float>(0.6 * attack * std::exp(-t / decay) *
                              (std::sin(phase) + overtone * std::sin(2.0 * phase)));
  }
  return s;
}

// Notes one after another (Hz, each `step` seconds), each a decaying bell of two partials.
std::vector<float> notes(std::initializer_list<double> freqs, double step, double decay) {
  std::vector<float> s = samples_for(step * static_cast<double>(freqs.size()) + 4.0 * decay);
  double start = 0.0;
  for (const double f : freqs) {
    for (std::size_t i = static_cast<std::size_t>(start * SoundBank::kRate); i < s.size(); ++i) {
      const double t = time_of(i) - start;
      const double attack = std::min(1.0, t / 0.003);
      s[i] += static_cast<float>(0.4 * attack * std::exp(-t / decay) *
                                 (std::sin(kTwoPi * f * t) + 0.3 * std::sin(kTwoPi * 3.0 * f * t)));
    }
    start += step;
  }
  return s;
}

// Ends every one-shot on a short fade to silence (no click when it stops).
void fade_out(std::vector<float>& s) {
  const std::size_t fade = std::min<std::size_t>(s.size(), SoundBank::kRate / 200);
  for (std::size_t i = 0; i < fade; ++i)
    s[s.size() - 1 - i] *= static_cast<float>(static_cast<double>(i) / static_cast<double>(fade));
}

}  // namespace

SoundBank::SoundBank() {
  const auto set = [this](SoundKind kind, std::vector<float> data) {
    Sample& s = samples_[static_cast<std::size_t>(kind)];
    s.loop = is_held(kind);
    if (!s.loop) fade_out(data);
    for (float& x : data) x = std::clamp(x, -1.0f, 1.0f);
    s.data = std::move(data);
    s.envelope.clear();
    for (std::size_t b = 0; b < s.data.size(); b += kEnvelopeBlock) {
      float peak = 0.0f;
      for (std::size_t i = b; i < std::min(s.data.size(), b + kEnvelopeBlock); ++i)
        peak = std::max(peak, std::abs(s.data[i]));
      s.envelope.push_back(peak);
    }
  };
  set(SoundKind::impact, thud());
  set(SoundKind::roll, tread());
  set(SoundKind::skid, skid());
  set(SoundKind::jump, sweep(0.2, 250.0, 700.0, 0.08, 0.3));
  set(SoundKind::checkpoint, notes({880.0, 1318.5}, 0.09, 0.12));
  set(SoundKind::message, sweep(0.1, 660.0, 700.0, 0.04, 0.0));
  set(SoundKind::win, notes({523.25, 659.25, 783.99, 1046.5}, 0.11, 0.18));
  set(SoundKind::lose, sweep(0.8, 400.0, 140.0, 0.35, 0.5));
  set(SoundKind::motor, motor());
}

double SoundBank::seconds(SoundKind kind, double pitch) const {
  return static_cast<double>(sample(kind).data.size()) / kRate / std::max(pitch, 1e-3);
}

double SoundBank::envelope(SoundKind kind, double seconds, double pitch) const {
  const Sample& s = sample(kind);
  if (s.envelope.empty()) return 0.0;
  const double at = seconds * pitch * kRate / kEnvelopeBlock;
  if (s.loop)
    return s.envelope[static_cast<std::size_t>(
        std::fmod(std::max(at, 0.0), static_cast<double>(s.envelope.size())))];
  if (!(at >= 0.0) || at >= static_cast<double>(s.envelope.size())) return 0.0;
  return s.envelope[static_cast<std::size_t>(at)];
}

}  // namespace game::sound
