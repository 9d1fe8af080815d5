// The demo's scene (urdf/scenes/table_ball.urdf): a touched ball stops, as a real one does,
// where table_sphere's (no rolling resistance, the paper's slide scenario) rolls on for ever at
// the speed a finger gave it. Simulated time, deterministic.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace god_finger
{
namespace
{
const std::string kScenes = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";

struct Roll
{
  double speed_after_1s = 0.0;  // m/s
  double distance_in_5s = 0.0;  // m
};

// The ball pushed to about 12 mm/s (a finger's stroke in the demo; 0.1 kg x 0.012 m/s x 7/5 for
// the rolling ball's inertia = 1.7 mN s), then left alone for 5 s.
Roll rollOf(const std::string& scene_file)
{
  const SceneDescription scene = loadUrdfScene(kScenes + "/" + scene_file);
  GodFingerWorld world(scene, WorldParams());
  const int ball = scene.find("ball");
  const Eigen::Vector3d start = world.bodyState(ball).center_of_mass;
  Roll roll;
  for (int k = 0; k < 5000; ++k)
  {
    if (k < 10)
    {
      world.applyBodyWrench(ball, Eigen::Vector3d(0.168, 0.0, 0.0), Eigen::Vector3d::Zero());
    }
    world.step();
    if (k == 999)
    {
      roll.speed_after_1s = world.bodyState(ball).linear_velocity.norm();
    }
  }
  roll.distance_in_5s = (world.bodyState(ball).center_of_mass - start).norm();
  return roll;
}

TEST(DemoScene, ATouchedBallStops)
{
  const Roll demo = rollOf("table_ball.urdf");
  EXPECT_LT(demo.speed_after_1s, 1e-4);
  EXPECT_LT(demo.distance_in_5s, 0.01);
  EXPECT_GT(demo.distance_in_5s, 1e-4);  // it did roll
  // table_sphere's ball keeps its speed: 5 s at about 12 mm/s.
  const Roll ideal = rollOf("table_sphere.urdf");
  std::printf(
      "pushed to 12 mm/s: table_ball's ball rolls %.1f mm and stops (%.2g m/s after 1 s); table_sphere's "
      "rolls %.1f mm in 5 s\n",
      1e3 * demo.distance_in_5s, demo.speed_after_1s, 1e3 * ideal.distance_in_5s);
  EXPECT_GT(ideal.speed_after_1s, 0.01);
  EXPECT_GT(ideal.distance_in_5s, 0.05);
}
}  // namespace
}  // namespace god_finger
