#include "god_finger/scenarios/overlap_metrics.h"

#include <algorithm>

namespace god_finger
{
OverlapMetrics::OverlapMetrics(const GodFingerWorld& world)
{
  for (int i = 0; i < world.interfaceCount(); ++i)
  {
    last_force_.push_back(world.interfaceState(i).user_force);
  }
}

void OverlapMetrics::add(const GodFingerWorld& world)
{
  for (int i = 0; i < world.interfaceCount() && i < static_cast<int>(last_force_.size()); ++i)
  {
    const InterfaceState& state = world.interfaceState(i);
    overlap_area_max_ = std::max(overlap_area_max_, state.overlap_area);
    max_force_step_ = std::max(max_force_step_, (state.user_force - last_force_[i]).norm());
    last_force_[i] = state.user_force;
  }
}

std::map<std::string, double> OverlapMetrics::metrics() const
{
  return {{"overlap_area_max_m2", overlap_area_max_}, {"max_force_step_N", max_force_step_}};
}
}  // namespace god_finger
