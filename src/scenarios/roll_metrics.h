// The roll_finger scenario's metrics (experiment.h), from the rolling finger's interface state
// step by step (ScenarioMetrics watches the object; these watch the finger):
//  - area_centre_travel_m: the distance between the centre of the finger's contact area on the
//    watched body at the roll's start (the last step ending at or before it) and at the end of
//    the run (the last step with an area on it), m;
//  - max_force_step_N: the largest |F(t) - F(t - dt)| of the force on the hand, from the roll's
//    start on (the touch-down before it is not the roll's), N;
//  - rolled_rad: the proxy's rotation from the roll's start to the end, rad;
//  - contact_lost_steps: steps from the roll's start on without an area on the body.
// Units SI, world frame. Internal to physics; not real-time (a map of results).
#pragma once

#include "god_finger/physics/god_finger_world.h"

#include <Eigen/Geometry>
#include <map>
#include <string>

namespace god_finger
{
class RollMetrics
{
 public:
  RollMetrics(int body, double roll_start);
  // The finger's state at the end of the step that ends at `time` (s).
  void add(double time, const InterfaceState& finger);
  void addTo(std::map<std::string, double>* metrics) const;

 private:
  int body_;
  double roll_start_;
  bool have_start_ = false;
  bool have_last_force_ = false;
  Eigen::Vector3d start_centre_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_centre_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond start_orientation_ = Eigen::Quaterniond::Identity();
  Eigen::Quaterniond last_orientation_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d last_force_ = Eigen::Vector3d::Zero();
  double max_force_step_ = 0.0;
  long lost_ = 0;
};
}  // namespace god_finger
