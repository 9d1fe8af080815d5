// The Omni/Touch backend as built against stand-ins of OpenHaptics (test/vendor/openhaptics: the
// vendor's headers with their `linux` guard, a libHD that needs the Touch driver's
// libPHANToMIO.so.4 and runs callbacks in its own servo thread), loaded as the registry loads it
// (devices/vendor_io.h). This binary links neither: the tests run in order, in one process, as a
// machine is set up: nothing of OpenHaptics loaded for a fake device; the module refused, saying
// what to install, without the Touch driver; with it, the device calibrates in the servo thread
// and renders.
#include "god_finger/devices/device_registry.h"
#include "god_finger/devices/vendor_frames.h"
#include "god_finger/devices/vendor_io.h"
#include "hd_stand_in_control.h"

#include <dlfcn.h>
#include <link.h>

#include <gtest/gtest.h>

#include <string>

namespace god_finger
{
namespace
{
// Whether a shared object whose path contains `name` is loaded in this process.
bool loaded(const std::string& name)
{
  struct Search
  {
    std::string name;
    bool found = false;
  } search{name};
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* data)
      {
        auto* search = static_cast<Search*>(data);
        search->found = search->found || std::string(info->dlpi_name).find(search->name) != std::string::npos;
        return 0;
      },
      &search);
  return search.found;
}

// A function of the stand-in libHD's control API (hd_stand_in_control.h), once libHD is loaded.
template <class Function>
Function control(const char* name)
{
  void* hd = dlopen("libHD.so.3.0", RTLD_NOW | RTLD_NOLOAD);
  EXPECT_NE(hd, nullptr) << "libHD is not loaded";
  return hd ? reinterpret_cast<Function>(dlsym(hd, name)) : nullptr;
}

TEST(OmniOpenHaptics, AFakeDeviceLoadsNothingOfOpenHaptics)
{
  MapParameterSource params("/finger/");
  DeviceContext context(params, 3.3);
  auto device = makeDevice(findDeviceBackend("fake", "backend"), context);
  device->start();
  for (int k = 0; k < 10; ++k)
  {
    device->update(k * 1e-3, Eigen::Vector3d::Zero());
  }
  EXPECT_FALSE(loaded("libHD"));
  EXPECT_FALSE(loaded("libPHANToMIO"));
  EXPECT_FALSE(loaded("god_finger_omni_io"));
}

TEST(OmniOpenHaptics, WithoutTheTouchDriverTheModuleSaysWhatToInstall)
{
  try
  {
    loadOpenHapticsIo(GOD_FINGER_OMNI_IO_STAND_IN);
    FAIL() << "the module loaded without libPHANToMIO.so.4";
  }
  catch (const DeviceError& error)
  {
    const std::string message = error.what();
    EXPECT_NE(message.find("libPHANToMIO.so.4"), std::string::npos) << message;
    EXPECT_NE(message.find("install 3D Systems' Touch device driver"), std::string::npos) << message;
    std::cout << "without the Touch driver: " << message << std::endl;
  }
  EXPECT_FALSE(loaded("libHD"));
}

// Records the reading the frame asked about, answers a fixed force.
class FixedResponder : public FrameResponder
{
 public:
  void respond(const DeviceReading& reading, Eigen::Vector3d* force, Eigen::Vector3d* torque) override
  {
    asked = reading;
    *force = Eigen::Vector3d(0.0, 0.0, 1.5);  // N, device frame: up
    torque->setZero();
  }
  DeviceReading asked;
};

TEST(OmniOpenHaptics, WithTheTouchDriverItCalibratesInTheServoThreadAndRenders)
{
  // The Touch driver installed: its library where the loader finds it (by its soname).
  ASSERT_NE(dlopen(GOD_FINGER_PHANTOM_IO_STAND_IN, RTLD_NOW | RTLD_GLOBAL), nullptr) << dlerror();
  std::unique_ptr<OmniIo> io = loadOpenHapticsIo(GOD_FINGER_OMNI_IO_STAND_IN);
  ASSERT_TRUE(loaded("libHD"));
  control<void (*)()>("hdStandInReset")();
  control<void (*)(unsigned)>("hdStandInSetCalibrationStatus")(0x5001);  // HD_CALIBRATION_NEEDS_UPDATE
  control<void (*)(double, double, double)>("hdStandInSetPositionMm")(10.0, 20.0, 30.0);

  OmniParams params;
  params.max_force = 3.3;
  double clock = 0.0;
  OmniDevice device(
      std::move(io), params, [&clock]() { return clock; }, [&clock]() { clock += 0.01; });
  device.start();
  const auto calls = control<int (*)(int)>("hdStandInUpdateCalibrationCalls");
  EXPECT_EQ(calls(1), 1) << "hdUpdateCalibration in a scheduled callback, as the vendor's example";
  EXPECT_EQ(calls(0), 0) << "hdUpdateCalibration from the application thread";
  EXPECT_EQ(control<int (*)()>("hdStandInForceOutputEnabled")(), 1);

  // A packet exchange: the stylus in the device frame, the force in the HD frame.
  const DeviceReading reading = device.update(0.001, Eigen::Vector3d(1.0, 0.0, 0.0));
  EXPECT_TRUE(reading.position.isApprox(hdFrame().toDevice(Eigen::Vector3d(10.0, 20.0, 30.0)) * 1e-3, 1e-12))
      << reading.position.transpose();
  double force[3];
  control<void (*)(double*)>("hdStandInLastForce")(force);
  EXPECT_DOUBLE_EQ(force[2], -1.0);  // device x (away from the user) is HD -z
  EXPECT_DOUBLE_EQ(force[0], 0.0);

  // A frame exchange: the force answers the reading of the same frame.
  control<void (*)(double, double, double)>("hdStandInSetPositionMm")(0.0, -5.0, 0.0);
  FixedResponder responder;
  device.exchangeFrame(0.002, responder);
  EXPECT_NEAR(responder.asked.position.z(), -0.005, 1e-12);
  control<void (*)(double*)>("hdStandInLastForce")(force);
  EXPECT_DOUBLE_EQ(force[1], 1.5);  // device up is HD y
  EXPECT_EQ(control<int (*)()>("hdStandInOffServoThreadCalls")(), 0)
      << "every device access in the servo thread while the scheduler runs";
}
}  // namespace
}  // namespace god_finger
