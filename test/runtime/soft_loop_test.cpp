// The servo loop on a soft body (urdf/scenes/soft_block.urdf, issue 28: "1 kHz for the hand,
// whatever the mesh"): through the deterministic stall seam (ServoLoopParams::physics_delay,
// simulated time) every soft step takes 4 haptic periods (a mesh 4 times too costly for 1 kHz);
// the hand still gets a force every period, and what a stiff press and a fast tap give the
// device is measured against the same run on time. Passivity: over a whole press (the handle
// starts and ends at rest in the air), the device receives no energy from the block, on time or
// slow, and so for a device that takes the force for a reading in the frame that read it (an
// Omni/Touch: DeviceExchange::kFrame, rendered at the read from the step before).
//
// Energy convention (multirate_test.cpp's): E = sum over ticks k of F_k . (x_{k+1} - x_k), F_k
// the force applied at tick k's update, x_k the position read there; positive: into the hand.
#include "god_finger/devices/fake_device.h"
#include "god_finger/runtime/servo_loop.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace god_finger
{
namespace
{
const std::string kScene = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/soft_block.urdf";
constexpr double kDt = 1e-3;
constexpr double kTop = 0.1;  // m: the block's top before it settles

DeviceProfile falcon()
{
  DeviceProfile profile;
  profile.coupling.stiffness = 800.0;  // config/devices/falcon.yaml's coupling: the stiffest shipped
  profile.coupling.damping = 2.0;
  profile.coupling.max_force = 8.9;
  profile.guard.soft_start = 0.0;  // a time-varying gain would give energy on time or not (multirate_test)
  return profile;
}

struct PressRun
{
  double energy = 0.0;           // J into the device over the whole run
  double largest_force = 0.0;    // N
  long ticks_without_force = 0;  // ticks whose sample says no force was decided (never, with the multi-rate loop)
  long stale_ticks = 0;
  double deepest_sink = 0.0;              // m, the block's surface
  std::vector<double> force_z;            // N, by tick: the applied force's z
  std::vector<double> handle_z;           // m, by tick
  std::vector<double> contact_stiffness;  // N/m, by tick: the world's, after the tick
};

// `path`: the hand's script (world = device frame). `delay`: haptic periods each soft step takes.
// `exchange`: the device's (haptic_device.h).
PressRun press(const WaypointPath& path, int delay, int ticks, DeviceExchange exchange = DeviceExchange::kPacket)
{
  FakeDeviceParams hand;
  hand.exchange = exchange;
  auto device = std::make_unique<FakeDevice>(hand, path);
  device->setScriptStart(0.0);
  std::vector<ServoInterface> interfaces(1);
  interfaces[0].name = "finger";
  interfaces[0].device = std::move(device);
  interfaces[0].profile = falcon();
  ServoLoopParams params;
  params.simulated_time = true;
  params.real_time_factor = 0.0;
  params.physics_delay = [delay](long) { return delay; };
  ServoLoop loop(std::make_unique<GodFingerWorld>(loadUrdfScene(kScene), WorldParams()), std::move(interfaces), params);
  loop.prepare();
  std::vector<ServoSample> samples;
  ServoSample sample;
  WorldSnapshot snapshot;
  PressRun run;
  for (int k = 0; k < ticks; ++k)
  {
    loop.tick(k * kDt);
    while (loop.samples().tryPop(&sample))
    {
      samples.push_back(sample);
      run.force_z.push_back(sample.applied_force.z());
      run.handle_z.push_back(sample.reading.position.z());
    }
    run.contact_stiffness.push_back(loop.world().interfaceState(0).contact_stiffness);
    while (loop.snapshots().tryPop(&snapshot))
    {
      for (const SoftSurfaceState& surface : snapshot.soft_surfaces)
      {
        for (const float sink : surface.sink)
        {
          run.deepest_sink = std::max(run.deepest_sink, double(sink));
        }
      }
    }
  }
  EXPECT_EQ(static_cast<int>(samples.size()), ticks);
  for (std::size_t k = 0; k + 1 < samples.size(); ++k)
  {
    run.energy += samples[k].applied_force.dot(samples[k + 1].reading.position - samples[k].reading.position);
    run.largest_force = std::max(run.largest_force, samples[k].applied_force.norm());
    run.ticks_without_force += samples[k].applied_force.allFinite() ? 0 : 1;
  }
  run.stale_ticks = loop.counters().stale_ticks.load();
  return run;
}

void expectPassive(const char* what, const WaypointPath& path, int ticks)
{
  const PressRun on_time = press(path, 0, ticks);
  const PressRun slow = press(path, 3, ticks);
  std::printf(
      "[ measured ] %s: energy to the device on time %.3g J (largest force %.2f N, dimple %.2f mm); soft steps "
      "4 periods long %.3g J (%.2f N, %.2f mm, %ld stale ticks)\n",
      what, on_time.energy, on_time.largest_force, 1e3 * on_time.deepest_sink, slow.energy, slow.largest_force,
      1e3 * slow.deepest_sink, slow.stale_ticks);
  EXPECT_GT(on_time.deepest_sink, 1e-3) << what;  // it pressed the block, not the air
  EXPECT_GT(slow.deepest_sink, 1e-3) << what;
  EXPECT_GT(slow.stale_ticks, 0) << what;  // the slow run did render between steps
  EXPECT_EQ(slow.ticks_without_force, 0) << what;
  EXPECT_LE(on_time.energy, 0.0) << what;
  EXPECT_LE(slow.energy, 0.0) << what;
  // A frame device: every tick rendered at the read from the step before (on time: not stale).
  const PressRun frame = press(path, 0, ticks, DeviceExchange::kFrame);
  const PressRun frame_slow = press(path, 3, ticks, DeviceExchange::kFrame);
  std::printf(
      "[ measured ] %s, a frame device: energy to the device on time %.3g J (largest force %.2f N, dimple %.2f "
      "mm, %ld stale ticks); soft steps 4 periods long %.3g J (%.2f N, %.2f mm)\n",
      what, frame.energy, frame.largest_force, 1e3 * frame.deepest_sink, frame.stale_ticks, frame_slow.energy,
      frame_slow.largest_force, 1e3 * frame_slow.deepest_sink);
  EXPECT_GT(frame.deepest_sink, 1e-3) << what;
  EXPECT_EQ(frame.stale_ticks, 0) << what;
  EXPECT_GT(frame_slow.stale_ticks, 0) << what;
  EXPECT_EQ(frame_slow.ticks_without_force, 0) << what;
  EXPECT_LE(frame.energy, 0.0) << what;
  EXPECT_LE(frame_slow.energy, 0.0) << what;
}

TEST(SoftLoop, AStiffPressGivesTheHandNoEnergyOnTimeOrWithSlowSoftSteps)
{
  // Down from 2 cm above the top to 1.5 cm past it in 0.1 s, held 0.4 s, back up in 0.1 s, at
  // rest in the air until 1 s.
  const WaypointPath path({{0.0, Eigen::Vector3d(0, 0, kTop + 0.02)},
                           {0.1, Eigen::Vector3d(0, 0, kTop - 0.015)},
                           {0.5, Eigen::Vector3d(0, 0, kTop - 0.015)},
                           {0.6, Eigen::Vector3d(0, 0, kTop + 0.02)}});
  expectPassive("stiff press", path, 1000);
}

TEST(SoftLoop, AFastTapGivesTheHandNoEnergyOnTimeOrWithSlowSoftSteps)
{
  // From 1 cm above the top to 1 cm past it and back in 40 ms (0.5 m/s), then at rest in the air.
  const WaypointPath path({{0.0, Eigen::Vector3d(0, 0, kTop + 0.01)},
                           {0.1, Eigen::Vector3d(0, 0, kTop + 0.01)},
                           {0.12, Eigen::Vector3d(0, 0, kTop - 0.01)},
                           {0.14, Eigen::Vector3d(0, 0, kTop + 0.01)}});
  expectPassive("fast tap", path, 600);
}
}  // namespace
}  // namespace god_finger
