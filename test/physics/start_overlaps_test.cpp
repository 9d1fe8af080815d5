// Bodies that start inside one another are warned about, naming both and the depth: a box
// placed 1 cm into the table, two balls at one place. Resting bodies (a box 0.5 mm over the
// table, a scene list's placement) and a fixed scene's interlocking parts are not.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <string>

namespace god_finger
{
namespace
{
std::string sceneXml(const std::string& bodies)
{
  return "<?xml version='1.0'?><robot name='t'><link name='world'/>"
         "<link name='table'><collision><geometry><box size='1 1 0.04'/></geometry></collision></link>"
         "<joint name='tj' type='fixed'><parent link='world'/><child link='table'/><origin xyz='0 0 -0.02'/></joint>" +
         bodies + "</robot>";
}

std::string box(const std::string& name, const std::string& xyz, bool fixed = false)
{
  return "<link name='" + name +
         "'><inertial><mass value='0.1'/><inertia ixx='6e-5' ixy='0' ixz='0' iyy='6e-5' iyz='0' izz='6e-5'/>"
         "</inertial><collision><geometry><box size='0.06 0.06 0.06'/></geometry></collision></link>"
         "<joint name='" +
         name + "_j' type='" + (fixed ? "fixed" : "floating") + "'><parent link='world'/><child link='" + name +
         "'/><origin xyz='" + xyz + "'/></joint>";
}

std::vector<std::string> warningsOf(const std::string& bodies)
{
  const GodFingerWorld world(parseUrdfScene(sceneXml(bodies), ".", "overlap.urdf"), WorldParams());
  return world.startWarnings();
}

TEST(StartOverlaps, ABodyPlacedIntoAnotherIsWarnedAboutNamingBoth)
{
  const std::vector<std::string> sunk = warningsOf(box("crate", "0 0 0.02"));
  ASSERT_EQ(sunk.size(), 1u);
  EXPECT_EQ(sunk[0],
            "bodies 'crate' and 'table' start 10.0 mm inside each other (more than 2 mm): the first step pushes them "
            "apart; move one of them");
  const std::vector<std::string> together = warningsOf(box("a", "0 0 0.0305") + box("b", "0.03 0 0.0305"));
  ASSERT_EQ(together.size(), 1u);
  EXPECT_NE(together[0].find("bodies 'a' and 'b' start 30.0 mm inside each other"), std::string::npos) << together[0];
}

TEST(StartOverlaps, RestingBodiesAndAFixedScenesOwnPartsAreNot)
{
  EXPECT_TRUE(warningsOf(box("crate", "0 0 0.0305")).empty());
  EXPECT_TRUE(warningsOf(box("a", "0 0 0.0305") + box("b", "0.0605 0 0.0305")).empty());
  EXPECT_TRUE(warningsOf(box("post", "0 0 0.02", true)).empty()) << "two static bodies: the scene's own shape";
}
}  // namespace
}  // namespace god_finger
