#include "audio_log.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

namespace game::sound {

namespace {

double rounded(double x) { return std::round(x * 1e4) / 1e4; }

bool moved(double now, double then) { return std::abs(now - then) > 0.1 * std::abs(then); }

}  // namespace

bool AudioLog::open(const std::string& file, std::string& error) {
  close();
  file_ = file;
  error_.clear();
  out_ = std::fopen(file.c_str(), "we");  // e: close on exec
  if (!out_) {
    fail(errno);
    error = error_;
    return false;
  }
  return true;
}

void AudioLog::fail(int error_number) {
  if (error_.empty()) error_ = "cannot write the audio log " + file_ + ": " + std::strerror(error_number);
}

void AudioLog::put(const std::string& line) {
  if (!out_ || !error_.empty()) return;  // after a failure nothing more is written
  if (std::fputs(line.c_str(), out_) == EOF || std::fputc('\n', out_) == EOF) fail(errno);
}

std::string AudioLog::close() {
  if (out_) {
    errno = 0;
    if (std::fflush(out_) != 0 || std::ferror(out_)) fail(errno ? errno : EIO);
    if (std::fclose(out_) != 0) fail(errno);
    out_ = nullptr;
  }
  return error_;
}

void AudioLog::write(const SoundEvent& e) {
  if (!out_) return;
  if (is_held(e.kind)) {
    const auto key = std::make_pair(e.kind, e.tire);
    const auto it = held_.find(key);
    const bool starts = it == held_.end() || it->second.tick + 1 < e.tick;
    if (!starts) {
      it->second.tick = e.tick;
      if (!moved(e.gain, it->second.gain) && !moved(e.pitch, it->second.pitch)) return;
    }
    held_[key] = {e.tick, e.gain, e.pitch};
  }
  nlohmann::ordered_json line;
  line["tick"] = e.tick;
  line["kind"] = kind_name(e.kind);
  if (e.surface != Surface::none) line["surface"] = surface_name(e.surface);
  if (e.tire >= 0) line["tire"] = e.tire;
  line["gain"] = rounded(e.gain);
  line["pitch"] = rounded(e.pitch);
  if (e.tire >= 0) line["pan"] = rounded(e.pan);
  put(line.dump());
}

void AudioLog::write_mix(std::uint64_t tick, const MixStats& stats) {
  if (!out_) return;
  if (mix_written_ && stats.playing == last_mix_.playing && stats.wanted == last_mix_.wanted) return;
  mix_written_ = true;
  last_mix_ = stats;
  nlohmann::ordered_json line;
  line["tick"] = tick;
  line["kind"] = "mix";
  line["playing"] = stats.playing;
  line["wanted"] = stats.wanted;
  put(line.dump());
}

}  // namespace game::sound
