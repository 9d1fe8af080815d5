// The servo loop on real time pressing a soft block (issue 28, "1 kHz for the hand, whatever the
// mesh"): its device period against the platform's floor, measured in the same run (an empty
// SCHED_FIFO thread's 1 ms wake-ups, as bench/hand_loop_bench.cpp), its device-to-force latency
// and the physics step, with the soft block meshed by about NODES nodes. The block: 10 cm, E 50
// kPa, nu 0.45, 1 kg, glued to the table (soft/block_mesh.h, grading 3, written as a
// <deformable> URDF scene in a temporary folder). The hand: the fake device (fake profile, 400
// N/m), down onto the top's centre in 0.5 s to 1.2 cm past it, then wavering 3 mm up and down
// at 2 Hz, so the block never sleeps. A step slower than the period makes the physics late; the
// multi-rate loop renders the force meanwhile (runtime/multirate_render.h: stale ticks).
// EXCHANGE: the fake device's (devices/haptic_device.h DeviceExchange): packet (a Falcon's: the
// force for a reading goes with the next exchange, decided at the next tick's start) or frame
// (an Omni/Touch's: the force for a reading rendered at the read and applied in its frame).
// usage: soft_loop_bench [NODES] [SECONDS] [packet|frame]   prints one JSON line (periods and
// latencies in us; the targets, at every size: bench/targets.yaml's soft.loop_period on
// p99_over_floor_us = period_us_p99 - floor_us_p99, soft.loop_latency_* on latency_us_p99)
#include "platform_floor.h"

#include "god_finger/devices/fake_device.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/runtime/servo_loop.h"
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/soft/block_mesh.h"
#include "god_finger/soft/vtk_tet_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
// The soft block's scene (a table and the block) written into `folder`; returns its path.
std::string writeScene(const std::string& folder, int nodes, std::size_t* written_nodes)
{
  god_finger::BlockMeshSpec spec;
  const int cells = god_finger::cubeCellsForNodes(nodes);
  spec.cells = {cells, cells, cells};
  spec.grading = 3.0;
  const god_finger::TetMesh mesh = god_finger::blockTetMesh(spec);
  *written_nodes = mesh.nodes.size();
  std::ofstream(folder + "/block.vtk") << god_finger::vtkTetMeshText(mesh, "soft_loop_bench block");
  std::ofstream(folder + "/scene.urdf")
      << "<robot name=\"soft_loop_bench\"><link name=\"world\"/>\n"
         "<link name=\"table\"><collision><geometry><box size=\"1 1 0.04\"/></geometry></collision></link>\n"
         "<joint name=\"j\" type=\"fixed\"><parent link=\"world\"/><child link=\"table\"/>"
         "<origin xyz=\"0 0 -0.02\"/></joint>\n"
         "<deformable name=\"block\"><inertial><mass value=\"1\"/></inertial><friction value=\"0.8\"/>"
         "<neohookean mu=\"17241.379310344826\" lambda=\"155172.41379310345\" damping=\"0.01\"/>"
         "<collision filename=\"block.vtk\"/></deformable>\n</robot>\n";
  return folder + "/scene.urdf";
}
}  // namespace

