// The Omni / Touch backend through its seam (no device, no OpenHaptics): axes and units to
// REP-103, force clamping to the profile and the device, calibration, device faults.
#include "god_finger/devices/omni_device.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace god_finger
{
namespace
{
// An Omni in memory: counts calls, fails on demand.
struct ScriptedOmni : OmniIo
{
  bool opens = true;
  std::string opened_name = "<not opened>";
  OmniCalibration state = OmniCalibration::ok;
  int calibration_checks = 0;
  int inkwell_after_checks = 0;  // with needs_manual_input: checks before the stylus is in the inkwell
  bool update_works = true;
  int updates = 0;
  bool servo_starts = true;
  bool servo_running = false;
  bool frames_ok = true;
  double nominal_max_force = 3.3;
  OmniFrame stylus;
  std::array<double, 3> force{0.0, 0.0, 0.0};
  int frames = 0;  // exchangeFrame() calls

  bool open(const std::string& name) override
  {
    opened_name = name;
    return opens;
  }
  OmniCalibration calibration() override
  {
    ++calibration_checks;
    if (state == OmniCalibration::needs_manual_input && calibration_checks > inkwell_after_checks)
    {
      state = OmniCalibration::ok;
    }
    return state;
  }
  bool updateCalibration() override
  {
    ++updates;
    if (update_works)
    {
      state = OmniCalibration::ok;
    }
    return update_works;
  }
  bool startServo() override
  {
    servo_running = servo_starts;
    return servo_starts;
  }
  bool exchange(const std::array<double, 3>& f, OmniFrame* frame) override
  {
    force = f;
    if (!frames_ok)
    {
      return false;
    }
    *frame = stylus;
    return true;
  }
  // A frame that answers its own reading: fails before reading when frames_ok is false.
  bool exchangeFrame(OmniFrameResponder& responder, OmniFrame* frame) override
  {
    ++frames;
    if (!frames_ok)
    {
      return false;
    }
    force = responder.forceFor(stylus);
    *frame = stylus;
    return true;
  }
  double nominalMaxForce() override
  {
    return nominal_max_force;
  }
  std::string lastError() override
  {
    return "HD_DEVICE_FAULT (scripted)";
  }
};

struct Fixture
{
  ScriptedOmni* io = new ScriptedOmni;
  double clock = 0.0;
  std::unique_ptr<OmniDevice> device;
  explicit Fixture(OmniParams params = OmniParams())
  {
    device = std::make_unique<OmniDevice>(
        std::unique_ptr<OmniIo>(io), params, [this] { return clock; }, [this] { clock += 0.01; });
  }
};

std::string startError(Fixture& f)
{
  try
  {
    f.device->start();
  }
  catch (const DeviceError& error)
  {
    return error.what();
  }
  return "<no error>";
}

TEST(OmniDevice, AxesAndUnitsFollowRep103)
{
  OmniParams params;
  params.center_mm = {0.0, -10.0, 20.0};
  Fixture f(params);
  f.device->start();
  EXPECT_TRUE(f.io->servo_running);
  // Stylus 30 mm towards the user's right (x+), 40 mm up from the centre (y+), 50 mm away from
  // the user (z smaller).
  f.io->stylus.position_mm = {30.0, 30.0, -30.0};
  f.io->stylus.buttons = 2;
  const DeviceReading reading = f.device->update(1.0, Eigen::Vector3d::Zero());
  EXPECT_LT((reading.position - Eigen::Vector3d(0.05, -0.03, 0.04)).norm(), 1e-15);
  EXPECT_EQ(reading.buttons, 2u);
  // A force away from the user and up: Omni -z and +y.
  f.device->update(1.001, Eigen::Vector3d(2.0, 0.0, 1.0));
  EXPECT_EQ(f.io->force, (std::array<double, 3>{-0.0, 1.0, -2.0}));
  // Velocity from successive frames: 1 mm towards the user in 1 ms is -1 m/s along device x.
  f.io->stylus.position_mm = {30.0, 30.0, -29.0};
  const DeviceReading moved = f.device->update(1.002, Eigen::Vector3d::Zero());
  EXPECT_NEAR(moved.velocity.x(), -1.0, 1e-9);
  // The rotation is proper: a force along the motion does the same work in both frames.
  const Eigen::Vector3d step(0.001, 0.002, -0.001);
  const Eigen::Vector3d force(1.0, -2.0, 0.5);
  const std::array<double, 3> omni_force = deviceForceToVendorAxes(force);
  const std::array<double, 3> omni_step{-step.y(), step.z(), -step.x()};
  EXPECT_NEAR(omni_force[0] * omni_step[0] + omni_force[1] * omni_step[1] + omni_force[2] * omni_step[2],
              force.dot(step), 1e-15);
}

// The stylus rotation (HD_CURRENT_TRANSFORM) to the finger frame in the device frame: at the home
// pose pulp down pointing away from the user; the pen rolled about its own axis rolls the finger
// about device x by the same angle; a pen turned left (about Omni y) turns the finger about
// device z. No rotation read: no orientation (a 3-DOF finger).
TEST(OmniDevice, TheStylusRotationGivesTheFingersOrientation)
{
  Fixture f;
  f.device->start();
  EXPECT_FALSE(f.device->update(1.0, Eigen::Vector3d::Zero()).has_orientation);
  f.io->stylus.has_rotation = true;
  const auto read = [&f](const Eigen::Matrix3d& stylus)
  {
    std::copy(stylus.data(), stylus.data() + 9, f.io->stylus.rotation.begin());
    const DeviceReading reading = f.device->update(1.0, Eigen::Vector3d::Zero());
    EXPECT_TRUE(reading.has_orientation);
    return reading.orientation;
  };
  const Eigen::Quaterniond home = read(Eigen::Matrix3d::Identity());
  const Eigen::Quaterniond pulp_down(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));
  EXPECT_LT(home.angularDistance(pulp_down), 1e-12);
  // Rolled 0.4 rad about the pen's axis (Omni z, device -x): the finger rolls about device x.
  const Eigen::Quaterniond rolled = read(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix());
  const Eigen::AngleAxisd roll(rolled * home.inverse());
  EXPECT_NEAR(roll.angle(), 0.4, 1e-12);
  EXPECT_NEAR(std::abs(roll.axis().x()), 1.0, 1e-12);
  // Turned 0.3 rad about Omni y (up): about device z (up), the same sense.
  const Eigen::Quaterniond turned = read(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix());
  const Eigen::AngleAxisd turn(turned * home.inverse());
  EXPECT_NEAR(turn.angle(), 0.3, 1e-12);
  EXPECT_NEAR(turn.axis().z(), 1.0, 1e-12);
  // The finger's x (towards the tip) then points 0.3 rad to the user's left of forward.
  const Eigen::Vector3d tip = turned * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(std::atan2(tip.y(), tip.x()), 0.3, 1e-12);
  // A non-finite rotation gives a non-finite orientation, which the servo loop refuses.
  Eigen::Matrix3d broken = Eigen::Matrix3d::Identity();
  broken(0, 0) = NAN;
  EXPECT_FALSE(read(broken).coeffs().allFinite());
}

TEST(OmniDevice, ForceIsClampedToTheProfileAndTheDeviceAndNaNSentAsZero)
{
  OmniParams params;
  params.max_force = 3.3;
  Fixture profile_bound(params);
  profile_bound.device->start();
  profile_bound.device->update(1.0, Eigen::Vector3d(0.0, 0.0, 30.0));
  EXPECT_NEAR(profile_bound.io->force[1], 3.3, 1e-12);
  profile_bound.device->update(1.001, Eigen::Vector3d(NAN, 0.0, 1.0));
  EXPECT_EQ(profile_bound.io->force, (std::array<double, 3>{0.0, 0.0, 0.0}));
  profile_bound.device->update(1.002, Eigen::Vector3d(INFINITY, 0.0, 1.0));
  EXPECT_EQ(profile_bound.io->force, (std::array<double, 3>{0.0, 0.0, 0.0}));

  // A Touch reports a lower nominal maximum than the profile: the lower one wins.
  Fixture device_bound(params);
  device_bound.io->nominal_max_force = 0.88;
  device_bound.device->start();
  EXPECT_DOUBLE_EQ(device_bound.device->forceLimit(), 0.88);
  device_bound.device->update(1.0, Eigen::Vector3d(3.0, 4.0, 0.0));
  const auto& sent = device_bound.io->force;
  EXPECT_NEAR(std::sqrt(sent[0] * sent[0] + sent[1] * sent[1] + sent[2] * sent[2]), 0.88, 1e-12);
  EXPECT_NEAR(sent[0] / sent[2], 4.0 / 3.0, 1e-12);  // direction kept: (-f_y)/(-f_x)
}

// A responder that answers a reading with a spring to the device frame's origin (400 N/m) and
// records what it was given.
struct SpringResponder : FrameResponder
{
  std::vector<DeviceReading> readings;
  void respond(const DeviceReading& reading, Eigen::Vector3d* force, Eigen::Vector3d* torque) override
  {
    readings.push_back(reading);
    *force = -400.0 * reading.position;
    torque->setZero();
  }
};

TEST(OmniDevice, AFrameAnswersItsOwnReadingWithTheForceClamped)
{
  OmniParams params;
  params.max_force = 3.3;
  Fixture f(params);
  f.device->start();
  EXPECT_EQ(f.device->exchangeForm(), DeviceExchange::kFrame);
  SpringResponder responder;
  // 5 mm away from the user (Omni z -5): device x = 0.005; the spring pulls back 2 N, Omni +z.
  f.io->stylus.position_mm = {0.0, 0.0, -5.0};
  const DeviceReading reading = f.device->exchangeFrame(1.0, responder);
  ASSERT_EQ(responder.readings.size(), 1u);
  EXPECT_EQ(f.io->frames, 1);
  EXPECT_NEAR(reading.position.x(), 0.005, 1e-15);
  EXPECT_EQ(responder.readings[0].position, reading.position);  // answered in the frame that read it
  EXPECT_NEAR(f.io->force[2], 2.0, 1e-12);
  EXPECT_NEAR(f.io->force[0], 0.0, 1e-15);
  EXPECT_NEAR(f.io->force[1], 0.0, 1e-15);
  // 10 mm: 4 N asked, clamped to the profile's 3.3 N.
  f.io->stylus.position_mm = {0.0, 0.0, -10.0};
  f.device->exchangeFrame(1.001, responder);
  EXPECT_NEAR(f.io->force[2], 3.3, 1e-12);
  // A velocity from consecutive frames, as update() estimates it.
  EXPECT_GT(responder.readings[1].velocity.x(), 0.0);
}

TEST(OmniDevice, AFailedFrameStillGetsItsTicksDecisionOnTheLastGoodPoseThenAnError)
{
  OmniParams params;
  params.io_failures_allowed = 3;
  Fixture f(params);
  f.device->start();
  SpringResponder responder;
  f.io->stylus.position_mm = {10.0, 0.0, 0.0};
  f.device->exchangeFrame(1.0, responder);
  f.io->frames_ok = false;
  f.io->stylus.position_mm = {50.0, 0.0, 0.0};  // not read: the frames fail before reading
  for (int i = 1; i <= 3; ++i)
  {
    const DeviceReading held = f.device->exchangeFrame(1.0 + i * 1e-3, responder);
    EXPECT_NEAR(held.position.y(), -0.01, 1e-15);  // the last good frame
  }
  EXPECT_EQ(responder.readings.size(), 4u);  // once per exchange, failed or not
  EXPECT_NEAR(responder.readings.back().position.y(), -0.01, 1e-15);
  try
  {
    f.device->exchangeFrame(1.004, responder);
    FAIL() << "no error";
  }
  catch (const DeviceError& error)
  {
    EXPECT_NE(std::string(error.what()).find("4 failed servo frames in a row"), std::string::npos) << error.what();
  }
}

TEST(OmniDevice, CalibrationUpdatesByItselfOrWaitsForTheInkwell)
{
  Fixture automatic;
  automatic.io->state = OmniCalibration::needs_update;
  automatic.device->start();
  EXPECT_EQ(automatic.io->updates, 1);
  EXPECT_EQ(automatic.clock, 0.0);

  Fixture inkwell;
  inkwell.io->state = OmniCalibration::needs_manual_input;
  inkwell.io->inkwell_after_checks = 50;
  inkwell.device->start();
  EXPECT_NEAR(inkwell.clock, 0.5, 1e-9);  // waited 50 x 10 ms for the user
  EXPECT_TRUE(inkwell.io->servo_running);

  OmniParams params;
  params.calibration_timeout = 2.0;
  Fixture never(params);
  never.io->state = OmniCalibration::needs_manual_input;
  never.io->inkwell_after_checks = 1000000;
  EXPECT_NE(startError(never).find("not calibrated within 2 s: put the stylus in the inkwell"), std::string::npos)
      << startError(never);
  EXPECT_FALSE(never.io->servo_running);

  Fixture broken;
  broken.io->state = OmniCalibration::needs_update;
  broken.io->update_works = false;
  EXPECT_NE(startError(broken).find("calibration update failed (HD_DEVICE_FAULT"), std::string::npos);
}

TEST(OmniDevice, MissingDeviceOrDeadMotorsSayWhatToCheck)
{
  OmniParams params;
  params.device_name = "Left Omni";
  Fixture missing(params);
  missing.io->opens = false;
  const std::string error = startError(missing);
  EXPECT_EQ(missing.io->opened_name, "Left Omni");
  EXPECT_NE(error.find("cannot open 'Left Omni' (HD_DEVICE_FAULT (scripted)): is the Touch / Phantom driver installed"),
            std::string::npos)
      << error;

  Fixture no_servo;
  no_servo.io->servo_starts = false;
  EXPECT_NE(startError(no_servo).find("cannot start the servo loop"), std::string::npos);
}

TEST(OmniDevice, FaultsAreToleratedBrieflyHoldingTheLastPoseThenAnError)
{
  OmniParams params;
  params.io_failures_allowed = 5;
  Fixture f(params);
  f.device->start();
  f.io->stylus.position_mm = {10.0, 0.0, 0.0};
  f.device->update(1.0, Eigen::Vector3d::Zero());
  f.io->frames_ok = false;
  for (int i = 1; i <= 5; ++i)
  {
    const DeviceReading held = f.device->update(1.0 + i * 1e-3, Eigen::Vector3d::Zero());
    EXPECT_NEAR(held.position.y(), -0.01, 1e-15);  // the last good frame, not zeros
  }
  try
  {
    f.device->update(1.006, Eigen::Vector3d::Zero());
    FAIL() << "no error";
  }
  catch (const DeviceError& error)
  {
    EXPECT_NE(std::string(error.what()).find("6 failed servo frames in a row"), std::string::npos) << error.what();
  }
}
}  // namespace
}  // namespace god_finger
