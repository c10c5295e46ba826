// Wall time per rendered frame, split into the simulation (Simulation::step, every tick of the
// frame) and the rendering (drawing the world, the HUD and ImGui, and presenting), kept for the
// summary the game prints at exit. The samples live in a buffer reserved up front: add() never
// allocates. When more frames run than it holds, it keeps the latest ones.
#pragma once

#include <cstddef>
#include <vector>

namespace game {

struct FrameSample {
  float sim_ms = 0.0f;      // Simulation::step, all ticks of the frame
  float render_ms = 0.0f;   // drawing (world, HUD, ImGui) and SDL_RenderPresent
  float present_ms = 0.0f;  // SDL_RenderPresent alone (part of render_ms)
  float frame_ms = 0.0f;    // the whole frame: events, simulation, rendering, presenting
};

// Median, 99th percentile (nearest rank) and maximum of one column, in ms.
struct TimeStats {
  double median = 0.0;
  double p99 = 0.0;
  double max = 0.0;
};

class FrameStats {
 public:
  // Keeps room for `capacity` frames (at least one); allocates here only.
  void reserve(std::size_t capacity);
  void add(const FrameSample& sample);
  void clear();
  std::size_t size() const { return samples_.size(); }
  std::size_t capacity() const { return capacity_; }

  // Each over the samples held; zeros when there are none. These allocate (call them at exit).
  TimeStats sim() const;
  TimeStats render() const;
  TimeStats present() const;
  TimeStats frame() const;
  // The simulation's over the last `count` frames held (all of them if fewer): a level's cost once
  // it has settled, where sim() mixes in how it got there.
  TimeStats sim_last(std::size_t count) const;

 private:
  TimeStats column(float FrameSample::*field, std::size_t count) const;

  std::vector<FrameSample> samples_;
  std::size_t capacity_ = 0;
  std::size_t next_ = 0;  // where the next sample overwrites once the buffer is full
};

// The nearest-rank percentile p (in (0, 1]) of `values`, which it reorders; 0 when empty.
double percentile(std::vector<double>& values, double p);

}  // namespace game
