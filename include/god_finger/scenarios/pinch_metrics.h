// The pinch_card scenario's metrics (docs/experiments.md), step by step from the object and the
// two pinching fingers' proxies (interfaces 0 and 1):
//  - held: 1 when the object stayed above half the lift height from the lift's end to the end
//    of the run, else 0;
//  - slip_m: how far the object slid in the grip: the largest distance, from the lift's start
//    on, between the point of the object that was at the proxies' mid-point at the lift's start
//    (fixed in the object's frame) and the proxies' mid-point now (m);
//  - turn_rad: the object's largest rotation from its pose at the lift's start, about any axis,
//    from then on (rad). Not for a soft body, whose pose only translates with its mean motion
//    (physics/soft_body.h): soft_contact_metrics.h measures its turn from its surface.
// Units: SI, world frame. Not real-time (a map of results).
#pragma once

#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scenarios/experiment.h"

#include <Eigen/Geometry>
#include <map>
#include <string>

namespace god_finger
{
class PinchMetrics
{
 public:
  // `object` is the watched body's index; `start` its state before the first step; `turn`:
  // whether turn_rad is measured (false for a soft body).
  PinchMetrics(int object, const ScenarioTimes& times, const BodyState& start, bool turn = true);
  // After each step that ended at `time` (s).
  void add(double time, const GodFingerWorld& world);
  std::map<std::string, double> metrics() const;

 private:
  int object_ = -1;
  ScenarioTimes times_;
  double start_height_ = 0.0;
  bool gripped_ = false;                                      // the lift has started
  Eigen::Vector3d grip_on_object_ = Eigen::Vector3d::Zero();  // object frame
  Eigen::Quaterniond grip_orientation_ = Eigen::Quaterniond::Identity();
  bool held_ = true;
  double slip_ = 0.0;
  double turn_ = 0.0;
  bool measure_turn_ = true;
};
}  // namespace god_finger
