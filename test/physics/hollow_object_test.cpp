// Hollow objects keep their hollow: a free cup and a free plate, resting on a table, collide
// with the table (and other bodies) through their convex decomposition, which fills the hollow;
// a finger collides with their true surface (the walk mesh, scene_body.h's FingerSurface). A
// finger brought down the axis from above the rim reaches the inner floor, feels it (the
// coupling force holds it up), and its pad lies on the floor. Before the finger surface, the
// finger stopped on the hulls' lid: 7.3 cm over a cup's 1.3 cm floor.
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/mesh_io/mesh_writer.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

namespace god_finger
{
namespace
{
// A cup 8 cm high, 4 cm in radius, 4 mm wall, its inner floor at 1.2 cm; a plate 10 cm in
// radius, 2 cm high, 4 mm thick (its floor's top at 4 mm).
constexpr double kCupFloor = 0.012;
constexpr double kPlateFloor = 0.004;

// A 2 cm cube, free, dropped on the dish's axis from 10 cm.
constexpr double kCubeHalf = 0.01;
const std::string kCube =
    "<link name='cube'><inertial><mass value='0.05'/><inertia ixx='3.3e-6' ixy='0' ixz='0' iyy='3.3e-6' iyz='0' "
    "izz='3.3e-6'/></inertial><collision><geometry><box size='0.02 0.02 0.02'/></geometry></collision></link>"
    "<joint name='cj' type='floating'><parent link='world'/><child link='cube'/><origin xyz='0 0 0.1'/></joint>";

std::string sceneXml(const std::string& mesh, double mass, const std::string& more = "")
{
  char inertial[200];
  std::snprintf(inertial, sizeof(inertial),
                "<inertial><origin xyz='0 0 0.02'/><mass value='%g'/>"
                "<inertia ixx='2e-4' ixy='0' ixz='0' iyy='2e-4' iyz='0' izz='2e-4'/></inertial>",
                mass);
  return std::string("<?xml version='1.0'?><robot name='t'><link name='world'/>") +
         "<link name='table'><collision><geometry><box size='1 1 0.04'/></geometry></collision></link>"
         "<joint name='tj' type='fixed'><parent link='world'/><child link='table'/><origin xyz='0 0 -0.02'/></joint>"
         "<link name='dish'>" +
         inertial + "<collision><geometry><mesh filename='" + mesh +
         "'/></geometry></collision></link>"
         "<joint name='dj' type='floating'><parent link='world'/><child link='dish'/></joint>" +
         more + "</robot>";
}

struct Press
{
  double proxy_bottom = 0.0;  // m, the proxy's lowest point
  double force_up = 0.0;      // N, the coupling's force on the hand, upwards
  double pad_height = 0.0;    // m, the sub-god-objects' largest height
  int sub_god_objects = 0;
  double dish_height = 0.0;  // m, the dish's link height after the press
};

// The dish settles for 0.5 s, then a finger comes down its axis from 12 cm to `target` (1 cm
// below the floor) and holds 0.8 s.
Press pressTheFloor(const SceneDescription& scene, double floor, ContactModel model)
{
  WorldParams params;
  params.model = model;
  GodFingerWorld world(scene, params);
  for (int i = 0; i < 500; ++i)
  {
    world.step();
  }
  const int finger = world.addInterface(Eigen::Vector3d(0.0, 0.0, 0.12));
  for (int i = 0; i < 800; ++i)
  {
    const double s = std::min(1.0, i / 400.0);
    world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, 0.12 + s * (floor - 0.01 - 0.12)));
    world.step();
  }
  const InterfaceState& state = world.interfaceState(finger);
  Press press;
  press.proxy_bottom = state.proxy_position.z() - params.coupling.proxy_radius;
  press.force_up = state.user_force.z();
  if (state.contact_count > 0)
  {
    const WorldContactArea& area = state.contacts[0];
    press.sub_god_objects = area.sub_god_object_count;
    press.pad_height = area.point.z();
    for (int k = 0; k < area.sub_god_object_count; ++k)
    {
      press.pad_height = std::max(press.pad_height, area.positions[k].z());
    }
  }
  press.dish_height = world.bodyState(scene.find("dish")).pose.translation().z();
  return press;
}

class HollowObject : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    folder_ = std::filesystem::temp_directory_path() / "god_finger_hollow_object";
    std::filesystem::create_directories(folder_);
    writeTriangleSoup(makeCup(0.04, 0.08, 0.004, kCupFloor, 32), (folder_ / "cup.obj").string());
    writeTriangleSoup(makePlate(0.1, 0.02, kPlateFloor, 48), (folder_ / "plate.obj").string());
  }
  void TearDown() override
  {
    std::filesystem::remove_all(folder_);
  }
  SceneDescription scene(const std::string& mesh, const std::string& more = "") const
  {
    return parseUrdfScene(sceneXml(mesh, 0.2, more), folder_.string(), "hollow.urdf");
  }
  std::filesystem::path folder_;
};

