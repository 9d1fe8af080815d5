#include "god_finger/runtime/loop_statistics.h"

#include "god_finger/runtime/servo_clock.h"
#include "god_finger/support/text_numbers.h"

#include <algorithm>

namespace god_finger
{
namespace
{
Percentiles percentilesOf(const std::vector<double>& values)
{
  Percentiles result;
  if (values.empty())
  {
    return result;
  }
  result.p50 = percentile(values, 0.5);
  result.p99 = percentile(values, 0.99);
  result.max = *std::max_element(values.begin(), values.end());
  return result;
}
}  // namespace

void LoopStatistics::add(const ServoSample& sample)
{
  if (window_start_ < 0.0)
  {
    window_start_ = steadySeconds();
  }
  if (sample.interface == 0)
  {
    period_us_.push_back(sample.period_us);
    step_us_.push_back(sample.step_us);
    stages_.add(sample.step_profile);
  }
  latency_us_.push_back(sample.latency_us);
}

LoopSummary LoopStatistics::summarize() const
{
  LoopSummary summary;
  summary.ticks = static_cast<long>(period_us_.size());
  const double seconds = window_start_ < 0.0 ? 0.0 : steadySeconds() - window_start_;
  summary.rate_hz = seconds > 0.0 ? summary.ticks / seconds : 0.0;
  summary.period_us = percentilesOf(period_us_);
  summary.latency_us = percentilesOf(latency_us_);
  summary.step_us = percentilesOf(step_us_);
  summary.stage_us = stages_.summarize();
  return summary;
}

void LoopStatistics::clear()
{
  period_us_.clear();
  latency_us_.clear();
  step_us_.clear();
  stages_.clear();
  window_start_ = steadySeconds();
}

void StepProfileStatistics::add(const StepProfile& profile)
{
  if (profile.step < 0 || profile.step == last_step_)
  {
    return;
  }
  last_step_ = profile.step;
  for (int s = 0; s < kStepStageCount; ++s)
  {
    stage_us_[s].push_back(1e-3 * static_cast<double>(profile.stage_ns[s]));
  }
}

std::array<Percentiles, kStepStageCount> StepProfileStatistics::summarize() const
{
  std::array<Percentiles, kStepStageCount> stages;
  for (int s = 0; s < kStepStageCount; ++s)
  {
    stages[s] = percentilesOf(stage_us_[s]);
  }
  return stages;
}

void StepProfileStatistics::clear()
{
  for (std::vector<double>& values : stage_us_)
  {
    values.clear();
  }
}
}  // namespace god_finger
