// The audio device: SDL's default output, mono float, pulling samples from a VoiceMixer in SDL's
// audio callback. Failing to open is not an error for the game: it plays on silently.
#pragma once

#include <SDL.h>

#include <string>

#include "voice_mixer.h"

namespace game::sound {

class AudioOutput {
 public:
  AudioOutput() = default;
  ~AudioOutput() { close(); }
  AudioOutput(const AudioOutput&) = delete;
  AudioOutput& operator=(const AudioOutput&) = delete;

  // Starts SDL's audio and opens the default device feeding from `mixer` (which must outlive the
  // device); false with the reason in `error`.
  bool open(VoiceMixer& mixer, std::string& error);
  void close();
  bool is_open() const { return device_ != 0; }
  const char* driver() const { return SDL_GetCurrentAudioDriver(); }

  // Holds the callback off while the mixer is changed (nothing when closed).
  void lock() {
    if (device_) SDL_LockAudioDevice(device_);
  }
  void unlock() {
    if (device_) SDL_UnlockAudioDevice(device_);
  }
  void set_paused(bool paused);

 private:
  static void callback(void* mixer, Uint8* stream, int bytes);

  SDL_AudioDeviceID device_ = 0;
  bool subsystem_ = false;
  bool paused_ = false;
};

}  // namespace game::sound
