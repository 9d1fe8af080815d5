// The C++ side of the Python module's overhead (bench/python_overhead.py runs both sides,
// interleaved, and scripts/bench_report shows them): the same two workloads the Python side runs
// through god_finger.World, timed here through GodFingerWorld.
//
//   python_overhead SCENE step_block|loop STEPS
//
// step_block: a finger behind the slide scene's ball (table_sphere.urdf), its target 4 cm ahead,
// then STEPS steps in one call each (the Python side: one step(STEPS)). loop: each step sets the
// target (moving at 5 cm/s), steps once and reads the finger's state (the Python side: set_target,
// step, finger per step). Prints one JSON line: {"workload", "steps", "us_per_step", "checksum"}:
// the finger's last force and position along x, which the Python side must match exactly.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/scene_file.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv)
{
  using namespace god_finger;
  if (argc != 4)
  {
    std::fprintf(stderr, "usage: python_overhead SCENE step_block|loop STEPS\n");
    return 2;
  }
  try
  {
    const std::string workload = argv[2];
    const long steps = std::stol(argv[3]);
    GodFingerWorld world(loadScene(argv[1]), WorldParams());
    const Eigen::Vector3d start(-0.06, 0.0, 0.0525);
    const int finger = world.addInterface(start);
    double checksum = 0.0;
    const auto begin = std::chrono::steady_clock::now();
    if (workload == "step_block")
    {
      world.setInterfaceTarget(finger, start + Eigen::Vector3d(0.04, 0.0, 0.0));
      for (long i = 0; i < steps; ++i)
      {
        world.step();
      }
      checksum = world.interfaceState(finger).user_force.x() + world.interfaceState(finger).proxy_position.x();
    }
    else if (workload == "loop")
    {
      const InterfaceState* state = nullptr;
      for (long i = 0; i < steps; ++i)
      {
        world.setInterfaceTarget(finger, Eigen::Vector3d(start.x() + 0.05 * ((i + 1) * 0.001), 0.0, start.z()));
        world.step();
        state = &world.interfaceState(finger);
      }
      checksum = state->user_force.x() + state->proxy_position.x();
    }
    else
    {
      std::fprintf(stderr, "python_overhead: unknown workload %s\n", argv[2]);
      return 2;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    std::printf("{\"workload\": \"%s\", \"steps\": %ld, \"us_per_step\": %.4f, \"checksum\": %.17g}\n", argv[2], steps,
                1e6 * seconds / static_cast<double>(steps), checksum);
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "python_overhead: %s\n", error.what());
    return 2;
  }
  return 0;
}
