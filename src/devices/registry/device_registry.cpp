#include "god_finger/devices/device_registry.h"

#include "god_finger/devices/fake_device.h"
#include "god_finger/devices/fake_hand.h"
#include "god_finger/devices/falcon_device.h"
#include "god_finger/devices/omni_device.h"
#include "god_finger/devices/pose_source.h"
#include "god_finger/devices/replay_device.h"
#include "god_finger/devices/vendor_io.h"
#include "god_finger/support/input_error.h"

#include <chrono>
#include <thread>

namespace god_finger
{
namespace
{
// Clock and wait for the hardware backends' start-up (homing, calibration), which waits for the user.
double steadySeconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void waitForUser()
{
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

// Test seams of the fake backend, in its script's time (s), for rostests: readings non-finite
// (position NaN) with every button pressed during [from, until), as a faulty device's are
// (a loop must reject them whole); buttons `mask` pressed during [press_from, press_until).
class ScriptedFaults : public HapticDevice
{
 public:
  ScriptedFaults(std::unique_ptr<FakeDevice> device, double from, double until, const Eigen::Vector3d& press)
      : device_(std::move(device)), from_(from), until_(until), press_(press)
  {
  }
  std::string name() const override
  {
    return device_->name();
  }
  void start() override
  {
    device_->start();
  }
  DeviceReading update(double time, const Eigen::Vector3d& force) override
  {
    return faulted(time, device_->update(time, force));
  }
  DeviceReading updateWrench(double time, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) override
  {
    return faulted(time, device_->updateWrench(time, force, torque));
  }
  void setScriptStart(double time) override
  {
    device_->setScriptStart(time);
  }
  bool setHandTarget(const Eigen::Vector3d& position) override
  {
    return device_->setHandTarget(position);
  }
  bool setHandPose(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation) override
  {
    return device_->setHandPose(position, orientation);
  }

 private:
  DeviceReading faulted(double time, DeviceReading reading) const
  {
    const double script_time = time - device_->startTime();
    if (script_time >= press_[0] && script_time < press_[1])
    {
      reading.buttons = static_cast<std::uint32_t>(press_[2]);
    }
    if (script_time >= from_ && script_time < until_)
    {
      reading.position.x() = NAN;
      reading.buttons = ~0u;
    }
    return reading;
  }

  std::unique_ptr<FakeDevice> device_;
  double from_;
  double until_;
  Eigen::Vector3d press_;  // from, until, buttons
};

std::unique_ptr<HapticDevice> makeFake(const DeviceContext& context)
{
  // No script: the hand holds the handle at the workspace centre. No orientation script: a
  // 3-DOF finger.
  auto device = std::make_unique<FakeDevice>(readFakeDeviceParams(context.params),
                                             readScript(context.params, Eigen::Vector3d::Zero()),
                                             readOrientationScript(context.params));
  // Test seams: non_finite_readings [from, until], pressed_buttons [from, until, buttons] (s of
  // the script's time; buttons: a bit mask); unset: none.
  const Eigen::VectorXd faulty = readVector(context.params, "non_finite_readings", Eigen::Vector2d(-1.0, -1.0));
  const Eigen::VectorXd press = readVector(context.params, "pressed_buttons", Eigen::Vector3d(-1.0, -1.0, 0.0));
  if (faulty[1] > faulty[0] || press[1] > press[0])
  {
    if (!(press[2] >= 0.0 && press[2] <= 65535.0))
    {
      throw InputError("parameter '" + context.params.fullName("pressed_buttons") +
                       "': its buttons (third number) must be a bit mask in [0, 65535]");
    }
    return std::make_unique<ScriptedFaults>(std::move(device), faulty[0], faulty[1], press);
  }
  return device;
}

std::unique_ptr<HapticDevice> makeInteractive(const DeviceContext& context)
{
  // A simulated handle whose hand is an rviz marker: it waits at `start` until dragged.
  const Eigen::Vector3d start = readVector(context.params, "start", Eigen::Vector3d(0.0, 0.0, 0.12));
  return std::make_unique<FakeDevice>(readFakeDeviceParams(context.params), WaypointPath({{0.0, start}}));
}

std::unique_ptr<HapticDevice> makeReplay(const DeviceContext& context)
{
  const std::string bag = readString(context.params, "bag", "");
  if (bag.empty())
  {
    throw InputError("parameter '" + context.params.fullName("bag") +
                     "' is required by backend 'replay' (a recorded bag)");
  }
  if (!context.read_track)
  {
    throw InputError("backend 'replay' needs a recording reader, which this program does not have");
  }
  const std::string topic = readString(context.params, "topic", context.default_track_topic);
  return std::make_unique<ReplayDevice>(context.read_track(bag, topic));
}

std::unique_ptr<HapticDevice> makeFakeHand(const DeviceContext& context)
{
  return makeHandDevice(makeFakeHand(readFakeHandParams(context.params)));
}

std::unique_ptr<HapticDevice> makePoseSource(const DeviceContext& context)
{
  const PoseSourceParams params = readPoseSourceParams(context.params);
  if (!context.connect_poses)
  {
    throw InputError(
        "backend 'pose_source' needs a pose subscriber, which this program does not have (run it "
        "with topology:=servo)");
  }
  auto feed = std::make_shared<PoseFeed>(params.fingers.size());
  feed->connection = context.connect_poses(params, feed);
  return makeHandDevice(makePoseSource(params, feed, context.now));
}

std::unique_ptr<HapticDevice> makeDriverBridge(const std::string& backend, const DeviceContext& context)
{
  const DriverBridgeParams params = readDriverBridgeParams(backend, context.params, context.max_force);
  if (!context.connect_driver || !context.now)
  {
    throw InputError("backend '" + backend + "' talks to a ROS driver, which this program cannot (run it from a node)");
  }
  auto link = std::make_shared<DriverLink>();
  link->connection = context.connect_driver(params, link);
  return std::make_unique<DriverBridgeDevice>(params, std::move(link), context.now);
}

std::unique_ptr<HapticDevice> makeOmniMsgs(const DeviceContext& context)
{
  return makeDriverBridge("omni_msgs", context);
}

std::unique_ptr<HapticDevice> makeRosGeomagic(const DeviceContext& context)
{
  return makeDriverBridge("ros_geomagic", context);
}

std::unique_ptr<HapticDevice> makeCrtk(const DeviceContext& context)
{
  return makeDriverBridge("crtk", context);
}

std::unique_ptr<HapticDevice> makeRosFalcon(const DeviceContext& context)
{
  return makeDriverBridge("ros_falcon", context);
}

std::unique_ptr<HapticDevice> makeFalcon(const DeviceContext& context)
{
  const FalconParams params = readFalconParams(context.params, context.max_force);
#ifdef GOD_FINGER_HAVE_NIFALCON
  return std::make_unique<FalconDevice>(makeNifalconIo(), params, steadySeconds, waitForUser);
#else
  (void)params;
  throw DeviceError(
      "backend 'falcon' needs libnifalcon, which this build did not find: build and install libnifalcon "
      "(https://github.com/libnifalcon/libnifalcon), then rebuild god_finger (docs/devices.md)");
#endif
}

std::unique_ptr<HapticDevice> makeOmni(const DeviceContext& context)
{
  const OmniParams params = readOmniParams(context.params, context.max_force);
  const VendorModule module = openHapticsModule();
  if (module.file_name.empty())
  {
    throw DeviceError(
        "backend 'omni' needs the OpenHaptics HD API, which this build did not find: install 3D Systems' "
        "OpenHaptics (and the Touch / Phantom device driver), then rebuild god_finger (docs/devices.md)");
  }
  std::unique_ptr<OmniIo> io;
  try
  {
    io = loadOpenHapticsIo(module.file_name);  // on the library path (the workspace's setup.bash)
  }
  catch (const DeviceError&)
  {
    io = loadOpenHapticsIo(module.build_path);  // where this build made it; its error says what to install
  }
  return std::make_unique<OmniDevice>(std::move(io), params, steadySeconds, waitForUser);
}
}  // namespace

const std::vector<DeviceBackend>& deviceBackends()
{
  // replay is a simulated handle: the fake device's profile; so are the hands, whose coupling
  // pulls proxies only. interactive is the fake handle with a workspace the views show.
  static const std::vector<DeviceBackend> backends = {
      // name, profile, simulated, hand_target, factory
      {"fake", "fake", true, false, makeFake},
      {"interactive", "interactive", true, true, makeInteractive},
      {"replay", "fake", true, false, makeReplay},
      {"falcon", "falcon", false, false, makeFalcon},
      {"omni", "omni", false, false, makeOmni},
      // Hands (devices/hand_device.h): one interface per finger, input only (no force rendered).
      {"fake_hand", "fake", true, false, makeFakeHand, false},
      {"pose_source", "fake", false, false, makePoseSource, false},
      // The ROS drivers labs run (devices/driver_bridge.h): the device is the driver, over its topics.
      // The device's profile is its hardware's; the driver's map is config/drivers/NAME.yaml.
      {"omni_msgs", "omni", false, false, makeOmniMsgs},
      {"ros_geomagic", "omni", false, false, makeRosGeomagic},
      {"crtk", "omni", false, false, makeCrtk},
      {"ros_falcon", "falcon", false, false, makeRosFalcon},
  };
  return backends;
}

std::string deviceBackendNames()
{
  std::string names;
  for (const DeviceBackend& backend : deviceBackends())
  {
    names += (names.empty() ? "" : ", ") + std::string(backend.name);
  }
  return names;
}

const DeviceBackend& findDeviceBackend(const std::string& name, const std::string& parameter)
{
  for (const DeviceBackend& backend : deviceBackends())
  {
    if (name == backend.name)
    {
      return backend;
    }
  }
  throw InputError("parameter '" + parameter + "' = '" + name + "' is not one of " + deviceBackendNames());
}

std::unique_ptr<HapticDevice> makeDevice(const DeviceBackend& backend, const DeviceContext& context)
{
  std::unique_ptr<HapticDevice> device = backend.make(context);
  if (std::isfinite(context.script_start))
  {
    device->setScriptStart(context.script_start);
  }
  return device;
}
}  // namespace god_finger