int main(int argc, char** argv)
{
  using namespace god_finger;
  const int nodes = argc > 1 ? std::atoi(argv[1]) : 1000;
  const double seconds = argc > 2 ? std::atof(argv[2]) : 10.0;
  FakeDeviceParams hand;
  if (nodes < 8 || nodes > 100000 || !(seconds > 1.0) || (argc > 3 && !parseDeviceExchange(argv[3], &hand.exchange)))
  {
    std::fprintf(stderr, "usage: soft_loop_bench [NODES 8..100000] [SECONDS > 1] [packet|frame]\n");
    return 2;
  }
  std::string pattern = (std::filesystem::temp_directory_path() / "soft_loop_bench_XXXXXX").string();
  const std::string folder = mkdtemp(pattern.data());
  std::size_t written_nodes = 0;
  const std::string scene = writeScene(folder, nodes, &written_nodes);
  const double build_start = steadySeconds();
  auto world = std::make_unique<GodFingerWorld>(loadUrdfScene(scene), WorldParams());
  const double build_s = steadySeconds() - build_start;
  std::filesystem::remove_all(folder);

  lockMemory();
  const std::vector<double> floor = floorPeriods(seconds);

  // Down in 0.5 s to 1.2 cm past the top, then wavering +-3 mm at 2 Hz (waypoints every 50 ms).
  std::vector<Waypoint> path{{0.0, Eigen::Vector3d(0, 0, 0.13)}, {0.5, Eigen::Vector3d(0, 0, 0.088)}};
  for (double t = 0.55; t < seconds + 2.0; t += 0.05)
  {
    path.push_back({t, Eigen::Vector3d(0, 0, 0.088 + 0.003 * std::sin(2.0 * M_PI * 2.0 * (t - 0.5)))});
  }
  std::vector<ServoInterface> interfaces(1);
  interfaces[0].name = "finger";
  interfaces[0].device = std::make_unique<FakeDevice>(hand, WaypointPath(path));
  ServoLoop loop(std::move(world), std::move(interfaces), ServoLoopParams());
  loop.start();
  std::vector<double> periods;
  std::vector<double> latencies;
  std::vector<double> steps;
  long stale = 0;
  long samples = 0;
  double largest_force = 0.0;
  const double begin = steadySeconds();
  const double end = begin + seconds;
  ServoSample sample;
  WorldSnapshot snapshot;
  while (steadySeconds() < end)
  {
    bool any = false;
    while (loop.samples().tryPop(&sample))
    {
      any = true;
      if (sample.tick == 0)
      {
        continue;
      }
      ++samples;
      periods.push_back(sample.period_us);
      latencies.push_back(sample.latency_us);
      steps.push_back(sample.step_us);
      stale += sample.stale ? 1 : 0;
      largest_force = std::max(largest_force, sample.applied_force.norm());
    }
    while (loop.snapshots().tryPop(&snapshot))
    {
    }
    if (!any)
    {
      sleepFor(5e-4);
    }
  }
  const long physics_steps = loop.counters().physics_steps.load();
  loop.stop();
  const double floor_p99 = benchPercentile(floor, 0.99);
  const double period_p99 = benchPercentile(periods, 0.99);
  std::printf(
      "{\"nodes\": %zu, \"exchange\": \"%s\", \"seconds\": %.0f, \"realtime\": %s, \"build_s\": %.2f, \"ticks\": %ld, "
      "\"overruns\": %ld, "
      "\"stale_ticks\": %ld, \"physics_steps_per_s\": %.1f, \"largest_force_N\": %.2f, \"floor_us_p50\": %.1f, "
      "\"floor_us_p99\": %.1f, \"period_us_p50\": %.1f, \"period_us_p99\": %.1f, \"period_us_max\": %.1f, "
      "\"latency_us_p50\": %.1f, \"latency_us_p99\": %.1f, \"step_us_p50\": %.1f, \"step_us_p99\": %.1f, "
      "\"p99_over_floor_us\": %.1f}\n",
      written_nodes, deviceExchangeName(hand.exchange).c_str(), seconds, loop.counters().realtime ? "true" : "false",
      build_s, samples, loop.counters().overruns.load(), stale, physics_steps / seconds, largest_force,
      benchPercentile(floor, 0.5), floor_p99, benchPercentile(periods, 0.5), period_p99,
      periods.empty() ? 0.0 : *std::max_element(periods.begin(), periods.end()), benchPercentile(latencies, 0.5),
      benchPercentile(latencies, 0.99), benchPercentile(steps, 0.5), benchPercentile(steps, 0.99),
      period_p99 - floor_p99);
  return 0;
}
