// Scenes that cannot fit are refused before anything is built, with the limit named
// (scene_budget.h).
#include "god_finger/scene/scene_budget.h"

#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/support/memory_budget.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace god_finger
{
namespace
{
SceneDescription boxes(int count)
{
  SceneDescription scene;
  scene.name = "crowd";
  for (int i = 0; i < count; ++i)
  {
    BodyDescription body;
    body.name = "box" + std::to_string(i);
    body.is_static = true;
    body.geometry.size = Eigen::Vector3d::Constant(0.01);
    body.pose.translation() = Eigen::Vector3d(0.02 * (i % 100), 0.02 * (i / 100), 0.0);
    scene.bodies.push_back(body);
  }
  return scene;
}

std::string refusal(const SceneDescription& scene)
{
  try
  {
    GodFingerWorld world(scene, WorldParams());
  }
  catch (const ResourceLimitError& error)
  {
    return error.what();
  }
  return std::string();
}

TEST(SceneBudget, TenThousandAndOneBodiesAreRefused)
{
  EXPECT_EQ(refusal(boxes(kMaxBodies + 1)), "scene 'crowd' has 10001 bodies, more than the limit of 10000");
  // The limit itself passes the check (building 10,000 boxes takes 0.1 s and 690 MiB: not done here).
  EXPECT_NO_THROW(checkSceneFits(boxes(kMaxBodies), 0.001));
}

TEST(SceneBudget, AUrdfOfTenThousandAndOneLinksIsRefused)
{
  std::string urdf = "<robot name='crowd'><link name='world'/>";
  for (int i = 0; i <= kMaxBodies; ++i)
  {
    const std::string name = "box" + std::to_string(i);
    urdf += "<link name='" + name + "'><collision><geometry><box size='0.01 0.01 0.01'/></geometry></collision></link>";
    urdf += "<joint name='" + name + "_fixed' type='fixed'><parent link='world'/><child link='" + name + "'/></joint>";
  }
  urdf += "</robot>";
  try
  {
    parseUrdfScene(urdf, "/tmp", "crowd.urdf");
    FAIL() << "accepted";
  }
  catch (const ResourceLimitError& error)
  {
    EXPECT_STREQ(error.what(), "URDF 'crowd.urdf': 10001 bodies, more than the limit of 10000");
  }
}

TEST(SceneBudget, PrimitivesThatDoNotFitInMemoryAreRefused)
{
  SceneDescription scene = boxes(3);
  scene.bodies[0].geometry.kind = GeometryKind::kSphere;
  scene.bodies[0].geometry.radius = 1.0;  // 81920 walk triangles
  setenv("GOD_FINGER_MEMORY_LIMIT", "1e7", 1);
  const std::string message = refusal(scene);
  unsetenv("GOD_FINGER_MEMORY_LIMIT");
  EXPECT_EQ(message,
            "scene 'crowd' has 3 bodies: they and their walk meshes need about 35.4 MiB, more than the limit of "
            "9.54 MiB (GOD_FINGER_MEMORY_LIMIT=1e7)");
  EXPECT_EQ(refusal(scene), "");
}
}  // namespace
}  // namespace god_finger
