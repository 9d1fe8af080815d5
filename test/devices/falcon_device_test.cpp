// The Falcon backend through its seam (no device, no libnifalcon): axes and units to REP-103,
// force clamping, firmware retries, homing, lost USB.
#include "god_finger/devices/falcon_device.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
// A Falcon in memory: counts calls, fails on demand.
struct ScriptedFalcon : FalconIo
{
  int devices = 1;
  bool opens = true;
  int firmware_loads_needed = 1;  // loadFirmware() calls before it is loaded
  int firmware_loads = 0;
  int homed_after_cycles = 3;
  int cycles = 0;
  bool homing = false;
  bool io_ok = true;
  std::array<double, 3> grip{0.0, 0.0, 0.11};
  std::array<double, 3> force{0.0, 0.0, 0.0};
  unsigned pressed = 0;

  int deviceCount() override
  {
    return devices;
  }
  bool open(int) override
  {
    return opens;
  }
  bool isFirmwareLoaded() override
  {
    return firmware_loads >= firmware_loads_needed;
  }
  bool loadFirmware() override
  {
    ++firmware_loads;
    return isFirmwareLoaded();
  }
  void setHomingMode(bool on) override
  {
    homing = on;
  }
  bool isHomed() override
  {
    return cycles >= homed_after_cycles;
  }
  bool runIoLoop() override
  {
    ++cycles;
    return io_ok;
  }
  std::array<double, 3> position() override
  {
    return grip;
  }
  void setForce(const std::array<double, 3>& f) override
  {
    force = f;
  }
  unsigned buttons() override
  {
    return pressed;
  }
  std::string lastError() override
  {
    return "scripted";
  }
};

struct Fixture
{
  ScriptedFalcon* io = new ScriptedFalcon;
  double clock = 0.0;
  std::unique_ptr<FalconDevice> device;
  explicit Fixture(FalconParams params = FalconParams())
  {
    device = std::make_unique<FalconDevice>(
        std::unique_ptr<FalconIo>(io), params, [this] { return clock; }, [this] { clock += 0.01; });
  }
};

TEST(FalconDevice, AxesAndUnitsFollowRep103)
{
  Fixture f;
  f.device->start();
  // Grip pushed away from the user (Falcon z smaller), to the user's right (x+), up (y+).
  f.io->grip = {0.01, 0.02, 0.11 - 0.03};
  const DeviceReading reading = f.device->update(1.0, Eigen::Vector3d::Zero());
  EXPECT_LT((reading.position - Eigen::Vector3d(0.03, -0.01, 0.02)).norm(), 1e-15);
  // A force pushing away from the user and up: Falcon -z and +y.
  f.device->update(1.001, Eigen::Vector3d(2.0, 0.0, 1.0));
  EXPECT_EQ(f.io->force, (std::array<double, 3>{-0.0, 1.0, -2.0}));
  // Round trip of the rotation (it is proper: a force along the motion does positive work).
  const Eigen::Vector3d step(0.001, 0.002, -0.001);
  const Eigen::Vector3d force(1.0, -2.0, 0.5);
  const std::array<double, 3> falcon_force = deviceForceToVendorAxes(force);
  const std::array<double, 3> falcon_step{-step.y(), step.z(), -step.x()};
  EXPECT_NEAR(falcon_force[0] * falcon_step[0] + falcon_force[1] * falcon_step[1] + falcon_force[2] * falcon_step[2],
              force.dot(step), 1e-15);
}

TEST(FalconDevice, ForceIsClampedToTheDeviceAndNaNSentAsZero)
{
  FalconParams params;
  params.max_force = 8.9;
  Fixture f(params);
  f.device->start();
  f.device->update(1.0, Eigen::Vector3d(0.0, 0.0, 30.0));
  EXPECT_NEAR(f.io->force[1], 8.9, 1e-12);
  f.device->update(1.001, Eigen::Vector3d(NAN, 0.0, 1.0));
  EXPECT_EQ(f.io->force, (std::array<double, 3>{0.0, 0.0, 0.0}));
}

TEST(FalconDevice, FirmwareIsRetriedThenGivesUpWithAMessage)
{
  Fixture retried;
  retried.io->firmware_loads_needed = 4;
  retried.device->start();
  EXPECT_EQ(retried.device->firmwareAttempts(), 4);

  FalconParams params;
  params.firmware_attempts = 3;
  Fixture failing(params);
  failing.io->firmware_loads_needed = 100;
  try
  {
    failing.device->start();
    FAIL() << "no error";
  }
  catch (const DeviceError& error)
  {
    EXPECT_NE(std::string(error.what()).find("firmware not loaded after 3 attempts"), std::string::npos)
        << error.what();
  }
}

TEST(FalconDevice, HomingWaitsForTheUserOrTimesOut)
{
  Fixture homed;
  homed.io->homed_after_cycles = 50;
  homed.device->start();
  EXPECT_FALSE(homed.io->homing);  // homing mode left after homing
  EXPECT_NEAR(homed.clock, 0.49, 1e-9);

  FalconParams params;
  params.homing_timeout = 2.0;
  Fixture never(params);
  never.io->homed_after_cycles = 1000000;
  try
  {
    never.device->start();
    FAIL() << "no error";
  }
  catch (const DeviceError& error)
  {
    EXPECT_NE(std::string(error.what()).find("not homed within 2 s: pull the grip all the way out"), std::string::npos)
        << error.what();
  }
}

TEST(FalconDevice, MissingOrBusyDeviceSaysWhatToCheck)
{
  Fixture none;
  none.io->devices = 0;
  EXPECT_THROW(none.device->start(), DeviceError);
  Fixture busy;
  busy.io->opens = false;
  try
  {
    busy.device->start();
    FAIL() << "no error";
  }
  catch (const DeviceError& error)
  {
    EXPECT_NE(std::string(error.what()).find("cannot open Falcon 0"), std::string::npos) << error.what();
  }
}

TEST(FalconDevice, LostUsbIsToleratedBrieflyThenAnError)
{
  FalconParams params;
  params.io_failures_allowed = 5;
  Fixture f(params);
  f.device->start();
  f.io->io_ok = false;
  for (int i = 0; i < 5; ++i)
  {
    EXPECT_NO_THROW(f.device->update(1.0 + i * 1e-3, Eigen::Vector3d::Zero()));
  }
  EXPECT_THROW(f.device->update(1.01, Eigen::Vector3d::Zero()), DeviceError);
  f.io->io_ok = true;
}
}  // namespace
}  // namespace god_finger
