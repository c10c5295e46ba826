#include "voice_mixer.h"

#include <algorithm>
#include <cmath>

namespace game::sound {

float soft_limit(float x) {
  const float a = std::abs(x);
  if (a <= kLimiterKnee) return x;
  const float room = 1.0f - kLimiterKnee;
  // Slope 1 at the knee (no kink), approaching 1 as |x| grows; tanh < 1 keeps it inside.
  return std::copysign(kLimiterKnee + room * std::tanh((a - kLimiterKnee) / room), x);
}

VoiceMixer::VoiceMixer(const SoundBank& bank) : bank_(bank) {
  voices_.reserve(kVoicePool);
  order_.reserve(kVoicePool);
}

void VoiceMixer::set_volume(double volume) { volume_ = std::clamp(volume, 0.0, 1.0); }

double VoiceMixer::loudness(const Voice& v) const { return v.gain * bank_.envelope(v.kind, v.age, v.pitch); }

// Equal power: the left and right gains' squares add up to 2 wherever the pan puts it, so a voice
// is as loud panned as in the middle, where both are 1.
void VoiceMixer::set_pan(Voice& v, double pan) {
  const double angle = (std::clamp(pan, -1.0, 1.0) + 1.0) * (M_PI / 4.0);
  v.left = static_cast<float>(M_SQRT2 * std::cos(angle));
  v.right = static_cast<float>(M_SQRT2 * std::sin(angle));
}

void VoiceMixer::play(const SoundEvent& e) {
  if (is_held(e.kind)) {
    for (Voice& v : voices_) {
      if (v.kind == e.kind && v.key == e.tire) {
        v.gain = e.gain;
        v.pitch = e.pitch;
        set_pan(v, e.pan);
        v.renewed = true;
        return;
      }
    }
  }
  Voice v;
  v.kind = e.kind;
  v.key = is_held(e.kind) ? e.tire : -1;
  v.gain = e.gain;
  v.pitch = e.pitch;
  set_pan(v, e.pan);
  v.loudness = loudness(v);
  if (voices_.size() >= kVoicePool) {
    // Full: the new voice takes the place of the quietest if it is louder, else it is dropped.
    const auto quietest =
        std::min_element(voices_.begin(), voices_.end(),
                         [](const Voice& a, const Voice& b) { return a.loudness < b.loudness; });
    if (quietest->loudness >= v.loudness) return;
    *quietest = v;
    return;
  }
  voices_.push_back(v);
}

MixStats VoiceMixer::end_tick(double dt) {
  // Drop what has ended: one-shots past their sample, held sounds not renewed.
  std::erase_if(voices_, [&](const Voice& v) {
    return is_held(v.kind) ? !v.renewed : v.finished || v.age >= bank_.seconds(v.kind, v.pitch);
  });
  order_.clear();
  for (std::size_t i = 0; i < voices_.size(); ++i) {
    Voice& v = voices_[i];
    v.loudness = loudness(v);
    v.selected = false;
    if (v.loudness > 0.0) order_.push_back(i);
  }
  MixStats stats;
  stats.wanted = order_.size();
  const std::size_t keep = std::min(kMaxVoices, order_.size());
  // The loudest first; equal ones in the order they came.
  std::partial_sort(
      order_.begin(), order_.begin() + static_cast<std::ptrdiff_t>(keep), order_.end(),
      [&](std::size_t a, std::size_t b) {
        return voices_[a].loudness != voices_[b].loudness ? voices_[a].loudness > voices_[b].loudness : a < b;
      });
  for (std::size_t k = 0; k < keep; ++k) {
    Voice& v = voices_[order_[k]];
    v.selected = true;
    // A voice heard for the first time starts where its age says (it may have waited its turn).
    if (!v.started && !is_held(v.kind)) v.position = v.age * v.pitch * SoundBank::kRate;
    v.started = true;
  }
  stats.playing = keep;
  // Age the one-shots into the next tick; held sounds must be renewed by then.
  for (Voice& v : voices_) {
    if (is_held(v.kind))
      v.renewed = false;
    else
      v.age += dt;
  }
  return stats;
}

void VoiceMixer::render(float* out, std::size_t frames) {
  std::fill(out, out + 2 * frames, 0.0f);
  // A gain change takes 5 ms: no clicks when a voice starts, stops or is dropped.
  const float ramp = static_cast<float>(step_scale_ / (0.005 * SoundBank::kRate));
  const double master = muted_ ? 0.0 : volume_ * kVoiceHeadroom;
  for (Voice& v : voices_) {
    if (v.finished || (!v.selected && v.level == 0.0f)) continue;
    const Sample& s = bank_.sample(v.kind);
    const auto length = static_cast<double>(s.data.size());
    if (length < 2.0) continue;
    const float target = v.selected ? static_cast<float>(v.gain * master) : 0.0f;
    const double step = v.pitch * step_scale_;
    for (std::size_t i = 0; i < frames; ++i) {
      if (v.position >= length - 1.0) {
        if (!s.loop) {
          v.finished = true;
          break;
        }
        v.position = std::fmod(v.position, length - 1.0);
      }
      const auto k = static_cast<std::size_t>(v.position);
      const auto f = static_cast<float>(v.position - static_cast<double>(k));
      const float x = s.data[k] + (s.data[k + 1] - s.data[k]) * f;
      v.level += std::clamp(target - v.level, -ramp, ramp);
      out[2 * i] += x * v.level * v.left;
      out[2 * i + 1] += x * v.level * v.right;
      v.position += step;
    }
  }
  for (std::size_t i = 0; i < 2 * frames; ++i) out[i] = soft_limit(out[i]);
}

}  // namespace game::sound
