#include "god_finger/devices/fake_device.h"

#include "god_finger/core/input_error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace god_finger
{
std::string validate(const FakeDeviceParams& params)
{
  std::ostringstream message;
  if (!(params.handle_mass > 0.0 && params.handle_mass <= 100.0))
  {
    message << "parameter 'handle_mass' = " << params.handle_mass << " is out of range (0, 100] (kg)";
  }
  else if (!(params.handle_damping >= 0.0 && params.handle_damping <= 1e4))
  {
    message << "parameter 'handle_damping' = " << params.handle_damping << " is out of range [0, 1e+04] (N s/m)";
  }
  else if (!(params.grip_stiffness > 0.0 && params.grip_stiffness <= 1e6))
  {
    message << "parameter 'grip_stiffness' = " << params.grip_stiffness << " is out of range (0, 1e+06] (N/m)";
  }
  else if (!(params.grip_damping >= 0.0 && params.grip_damping <= 1e4))
  {
    message << "parameter 'grip_damping' = " << params.grip_damping << " is out of range [0, 1e+04] (N s/m)";
  }
  return message.str();
}

FakeDeviceParams readFakeDeviceParams(const ParameterSource& source)
{
  FakeDeviceParams params;
  params.handle_mass = readDouble(source, "handle_mass", params.handle_mass, 0.0, 100.0, "kg", true);
  params.handle_damping = readDouble(source, "handle_damping", params.handle_damping, 0.0, 1e4, "N s/m");
  params.grip_stiffness = readDouble(source, "grip_stiffness", params.grip_stiffness, 0.0, 1e6, "N/m", true);
  params.grip_damping = readDouble(source, "grip_damping", params.grip_damping, 0.0, 1e4, "N s/m");
  return params;
}

WaypointPath readScript(const ParameterSource& source, const Eigen::Vector3d& fallback)
{
  std::vector<std::vector<double>> rows;
  if (!readTable(source, "script", 4, "a list of [t, x, y, z] waypoints (s, m)", &rows))
  {
    return WaypointPath({{0.0, fallback}});
  }
  std::vector<Waypoint> waypoints;
  for (const std::vector<double>& row : rows)
  {
    waypoints.push_back({row[0], Eigen::Vector3d(row[1], row[2], row[3])});
  }
  try
  {
    return WaypointPath(waypoints);
  }
  catch (const InputError& error)
  {
    throw InputError("parameter '" + source.fullName("script") + "': " + error.what());
  }
}

FakeDevice::FakeDevice(const FakeDeviceParams& params, WaypointPath hand)
    : params_(params), hand_(std::move(hand)), position_(hand_.at(0.0))
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
}

void FakeDevice::start() {}

bool FakeDevice::setHandTarget(const Eigen::Vector3d& position)
{
  if (position.allFinite())
  {
    std::lock_guard<std::mutex> lock(target_mutex_);
    target_ = position;
    has_target_ = true;
  }
  return true;
}

DeviceReading FakeDevice::update(double time, const Eigen::Vector3d& force)
{
  bool has_target = false;
  Eigen::Vector3d target;
  {
    std::lock_guard<std::mutex> lock(target_mutex_);
    has_target = has_target_;
    target = target_;
  }
  if (!started_clock_)
  {
    started_clock_ = true;
    if (!script_start_set_)
    {
      start_time_ = time;
    }
    last_time_ = time;
  }
  double remaining = std::min(std::max(time - last_time_, 0.0), 0.1);
  double t = last_time_ - start_time_;
  const Eigen::Vector3d applied = force.allFinite() ? force : Eigen::Vector3d::Zero();
  while (remaining > 1e-12)
  {
    const double dt = std::min(remaining, 1e-3);
    t += dt;
    // A dragged marker jumps between mouse events: the hand moves there, and its velocity is
    // left to the grip's damping rather than differentiated from the jumps.
    const Eigen::Vector3d hand = has_target ? target : hand_.at(t);
    const Eigen::Vector3d hand_velocity =
        has_target ? Eigen::Vector3d::Zero() : Eigen::Vector3d((hand_.at(t) - hand_.at(t - dt)) / dt);
    const Eigen::Vector3d total = applied + params_.grip_stiffness * (hand - position_) +
                                  params_.grip_damping * (hand_velocity - velocity_) -
                                  params_.handle_damping * velocity_;
    velocity_ += dt * total / params_.handle_mass;
    position_ += dt * velocity_;
    remaining -= dt;
  }
  last_time_ = time;
  DeviceReading reading;
  reading.position = position_;
  reading.velocity = velocity_;
  return reading;
}
}  // namespace god_finger
