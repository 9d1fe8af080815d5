// Statistics of the servo loop's samples over a window (the publisher side: not real-time,
// it keeps every sample of the window): rate, and percentiles of the period, the
// device-to-force latency and the world step, whole and stage by stage (step_profile.h).
// Units: Hz and microseconds.
#pragma once

#include "god_finger/physics/step_profile.h"
#include "god_finger/runtime/servo_loop.h"

#include <array>
#include <vector>

namespace god_finger
{
struct Percentiles
{
  double p50 = 0.0;
  double p99 = 0.0;
  double max = 0.0;
};

struct LoopSummary
{
  long ticks = 0;
  double rate_hz = 0.0;  // ticks per wall-clock second of the window
  Percentiles period_us;
  Percentiles latency_us;
  Percentiles step_us;
  std::array<Percentiles, kStepStageCount> stage_us;  // by StepStage
};

// Percentiles of each stage of the world's timed steps over a window (the publisher side: it keeps
// every timed step's profile of the window; adding allocates as the window grows).
class StepProfileStatistics
{
 public:
  // A profile of a step added before (the world times one step in profile_every and keeps its
  // profile until the next), or of none yet (step -1), is not added again.
  void add(const StepProfile& profile);
  std::array<Percentiles, kStepStageCount> summarize() const;
  void clear();

 private:
  std::array<std::vector<double>, kStepStageCount> stage_us_;
  long last_step_ = -1;  // the step of the last profile added (kept across windows)
};

class LoopStatistics
{
 public:
  // Counts interface 0's samples as ticks; every interface's latency.
  void add(const ServoSample& sample);
  LoopSummary summarize() const;
  // Starts a new window.
  void clear();

 private:
  std::vector<double> period_us_;
  std::vector<double> latency_us_;
  std::vector<double> step_us_;
  StepProfileStatistics stages_;
  double window_start_ = -1.0;  // steady seconds
};
}  // namespace god_finger
