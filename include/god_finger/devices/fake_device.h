// A simulated device: a handle of mass m with viscous damping, held by a scripted hand
// through a spring-damper (the hand's grip) and pushed by the commanded force. The loop
// through the physics is therefore closed as with a real device: the coupling force moves the
// handle, and a stiff virtual coupling can make it ring, as it would a real one.
//
// An optional orientation script makes it an oriented finger: the hand turns the handle rigidly
// (no rotational dynamics; the reading's orientation is the script's), and a torque given to
// updateWrench() is recorded (lastTorque()) but moves nothing.
//
// Units: kg, N/m, N s/m, s, m, N m. Integration: semi-implicit Euler over the time between two
// update() calls, split into sub-steps of at most 1 ms. Deterministic for identical calls.
#pragma once

#include "god_finger/devices/haptic_device.h"
#include "god_finger/haptics/orientation_path.h"
#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/support/parameter_source.h"
#include "god_finger/support/parameter_table.h"

#include <mutex>
#include <optional>

namespace god_finger
{
struct FakeDeviceParams
{
  double handle_mass = 0.1;      // kg
  double handle_damping = 0.5;   // N s/m: the mechanism's friction
  double grip_stiffness = 2000;  // N/m: how firmly the hand holds the handle
  double grip_damping = 20;      // N s/m
  // s: 0 plays the script once; else, once it ends, the hand goes back to the script's first
  // waypoint in this time (a straight line) and plays it again, for ever.
  double repeat_return = 0.0;
  // packet: update() applies the force for the last reading with the next one (a Falcon's
  // exchange, the default); frame: exchangeFrame() applies the force for the reading it just
  // took (an Omni/Touch's servo frame), so the servo loop renders at the read
  // (haptic_device.h DeviceExchange). The simulated hand: with packet, the force given to
  // update() acts over the period that call ends (the simulation's convention since the start:
  // it models no period of the packet's delay); with frame, the force for a frame's reading
  // acts over the period after that frame, as on a device.
  DeviceExchange exchange = DeviceExchange::kPacket;
};
// handle_mass, handle_damping, grip_stiffness, grip_damping, repeat_return, exchange: units,
// ranges, meanings.
const ParameterTable<FakeDeviceParams>& fakeDeviceParameterTable();
std::string validate(const FakeDeviceParams& params);
// Every row `source` sets (defaults above); InputError on a bad one.
FakeDeviceParams readFakeDeviceParams(const ParameterSource& source);
// `script`: a list of [t, x, y, z] waypoints (s, m, device frame); without it the hand holds
// the handle at `fallback` (m). InputError on a malformed script.
WaypointPath readScript(const ParameterSource& source, const Eigen::Vector3d& fallback);
// `orientation_script`: a list of [t, w, x, y, z] waypoints (s, a quaternion: the finger frame
// of physics/oriented_finger.h in the device frame; slerped between, haptics/orientation_path.h);
// unset: none (a 3-DOF finger). InputError on a malformed one.
std::optional<OrientationPath> readOrientationScript(const ParameterSource& source);

class FakeDevice : public HapticDevice
{
 public:
  // Throws InputError on bad parameters. The handle starts at the script's first position.
  FakeDevice(const FakeDeviceParams& params, WaypointPath hand);
  // An oriented finger: every reading carries `orientation`'s orientation at the script's time.
  FakeDevice(const FakeDeviceParams& params, WaypointPath hand, std::optional<OrientationPath> orientation);
  std::string name() const override
  {
    return "fake";
  }
  void start() override;
  DeviceReading update(double time, const Eigen::Vector3d& force) override;
  // As update(), recording `torque` (N m, device frame) for lastTorque().
  DeviceReading updateWrench(double time, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) override;
  DeviceExchange exchangeForm() const override
  {
    return params_.exchange;
  }
  // exchange: frame: the hand moves under the wrench the last frame's responder gave, then the
  // reading goes to `responder` and its wrench is kept for the next frame. With exchange:
  // packet it throws DeviceError (HapticDevice's).
  DeviceReading exchangeFrame(double time, FrameResponder& responder) override;
  // The torque of the last updateWrench() (zero after update()). Read it from the thread that
  // calls update() (or after the loop stopped).
  const Eigen::Vector3d& lastTorque() const
  {
    return torque_;
  }
  // Makes the script's time 0 the given time of update()'s clock (several fake devices then
  // follow their scripts in step); before it the hand waits at the first waypoint. Without
  // it, the script starts at the first update.
  void setScriptStart(double time) override
  {
    start_time_ = time;
    script_start_set_ = true;
  }
  // From now on the hand holds the handle at `position` (m, device frame) instead of following
  // the script: an interactive hand (an rviz marker dragged with the mouse). Thread-safe; a
  // non-finite position is ignored.
  bool setHandTarget(const Eigen::Vector3d& position) override;
  // As setHandTarget(), and from now on every reading carries `orientation` (normalised; the
  // finger frame in the device frame) instead of the orientation script's: the interactive
  // hand rotated. Thread-safe; a non-finite position or an orientation whose norm is not within
  // 1e-3 of 1 is ignored (each on its own).
  bool setHandPose(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation) override;
  // The update() time at which the script's time is 0.
  double startTime() const
  {
    return start_time_;
  }

 private:
  // Where script time `t` (s) falls with params_.repeat_return: a time of the script, and how far
  // (0 to 1) the hand is on its way back from the script's end to its start.
  struct ScriptTime
  {
    double time;
    double back;
  };
  ScriptTime scriptTime(double t) const;
  // The scripted hand's position and orientation at script time `t`, repeating with it (a
  // straight line and a slerp back to the start).
  Eigen::Vector3d handAt(double t) const;
  Eigen::Quaterniond orientationAt(double t) const;

  FakeDeviceParams params_;
  WaypointPath hand_;
  std::optional<OrientationPath> orientation_;
  Eigen::Vector3d torque_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d frame_force_ = Eigen::Vector3d::Zero();  // N: exchange frame, the last responder's
  Eigen::Vector3d position_;
  Eigen::Vector3d velocity_ = Eigen::Vector3d::Zero();
  double last_time_ = 0.0;
  double start_time_ = 0.0;
  bool started_clock_ = false;
  bool script_start_set_ = false;
  std::mutex target_mutex_;
  bool has_target_ = false;
  Eigen::Vector3d target_ = Eigen::Vector3d::Zero();
  bool has_target_orientation_ = false;  // setHandPose() was given a usable orientation
  Eigen::Quaterniond target_orientation_ = Eigen::Quaterniond::Identity();
};
}  // namespace god_finger
