#include "god_finger/devices/device_registry.h"

#include "god_finger/core/input_error.h"
#include "god_finger/devices/fake_device.h"
#include "god_finger/devices/falcon_device.h"
#include "god_finger/devices/omni_device.h"
#include "god_finger/devices/replay_device.h"
#include "god_finger/devices/vendor_io.h"

#include <chrono>
#include <thread>

namespace god_finger
{
namespace
{
#if defined(GOD_FINGER_HAVE_NIFALCON) || defined(GOD_FINGER_HAVE_OPENHAPTICS)
// Clock and wait for the hardware backends' start-up (homing, calibration), which waits for the user.
double steadySeconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void waitForUser()
{
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
}
#endif

std::unique_ptr<HapticDevice> makeFake(const DeviceContext& context)
{
  // No script: the hand holds the handle at the workspace centre.
  return std::make_unique<FakeDevice>(readFakeDeviceParams(context.params),
                                      readScript(context.params, Eigen::Vector3d::Zero()));
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

std::unique_ptr<HapticDevice> makeFalcon(const DeviceContext& context)
{
  const FalconParams params = readFalconParams(context.params, context.max_force);
#ifdef GOD_FINGER_HAVE_NIFALCON
  return std::make_unique<FalconDevice>(makeNifalconIo(), params, steadySeconds, waitForUser);
#else
  (void)params;
  throw DeviceError(
      "backend 'falcon' needs libnifalcon, which this build did not find: build and install libnifalcon "
      "(https://github.com/libnifalcon/libnifalcon), then rebuild god_finger (README, Devices)");
#endif
}

std::unique_ptr<HapticDevice> makeOmni(const DeviceContext& context)
{
  const OmniParams params = readOmniParams(context.params, context.max_force);
#ifdef GOD_FINGER_HAVE_OPENHAPTICS
  return std::make_unique<OmniDevice>(makeOpenHapticsIo(), params, steadySeconds, waitForUser);
#else
  (void)params;
  throw DeviceError(
      "backend 'omni' needs the OpenHaptics HD API, which this build did not find: install 3D Systems' "
      "OpenHaptics (and the Touch / Phantom device driver), then rebuild god_finger (README, Devices)");
#endif
}
}  // namespace

const std::vector<DeviceBackend>& deviceBackends()
{
  // replay and interactive are simulated handles: the fake device's profile.
  static const std::vector<DeviceBackend> backends = {
      // name, profile, simulated, hand_target, factory
      {"fake", "fake", true, false, makeFake},     {"interactive", "fake", true, true, makeInteractive},
      {"replay", "fake", true, false, makeReplay}, {"falcon", "falcon", false, false, makeFalcon},
      {"omni", "omni", false, false, makeOmni},
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
