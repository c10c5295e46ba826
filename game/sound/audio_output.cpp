#include "audio_output.h"

namespace game::sound {

void AudioOutput::callback(void* mixer, Uint8* stream, int bytes) {
  static_cast<VoiceMixer*>(mixer)->render(reinterpret_cast<float*>(stream),
                                          static_cast<std::size_t>(bytes) / (2 * sizeof(float)));
}

bool AudioOutput::open(VoiceMixer& mixer, std::string& error) {
  if (!subsystem_) {
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
      error = std::string("SDL audio: ") + SDL_GetError();
      return false;
    }
    subsystem_ = true;
  }
  SDL_AudioSpec want{};
  want.freq = SoundBank::kRate;
  want.format = AUDIO_F32SYS;
  want.channels = 2;   // left, right (VoiceMixer::render)
  want.samples = 512;  // 12 ms at 44.1 kHz: short enough for a hit to land with its frame
  want.callback = &AudioOutput::callback;
  want.userdata = &mixer;
  SDL_AudioSpec have{};
  // The format and channels are as asked (SDL converts if the device differs); the rate may differ,
  // and the mixer resamples to it.
  device_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, SDL_AUDIO_ALLOW_FREQUENCY_CHANGE);
  if (device_ == 0) {
    error = std::string("cannot open an audio device: ") + SDL_GetError();
    return false;
  }
  mixer.set_output_rate(have.freq);
  SDL_PauseAudioDevice(device_, 0);
  return true;
}

void AudioOutput::set_paused(bool paused) {
  if (device_ && paused != paused_) SDL_PauseAudioDevice(device_, paused ? 1 : 0);
  paused_ = paused;
}

void AudioOutput::close() {
  if (device_) SDL_CloseAudioDevice(device_);
  device_ = 0;
  if (subsystem_) SDL_QuitSubSystem(SDL_INIT_AUDIO);
  subsystem_ = false;
}

}  // namespace game::sound
