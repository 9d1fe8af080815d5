// Scenes from URDF: the shipped scenes load as documented, and every malformed input gives one
// InputError naming the file, the link and the problem.
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <string>

namespace god_finger
{
namespace
{
const std::string kScenes = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";

// A URDF with a table and one free body whose link body is `link_xml`.
std::string sceneWith(const std::string& link_xml, const std::string& joint_type = "floating")
{
  return "<?xml version='1.0'?><robot name='t'><link name='world'/>"
         "<link name='table'><collision><geometry><box size='1 1 0.04'/></geometry></collision></link>"
         "<joint name='tj' type='fixed'><parent link='world'/><child link='table'/></joint>"
         "<link name='thing'>" +
         link_xml + "</link><joint name='j' type='" + joint_type +
         "'><parent link='world'/><child link='thing'/>"
         "<origin xyz='0 0 0.5'/></joint></robot>";
}

const std::string kGoodInertial =
    "<inertial><mass value='0.1'/><inertia ixx='1e-4' ixy='0' ixz='0' iyy='1e-4' iyz='0' izz='1e-4'/></inertial>";

std::string errorOf(const std::string& xml)
{
  try
  {
    parseUrdfScene(xml, kScenes, "test.urdf");
  }
  catch (const InputError& error)
  {
    return error.what();
  }
  return "";
}

TEST(UrdfScene, ShippedSphereSceneHasAStaticTableAndAFreeBall)
{
  const SceneDescription scene = loadUrdfScene(kScenes + "/table_sphere.urdf");
  ASSERT_EQ(scene.bodies.size(), 2u);
  const BodyDescription& table = scene.bodies[scene.find("table")];
  const BodyDescription& ball = scene.bodies[scene.find("ball")];
  EXPECT_TRUE(table.is_static);
  EXPECT_FALSE(ball.is_static);
  EXPECT_EQ(ball.geometry.kind, GeometryKind::kSphere);
  EXPECT_DOUBLE_EQ(ball.geometry.radius, 0.04);
  EXPECT_DOUBLE_EQ(ball.mass, 0.1);
  EXPECT_DOUBLE_EQ(ball.inertia(0, 0), 6.4e-5);
  EXPECT_DOUBLE_EQ(ball.pose.translation().z(), 0.04);
  EXPECT_DOUBLE_EQ(ball.material.friction, 0.8);
  EXPECT_DOUBLE_EQ(table.material.friction, 0.6);
  EXPECT_DOUBLE_EQ(table.pose.translation().z(), -0.02);
}

TEST(UrdfScene, EveryShippedSceneLoads)
{
  for (const char* name : {"table_ball", "table_sphere", "table_cylinder", "table_box", "table_torus", "rails_plate"})
  {
    SCOPED_TRACE(name);
    const SceneDescription scene = loadUrdfScene(kScenes + "/" + name + ".urdf");
    int dynamic = 0;
    for (const BodyDescription& body : scene.bodies)
    {
      dynamic += body.is_static ? 0 : 1;
    }
    EXPECT_EQ(dynamic, 1);
  }
}

TEST(UrdfScene, ConcaveMeshSceneResolvesItsMeshWithScale)
{
  const SceneDescription scene = loadUrdfScene(kScenes + "/table_torus.urdf");
  int mesh_bodies = 0;
  for (const BodyDescription& body : scene.bodies)
  {
    if (body.geometry.kind == GeometryKind::kMesh)
    {
      ++mesh_bodies;
      EXPECT_NE(body.geometry.mesh_path.find("urdf/meshes/torus.dae"), std::string::npos) << body.geometry.mesh_path;
    }
  }
  EXPECT_EQ(mesh_bodies, 1);
}

TEST(UrdfScene, MaterialComesFromThePyBulletContactTag)
{
  const SceneDescription scene =
      parseUrdfScene(sceneWith("<collision><geometry><sphere radius='0.1'/></geometry></collision>" + kGoodInertial +
                               "<contact><lateral_friction value='0.3'/><rolling_friction value='0.01'/>"
                               "<spinning_friction value='0.02'/><restitution value='0.5'/></contact>"),
                     kScenes);
  const ContactMaterial& material = scene.bodies[scene.find("thing")].material;
  EXPECT_DOUBLE_EQ(material.friction, 0.3);
  EXPECT_DOUBLE_EQ(material.rolling_friction, 0.01);
  EXPECT_DOUBLE_EQ(material.spinning_friction, 0.02);
  EXPECT_DOUBLE_EQ(material.restitution, 0.5);
}

TEST(UrdfScene, MissingFileIsNamed)
{
  try
  {
    loadUrdfScene("/nonexistent/scene.urdf");
    FAIL() << "no error";
  }
  catch (const InputError& error)
  {
    EXPECT_EQ(std::string(error.what()), "URDF '/nonexistent/scene.urdf': no such file or not readable");
  }
}

TEST(UrdfScene, MalformedXmlIsRejected)
{
  const std::string error = errorOf("<robot name='x'><link name='a'>");
  EXPECT_NE(error.find("URDF 'test.urdf'"), std::string::npos) << error;
  EXPECT_NE(error.find("not a valid URDF"), std::string::npos) << error;
}

TEST(UrdfScene, MissingMeshNamesTheLinkAndThePath)
{
  const std::string error = errorOf(sceneWith(
      "<collision><geometry><mesh filename='meshes/nothing_here.stl'/></geometry></collision>" + kGoodInertial));
  EXPECT_NE(error.find("link 'thing'"), std::string::npos) << error;
  EXPECT_NE(error.find("mesh 'meshes/nothing_here.stl' not found"), std::string::npos) << error;
}

TEST(UrdfScene, NonPositiveMassNamesTheLink)
{
  const std::string error = errorOf(sceneWith(
      "<collision><geometry><sphere radius='0.1'/></geometry></collision>"
      "<inertial><mass value='0'/><inertia ixx='1e-4' ixy='0' ixz='0' iyy='1e-4' iyz='0' izz='1e-4'/></inertial>"));
  EXPECT_NE(error.find("link 'thing': mass 0 kg is not positive"), std::string::npos) << error;
}

TEST(UrdfScene, NonPositiveDefiniteInertiaNamesTheLink)
{
  const std::string error = errorOf(sceneWith(
      "<collision><geometry><sphere radius='0.1'/></geometry></collision>"
      "<inertial><mass value='1'/><inertia ixx='1e-4' ixy='0' ixz='0' iyy='-1e-4' iyz='0' izz='1e-4'/></inertial>"));
  EXPECT_NE(error.find("link 'thing': inertia is not positive definite"), std::string::npos) << error;
}

TEST(UrdfScene, FreeBodyWithoutInertialIsRejected)
{
  const std::string error = errorOf(sceneWith("<collision><geometry><sphere radius='0.1'/></geometry></collision>"));
  EXPECT_NE(error.find("link 'thing': a floating body needs an <inertial>"), std::string::npos) << error;
}

TEST(UrdfScene, AJointToTheWorldThatTurnsMakesAnArticulatedBody)
{
  const SceneDescription scene = parseUrdfScene(
      sceneWith("<collision><geometry><sphere radius='0.1'/></geometry></collision>" + kGoodInertial, "continuous"),
      kScenes, "knob.urdf");
  ASSERT_EQ(scene.joints.size(), 1u);
  EXPECT_EQ(scene.joints[0].kind, JointKind::kContinuous);
  EXPECT_EQ(scene.joints[0].parent, -1);
  EXPECT_EQ(scene.bodies[scene.joints[0].child].name, "thing");
  EXPECT_FALSE(scene.bodies[scene.joints[0].child].is_static);
  const std::string error = errorOf(
      sceneWith("<collision><geometry><sphere radius='0.1'/></geometry></collision>" + kGoodInertial, "planar"));
  EXPECT_NE(error.find("link 'thing': joint 'j' must be 'fixed' (static body), 'floating' (free body), 'revolute', "
                       "'continuous' or 'prismatic'"),
            std::string::npos)
      << error;
}

TEST(UrdfScene, BadGeometryValuesAreRejected)
{
  EXPECT_NE(errorOf(sceneWith("<collision><geometry><sphere radius='-1'/></geometry></collision>" + kGoodInertial))
                .find("link 'thing': sphere radius must be positive"),
            std::string::npos);
  EXPECT_NE(errorOf(sceneWith("<collision><geometry><box size='0 1 1'/></geometry></collision>" + kGoodInertial))
                .find("link 'thing': box size must be positive"),
            std::string::npos);
}

TEST(UrdfScene, LinkWithoutCollisionIsRejected)
{
  EXPECT_NE(errorOf(sceneWith(kGoodInertial)).find("link 'thing': has no <collision>"), std::string::npos);
}

// An object file as PyBullet ships one: the root link is the body, at the origin.
std::string objectFile(const std::string& root_xml, const std::string& more = "")
{
  return "<?xml version='1.0'?><robot name='duck'><link name='baseLink'>" + root_xml + "</link>" + more + "</robot>";
}

TEST(UrdfScene, AnObjectFilesRootLinkIsTheBodyFreeWithMassFixedWithout)
{
  const SceneDescription free = parseUrdfScene(
      objectFile("<collision><origin xyz='0 0 0.01'/><geometry><sphere radius='0.02'/></geometry></collision>" +
                 kGoodInertial),
      kScenes, "duck.urdf");
  ASSERT_EQ(free.bodies.size(), 1u);
  EXPECT_EQ(free.bodies[0].name, "baseLink");
  EXPECT_FALSE(free.bodies[0].is_static);
  EXPECT_DOUBLE_EQ(free.bodies[0].mass, 0.1);
  EXPECT_TRUE(free.bodies[0].pose.isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_DOUBLE_EQ(free.bodies[0].collision_origin.translation().z(), 0.01);
  // PyBullet's fixed base: mass 0, or no <inertial> at all.
  for (const std::string& inertial :
       {std::string("<inertial><mass value='0'/><inertia ixx='0' ixy='0' ixz='0' iyy='0' iyz='0' izz='0'/></inertial>"),
        std::string()})
  {
    const SceneDescription fixed =
        parseUrdfScene(objectFile("<collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision>" + inertial),
                       kScenes, "tray.urdf");
    ASSERT_EQ(fixed.bodies.size(), 1u);
    EXPECT_TRUE(fixed.bodies[0].is_static);
  }
}

// A box with a lid on a hinge, as an object file: the lid is a body of its own on a joint to the
// box, placed with the joint at 0, with the joint's axis, limits and dynamics.
std::string boxWithLid(const std::string& joint)
{
  return objectFile("<collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision>" + kGoodInertial,
                    "<link name='lid'><collision><origin xyz='0.05 0 0'/><geometry><box size='0.1 0.1 0.01'/>"
                    "</geometry></collision>" +
                        kGoodInertial + "</link>" + joint);
}

TEST(UrdfScene, AnObjectFilesJointedLinksAreItsMovingParts)
{
  const SceneDescription scene = parseUrdfScene(
      boxWithLid("<joint name='hinge' type='revolute'><parent link='baseLink'/><child link='lid'/>"
                 "<origin xyz='-0.05 0 0.055'/><axis xyz='0 2 0'/><limit lower='-1.5' upper='0' effort='1' "
                 "velocity='2'/><dynamics damping='0.01' friction='0.02'/></joint>"),
      kScenes, "box.urdf");
  ASSERT_EQ(scene.bodies.size(), 2u);
  ASSERT_EQ(scene.joints.size(), 1u);
  const JointDescription& hinge = scene.joints[0];
  EXPECT_EQ(hinge.name, "hinge");
  EXPECT_EQ(hinge.kind, JointKind::kRevolute);
  EXPECT_EQ(scene.bodies[hinge.parent].name, "baseLink");
  EXPECT_EQ(scene.bodies[hinge.child].name, "lid");
  EXPECT_TRUE(hinge.axis.isApprox(Eigen::Vector3d::UnitY())) << "normalised";
  EXPECT_DOUBLE_EQ(hinge.lower, -1.5);
  EXPECT_DOUBLE_EQ(hinge.upper, 0.0);
  EXPECT_DOUBLE_EQ(hinge.effort, 1.0);
  EXPECT_DOUBLE_EQ(hinge.velocity, 2.0);
  EXPECT_DOUBLE_EQ(hinge.damping, 0.01);
  EXPECT_DOUBLE_EQ(hinge.friction, 0.02);
  EXPECT_TRUE(scene.bodies[hinge.child].pose.translation().isApprox(Eigen::Vector3d(-0.05, 0, 0.055)));
}

// A link on a fixed joint is a piece of its parent's body (URDF objects built of several links,
// as Gazebo's and PyBullet's often are): one body whose parts are both links' <collision>s,
// whose mass is their sum, its centre of mass and inertia combined by the parallel-axis theorem.
TEST(UrdfScene, ALinkOnAFixedJointIsAPieceOfItsParentsBody)
{
  const SceneDescription scene =
      parseUrdfScene(boxWithLid("<joint name='glued' type='fixed'><parent link='baseLink'/><child link='lid'/>"
                                "<origin xyz='0 0 0.055'/></joint>"),
                     kScenes, "box.urdf");
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_TRUE(scene.joints.empty());
  const BodyDescription& body = scene.bodies[0];
  EXPECT_EQ(body.name, "baseLink");
  EXPECT_FALSE(body.is_static);
  ASSERT_EQ(body.more_parts.size(), 1u);
  // The lid's collision: its own origin (5 cm along x) in the joint's frame (5.5 cm up).
  EXPECT_TRUE(body.more_parts[0].origin.translation().isApprox(Eigen::Vector3d(0.05, 0.0, 0.055)));
  EXPECT_DOUBLE_EQ(body.mass, 0.2);
  // Two 0.1 kg masses (inertia 1e-4 each) 5.5 cm apart along z: the centre halfway, and
  // 2 * 1e-4 + 2 * 0.1 * 0.0275^2 about x and y, 2e-4 about z.
  EXPECT_TRUE(body.inertial_origin.translation().isApprox(Eigen::Vector3d(0.0, 0.0, 0.0275)));
  const double across = 2e-4 + 2 * 0.1 * 0.0275 * 0.0275;
  EXPECT_NEAR(body.inertia(0, 0), across, 1e-12);
  EXPECT_NEAR(body.inertia(1, 1), across, 1e-12);
  EXPECT_NEAR(body.inertia(2, 2), 2e-4, 1e-12);
  EXPECT_NEAR(body.inertia(0, 2), 0.0, 1e-12);
}

// A frame without geometry fixed to a body (a tool or camera frame) adds nothing: the body keeps
// its visual mesh as its surface.
TEST(UrdfScene, AnEmptyFrameFixedToABodyKeepsItsVisualSurface)
{
  const SceneDescription scene =
      parseUrdfScene(objectFile("<visual><geometry><mesh filename='../meshes/sphere.obj'/></geometry></visual>"
                                "<collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision>" +
                                    kGoodInertial,
                                "<link name='camera_frame'/><joint name='mount' type='fixed'><parent link='baseLink'/>"
                                "<child link='camera_frame'/><origin xyz='0 0 0.1'/></joint>"),
                     kScenes, "box.urdf");
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_TRUE(scene.bodies[0].visual_mesh.has_value());
  EXPECT_TRUE(scene.bodies[0].more_parts.empty());
  EXPECT_DOUBLE_EQ(scene.bodies[0].mass, 0.1);
}

// A hinge on a fixed piece: the joint's parent is the body the piece belongs to, its frame
// composed through the fixed joint; the door's handle, fixed to the door, moves with it.
TEST(UrdfScene, AJointOnAFixedPieceJoinsTheBodyItBelongsTo)
{
  const std::string box = "<collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision>" + kGoodInertial;
  const SceneDescription scene = parseUrdfScene(
      objectFile(box, "<link name='bracket'>" + box +
                          "</link><joint name='glued' type='fixed'><parent link='baseLink'/><child link='bracket'/>"
                          "<origin xyz='0 0 0.1'/></joint>"
                          "<link name='lid'>" +
                          box +
                          "</link><joint name='hinge' type='revolute'><parent link='bracket'/><child link='lid'/>"
                          "<origin xyz='0.1 0 0'/><axis xyz='0 1 0'/><limit lower='-1' upper='0' effort='1' "
                          "velocity='1'/></joint>"
                          "<link name='knob'>" +
                          box +
                          "</link><joint name='knob_glued' type='fixed'><parent link='lid'/><child link='knob'/>"
                          "<origin xyz='0 0 0.1'/></joint>"),
      kScenes, "box.urdf");
  ASSERT_EQ(scene.bodies.size(), 2u);
  ASSERT_EQ(scene.joints.size(), 1u);
  const JointDescription& hinge = scene.joints[0];
  EXPECT_EQ(scene.bodies[hinge.parent].name, "baseLink");
  EXPECT_EQ(scene.bodies[hinge.child].name, "lid");
  EXPECT_TRUE(hinge.joint_in_parent.translation().isApprox(Eigen::Vector3d(0.1, 0.0, 0.1)));
  EXPECT_EQ(scene.bodies[hinge.child].more_parts.size(), 1u);  // the knob
  EXPECT_TRUE(scene.bodies[hinge.child].pose.translation().isApprox(Eigen::Vector3d(0.1, 0.0, 0.1)));
}

TEST(UrdfScene, JointsThatCannotMoveABodyAreRefusedNamingThem)
{
  const auto joint = [](const std::string& type, const std::string& more) {
    return "<joint name='hinge' type='" + type + "'><parent link='baseLink'/><child link='lid'/>" + more + "</joint>";
  };
  const std::string floating = errorOf(boxWithLid(joint("floating", "")));
  EXPECT_NE(floating.find("link 'lid': joint 'hinge' is 'floating' to link 'baseLink'"), std::string::npos) << floating;
  EXPECT_NE(floating.find("or is a piece of it on a 'fixed' joint"), std::string::npos) << floating;
  const std::string wide =
      errorOf(boxWithLid(joint("revolute", "<limit lower='-4' upper='0' effort='1' velocity='1'/>")));
  EXPECT_NE(wide.find("link 'lid': joint 'hinge': a revolute joint's <limit> must lie within [-pi, pi] rad"),
            std::string::npos)
      << wide;
  const std::string reversed =
      errorOf(boxWithLid(joint("prismatic", "<limit lower='0.2' upper='0.1' effort='1' velocity='1'/>")));
  EXPECT_NE(reversed.find("link 'lid': joint 'hinge': <limit> needs finite lower <= upper"), std::string::npos)
      << reversed;
  const std::string damping = errorOf(boxWithLid(joint("continuous", "<dynamics damping='-1'/>")));
  EXPECT_NE(damping.find("link 'lid': joint 'hinge': <dynamics> damping and friction must be finite and >= 0"),
            std::string::npos)
      << damping;
  const std::string no_axis = errorOf(boxWithLid(joint("continuous", "<axis xyz='0 0 0'/>")));
  EXPECT_NE(no_axis.find("link 'lid': joint 'hinge': <axis> must be a non-zero direction"), std::string::npos)
      << no_axis;
}

// urdfdom drops what it cannot read and goes on: the real problem must be named, not the
// missing element it leaves behind.
TEST(UrdfScene, NonFiniteNumbersAreNamedNotTheElementUrdfdomDrops)
{
  const std::string infinite_mass = errorOf(sceneWith(
      "<collision><geometry><sphere radius='0.1'/></geometry></collision>"
      "<inertial><mass value='inf'/><inertia ixx='1e-4' ixy='0' ixz='0' iyy='1e-4' iyz='0' izz='1e-4'/></inertial>"));
  EXPECT_NE(infinite_mass.find("link 'thing': <inertial><mass value> 'inf' is not a finite number"), std::string::npos)
      << infinite_mass;
  const std::string nan_scale = errorOf(
      sceneWith("<collision><geometry><mesh filename='meshes/nothing.stl' scale='nan 1 1'/></geometry></collision>" +
                kGoodInertial));
  EXPECT_NE(nan_scale.find("link 'thing': <collision> <mesh scale> 'nan 1 1' is not 3 finite numbers"),
            std::string::npos)
      << nan_scale;
  const std::string short_origin = errorOf(sceneWith(
      "<collision><origin xyz='0 1'/><geometry><sphere radius='0.1'/></geometry></collision>" + kGoodInertial));
  EXPECT_NE(short_origin.find("link 'thing': <collision><origin xyz> '0 1' is not 3 finite numbers"), std::string::npos)
      << short_origin;
  const std::string bad_inertia = errorOf(sceneWith(
      "<collision><geometry><sphere radius='0.1'/></geometry></collision>"
      "<inertial><mass value='1'/><inertia ixx='nan' ixy='0' ixz='0' iyy='1e-4' iyz='0' izz='1e-4'/></inertial>"));
  EXPECT_NE(bad_inertia.find("link 'thing': <inertia ixx> 'nan' is not a finite number"), std::string::npos)
      << bad_inertia;
}

TEST(UrdfScene, SizesOutsideWhatASceneHoldsAreRefusedNamingTheRange)
{
  const std::string huge =
      errorOf(sceneWith("<collision><geometry><box size='1e30 1 1'/></geometry></collision>" + kGoodInertial));
  EXPECT_NE(huge.find("link 'thing': box size 1e+30 m is outside the sizes a scene can hold, [0.0001, 100] m"),
            std::string::npos)
      << huge;
  const std::string tiny =
      errorOf(sceneWith("<collision><geometry><sphere radius='1e-6'/></geometry></collision>" + kGoodInertial));
  EXPECT_NE(tiny.find("link 'thing': sphere radius 1e-06 m is outside"), std::string::npos) << tiny;
  const std::string long_cylinder = errorOf(
      sceneWith("<collision><geometry><cylinder radius='0.1' length='500'/></geometry></collision>" + kGoodInertial));
  EXPECT_NE(long_cylinder.find("link 'thing': cylinder length 500 m is outside"), std::string::npos) << long_cylinder;
}
}  // namespace
}  // namespace god_finger

namespace god_finger
{
namespace
{
TEST(UrdfScene, PackageMeshesGoThroughTheResolverGiven)
{
  const std::string xml = sceneWith(
      "<collision><geometry><mesh filename='package://some_pkg/urdf/meshes/torus.dae'/></geometry></collision>" +
          kGoodInertial,
      "fixed");
  std::vector<std::string> asked;
  const SceneDescription scene = parseUrdfScene(xml, kScenes, "test.urdf",
                                                [&asked](const std::string& name)
                                                {
                                                  asked.push_back(name);
                                                  return std::string(GOD_FINGER_SOURCE_DIR);
                                                });
  ASSERT_EQ(asked, std::vector<std::string>{"some_pkg"});
  const int thing = scene.find("thing");
  ASSERT_GE(thing, 0);
  EXPECT_EQ(scene.bodies[thing].geometry.mesh_path, std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/meshes/torus.dae");
  try
  {
    parseUrdfScene(xml, kScenes, "test.urdf", [](const std::string&) { return std::string(); });
    FAIL() << "an unknown package was accepted";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(),
                 "URDF 'test.urdf': link 'thing': mesh 'package://some_pkg/urdf/meshes/torus.dae': ROS package "
                 "'some_pkg' not found");
  }
}

TEST(UrdfScene, WithoutAResolverPackagesAreTheFoldersAboveTheUrdfThatNameThem)
{
  // No ROS: the shipped torus scene's package://god_finger/... is the repository above it.
  const SceneDescription scene = loadUrdfScene(kScenes + "/table_torus.urdf");
  const int torus = scene.find("torus");
  ASSERT_GE(torus, 0);
  EXPECT_NE(scene.bodies[torus].geometry.mesh_path.find("/urdf/meshes/torus.dae"), std::string::npos);
}
TEST(UrdfScene, FileUrlsAndRelativePathsFindMeshesOutsideThePackage)
{
  // file:// takes an absolute path; a bare path is relative to the URDF's folder.
  const std::string meshes = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/meshes";
  const SceneDescription by_url = parseUrdfScene(sceneWith("<collision><geometry><mesh filename='file://" + meshes +
                                                           "/box.stl'/></geometry></collision>" + kGoodInertial),
                                                 "/nonexistent", "test.urdf");
  EXPECT_EQ(by_url.bodies[by_url.find("thing")].geometry.mesh_path, meshes + "/box.stl");
  EXPECT_EQ(errorOf(sceneWith("<collision><geometry><mesh filename='file:///no/such/box.stl'/></geometry></collision>" +
                              kGoodInertial)),
            "URDF 'test.urdf': link 'thing': mesh 'file:///no/such/box.stl' not found (looked for "
            "'/no/such/box.stl')");
  // A user's scene outside urdf/scenes (own_scene.test launches it): package:// and relative.
  const SceneDescription own =
      loadUrdfScene(std::string(GOD_FINGER_SOURCE_DIR) + "/test/data/own_scene/own_scene.urdf");
  ASSERT_EQ(own.bodies.size(), 3u);
  EXPECT_NE(own.bodies[own.find("own_widget")].geometry.mesh_path.find("/urdf/meshes/box.stl"), std::string::npos);
  EXPECT_EQ(own.bodies[own.find("own_pebble")].geometry.mesh_path,
            std::string(GOD_FINGER_SOURCE_DIR) + "/test/data/own_scene/../../../urdf/meshes/sphere.obj");
  EXPECT_DOUBLE_EQ(own.bodies[own.find("own_pebble")].material.rolling_friction, 0.002);
}
}  // namespace
}  // namespace god_finger
