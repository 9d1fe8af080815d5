// The overlap scenario's hand metrics (docs/experiments.md; pinch_thin), step by step from the
// world's interfaces:
//  - overlap_area_max_m2: the largest overlap area of any finger's contact areas with the other
//    fingers' (InterfaceState::overlap_area, m^2; physics/overlap_push.h) over the run;
//  - max_force_step_N: the largest change of the force on any hand (InterfaceState::user_force,
//    N) from one step to the next, the first step measured from the force before it.
// Units: SI. Not real-time (a map of results).
#pragma once

#include "god_finger/physics/god_finger_world.h"

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

namespace god_finger
{
class OverlapMetrics
{
 public:
  // The hands' forces before the first step.
  explicit OverlapMetrics(const GodFingerWorld& world);
  // After each step.
  void add(const GodFingerWorld& world);
  std::map<std::string, double> metrics() const;

 private:
  std::vector<Eigen::Vector3d> last_force_;
  double overlap_area_max_ = 0.0;
  double max_force_step_ = 0.0;
};
}  // namespace god_finger
