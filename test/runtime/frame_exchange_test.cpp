// A device whose servo frame reads and writes with room between (DeviceExchange::kFrame: the
// Omni/Touch's hdBeginFrame ... hdEndFrame) gets the force for a reading in the frame that read
// it, rendered at the read from the step before (runtime/servo_loop.h); a packet device gets
// it with the next exchange. On simulated time, on the paper's table and ball
// (urdf/scenes/table_sphere.urdf, the table's top at z = 0):
//  - through the Omni backend's seam (an HD API in memory): a reading 1 mm deeper into the table
//    is answered by a force 1 mm of coupling stiffer in its own frame;
//  - a packet device gets that force a period later;
//  - a hand crossing the air feels exactly nothing, every tick on time;
//  - a press on the ball settles to the packet device's force.
#include "god_finger/devices/fake_device.h"
#include "god_finger/devices/omni_device.h"
#include "god_finger/runtime/servo_loop.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace god_finger
{
namespace
{
const std::string kScene = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/table_sphere.urdf";

// An Omni in memory whose stylus the test moves; it records the force set in each frame.
struct MovedOmni : OmniIo
{
  OmniFrame stylus;
  std::vector<std::array<double, 3>> forces;  // Omni frame, one per servo frame; reserved: a tick allocates nothing
  MovedOmni()
  {
    forces.reserve(1 << 14);
  }
  bool open(const std::string&) override
  {
    return true;
  }
  OmniCalibration calibration() override
  {
    return OmniCalibration::ok;
  }
  bool updateCalibration() override
  {
    return true;
  }
  bool startServo() override
  {
    return true;
  }
  bool exchange(const std::array<double, 3>& force, OmniFrame* frame) override
  {
    forces.push_back(force);
    *frame = stylus;
    return true;
  }
  bool exchangeFrame(OmniFrameResponder& responder, OmniFrame* frame) override
  {
    forces.push_back(responder.forceFor(stylus));
    *frame = stylus;
    return true;
  }
  double nominalMaxForce() override
  {
    return 10.0;  // the test's forces pass unclamped
  }
  std::string lastError() override
  {
    return "";
  }
};

// The stylus at device position `p` (m): Omni millimetres (omni_device.h's axes, centre 0).
std::array<double, 3> omniMillimetres(const Eigen::Vector3d& p)
{
  return {-1000.0 * p.y(), 1000.0 * p.z(), -1000.0 * p.x()};
}

DeviceProfile profile()
{
  DeviceProfile profile;           // coupling 400 N/m, 4 N s/m
  profile.guard.soft_start = 0.0;  // the force as decided, from the first tick
  return profile;
}

std::unique_ptr<ServoLoop> makeLoop(std::unique_ptr<HapticDevice> device)
{
  std::vector<ServoInterface> interfaces(1);
  interfaces[0].name = "finger";
  interfaces[0].device = std::move(device);
  interfaces[0].profile = profile();
  ServoLoopParams params;
  params.simulated_time = true;
  params.real_time_factor = 0.0;
  auto loop = std::make_unique<ServoLoop>(std::make_unique<GodFingerWorld>(loadUrdfScene(kScene), WorldParams()),
                                          std::move(interfaces), params);
  loop->prepare();
  return loop;
}

std::vector<ServoSample> drain(ServoLoop& loop)
{
  std::vector<ServoSample> samples;
  ServoSample sample;
  while (loop.samples().tryPop(&sample))
  {
    samples.push_back(sample);
  }
  WorldSnapshot snapshot;
  while (loop.snapshots().tryPop(&snapshot))
  {
  }
  return samples;
}

// The hand over the table, away from the ball: down from 1 cm above the top to 2 mm into it in
// 0.2 s, held; at tick kStep it goes 1 mm deeper at once, and stays.
constexpr int kStep = 500;
Eigen::Vector3d handAt(int tick)
{
  const double t = tick * 1e-3;
  const double z = tick >= kStep ? -0.003 : (t < 0.2 ? 0.01 - 0.012 * t / 0.2 : -0.002);
  return Eigen::Vector3d(0.25, 0.0, z);
}

TEST(FrameExchange, AnOmniGetsTheForceForAReadingInTheFrameThatReadIt)
{
  auto io = std::make_unique<MovedOmni>();
  MovedOmni* omni = io.get();
  omni->stylus.position_mm = omniMillimetres(handAt(0));
  OmniParams params;
  params.max_force = 10.0;
  auto device = std::make_unique<OmniDevice>(
      std::move(io), params, [] { return 0.0; }, [] {});
  auto loop = makeLoop(std::move(device));
  omni->forces.clear();  // prepare()'s first reading
  for (int k = 0; k <= kStep + 5; ++k)
  {
    omni->stylus.position_mm = omniMillimetres(handAt(k));
    loop->tick(k * loop->period());
  }
  const std::vector<ServoSample> samples = drain(*loop);
  ASSERT_EQ(samples.size(), static_cast<std::size_t>(kStep + 6));
  ASSERT_EQ(omni->forces.size(), samples.size());
  const double k_c = profile().coupling.stiffness;
  // The force set in frame k is the one the loop applied at tick k (Omni axes: f_z = -device x,
  // f_y = device z), answering tick k's reading.
  for (std::size_t k = 1; k < samples.size(); ++k)
  {
    ASSERT_NEAR(omni->forces[k][1], samples[k].applied_force.z(), 1e-12) << "tick " << k;
    ASSERT_NEAR(omni->forces[k][2], -samples[k].applied_force.x(), 1e-12) << "tick " << k;
    ASSERT_EQ(samples[k].physics_lag, 1) << "tick " << k;  // the step before: on time for a frame
    ASSERT_FALSE(samples[k].stale) << "tick " << k;
  }
  EXPECT_EQ(loop->counters().stale_ticks.load(), 0);
  // Pressed into the table (the hand 2 mm under its top, the proxy on it, a fingertip's radius
  // above): the coupling's spring.
  const ServoSample& before = samples[kStep - 1];
  const auto spring = [k_c](const ServoSample& sample)
  { return k_c * (sample.proxy_position.z() - sample.interface_position.z()); };
  EXPECT_GT(before.proxy_position.z(), 0.0);
  EXPECT_NEAR(before.applied_force.z(), spring(before), 1e-6);
  // The frame that read 1 mm deeper set the stiffer force itself: 1 mm of spring more, and the
  // damping of that millimetre's velocity (1 m/s over the tick).
  const ServoSample& stepped = samples[kStep];
  const double damping = profile().coupling.damping;
  std::printf("[ measured ] the Omni's force: %.4f N at 2 mm, %.4f N in the frame that read 3 mm, %.4f N after\n",
              before.applied_force.z(), stepped.applied_force.z(), samples[kStep + 1].applied_force.z());
  EXPECT_NEAR(stepped.applied_force.z() - before.applied_force.z(), k_c * 0.001 + damping * 1.0, 0.02);
  EXPECT_NEAR(samples[kStep + 5].applied_force.z(), spring(samples[kStep + 5]), 1e-6);
  // 1 mm of spring more, less what the proxy sank under it (micrometres).
  EXPECT_NEAR(samples[kStep + 5].applied_force.z() - before.applied_force.z(), k_c * 0.001, 0.005);
}

// A hand exactly where the script puts it at each tick (handAt), of either exchange.
class PlacedHand : public HapticDevice
{
 public:
  explicit PlacedHand(DeviceExchange exchange) : exchange_(exchange) {}
  std::string name() const override
  {
    return "placed";
  }
  void start() override {}
  DeviceExchange exchangeForm() const override
  {
    return exchange_;
  }
  DeviceReading update(double time, const Eigen::Vector3d&) override
  {
    DeviceReading reading;
    reading.position = handAt(static_cast<int>(std::lround(time * 1e3)));
    return reading;
  }
  DeviceReading exchangeFrame(double time, FrameResponder& responder) override
  {
    const DeviceReading reading = update(time, Eigen::Vector3d::Zero());
    Eigen::Vector3d force;
    Eigen::Vector3d torque;
    responder.respond(reading, &force, &torque);
    return reading;
  }

 private:
  DeviceExchange exchange_;
};

TEST(FrameExchange, APacketDeviceGetsTheSameForceAPeriodLater)
{
  std::vector<ServoSample> runs[2];
  for (int frame = 0; frame < 2; ++frame)
  {
    auto loop = makeLoop(std::make_unique<PlacedHand>(frame ? DeviceExchange::kFrame : DeviceExchange::kPacket));
    for (int k = 0; k <= kStep + 5; ++k)
    {
      loop->tick(k * loop->period());
    }
    runs[frame] = drain(*loop);
    ASSERT_EQ(runs[frame].size(), static_cast<std::size_t>(kStep + 6));
  }
  const std::vector<ServoSample>& packet = runs[0];
  const std::vector<ServoSample>& frame = runs[1];
  // A packet device applies at tick k what was commanded for tick k - 1's reading; a frame
  // device what was commanded for tick k's.
  for (std::size_t k = 2; k < packet.size(); ++k)
  {
    ASSERT_NEAR((packet[k].applied_force - packet[k - 1].commanded_force).norm(), 0.0, 1e-12) << "tick " << k;
    ASSERT_NEAR((frame[k].applied_force - frame[k].commanded_force).norm(), 0.0, 1e-12) << "tick " << k;
  }
  const double deeper = profile().coupling.stiffness * 0.001;  // N: 1 mm of spring
  std::printf(
      "[ measured ] 1 mm deeper at tick %d: the applied force steps by %.4f N there (frame), by %.4f N "
      "there and %.4f N a tick later (packet)\n",
      kStep, frame[kStep].applied_force.z() - frame[kStep - 1].applied_force.z(),
      packet[kStep].applied_force.z() - packet[kStep - 1].applied_force.z(),
      packet[kStep + 1].applied_force.z() - packet[kStep].applied_force.z());
  EXPECT_GT(frame[kStep].applied_force.z() - frame[kStep - 1].applied_force.z(), deeper);
  EXPECT_LT(std::abs(packet[kStep].applied_force.z() - packet[kStep - 1].applied_force.z()), 0.01);
  EXPECT_GT(packet[kStep + 1].applied_force.z() - packet[kStep].applied_force.z(), deeper);
  // Held 3 mm deep, both settle on the same spring.
  EXPECT_NEAR(frame.back().applied_force.z(), packet.back().applied_force.z(), 0.01);
}

TEST(FrameExchange, AHandCrossingTheAirFeelsNothingAndSettlesOnTheBallAsAPacketDevice)
{
  // Across the air over the ball at 0.5 m/s, then down onto its top (z = 0.08) 5 mm past it.
  const WaypointPath path({{0.0, Eigen::Vector3d(0.2, 0.0, 0.15)},
                           {0.4, Eigen::Vector3d(0.0, 0.0, 0.15)},
                           {0.8, Eigen::Vector3d(0.0, 0.0, 0.075)}});
  double settled[2] = {0.0, 0.0};
  double largest_in_air[2] = {0.0, 0.0};
  for (int frame = 0; frame < 2; ++frame)
  {
    FakeDeviceParams hand;
    hand.exchange = frame ? DeviceExchange::kFrame : DeviceExchange::kPacket;
    auto device = std::make_unique<FakeDevice>(hand, path);
    device->setScriptStart(0.0);
    auto loop = makeLoop(std::move(device));
    std::vector<ServoSample> samples;
    for (int k = 0; k < 2000; ++k)
    {
      loop->tick(k * loop->period());
      for (const ServoSample& sample : drain(*loop))
      {
        samples.push_back(sample);
      }
    }
    for (int k = 1; k < 400; ++k)
    {
      largest_in_air[frame] = std::max(largest_in_air[frame], samples[k].applied_force.norm());
      if (frame)
      {
        ASSERT_EQ(samples[k].applied_force, Eigen::Vector3d::Zero()) << "tick " << k;
      }
    }
    settled[frame] = samples.back().applied_force.z();
    if (frame)
    {
      EXPECT_EQ(loop->counters().stale_ticks.load(), 0);
    }
  }
  std::printf(
      "[ measured ] crossing the air: largest force %.3g N (packet), %.3g N (frame); pressing the ball: %.4f N, "
      "%.4f N\n",
      largest_in_air[0], largest_in_air[1], settled[0], settled[1]);
  EXPECT_GT(settled[0], 1.0);  // it did press the ball
  EXPECT_NEAR(settled[1], settled[0], 0.01 * settled[0]);
}
}  // namespace
}  // namespace god_finger
