// The C++ side of test/python/test_world.py's parity check: a scene stepped for 2 s by a fixed
// script through GodFingerWorld, printed at full precision, so that the same calls from Python
// (god_finger.World) can be compared number for number.
//
//   god_finger_world_trace SCENE MODEL
//
// The script (the Python test repeats it): finger 0 starts at (-0.06, 0, 0.05) and its target
// moves along +x at 0.05 m/s; finger 1, oriented, starts at (0.2, 0.2, 0.012) with the identity
// orientation, its target sinking at 0.008 m/s and rolling about x at 0.3 rad/s. 2000 steps of
// 1 ms. Every 100 steps one line: the step, then per body its pose (4x4, row-major) and linear
// velocity, then per finger its proxy position, force and contact count; numbers as %.17g.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/scene_file.h"

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv)
{
  using namespace god_finger;
  if (argc != 3)
  {
    std::fprintf(stderr, "usage: god_finger_world_trace SCENE MODEL\n");
    return 2;
  }
  try
  {
    WorldParams params;
    if (!parseContactModel(argv[2], &params.model))
    {
      std::fprintf(stderr, "unknown model %s\n", argv[2]);
      return 2;
    }
    GodFingerWorld world(loadScene(argv[1]), params);
    const Eigen::Vector3d start0(-0.06, 0.0, 0.05);
    const Eigen::Vector3d velocity0(0.05, 0.0, 0.0);
    const Eigen::Vector3d start1(0.2, 0.2, 0.012);
    const Eigen::Vector3d velocity1(0.0, 0.0, -0.008);
    world.addInterface(start0, params.coupling);
    world.addInterface(start1, params.coupling);
    world.setInterfaceTarget(1, start1, Eigen::Quaterniond::Identity());
    auto print = [](double value) { std::printf(" %.17g", value); };
    for (int i = 0; i < 2000; ++i)
    {
      const double t = (i + 1) * 0.001;
      world.setInterfaceTarget(0, start0 + velocity0 * t);
      const Eigen::Quaterniond roll(Eigen::AngleAxisd(0.3 * t, Eigen::Vector3d::UnitX()));
      world.setInterfaceTarget(1, start1 + velocity1 * t, roll);
      world.step();
      if ((i + 1) % 100 != 0)
      {
        continue;
      }
      std::printf("%d", i + 1);
      for (int b = 0; b < world.bodyCount(); ++b)
      {
        const BodyState state = world.bodyState(b);
        for (int r = 0; r < 4; ++r)
        {
          for (int c = 0; c < 4; ++c)
          {
            print(state.pose.matrix()(r, c));
          }
        }
        for (int k = 0; k < 3; ++k)
        {
          print(state.linear_velocity[k]);
        }
      }
      for (int f = 0; f < world.interfaceCount(); ++f)
      {
        const InterfaceState& state = world.interfaceState(f);
        for (int k = 0; k < 3; ++k)
        {
          print(state.proxy_position[k]);
        }
        for (int k = 0; k < 3; ++k)
        {
          print(state.user_force[k]);
        }
        print(state.contact_count);
      }
      std::printf("\n");
    }
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "god_finger_world_trace: %s\n", error.what());
    return 2;
  }
  return 0;
}
