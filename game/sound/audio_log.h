// --audio-log FILE: every sound event as one line of JSON, streamed as the game runs and flushed
// when it ends (close, or the destructor), so that tests can check what would be heard without
// listening:
//   {"tick":120,"kind":"impact","surface":"ground","tire":0,"gain":0.81,"pitch":0.93}
//   {"tick":121,"kind":"mix","playing":3,"wanted":3}
// One-shots (impact, jump, checkpoint, message, win, lose) each get a line. A held sound (roll,
// skid) gets one when it starts and whenever its gain or pitch has moved by more than a tenth
// since its last line, not every tick. A "mix" line says how many voices the mixer plays and how
// many it would without its limit, whenever either changes. Gains and pitches are rounded to 1e-4.
// A stream, not an atomic write: the file is opened as given and written in blocks as the game runs,
// so a FIFO or /dev/stdout can take it. A failed write is never silent: the first one
// (a full disk shows at a write, the flush or the close) is kept, writing stops, and close()
// returns it naming the file and the system's reason, for the game to exit non-zero. No SDL.
#pragma once

#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "sound_event.h"
#include "voice_mixer.h"

namespace game::sound {

class AudioLog {
 public:
  AudioLog() = default;
  ~AudioLog() { close(); }
  AudioLog(const AudioLog&) = delete;
  AudioLog& operator=(const AudioLog&) = delete;

  // Opens (truncates) `file`; false with the reason in `error`.
  bool open(const std::string& file, std::string& error);
  bool is_open() const { return out_ != nullptr; }
  void write(const SoundEvent& event);
  void write_mix(std::uint64_t tick, const MixStats& stats);
  // Flushes and closes the file: "" when every line reached it, else the first failure
  // ("cannot write the audio log F: No space left on device"), as after it every call.
  std::string close();
  // The first failure so far, "" while none.
  const std::string& error() const { return error_; }

 private:
  void put(const std::string& line);
  void fail(int error_number);

  std::FILE* out_ = nullptr;
  std::string file_;
  std::string error_;
  struct Held {
    std::uint64_t tick = 0;          // last tick it sounded
    double gain = 0.0, pitch = 0.0;  // as last written
  };
  std::map<std::pair<SoundKind, std::int64_t>, Held> held_;
  MixStats last_mix_;
  bool mix_written_ = false;
};

}  // namespace game::sound
