// Backends for the ROS drivers a lab already runs (omni_msgs, ros_geomagic, crtk, ros_falcon):
// the device is the driver, reached through its own topics. This side knows no ROS: the ROS
// side (src/ros/driver_link_ros.h) writes each state the driver publishes into a DriverLink and
// publishes the forces the device leaves there, in the driver's own message types.
//
// Frames and units: a driver reports positions in its own frame (devices/vendor_frames.h, the
// profile's `driver_frame`) and units (`driver_position_unit`, m per unit); its workspace
// centre is `driver_center` (driver frame and units). So
//   device position = frame.to_device * (driver - center) * position_unit   (m)
//   driver force    = frame.to_device^T * device force                      (N)
// Velocities are estimated from the positions on the arrival clock (the drivers' own are in
// other units or absent).
//
// Faults: a driver whose newest state is older than `stale_timeout` (or that has sent none) is a
// device fault: the reading is untracked (the servo loop lets the finger go; the driver node
// stops the force and resumes it with the soft start) at the last known position, and the force
// sent is zero. The device never sends anything but a zero force while the driver is stale.
// These drivers hold the last force forever, so the last force this side sends is zero: at
// destruction (the device's destructor), and on a signal (the ROS side's stop hook).
//
// Threads: DriverLink's write*() from the ROS callback thread (one at a time), read() and
// sendForce() from the device's loop, takeForce() from the ROS side's sender thread. Lock-free
// mailboxes and a semaphore between them: update() is real-time safe.
#pragma once

#include "god_finger/devices/device_signals.h"
#include "god_finger/devices/haptic_device.h"
#include "god_finger/devices/vendor_frames.h"
#include "god_finger/support/latest_value.h"
#include "god_finger/support/parameter_source.h"
#include "god_finger/support/parameter_table.h"

#include <semaphore.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace god_finger
{
struct DriverBridgeParams
{
  std::string backend;                 // the registry's name: omni_msgs, ros_geomagic, crtk, ros_falcon
  std::string driver_ns;               // the driver's topics' namespace (`driver_ns`; the profile gives its default)
  std::string arm;                     // crtk: the arm's name under driver_ns ("" = the topics are in driver_ns)
  const VendorFrame* frame = nullptr;  // `driver_frame`
  double position_unit = 1.0;          // m per driver position unit (`driver_position_unit`)
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // driver frame and units (`driver_center`)
  double stale_timeout = 0.1;                        // s: an older driver state is a device fault
  double state_wait = 0.0005;  // s: how long the servo loop's tick waits for the driver's next state
  double max_force = 3.3;      // N: the profile's limit (what is sent never exceeds it)
};

// stale_timeout, state_wait (the numeric rows; the others are names, a frame and a vector).
const ParameterTable<DriverBridgeParams>& driverBridgeParameterTable();

// `backend`'s parameters: driver_ns (required: the profile sets it), arm, driver_frame,
// driver_position_unit (> 0), driver_center, the table's rows; max_force is the profile's limit.
// InputError naming a bad one.
DriverBridgeParams readDriverBridgeParams(const std::string& backend, const ParameterSource& source, double max_force);

// The driver's newest state, as it sent it (driver frame and units).
struct DriverState
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double stamp = -1.0;  // s, the link's clock (arrival); < 0: none yet
};

class DriverLink
{
 public:
  DriverLink();
  ~DriverLink();
  DriverLink(const DriverLink&) = delete;
  DriverLink& operator=(const DriverLink&) = delete;

  // ROS side (one callback thread at a time). A non-finite position is dropped (counted).
  void writeState(const Eigen::Vector3d& position, double stamp);
  void setButtons(std::uint32_t buttons);
  void setButton(int index, bool pressed);
  // Device side: the newest state; awaitState() first waits up to `timeout` s for one newer
  // than the last read (a semaphore's bounded wait: real-time safe, as a vendor's servo frame).
  const DriverState& read();
  const DriverState& awaitState(double timeout);
  std::uint32_t buttons() const
  {
    return buttons_.load(std::memory_order_relaxed);
  }
  // The force to send (N, driver frame); wakes the sender. Real-time safe.
  void sendForce(const Eigen::Vector3d& force);
  // Sender: waits up to `timeout` s for a force sent since the last take; false on time-out.
  bool takeForce(double timeout, Eigen::Vector3d* force);
  // Statistics (any thread): states received and dropped as non-finite.
  long states() const
  {
    return states_.load(std::memory_order_relaxed);
  }
  long rejectedStates() const
  {
    return rejected_.load(std::memory_order_relaxed);
  }

  std::shared_ptr<void> connection;  // the ROS side's subscriptions and sender (DeviceContext::connect_driver)

 private:
  LatestValue<DriverState> state_;
  LatestValue<Eigen::Vector3d> force_;
  sem_t force_ready_;
  sem_t state_ready_;  // posted per state written
  std::atomic<std::uint32_t> buttons_{0};
  std::atomic<long> states_{0};
  std::atomic<long> rejected_{0};
};

class DriverBridgeDevice : public HapticDevice
{
 public:
  // `now`: the link's clock (s), what the ROS side stamps states with.
  DriverBridgeDevice(const DriverBridgeParams& params, std::shared_ptr<DriverLink> link, std::function<double()> now);
  // Sends a zero force: the driver holds whatever it got last.
  ~DriverBridgeDevice() override;
  std::string name() const override
  {
    return params_.backend;
  }
  // Nothing to open: the driver runs apart. A driver not yet heard from reads untracked.
  void start() override {}
  // Sends `force` (decided for the last reading), then reads the newest state.
  DeviceReading update(double time, const Eigen::Vector3d& force) override;
  // The servo loop answers each state in the tick that read it (devices/haptic_device.h,
  // kFrame): wait up to state_wait for a state newer than the last (the driver's clock, not the
  // loop's, then paces the answer: a state arriving in that window is answered at once, one after
  // it at the next tick), ask `responder`, send its force at once. The topic topologies' driver
  // node uses update(), which never waits.
  DeviceExchange exchangeForm() const override
  {
    return DeviceExchange::kFrame;
  }
  DeviceReading exchangeFrame(double time, FrameResponder& responder) override;

  Eigen::Vector3d toDevice(const Eigen::Vector3d& driver_position) const;
  Eigen::Vector3d forceToDriver(const Eigen::Vector3d& device_force) const;

 private:
  DeviceReading read(double wait);  // the newest state, after waiting up to `wait` s for one (untracked when stale)
  void send(const DeviceReading& reading, const Eigen::Vector3d& force);  // zero when untracked

  DriverBridgeParams params_;
  std::shared_ptr<DriverLink> link_;
  std::function<double()> now_;
  VelocityEstimator velocity_;
  double last_stamp_ = -1.0;
  Eigen::Vector3d last_position_ = Eigen::Vector3d::Zero();  // m, device frame
  Eigen::Vector3d last_velocity_ = Eigen::Vector3d::Zero();
};
}  // namespace god_finger
