// The articulated scenarios' metrics (door, drawer; docs/experiments.md), step by step from the
// scene's first joint and the pushing finger (interface 0). Over the motion, [times.lift_start,
// times.lift_end] (the script's opening or pull at constant speed):
//  - opened_rad (door) or pulled_m (drawer): the joint's position at the end of the run;
//  - beyond_limit: how far the joint went past its limits at most (rad or m; 0 inside them);
//  - hand_force_N: the force on the hand along the motion (the door's face normal, the
//    drawer's axis), its mean over the middle half of the motion;
//  - resistance_force_N: what the joint's own resistance asks of the hand there, (friction +
//    damping x the joint's mean speed) / lever, the lever being the finger's distance from the
//    hinge (1 for a prismatic joint): the hinge's damping the hand should feel;
//  - slip_m (drawer): the finger's travel along the axis over the motion less the drawer's: how
//    far the pad slid on it.
// Units: SI, world frame. Not real-time (a map of results).
#pragma once

#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scenarios/experiment.h"

#include <map>
#include <string>

namespace god_finger
{
class JointMetrics
{
 public:
  JointMetrics(const SceneDescription& scene, const ScenarioTimes& times);
  // After each step that ended at `time` (s).
  void add(double time, const GodFingerWorld& world);
  std::map<std::string, double> metrics() const;

 private:
  JointDescription joint_;
  ScenarioTimes times_;
  double position_ = 0.0;
  double beyond_limit_ = 0.0;
  double force_sum_ = 0.0;
  double speed_sum_ = 0.0;
  double lever_sum_ = 0.0;
  int samples_ = 0;
  double start_position_ = 0.0;
  double start_finger_ = 0.0;
  double finger_travel_ = 0.0;
  double joint_travel_ = 0.0;
  bool started_ = false;
};
}  // namespace god_finger
