// The ROS driver bridges without ROS (devices/driver_bridge.h): the named frames (one table), a
// driver's state in its units and axes to the device frame, the force back, a stale or silent
// driver as a fault (untracked, zero force), the last force zero, bad parameters named.
#include "god_finger/devices/driver_bridge.h"
#include "god_finger/devices/device_registry.h"
#include "god_finger/devices/vendor_frames.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

namespace god_finger
{
namespace
{
TEST(VendorFrames, EachIsARotationAndSaysItsAxes)
{
  EXPECT_EQ(vendorFrameNames(), "device, hd, omni_common, force_dimension");
  for (const VendorFrame& frame : vendorFrames())
  {
    EXPECT_TRUE((frame.to_device * frame.to_device.transpose()).isIdentity(1e-15)) << frame.name;
    EXPECT_DOUBLE_EQ(frame.to_device.determinant(), 1.0) << frame.name;  // right-handed
  }
  // The axes each frame's text names, written out: up, away from the user, to the user's right.
  const Eigen::Vector3d up(0, 0, 1), away(1, 0, 0), right(0, -1, 0);
  const VendorFrame& hd = findVendorFrame("hd", "driver_frame");  // x right, y up, z towards the user
  EXPECT_EQ(hd.toDevice(Eigen::Vector3d(1, 0, 0)), right);
  EXPECT_EQ(hd.toDevice(Eigen::Vector3d(0, 1, 0)), up);
  EXPECT_EQ(hd.toDevice(Eigen::Vector3d(0, 0, 1)), -away);
  const VendorFrame& omni = findVendorFrame("omni_common", "driver_frame");  // x right, y away, z up
  EXPECT_EQ(omni.toDevice(Eigen::Vector3d(1, 0, 0)), right);
  EXPECT_EQ(omni.toDevice(Eigen::Vector3d(0, 1, 0)), away);
  EXPECT_EQ(omni.toDevice(Eigen::Vector3d(0, 0, 1)), up);
  const VendorFrame& fd = findVendorFrame("force_dimension", "driver_frame");  // x towards the user, y right, z up
  EXPECT_EQ(fd.toDevice(Eigen::Vector3d(1, 0, 0)), -away);
  EXPECT_EQ(fd.toDevice(Eigen::Vector3d(0, 1, 0)), right);
  EXPECT_EQ(fd.toDevice(Eigen::Vector3d(0, 0, 1)), up);
  // A force goes back by the inverse.
  const Eigen::Vector3d force(0.3, -0.2, 1.5);
  EXPECT_TRUE(hd.toDevice(hd.toVendor(force)).isApprox(force, 1e-15));
  try
  {
    findVendorFrame("opengl", "/finger/driver_frame");
    FAIL();
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(),
                 "parameter '/finger/driver_frame' = 'opengl' is not one of device, hd, omni_common, force_dimension");
  }
}

// The geomagic driver's map: mm in the HD frame.
MapParameterSource geomagicParams()
{
  MapParameterSource params("/finger/");
  params.set("driver_ns", ParameterValue::of(std::string("/Geomagic")));
  params.set("driver_frame", ParameterValue::of(std::string("hd")));
  params.set("driver_position_unit", ParameterValue::of(0.001));
  params.set("driver_center", ParameterValue::of(std::vector<double>{0.0, 10.0, 0.0}));
  return params;
}

struct Bridge
{
  double clock = 100.0;
  std::shared_ptr<DriverLink> link = std::make_shared<DriverLink>();
  std::unique_ptr<DriverBridgeDevice> device;
  explicit Bridge(const MapParameterSource& params)
      : device(std::make_unique<DriverBridgeDevice>(readDriverBridgeParams("ros_geomagic", params, 3.3), link,
                                                    [this]() { return clock; }))
  {
  }
  // The force the device left for the sender (driver frame), or NaN when none.
  Eigen::Vector3d sent()
  {
    Eigen::Vector3d force = Eigen::Vector3d::Constant(NAN);
    link->takeForce(0.0, &force);
    return force;
  }
};

TEST(DriverBridge, MapsTheDriversStateAndSendsTheForceInItsFrame)
{
  Bridge bridge(geomagicParams());
  // 20 mm to the user's right, 30 mm up from the centre (y 10 mm), 40 mm towards the user.
  bridge.link->writeState(Eigen::Vector3d(20.0, 40.0, 40.0), bridge.clock);
  bridge.link->setButton(1, true);
  DeviceReading reading = bridge.device->update(0.0, Eigen::Vector3d(0.0, 0.0, 2.0));
  EXPECT_TRUE(reading.tracked);
  EXPECT_TRUE(reading.position.isApprox(Eigen::Vector3d(-0.04, -0.02, 0.03), 1e-12)) << reading.position.transpose();
  EXPECT_EQ(reading.buttons, 2u);
  EXPECT_TRUE(bridge.sent().isApprox(Eigen::Vector3d(0.0, 2.0, 0.0), 1e-15));  // up is the HD frame's y
  // Over the profile's limit: sent at the limit, direction kept; not finite: zero.
  bridge.device->update(0.001, Eigen::Vector3d(0.0, 0.0, 10.0));
  EXPECT_NEAR(bridge.sent().y(), 3.3, 1e-12);
  bridge.device->update(0.002, Eigen::Vector3d(NAN, 0.0, 1.0));
  EXPECT_TRUE(bridge.sent().isZero());
  // Velocity from successive states on the arrival clock: 5 mm up in 5 ms.
  bridge.clock += 0.005;
  bridge.link->writeState(Eigen::Vector3d(20.0, 45.0, 40.0), bridge.clock);
  reading = bridge.device->update(0.007, Eigen::Vector3d::Zero());
  EXPECT_NEAR(reading.velocity.z(), 1.0, 1e-9);
}

// Answers a reading with a force 100 N/m above the ball's top at z = 0 (device frame).
class SpringResponder : public FrameResponder
{
 public:
  void respond(const DeviceReading& reading, Eigen::Vector3d* force, Eigen::Vector3d* torque) override
  {
    asked = reading;
    *force = Eigen::Vector3d(0.0, 0.0, std::max(0.0, -100.0 * reading.position.z()));
    torque->setZero();
  }
  DeviceReading asked;
};

TEST(DriverBridge, TheServoLoopAnswersEachStateInTheTickThatReadIt)
{
  Bridge bridge(geomagicParams());
  EXPECT_EQ(bridge.device->exchangeForm(), DeviceExchange::kFrame);
  SpringResponder responder;
  bridge.link->writeState(Eigen::Vector3d(0.0, 0.0, 0.0), bridge.clock);  // 10 mm down
  const DeviceReading reading = bridge.device->exchangeFrame(0.0, responder);
  EXPECT_NEAR(responder.asked.position.z(), -0.01, 1e-15);
  EXPECT_EQ(reading.position, responder.asked.position);
  EXPECT_NEAR(bridge.sent().y(), 1.0, 1e-12);  // its own force, in the same exchange
  bridge.clock += 1.0;                         // stale: whatever the responder says, zero
  bridge.device->exchangeFrame(1.0, responder);
  EXPECT_TRUE(bridge.sent().isZero());
}

TEST(DriverBridge, TheTickWaitsForTheDriversNextStateOnly)
{
  DriverLink link;
  link.writeState(Eigen::Vector3d(1.0, 0.0, 0.0), 1.0);
  // A state not yet read: no wait (a 10 s timeout would fail the test's own time limit).
  EXPECT_EQ(link.awaitState(10.0).position.x(), 1.0);
  // None newer: the wait ends with the driver's next state, written by its own thread.
  std::thread driver([&link]() { link.writeState(Eigen::Vector3d(2.0, 0.0, 0.0), 2.0); });
  EXPECT_EQ(link.awaitState(10.0).position.x(), 2.0);
  driver.join();
  // None newer and no driver: the last one, after the bounded wait.
  EXPECT_EQ(link.awaitState(1e-4).position.x(), 2.0);
}

TEST(DriverBridge, ASilentOrStaleDriverIsAFaultWithZeroForce)
{
  Bridge bridge(geomagicParams());
  DeviceReading reading = bridge.device->update(0.0, Eigen::Vector3d(0.0, 0.0, 2.0));
  EXPECT_FALSE(reading.tracked) << "no state yet";
  EXPECT_TRUE(bridge.sent().isZero());
  bridge.link->writeState(Eigen::Vector3d(0.0, 10.0, 0.0), bridge.clock);
  bridge.clock += 0.1;  // the default stale_timeout: still fresh
  EXPECT_TRUE(bridge.device->update(0.1, Eigen::Vector3d(0.0, 0.0, 2.0)).tracked);
  EXPECT_DOUBLE_EQ(bridge.sent().y(), 2.0);
  bridge.clock += 0.001;
  reading = bridge.device->update(0.101, Eigen::Vector3d(0.0, 0.0, 2.0));
  EXPECT_FALSE(reading.tracked);
  EXPECT_TRUE(reading.position.isZero(1e-15)) << "at the last known position";
  EXPECT_TRUE(reading.velocity.isZero());
  EXPECT_TRUE(bridge.sent().isZero());
  // A non-finite state is dropped and counted; the driver stays stale.
  bridge.link->writeState(Eigen::Vector3d(NAN, 0.0, 0.0), bridge.clock);
  EXPECT_EQ(bridge.link->rejectedStates(), 1);
  EXPECT_FALSE(bridge.device->update(0.102, Eigen::Vector3d::Zero()).tracked);
  // Back: tracked again.
  bridge.link->writeState(Eigen::Vector3d(0.0, 10.0, 0.0), bridge.clock);
  EXPECT_TRUE(bridge.device->update(0.103, Eigen::Vector3d::Zero()).tracked);
  EXPECT_EQ(bridge.link->states(), 2);
}

TEST(DriverBridge, TheLastForceIsZero)
{
  Bridge bridge(geomagicParams());
  bridge.link->writeState(Eigen::Vector3d(0.0, 10.0, 0.0), bridge.clock);
  bridge.device->update(0.0, Eigen::Vector3d(0.0, 0.0, 2.0));
  bridge.device.reset();
  EXPECT_TRUE(bridge.sent().isZero());
}

TEST(DriverBridge, BadParametersAreNamed)
{
  MapParameterSource params = geomagicParams();
  params.set("driver_frame", ParameterValue::of(std::string("left")));
  EXPECT_THROW(readDriverBridgeParams("ros_geomagic", params, 3.3), InputError);
  params = geomagicParams();
  params.set("driver_position_unit", ParameterValue::of(0.0));
  EXPECT_THROW(readDriverBridgeParams("ros_geomagic", params, 3.3), InputError);
  params = geomagicParams();
  params.set("stale_timeout", ParameterValue::of(-1.0));
  EXPECT_THROW(readDriverBridgeParams("ros_geomagic", params, 3.3), InputError);
  MapParameterSource none("/finger/");
  try
  {
    readDriverBridgeParams("crtk", none, 3.3);
    FAIL();
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(),
                 "parameter '/finger/driver_ns' is required by backend 'crtk' (the driver's namespace; "
                 "config/drivers/crtk.yaml sets its default)");
  }
  // Without ROS (no connect_driver) the registry refuses the backend, saying why.
  const MapParameterSource geomagic = geomagicParams();
  DeviceContext context(geomagic, 3.3);
  context.now = []() { return 0.0; };
  EXPECT_THROW(makeDevice(findDeviceBackend("ros_geomagic", "backend"), context), InputError);
}
}  // namespace
}  // namespace god_finger
