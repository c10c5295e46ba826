#include "app/frame_stats.h"

#include <algorithm>
#include <cmath>

namespace game {

void FrameStats::reserve(std::size_t capacity) {
  capacity_ = std::max<std::size_t>(capacity, 1);
  samples_.clear();
  samples_.reserve(capacity_);
  next_ = 0;
}

void FrameStats::clear() {
  samples_.clear();
  next_ = 0;
}

void FrameStats::add(const FrameSample& sample) {
  if (capacity_ == 0) return;  // never reserved: keep nothing rather than allocate in the loop
  if (samples_.size() < capacity_) {
    samples_.push_back(sample);
    return;
  }
  samples_[next_] = sample;
  next_ = (next_ + 1) % capacity_;
}

double percentile(std::vector<double>& values, double p) {
  if (values.empty()) return 0.0;
  const double rank = std::ceil(std::clamp(p, 0.0, 1.0) * static_cast<double>(values.size()));
  const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(std::max(rank, 1.0)) - 1);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

TimeStats FrameStats::column(float FrameSample::*field, std::size_t count) const {
  std::vector<double> values;
  count = std::min(count, samples_.size());
  values.reserve(count);
  // The newest sample is just before next_ (the ring's oldest once it is full).
  for (std::size_t k = 0; k < count; ++k)
    values.push_back(samples_[(next_ + samples_.size() - 1 - k) % samples_.size()].*field);
  TimeStats out;
  if (values.empty()) return out;
  out.max = *std::max_element(values.begin(), values.end());
  out.median = percentile(values, 0.5);
  out.p99 = percentile(values, 0.99);
  return out;
}

TimeStats FrameStats::sim() const { return column(&FrameSample::sim_ms, samples_.size()); }
TimeStats FrameStats::render() const { return column(&FrameSample::render_ms, samples_.size()); }
TimeStats FrameStats::present() const { return column(&FrameSample::present_ms, samples_.size()); }
TimeStats FrameStats::frame() const { return column(&FrameSample::frame_ms, samples_.size()); }
TimeStats FrameStats::sim_last(std::size_t count) const { return column(&FrameSample::sim_ms, count); }

}  // namespace game
