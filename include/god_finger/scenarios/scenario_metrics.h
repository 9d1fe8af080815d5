// The paper's scenario metrics (docs/experiments.md), accumulated step by step from the
// watched object's state: the one definition every system measured against them uses (the
// experiments, the servo loop's runs, the MuJoCo baseline in bench/).
//
//  - slide: translation_m, rolled_rad (the angular velocity about horizontal axes, integrated),
//    rolling_ratio (rolled arc over translation: 1 rolls, 0 slides);
//  - lift_one, lift_two: lift_height_m, held_s (lifted above half the commanded height after the
//    lift), max_tilt_rad, dropped;
//  - pinch_cylinder: rotation_about_normal_rad and angular_velocity_about_normal_max (about the
//    cylinder's axis, x of its link frame, after the lift), fz_oscillation_amplitude_N (half the
//    peak-to-peak vertical force on the centre of mass over the script's last 10 s), held_s,
//    lift_height_m;
//  - clutter: held, held_s, lift_height_m, turn_rad, placed_error_m (experiment.h), and from
//    setNeighbours: disturbed_neighbours (moved more than kDisturbedDistance),
//    max_neighbour_displacement_m;
//  - hand_grasp: held_s, lift_height_m, max_tilt_rad, turn_rad, fell_after_release
//    (experiment.h);
//  - pinch_thin: none of the plate's (it is clamped); overlap_metrics.h measures the hands.
// Units: SI; states in the world frame. Not real-time (a map of results).
#pragma once

#include "god_finger/scenarios/experiment.h"
#include "god_finger/physics/god_finger_world.h"

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

namespace god_finger
{
class ScenarioMetrics
{
 public:
  // `initial`: the watched object before the first step; `object`: its description (a
  // sphere's radius gives the rolling ratio).
  ScenarioMetrics(Scenario scenario, const ScenarioTimes& times, const BodyState& initial,
                  const BodyDescription& object);
  // The object's state at the end of the step that ends at `time` (s), `dt` long.
  void add(double time, double dt, const BodyState& state);
  // clutter: the other dynamic bodies' centres of mass (m, world) before the first step and
  // after the last, in the same order.
  void setNeighbours(const std::vector<Eigen::Vector3d>& before, const std::vector<Eigen::Vector3d>& after);
  static constexpr double kDisturbedDistance = 0.005;  // m
  std::map<std::string, double> metrics() const;

 private:
  Scenario scenario_;
  ScenarioTimes times_;
  BodyState initial_;
  BodyState last_;
  double object_radius_;
  double rolled_ = 0.0;
  double held_ = 0.0;
  double max_tilt_ = 0.0;
  bool have_lift_pose_ = false;
  Eigen::Matrix3d lift_pose_ = Eigen::Matrix3d::Identity();
  double max_rotation_ = 0.0;
  double max_spin_ = 0.0;
  double fz_min_ = INFINITY;
  double fz_max_ = -INFINITY;
  double carry_height_ = 0.0;
  double max_turn_ = 0.0;
  double lowest_after_release_ = INFINITY;  // m, hand_grasp: above the start, after the release
  int disturbed_ = -1;  // -1: setNeighbours not called
  double max_neighbour_displacement_ = 0.0;
};
}  // namespace god_finger
