// The servo loop with a hand of N fingers (default 10) on real time: its period's p99 against
// the platform's floor, measured in the same run (an empty SCHED_FIFO thread's 1 ms wake-ups,
// as bench/wakeup_latency.cpp). The fingers are a pose source fed at 100 Hz by another thread
// (a tracker), each 5 mm into the table of table_sphere.urdf, far from the ball, so every
// finger's proxy is in contact each tick.
// usage: hand_loop_bench [FINGERS] [SECONDS]   prints one JSON line (periods in us; the target,
// bench/targets.yaml's hand.ten_fingers: p99_over_floor_us = period_us_p99 - floor_us_p99)
#include "platform_floor.h"

#include "god_finger/devices/hand_device.h"
#include "god_finger/devices/pose_source.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/runtime/servo_loop.h"
#include "god_finger/scene/urdf_scene.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

int main(int argc, char** argv)
{
  using namespace god_finger;
  const int fingers = argc > 1 ? std::atoi(argv[1]) : 10;
  const double seconds = argc > 2 ? std::atof(argv[2]) : 20.0;
  if (fingers < 1 || fingers > 10 || !(seconds > 0.0))
  {
    std::fprintf(stderr, "usage: hand_loop_bench [FINGERS 1..10] [SECONDS > 0]\n");
    return 2;
  }
  lockMemory();
  const std::vector<double> floor = floorPeriods(seconds);

  PoseSourceParams params;
  params.fingers.clear();
  for (int i = 0; i < fingers; ++i)
  {
    params.fingers.push_back("f" + std::to_string(i));
  }
  auto feed = std::make_shared<PoseFeed>(params.fingers.size());
  std::vector<FingerPose> poses(params.fingers.size());
  auto write = [&]()
  {
    for (int i = 0; i < fingers; ++i)
    {
      poses[i].position = Eigen::Vector3d(0.1 + 0.03 * (i % 5), 0.1 + 0.05 * (i / 5), -0.005);
      poses[i].stamp = steadySeconds();
    }
    feed->write(poses);
  };
  // No pose before the loop starts: the fingers start at the source's rest, above the table.
  std::unique_ptr<HapticDevice> hand = makeHandDevice(makePoseSource(params, feed, steadySeconds));
  std::vector<ServoInterface> interfaces;
  for (DeviceFinger& finger : hand->fingers())
  {
    ServoInterface interface;
    interface.name = "hand/" + finger.name;
    interface.device = std::move(finger.device);
    interfaces.push_back(std::move(interface));
  }
  ServoLoop loop(
      std::make_unique<GodFingerWorld>(
          loadUrdfScene(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/table_sphere.urdf"), WorldParams()),
      std::move(interfaces), ServoLoopParams());
  loop.start();
  std::atomic<bool> tracking{true};
  std::thread tracker(
      [&]()
      {
        double next = steadySeconds();
        while (tracking)
        {
          next += 0.01;
          sleepUntil(next);
          write();
        }
      });
  std::vector<double> periods;
  std::vector<double> steps;
  long untracked = 0;
  long samples = 0;
  const double end = steadySeconds() + seconds;
  ServoSample sample;
  while (steadySeconds() < end)
  {
    bool any = false;
    while (loop.samples().tryPop(&sample))
    {
      any = true;
      ++samples;
      untracked += sample.tracked ? 0 : 1;
      if (sample.interface == 0 && sample.tick > 0)
      {
        periods.push_back(sample.period_us);
        steps.push_back(sample.step_us);
      }
    }
    WorldSnapshot snapshot;
    while (loop.snapshots().tryPop(&snapshot))
    {
    }
    if (!any)
    {
      sleepFor(5e-4);
    }
  }
  loop.stop();
  tracking = false;
  tracker.join();
  const double floor_p99 = benchPercentile(floor, 0.99);
  const double period_p99 = benchPercentile(periods, 0.99);
  std::printf(
      "{\"fingers\": %d, \"seconds\": %.0f, \"realtime\": %s, \"ticks\": %zu, \"overruns\": %ld, "
      "\"untracked_samples\": %ld, \"floor_us_p50\": %.1f, \"floor_us_p99\": %.1f, \"period_us_p50\": %.1f, "
      "\"period_us_p99\": %.1f, \"period_us_max\": %.1f, \"step_us_p50\": %.1f, \"step_us_p99\": %.1f, "
      "\"p99_over_floor_us\": %.1f}\n",
      fingers, seconds, loop.counters().realtime ? "true" : "false", periods.size(), loop.counters().overruns.load(),
      untracked, benchPercentile(floor, 0.5), floor_p99, benchPercentile(periods, 0.5), period_p99,
      periods.empty() ? 0.0 : *std::max_element(periods.begin(), periods.end()), benchPercentile(steps, 0.5),
      benchPercentile(steps, 0.99), period_p99 - floor_p99);
  return 0;
}