TEST_F(HollowObject, AFingerReachesTheInnerFloorOfACupAndOfAPlateAndFeelsIt)
{
  for (const ContactModel model : {ContactModel::kGodObject, ContactModel::kGodFinger})
  {
    for (const auto& [mesh, floor] : {std::pair<std::string, double>{"cup.obj", kCupFloor}, {"plate.obj", kPlateFloor}})
    {
      SCOPED_TRACE(mesh + (model == ContactModel::kGodFinger ? " god_finger" : " god_object"));
      const Press press = pressTheFloor(scene(mesh), floor, model);
      std::printf(
          "hollow_object: %s %s: proxy's lowest point %.2f mm (floor %.1f mm), %.2f N up, pad up to %.2f mm (%d)\n",
          mesh.c_str(), model == ContactModel::kGodFinger ? "god_finger" : "god_object", 1e3 * press.proxy_bottom,
          1e3 * floor, press.force_up, 1e3 * press.pad_height, press.sub_god_objects);
      // On the floor, not on a lid over the opening: within 1 mm of it (Bullet's contact margin and
      // the coupling's push into it).
      EXPECT_NEAR(press.proxy_bottom, floor, 1e-3);
      // Held up by the floor: the coupling pulls the hand up by its stiffness times the ~1 cm the
      // device is below the proxy.
      EXPECT_GT(press.force_up, 1.0);
      // The dish stays on the table, not pushed through it.
      EXPECT_NEAR(press.dish_height, 0.0, 1e-3);
      if (model == ContactModel::kGodFinger)
      {
        ASSERT_GE(press.sub_god_objects, 3) << "a pad on the floor";
        EXPECT_LT(press.pad_height, floor + 1e-3) << "every sub-god-object on the floor";
      }
    }
  }
}

TEST_F(HollowObject, ACubeDroppedIntoACupOrOntoAPlateRestsOnItsInnerFloor)
{
  for (const auto& [mesh, floor] : {std::pair<std::string, double>{"cup.obj", kCupFloor}, {"plate.obj", kPlateFloor}})
  {
    SCOPED_TRACE(mesh);
    const SceneDescription dish_and_cube = scene(mesh, kCube);
    WorldParams params;
    GodFingerWorld world(dish_and_cube, params);
    for (int i = 0; i < 1500; ++i)
    {
      world.step();
    }
    const BodyState cube = world.bodyState(dish_and_cube.find("cube"));
    const BodyState dish = world.bodyState(dish_and_cube.find("dish"));
    const double above_dish = cube.pose.translation().z() - dish.pose.translation().z();
    std::printf(
        "hollow_object: a cube in %s rests %.2f mm above the dish's base (floor + half edge %.1f mm), %.1f mm "
        "off its axis\n",
        mesh.c_str(), 1e3 * above_dish, 1e3 * (floor + kCubeHalf),
        1e3 * (cube.pose.translation() - dish.pose.translation()).head<2>().norm());
    // On the inner floor (within Bullet's 0.5 mm margins), inside the hollow, at rest; the dish
    // still on the table.
    EXPECT_NEAR(above_dish, floor + kCubeHalf, 1e-3);
    EXPECT_LT((cube.pose.translation() - dish.pose.translation()).head<2>().norm(), 0.02);
    EXPECT_LT(cube.linear_velocity.norm(), 1e-2);
    EXPECT_NEAR(dish.pose.translation().z(), 0.0, 1e-3);
  }
}
// What the steps see is what the load-time checks see: a cube resting on the cup's floor at load
// is not "inside" the cup (its hulls fill the hollow, its true surface does not), and a finger
// may start in the hollow.
TEST_F(HollowObject, ABodyOrAFingerInTheHollowIsNotInsideTheCup)
{
  const std::string resting =
      "<link name='cube'><inertial><mass value='0.05'/><inertia ixx='3.3e-6' ixy='0' ixz='0' iyy='3.3e-6' iyz='0' "
      "izz='3.3e-6'/></inertial><collision><geometry><box size='0.02 0.02 0.02'/></geometry></collision></link>"
      "<joint name='cj' type='floating'><parent link='world'/><child link='cube'/><origin xyz='0 0 0.0226'/></joint>";
  GodFingerWorld world(scene("cup.obj", resting), WorldParams());
  EXPECT_TRUE(world.startWarnings().empty()) << world.startWarnings().front();
  EXPECT_NO_THROW(world.addInterface(Eigen::Vector3d(0.02, 0.0, 0.05))) << "a finger in the hollow, over the cube";
}
}  // namespace
}  // namespace god_finger
