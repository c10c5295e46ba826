#include "sound_system.h"

#include <algorithm>

namespace game::sound {

SoundSystem::SoundSystem()
    : bank_(std::make_unique<SoundBank>()), mixer_(std::make_unique<VoiceMixer>(*bank_)) {}

std::vector<std::string> SoundSystem::open(const SoundOptions& options) {
  std::vector<std::string> problems;
  mixer_->set_volume(options.volume);
  std::string error;
  if (!output_.open(*mixer_, error)) problems.push_back("no sound: " + error);
  return problems;
}

std::string SoundSystem::open_log(const std::string& file) {
  std::string error;
  return log_.open(file, error) ? "" : error;
}

std::string SoundSystem::close_log() { return log_.close(); }

void SoundSystem::close() {
  output_.close();
  log_.close();
}

void SoundSystem::after_tick(const tire::Simulation& simulation, const tire::TickInput& input) {
  tick_events_.clear();
  extractor_.after_tick(simulation, input, tick_events_);
  for (const SoundEvent& e : tick_events_) log_.write(e);
  events_ += tick_events_.size();
  output_.lock();
  for (const SoundEvent& e : tick_events_) mixer_->play(e);
  const MixStats stats = mixer_->end_tick(simulation.config().dt);
  output_.unlock();
  log_.write_mix(simulation.tick(), stats);
  max_playing_ = std::max(max_playing_, stats.playing);
}

void SoundSystem::new_level() {
  extractor_.reset();
  output_.lock();
  mixer_->end_held();
  output_.unlock();
}

bool SoundSystem::toggle_mute() {
  set_muted(!muted());
  return muted();
}

void SoundSystem::set_muted(bool muted) {
  output_.lock();  // the device's callback mixes on its own thread
  mixer_->set_muted(muted);
  output_.unlock();
}

void SoundSystem::set_volume(double volume) {
  output_.lock();
  mixer_->set_volume(volume);
  output_.unlock();
}

}  // namespace game::sound
