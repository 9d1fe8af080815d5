#include "god_finger/devices/fake_device.h"

#include "god_finger/support/denormals.h"
#include "god_finger/support/input_error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace god_finger
{
const ParameterTable<FakeDeviceParams>& fakeDeviceParameterTable()
{
  using P = FakeDeviceParams;
  static const ParameterTable<P> table = {
      realRow<P>("handle_mass", "kg", openClosed(0.0, 100.0), "mass of the simulated handle",
                 [](P& p) -> double& { return p.handle_mass; }),
      realRow<P>("handle_damping", "N s/m", closed(0.0, 1e4), "the simulated mechanism's friction",
                 [](P& p) -> double& { return p.handle_damping; }),
      realRow<P>("grip_stiffness", "N/m", openClosed(0.0, 1e6), "how firmly the scripted hand holds the handle",
                 [](P& p) -> double& { return p.grip_stiffness; }),
      realRow<P>("grip_damping", "N s/m", closed(0.0, 1e4), "damping of the scripted hand's grip",
                 [](P& p) -> double& { return p.grip_damping; }),
      realRow<P>("repeat_return", "s", closed(0.0, 60.0),
                 "0 plays the script once; else the hand goes back to the script's start in this time once it "
                 "ends, and plays it again",
                 [](P& p) -> double& { return p.repeat_return; }),
      choiceRow<P>(
          "exchange", "packet, frame",
          "packet: the force for a reading goes with the next exchange (a Falcon's); frame: the force for a reading "
          "is applied in the same frame (an Omni/Touch's), so the servo loop renders it at the read",
          [](const P& p) -> std::string { return deviceExchangeName(p.exchange); },
          [](P* p, const std::string& text) { return parseDeviceExchange(text, &p->exchange); }),
  };
  return table;
}

std::string validate(const FakeDeviceParams& params)
{
  return validateRows(fakeDeviceParameterTable(), params);
}

FakeDeviceParams readFakeDeviceParams(const ParameterSource& source)
{
  FakeDeviceParams params;
  readRows(source, fakeDeviceParameterTable(), &params);
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

std::optional<OrientationPath> readOrientationScript(const ParameterSource& source)
{
  std::vector<std::vector<double>> rows;
  if (!readTable(source, "orientation_script", 5, "a list of [t, w, x, y, z] orientation waypoints (s, quaternion)",
                 &rows))
  {
    return std::nullopt;
  }
  std::vector<OrientationWaypoint> waypoints;
  for (const std::vector<double>& row : rows)
  {
    waypoints.push_back({row[0], Eigen::Quaterniond(row[1], row[2], row[3], row[4])});
  }
  try
  {
    return OrientationPath(waypoints);
  }
  catch (const InputError& error)
  {
    throw InputError("parameter '" + source.fullName("orientation_script") + "': " + error.what());
  }
}

FakeDevice::FakeDevice(const FakeDeviceParams& params, WaypointPath hand) : FakeDevice(params, std::move(hand), {}) {}

FakeDevice::FakeDevice(const FakeDeviceParams& params, WaypointPath hand, std::optional<OrientationPath> orientation)
    : params_(params), hand_(std::move(hand)), orientation_(std::move(orientation)), position_(hand_.at(0.0))
{
  const std::string error = validate(params);
  if (!error.empty())
  {
    throw InputError(error);
  }
}

FakeDevice::ScriptTime FakeDevice::scriptTime(double t) const
{
  const double end = hand_.endTime();
  if (params_.repeat_return <= 0.0 || t <= end)
  {
    return {t, 0.0};
  }
  const double in_period = std::fmod(t, end + params_.repeat_return);
  if (in_period <= end)
  {
    return {in_period, 0.0};
  }
  return {end, (in_period - end) / params_.repeat_return};
}

Eigen::Vector3d FakeDevice::handAt(double t) const
{
  const ScriptTime at = scriptTime(t);
  return at.back == 0.0 ? hand_.at(at.time)
                        : Eigen::Vector3d((1.0 - at.back) * hand_.at(at.time) + at.back * hand_.at(0.0));
}

Eigen::Quaterniond FakeDevice::orientationAt(double t) const
{
  const ScriptTime at = scriptTime(t);
  return at.back == 0.0 ? orientation_->at(at.time) : orientation_->at(at.time).slerp(at.back, orientation_->at(0.0));
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

bool FakeDevice::setHandPose(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation)
{
  setHandTarget(position);
  if (orientation.coeffs().allFinite() && std::abs(orientation.norm() - 1.0) < 1e-3)
  {
    std::lock_guard<std::mutex> lock(target_mutex_);
    target_orientation_ = orientation.normalized();
    has_target_orientation_ = true;
  }
  return true;
}

DeviceReading FakeDevice::updateWrench(double time, const Eigen::Vector3d& force, const Eigen::Vector3d& torque)
{
  DeviceReading reading = update(time, force);
  torque_ = torque;
  return reading;
}

DeviceReading FakeDevice::exchangeFrame(double time, FrameResponder& responder)
{
  if (params_.exchange != DeviceExchange::kFrame)
  {
    return HapticDevice::exchangeFrame(time, responder);
  }
  DeviceReading reading = update(time, frame_force_);
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  responder.respond(reading, &force, &torque);
  frame_force_ = force;
  torque_ = torque;
  return reading;
}

DeviceReading FakeDevice::update(double time, const Eigen::Vector3d& force)
{
  torque_.setZero();
  bool has_target = false;
  Eigen::Vector3d target;
  bool has_target_orientation = false;
  Eigen::Quaterniond target_orientation;
  {
    std::lock_guard<std::mutex> lock(target_mutex_);
    has_target = has_target_;
    target = target_;
    has_target_orientation = has_target_orientation_;
    target_orientation = target_orientation_;
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
    const Eigen::Vector3d hand = has_target ? target : handAt(t);
    const Eigen::Vector3d hand_velocity =
        has_target ? Eigen::Vector3d::Zero() : Eigen::Vector3d((handAt(t) - handAt(t - dt)) / dt);
    const Eigen::Vector3d total = applied + params_.grip_stiffness * (hand - position_) +
                                  params_.grip_damping * (hand_velocity - velocity_) -
                                  params_.handle_damping * velocity_;
    velocity_ += dt * total / params_.handle_mass;
    position_ += dt * velocity_;
    remaining -= dt;
  }
  // An idle handle settles on its hand exponentially: a component settling on 0 would walk into
  // the subnormal range (support/denormals.h) within seconds, and stick at its smallest value.
  flushTiny(&position_);
  flushTiny(&velocity_);
  last_time_ = time;
  DeviceReading reading;
  reading.position = position_;
  reading.velocity = velocity_;
  if (has_target_orientation)
  {
    reading.has_orientation = true;
    reading.orientation = target_orientation;
  }
  else if (orientation_)
  {
    reading.has_orientation = true;
    reading.orientation = orientationAt(last_time_ - start_time_);
  }
  return reading;
}
}  // namespace god_finger
