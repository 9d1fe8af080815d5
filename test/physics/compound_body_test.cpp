// A compound body (a link with several <collision>s, as PyBullet's table, plate and pan are
// written): one rigid body that collides as all its pieces and whose walk surface covers them
// all. A dumbbell (two 2 cm balls at x = +-5 cm on a 1 cm bar) rests on the table on both balls,
// and a finger pressing either ball gets a contact area on that ball.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace god_finger
{
namespace
{
const std::string kDumbbell =
    "<?xml version='1.0'?><robot name='dumbbell_scene'><link name='world'/>"
    "<link name='table'><collision><geometry><box size='1 1 0.04'/></geometry></collision></link>"
    "<joint name='tj' type='fixed'><parent link='world'/><child link='table'/><origin xyz='0 0 -0.02'/></joint>"
    "<link name='dumbbell'>"
    "<inertial><mass value='0.1'/><inertia ixx='2e-5' ixy='0' ixz='0' iyy='1.5e-4' iyz='0' izz='1.5e-4'/></inertial>"
    "<collision><origin xyz='-0.05 0 0'/><geometry><sphere radius='0.02'/></geometry></collision>"
    "<collision><origin xyz='0.05 0 0'/><geometry><sphere radius='0.02'/></geometry></collision>"
    "<collision><origin rpy='0 1.5707963267948966 0'/><geometry><cylinder radius='0.005' length='0.1'/>"
    "</geometry></collision></link>"
    "<joint name='dj' type='floating'><parent link='world'/><child link='dumbbell'/><origin xyz='0 0 0.03'/></joint>"
    "</robot>";

TEST(CompoundBody, ALinkWithSeveralCollisionsIsOneBodyOfAllItsPieces)
{
  const SceneDescription scene = parseUrdfScene(kDumbbell, ".", "dumbbell.urdf");
  ASSERT_EQ(scene.bodies.size(), 2u);
  ASSERT_GE(scene.find("dumbbell"), 0);
  const BodyDescription& dumbbell = scene.bodies[scene.find("dumbbell")];
  EXPECT_EQ(dumbbell.geometry.kind, GeometryKind::kSphere);
  EXPECT_DOUBLE_EQ(dumbbell.collision_origin.translation().x(), -0.05);
  ASSERT_EQ(dumbbell.more_parts.size(), 2u);
  EXPECT_EQ(dumbbell.more_parts[0].geometry.kind, GeometryKind::kSphere);
  EXPECT_DOUBLE_EQ(dumbbell.more_parts[0].origin.translation().x(), 0.05);
  EXPECT_EQ(dumbbell.more_parts[1].geometry.kind, GeometryKind::kCylinder);
}

TEST(CompoundBody, RestsOnAllItsPiecesAndEveryPieceCanBeTouched)
{
  for (const double side : {-1.0, 1.0})
  {
    SCOPED_TRACE(side);
    WorldParams params;
    params.model = ContactModel::kGodFinger;
    const SceneDescription scene = parseUrdfScene(kDumbbell, ".", "dumbbell.urdf");
    const int dumbbell = scene.find("dumbbell");
    GodFingerWorld world(scene, params);
    // Dropped from 1 cm above the table, it settles on both balls: its link (the bar's axis)
    // 2 cm above the table, level.
    for (int i = 0; i < 1000; ++i)
    {
      world.step();
    }
    const Eigen::Isometry3d settled = world.bodyState(dumbbell).pose;
    EXPECT_NEAR(settled.translation().z(), 0.02, 1e-3);
    EXPECT_NEAR((settled.linear() * Eigen::Vector3d::UnitX()).z(), 0.0, 1e-3) << "level: both balls on the table";
    // A finger pressing down on one ball, at its top.
    const Eigen::Vector3d top = settled * Eigen::Vector3d(side * 0.05, 0.0, 0.02);
    const int finger = world.addInterface(top + Eigen::Vector3d(0, 0, 0.02));
    world.setInterfaceTarget(finger, top - Eigen::Vector3d(0, 0, 0.005));
    for (int i = 0; i < 500; ++i)
    {
      world.step();
    }
    const InterfaceState& state = world.interfaceState(finger);
    ASSERT_EQ(state.contact_count, 1);
    const WorldContactArea& area = state.contacts[0];
    EXPECT_EQ(area.body, dumbbell);
    EXPECT_GT(area.radius, 0.002) << "a pad, not a point";
    // Every sub-god-object on that ball's surface (the walk stays on the touched piece).
    const Eigen::Isometry3d pose = world.bodyState(dumbbell).pose;
    const Eigen::Vector3d centre = pose * Eigen::Vector3d(side * 0.05, 0.0, 0.0);
    ASSERT_GE(area.sub_god_object_count, 3);
    for (int k = 0; k < area.sub_god_object_count; ++k)
    {
      EXPECT_NEAR((area.positions[k] - centre).norm(), 0.02, 1e-3) << "sub-god-object " << k;
    }
    EXPECT_GT(state.user_force.z(), 1.0) << "the hand feels the ball";
  }
}
}  // namespace
}  // namespace god_finger
