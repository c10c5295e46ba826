#include "app/hot_reload.h"

namespace game {

std::optional<HotReload::Stamp> HotReload::stamp(const std::filesystem::path& file) {
  std::error_code ec;
  const auto time = std::filesystem::last_write_time(file, ec);
  if (ec) return std::nullopt;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) return std::nullopt;
  return Stamp{time, size};
}

void HotReload::watch(const std::filesystem::path& file) {
  file_ = file;
  last_ = stamp(file);
  next_poll_ = 0.0;
}

bool HotReload::poll(double now) {
  if (file_.empty() || now < next_poll_) return false;
  next_poll_ = now + interval_;
  const auto current = stamp(file_);
  if (!current || current == last_) return false;
  last_ = current;
  return true;
}

}  // namespace game
