// The game's sound, as the app sees it: after every tick the world's and script's events
// (EventExtractor) go to the mixer (VoiceMixer, the loudest kMaxVoices heard) and the audio log;
// SDL's audio device plays the mix. Without a device (none, or SDL_AUDIODRIVER=dummy) everything
// but the output still runs, so the log is the same.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sound/audio_log.h"
#include "sound/audio_output.h"
#include "sound/event_extractor.h"
#include "sound/sound_bank.h"
#include "sound/voice_mixer.h"

namespace game::sound {

struct SoundOptions {
  double volume = 0.8;   // [0, 1]
  std::string log_file;  // --audio-log: empty for none (opened by open_log)
};

class SoundSystem {
 public:
  SoundSystem();
  ~SoundSystem() { close(); }
  SoundSystem(const SoundSystem&) = delete;
  SoundSystem& operator=(const SoundSystem&) = delete;

  // Synthesises the sounds and opens the device. Returns the problems (for the app to show as
  // warnings); the game goes on without sound whatever they are.
  std::vector<std::string> open(const SoundOptions& options);
  // The audio log (--audio-log FILE): "" when opened, else why not. Closed by close_log, which
  // returns the first write that failed ("" when none), or by close, which drops it.
  std::string open_log(const std::string& file);
  std::string close_log();
  void close();

  // After each tick of `simulation`, driven by `input`.
  void after_tick(const tire::Simulation& simulation, const tire::TickInput& input);
  // A new world: forget its tires and end their held sounds.
  void new_level();
  // While the game stands still (paused, a menu), held sounds must not drone on.
  void set_paused(bool paused) { output_.set_paused(paused); }
  bool toggle_mute();
  // The volume in [0, 1] (--volume at start, the tuning panel's slider after) and the mute (M).
  double volume() const { return mixer_->volume(); }
  void set_volume(double volume);
  bool muted() const { return mixer_->muted(); }
  void set_muted(bool muted);

  std::size_t events() const { return events_; }  // sound events so far
  std::size_t max_playing() const { return max_playing_; }
  bool device_open() const { return output_.is_open(); }

 private:
  std::unique_ptr<SoundBank> bank_;
  std::unique_ptr<VoiceMixer> mixer_;
  AudioOutput output_;
  AudioLog log_;
  EventExtractor extractor_;
  std::vector<SoundEvent> tick_events_;  // scratch
  std::size_t events_ = 0;
  std::size_t max_playing_ = 0;
};

}  // namespace game::sound
