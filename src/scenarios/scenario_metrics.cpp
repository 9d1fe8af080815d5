#include "god_finger/scenarios/scenario_metrics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace god_finger
{
ScenarioMetrics::ScenarioMetrics(Scenario scenario, const ScenarioTimes& times, const BodyState& initial,
                                 const BodyDescription& object)
    : scenario_(scenario),
      times_(times),
      initial_(initial),
      last_(initial),
      object_radius_(object.geometry.kind == GeometryKind::kSphere ? object.geometry.radius : 0.0)
{
}

void ScenarioMetrics::add(double time, double dt, const BodyState& state)
{
  const double height = state.center_of_mass.z() - initial_.center_of_mass.z();
  const bool lifted = height > 0.5 * times_.lift_height;
  switch (scenario_)
  {
    case Scenario::kSlide:
    {
      // Rolling: the angular velocity about horizontal axes, integrated.
      const Eigen::Vector3d w = state.angular_velocity;
      rolled_ += std::hypot(w.x(), w.y()) * dt;
      break;
    }
    case Scenario::kLiftOne:
    case Scenario::kLiftTwo:
    {
      const Eigen::Vector3d up = state.pose.linear().col(2);
      max_tilt_ = std::max(max_tilt_, std::acos(std::min(1.0, std::max(-1.0, up.z()))));
      if (time >= times_.lift_end && lifted)
      {
        held_ += dt;
      }
      break;
    }
    case Scenario::kPinchCylinder:
    {
      if (time >= times_.lift_end)
      {
        if (lifted)
        {
          held_ += dt;
        }
        if (!have_lift_pose_)
        {
          lift_pose_ = state.pose.linear();
          have_lift_pose_ = true;
        }
        // The contact normal is the cylinder's axis (x of the link frame).
        const Eigen::Vector3d axis = state.pose.linear().col(0);
        const Eigen::Matrix3d relative = state.pose.linear() * lift_pose_.transpose();
        const Eigen::AngleAxisd angle_axis(relative);
        const double about_normal = angle_axis.angle() * std::abs(angle_axis.axis().dot(axis));
        max_rotation_ = std::max(max_rotation_, about_normal);
        max_spin_ = std::max(max_spin_, std::abs(state.angular_velocity.dot(axis)));
        if (time >= times_.duration - 10.0)
        {
          fz_min_ = std::min(fz_min_, state.net_force.z());
          fz_max_ = std::max(fz_max_, state.net_force.z());
        }
      }
      break;
    }
    case Scenario::kClutter:
    {
      if (time > times_.lift_end + 1e-9 && time <= times_.carry_end + 1e-9)
      {
        if (lifted)
        {
          held_ += dt;
        }
        carry_height_ = height;
      }
      if (time >= times_.lift_start && time <= times_.release + 1e-9)
      {
        const Eigen::AngleAxisd turn(state.pose.linear() * initial_.pose.linear().transpose());
        max_turn_ = std::max(max_turn_, std::abs(turn.angle()));
      }
      break;
    }
    case Scenario::kHandGrasp:
    {
      if (time >= times_.lift_start && time <= times_.release + 1e-9)
      {
        const Eigen::Vector3d up = state.pose.linear().col(2);
        max_tilt_ = std::max(max_tilt_, std::acos(std::min(1.0, std::max(-1.0, up.z()))));
        const Eigen::AngleAxisd turn(state.pose.linear() * initial_.pose.linear().transpose());
        max_turn_ = std::max(max_turn_, std::abs(turn.angle()));
        if (time > times_.lift_end && lifted)
        {
          held_ += dt;
        }
        carry_height_ = height;
      }
      if (time > times_.release)
      {
        lowest_after_release_ = std::min(lowest_after_release_, height);
      }
      break;
    }
    case Scenario::kRollFinger:  // the finger's own metrics (roll_metrics.h)
      break;
    case Scenario::kPinchThin:
      break;  // the plate is clamped: the hands' metrics are overlap_metrics.h's
    case Scenario::kPinchCard:
      break;  // the grip's metrics (pinch_metrics.h)
    case Scenario::kDoor:
    case Scenario::kDrawer:
      break;  // the joint's metrics (joint_metrics.h)
    case Scenario::kPressSoft:
    case Scenario::kStrokeSoft:
    case Scenario::kPinchSoft:
      break;  // the soft body's metrics (soft_contact_metrics.h; pinch_soft's grip: pinch_metrics.h)
  }
  last_ = state;
}

void ScenarioMetrics::setNeighbours(const std::vector<Eigen::Vector3d>& before,
                                    const std::vector<Eigen::Vector3d>& after)
{
  disturbed_ = 0;
  max_neighbour_displacement_ = 0.0;
  for (std::size_t i = 0; i < std::min(before.size(), after.size()); ++i)
  {
    const double moved = (after[i] - before[i]).norm();
    // NaN counts as disturbed.
    if (!(moved <= kDisturbedDistance))
    {
      ++disturbed_;
    }
    max_neighbour_displacement_ = std::isnan(moved) ? moved : std::max(max_neighbour_displacement_, moved);
  }
}

std::map<std::string, double> ScenarioMetrics::metrics() const
{
  std::map<std::string, double> result;
  const double height = last_.center_of_mass.z() - initial_.center_of_mass.z();
  switch (scenario_)
  {
    case Scenario::kSlide:
    {
      const Eigen::Vector3d moved = last_.center_of_mass - initial_.center_of_mass;
      const double translation = std::hypot(moved.x(), moved.y());
      result["translation_m"] = translation;
      result["rolled_rad"] = rolled_;
      result["rolling_ratio"] = translation > 0.0 ? rolled_ * object_radius_ / translation : 0.0;
      break;
    }
    case Scenario::kLiftOne:
    case Scenario::kLiftTwo:
      result["lift_height_m"] = height;
      result["held_s"] = held_;
      result["max_tilt_rad"] = max_tilt_;
      result["dropped"] = height > 0.5 * times_.lift_height ? 0.0 : 1.0;
      break;
    case Scenario::kPinchCylinder:
      result["rotation_about_normal_rad"] = max_rotation_;
      result["angular_velocity_about_normal_max"] = max_spin_;
      result["fz_oscillation_amplitude_N"] = fz_max_ >= fz_min_ ? 0.5 * (fz_max_ - fz_min_) : 0.0;
      result["held_s"] = held_;
      result["lift_height_m"] = height;
      break;
    case Scenario::kClutter:
    {
      const double carry = times_.carry_end - times_.lift_end;
      result["held_s"] = held_;
      result["held"] = held_ >= carry - 1e-6 ? 1.0 : 0.0;
      result["lift_height_m"] = carry_height_;
      result["turn_rad"] = max_turn_;
      result["placed_error_m"] = (last_.center_of_mass - times_.place_target).norm();
      if (disturbed_ >= 0)
      {
        result["disturbed_neighbours"] = disturbed_;
        result["max_neighbour_displacement_m"] = max_neighbour_displacement_;
      }
      break;
    }
    case Scenario::kRollFinger:  // the finger's own metrics (roll_metrics.h)
      break;
    case Scenario::kHandGrasp:
      result["held_s"] = held_;
      result["lift_height_m"] = carry_height_;
      result["max_tilt_rad"] = max_tilt_;
      result["turn_rad"] = max_turn_;
      result["fell_after_release"] = lowest_after_release_ < 0.5 * times_.lift_height ? 1.0 : 0.0;
      break;
    case Scenario::kPinchThin:
    case Scenario::kPinchCard:
    case Scenario::kDoor:  // the joint's metrics (joint_metrics.h)
    case Scenario::kDrawer:
    case Scenario::kPressSoft:  // the soft body's (soft_contact_metrics.h)
    case Scenario::kStrokeSoft:
    case Scenario::kPinchSoft:
      break;
  }
  return result;
}
}  // namespace god_finger
