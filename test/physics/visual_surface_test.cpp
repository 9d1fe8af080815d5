// The visual mesh is the true surface: an object colliding through coarse hulls (here an
// icosahedron, up to 20 % inside the sphere it stands for) and drawn with a fine mesh has its
// pad on the fine mesh. A finger presses a 4 cm ball whose collision is the 20-triangle
// icosahedron and whose <visual> is a 1280-triangle icosphere: every sub-god-object lies on the
// fine sphere (within the fine mesh's own chord error), where on the collision mesh they would
// lie up to 8 mm inside it.
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/mesh_io/mesh_writer.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace god_finger
{
namespace
{
constexpr double kRadius = 0.04;

std::string sceneXml(const std::string& visual)
{
  return "<?xml version='1.0'?><robot name='t'><link name='world'/>"
         "<link name='table'><collision><geometry><box size='1 1 0.04'/></geometry></collision></link>"
         "<joint name='tj' type='fixed'><parent link='world'/><child link='table'/><origin xyz='0 0 -0.02'/></joint>"
         "<link name='ball'>" +
         visual +
         "<collision><geometry><mesh filename='coarse.obj'/></geometry></collision></link>"
         "<joint name='bj' type='fixed'><parent link='world'/><child link='ball'/><origin xyz='0 0 0.05'/></joint>"
         "</robot>";
}

// The largest distance of the finger's sub-god-objects from the true sphere, pressing its top.
double padOffTheSphere(const SceneDescription& scene, int* count)
{
  WorldParams params;
  params.model = ContactModel::kGodFinger;
  GodFingerWorld world(scene, params);
  const Eigen::Vector3d centre(0.0, 0.0, 0.05);
  // Beside the icosahedron's vertex at the top: over a face, where hull and sphere differ.
  const Eigen::Vector3d direction = Eigen::Vector3d(0.3, 0.2, 1.0).normalized();
  const int finger = world.addInterface(centre + 0.07 * direction);
  world.setInterfaceTarget(finger, centre + 0.02 * direction);
  for (int i = 0; i < 800; ++i)
  {
    world.step();
  }
  const InterfaceState& state = world.interfaceState(finger);
  EXPECT_EQ(state.contact_count, 1);
  double worst = 0.0;
  *count = state.contact_count > 0 ? state.contacts[0].sub_god_object_count : 0;
  for (int k = 0; k < *count; ++k)
  {
    worst = std::max(worst, std::abs((state.contacts[0].positions[k] - centre).norm() - kRadius));
  }
  return worst;
}

TEST(VisualSurface, ThePadLiesOnTheVisualMeshNotOnTheCoarseCollisionMesh)
{
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "god_finger_visual_surface";
  std::filesystem::create_directories(folder);
  writeTriangleSoup(makeIcosphere(kRadius, 0), (folder / "coarse.obj").string());
  writeTriangleSoup(makeIcosphere(kRadius, 3), (folder / "fine.obj").string());
  const SceneDescription with_visual = parseUrdfScene(
      sceneXml("<visual><geometry><mesh filename='fine.obj'/></geometry></visual>"), folder.string(), "visual.urdf");
  const BodyDescription& ball = with_visual.bodies[with_visual.find("ball")];
  ASSERT_TRUE(ball.visual_mesh.has_value());
  EXPECT_NE(ball.visual_mesh->geometry.mesh_path.find("fine.obj"), std::string::npos);
  // The same file as visual and collision is no separate surface.
  EXPECT_FALSE(parseUrdfScene(sceneXml("<visual><geometry><mesh filename='coarse.obj'/></geometry></visual>"),
                              folder.string(), "same.urdf")
                   .bodies[0]
                   .visual_mesh.has_value());

  int on_visual_count = 0;
  int on_collision_count = 0;
  const double on_visual = padOffTheSphere(with_visual, &on_visual_count);
  const double on_collision =
      padOffTheSphere(parseUrdfScene(sceneXml(""), folder.string(), "coarse.urdf"), &on_collision_count);
  std::printf(
      "visual_surface: sub-god-objects up to %.3f mm off the sphere on the visual mesh (%d), %.3f mm on the "
      "collision mesh (%d)\n",
      1e3 * on_visual, on_visual_count, 1e3 * on_collision, on_collision_count);
  ASSERT_GE(on_visual_count, 3);
  // The 1280-triangle icosphere's chord error at r = 4 cm is about 0.15 mm.
  EXPECT_LT(on_visual, 0.3e-3);
  EXPECT_GT(on_collision, 2e-3) << "the coarse mesh is far from the sphere: the test can tell the two apart";
  std::filesystem::remove_all(folder);
}
// A visual mesh far larger than the collision shape (a scanned surface over a small core): the
// finger meets the visual surface, 8 cm from the centre, although the collision shape's box ends
// 1 cm from it (the body's broadphase box covers the visual mesh too).
TEST(VisualSurface, AFingerMeetsAVisualMeshReachingFarBeyondTheCollisionShape)
{
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "god_finger_visual_reach";
  std::filesystem::create_directories(folder);
  writeTriangleSoup(makeIcosphere(0.01, 1), (folder / "coarse.obj").string());
  writeTriangleSoup(makeIcosphere(0.08, 3), (folder / "fine.obj").string());
  // The ball's centre 10 cm over the table: the visual sphere clears it.
  std::string xml = sceneXml("<visual><geometry><mesh filename='fine.obj'/></geometry></visual>");
  xml.replace(xml.find("xyz='0 0 0.05'"), 14, "xyz='0 0 0.10'");
  const SceneDescription scene = parseUrdfScene(xml, folder.string(), "reach.urdf");
  GodFingerWorld world(scene, WorldParams());
  const Eigen::Vector3d centre(0.0, 0.0, 0.10);
  const int finger = world.addInterface(centre + Eigen::Vector3d(0.0, 0.0, 0.12));
  world.setInterfaceTarget(finger, centre + Eigen::Vector3d(0.0, 0.0, 0.06));
  for (int i = 0; i < 1500; ++i)
  {
    world.step();
  }
  const InterfaceState& state = world.interfaceState(finger);
  const double reach = (state.proxy_position - centre).norm();
  std::printf(
      "visual_surface: a finger pressing a visual sphere of 8 cm over a 1 cm core stops %.2f mm from its "
      "centre, pressing %.2f N\n",
      1e3 * reach, state.user_force.norm());
  ASSERT_EQ(state.contact_count, 1);
  EXPECT_GT(reach, 0.08);  // on the visual sphere (its chord error ~0.3 mm inward, the proxy's radius outward)
  EXPECT_LT(reach, 0.08 + 0.004);
  EXPECT_GT(state.user_force.norm(), 1.0);
  std::filesystem::remove_all(folder);
}
}  // namespace
}  // namespace god_finger
