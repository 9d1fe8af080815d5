// One interface for every haptic device backend (fake, replay, Falcon, Omni).
//
// Frames and units: positions in metres and velocities in m/s in the device frame, whose axes
// follow REP-103 as the user sees them (x forward, away from the user; y to the user's left;
// z up; origin at the workspace centre); forces in newtons and torques in N m in the same frame. A backend converts its
// vendor's units and axes and nothing else: saturation and the watchdog live in ForceGuard, the workspace mapping in
// WorkspaceMapping, so they are the same for every device.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace god_finger
{
// A device that cannot start or has failed; the message says what to do.
class DeviceError : public std::runtime_error
{
 public:
  using std::runtime_error::runtime_error;
};

struct DeviceReading
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m, device frame
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s
  std::uint32_t buttons = 0;                           // bit i: button i pressed
  // False: the source lost this finger (a pose source's stream lost or late,
  // devices/hand_device.h); the position is then not the finger's, and the loop lets it go.
  bool tracked = true;
  // Untracked because the source's newest message lacked this finger (a PoseArray with fewer
  // poses than fingers), not because its poses stopped or came late.
  bool missing = false;
  // A backend that knows the finger's orientation (an Omni/Touch stylus, a fake script with
  // orientations, a pose source) sets has_orientation and `orientation`: the finger frame
  // (physics/oriented_finger.h: z out of the pulp, x towards the tip) in the device frame, a
  // unit quaternion. False (every force-only backend): the finger is a 3-DOF point and the
  // loop runs exactly the 3-DOF code. The servo loop never lets a non-finite or non-unit-ish
  // orientation (norm outside [0.5, 2]) reach the physics (runtime/servo_loop.h).
  bool has_orientation = false;
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

// How a device's servo frame meets the force (runtime/servo_loop.h).
//  - kPacket: one exchange applies the force decided for the last reading and reads the next
//    (a Falcon's USB packet carries both ways): the force for a reading reaches the motors with
//    the next exchange, a period later. update() / updateWrench().
//  - kFrame: one exchange reads, asks for the force for that very reading, and applies it before
//    the frame ends (the Omni/Touch's servo frame: hdBeginFrame, read, set the force,
//    hdEndFrame). exchangeFrame().
enum class DeviceExchange
{
  kPacket,
  kFrame,
};
// "packet", "frame": the names device parameters use.
inline std::string deviceExchangeName(DeviceExchange exchange)
{
  return exchange == DeviceExchange::kFrame ? "frame" : "packet";
}
// False, `exchange` untouched, for any other name.
inline bool parseDeviceExchange(const std::string& name, DeviceExchange* exchange)
{
  if (name != "packet" && name != "frame")
  {
    return false;
  }
  *exchange = name == "frame" ? DeviceExchange::kFrame : DeviceExchange::kPacket;
  return true;
}

// Decides the wrench for a reading while a kFrame device holds its frame open. Called once per
// exchangeFrame(), from the thread that called it or the device's own servo thread while that
// one waits; must be real-time safe (no allocation, lock or log).
class FrameResponder
{
 public:
  virtual ~FrameResponder() = default;
  // `reading` (device frame) in; the force (N) and torque (N m) for it out, device frame, already
  // guarded (saturated, watchdog, soft start): the device applies them as given (clamped to its
  // own limit).
  virtual void respond(const DeviceReading& reading, Eigen::Vector3d* force, Eigen::Vector3d* torque) = 0;
};

class HapticDevice;
struct DeviceFinger
{
  std::string name;  // e.g. thumb; its interface is named INTERFACE/NAME
  std::unique_ptr<HapticDevice> device;
};

class HapticDevice
{
 public:
  virtual ~HapticDevice() = default;
  virtual std::string name() const = 0;
  // Opens and prepares the device (firmware, homing, calibration). Throws DeviceError.
  virtual void start() = 0;
  // One servo tick at `time` (s, monotonic): applies `force` (N, device frame, already
  // guarded) and reads the state. Throws DeviceError on a fault it cannot recover from.
  virtual DeviceReading update(double time, const Eigen::Vector3d& force) = 0;
  // As update(), with a torque (N m, device frame, already masked to the profile's torque axes
  // and saturated at its max_torque by the servo loop). A device that renders no torque keeps
  // this default, which drops the torque. Same real-time rules as update().
  // (A name of its own: an override of update() alone does not hide it.) The servo loop calls
  // this one.
  virtual DeviceReading updateWrench(double time, const Eigen::Vector3d& force, const Eigen::Vector3d& /*torque*/)
  {
    return update(time, force);
  }
  // kFrame: the servo loop calls exchangeFrame() instead of updateWrench() (update() still works,
  // for loops that decide the force apart from the exchange: the topic topologies' driver).
  virtual DeviceExchange exchangeForm() const
  {
    return DeviceExchange::kPacket;
  }
  // kFrame devices: one servo tick at `time` (s, monotonic): reads the state, calls `responder`
  // exactly once with it (also when the frame failed: then with the last good state, whose
  // force waits for the next frame), applies the wrench it gives, and returns the reading. Same
  // real-time rules and faults as update(). A kPacket device throws DeviceError.
  virtual DeviceReading exchangeFrame(double /*time*/, FrameResponder& /*responder*/)
  {
    throw DeviceError(name() + ": this device reads and writes in one packet; it has no frame exchange");
  }
  // Simulated devices that follow a script (fake, replay): the time of update()'s clock at
  // which the script's time 0 is played, so that the devices of one session move in step.
  // Devices a person holds ignore it.
  virtual void setScriptStart(double /*time*/) {}
  // Devices moved by a simulated hand (interactive): from now on the hand holds the handle at
  // `position` (m, device frame). Returns false for devices that take no hand target. The fake
  // backend's is thread-safe; the servo loop calls it from its own thread.
  virtual bool setHandTarget(const Eigen::Vector3d& /*position*/)
  {
    return false;
  }
  // As setHandTarget(), the hand also turning the handle to `orientation` (the finger frame of
  // physics/oriented_finger.h in the device frame): from the first such call on, every reading
  // has_orientation with the last one given (an interactive marker the user rotated); before
  // it the device reports what it did (a 3-DOF finger stays one). A non-unit or non-finite
  // orientation is ignored (the position is still taken). Devices that take no hand target:
  // false. Same threads as setHandTarget().
  virtual bool setHandPose(const Eigen::Vector3d& /*position*/, const Eigen::Quaterniond& /*orientation*/)
  {
    return false;
  }
  // A device that carries several fingers (devices/hand_device.h): one device per finger, in
  // order, each run as its own interface; called once, before start(). Empty (every other
  // device): the device is one finger.
  virtual std::vector<DeviceFinger> fingers()
  {
    return {};
  }
};
}  // namespace god_finger
