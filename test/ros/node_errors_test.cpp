// rostest: every node (god_finger_delay too) stops on bad input with one clear line and exit code 1: bad parameters,
// a missing, malformed or incomplete URDF, an unavailable device backend. Runs the node
// binaries as a user would (rosrun-style, private parameters on the command line; lists set in
// node_errors.test) against rostest's master.
#include "tool_run.h"

#include <gtest/gtest.h>

#include <string>

namespace god_finger
{
namespace
{
const std::string kData = std::string(GOD_FINGER_SOURCE_DIR) + "/test/data";
const std::string kScene = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/table_sphere.urdf";

void expectFails(const std::string& binary, const std::string& arguments, const std::string& message)
{
  SCOPED_TRACE(arguments);
  const test::ToolRun result = test::runTool("timeout 20 " + binary, arguments);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.err.find(message), std::string::npos) << result.err;
}

TEST(NodeErrors, PhysicsNode)
{
  const std::string node = GOD_FINGER_PHYSICS_NODE;
  expectFails(node, "__name:=p1",
              "/p1: parameter '/p1/scene' is required (the scene's file: a URDF, an object's URDF or a scene list)");
  expectFails(node, "__name:=p2 _scene:=/nonexistent/scene.urdf",
              "URDF '/nonexistent/scene.urdf': no such file or not readable");
  expectFails(node, "__name:=p3 _scene:=" + kData + "/malformed.urdf", "not a valid URDF");
  expectFails(node, "__name:=p4 _scene:=" + kData + "/missing_mesh.urdf",
              "link 'widget': mesh 'meshes/not_here.stl' not found");
  expectFails(node, "__name:=p5 _scene:=" + kScene + " _r_max:=-0.01",
              "parameter '/p5/r_max' = -0.01 is out of range (0, 1000] (m)");
  expectFails(node, "__name:=p6 _scene:=" + kScene + " _rate:=5",
              "parameter '/p6/rate' = 5 is out of range [10, 10000] (Hz)");
  expectFails(node, "__name:=p7 _scene:=" + kScene + " _model:=point",
              "parameter '/p7/model' = 'point' is not one of god_object, god_finger, soft_finger");
  expectFails(node, "__name:=p8 _scene:=" + kScene + " _proxy_mass:=abc",
              "parameter '/p8/proxy_mass' must be a number (kg)");
  // An interface's profile is checked where the physics reads it (node_errors.test sets it).
  expectFails(node, "__name:=p10 _scene:=" + kScene,
              "parameter '/p10_finger/coupling_stiffness' must be a number (N/m)");
  expectFails(node, "__name:=p9 _scene:=" + kScene, "parameter '/p9/interfaces' must be a non-empty list of names");
}

TEST(NodeErrors, ServoNode)
{
  const std::string node = GOD_FINGER_SERVO_NODE;
  expectFails(node, "__name:=s1",
              "/s1: parameter '/s1/scene' is required (the scene's file: a URDF, an object's URDF or a scene list)");
  expectFails(node, "__name:=s2 _scene:=" + kScene + " _real_time_factor:=-1",
              "parameter '/s2/real_time_factor' = -1 is out of range [0, 1000] (dimensionless)");
  expectFails(
      node, "__name:=s3 _scene:=" + kScene + " _sim_time:=true",
      "interface 's3_finger' has the hardware backend 'falcon': a person's hand does not run on simulated time");
  expectFails(node, "__name:=s4 _scene:=" + kScene, "coupling unstable at this time step");
  expectFails(node, "__name:=s5 _scene:=" + kScene + " _sim_time:=true _model:=point",
              "parameter '/s5/model' = 'point' is not one of god_object, god_finger, soft_finger");
}

TEST(NodeErrors, HapticNode)
{
  const std::string node = GOD_FINGER_HAPTIC_NODE;
  expectFails(node, "__name:=h1 _workspace_scale:=0",
              "parameter '/h1/workspace_scale' = 0 is out of range (0, 1000] (dimensionless)");
  expectFails(node, "__name:=h2", "parameter '/h2/workspace_offset' must be a list of 3 numbers");
  expectFails(node, "__name:=h3 _local_coupling:=7", "parameter '/h3/local_coupling' must be true or false");
}

TEST(NodeErrors, DeviceDriverNode)
{
  const std::string node = GOD_FINGER_DEVICE_DRIVER_NODE;
  expectFails(node, "__name:=d1 _backend:=falcon", "backend 'falcon' needs libnifalcon");
  expectFails(node, "__name:=d2 _backend:=omni", "backend 'omni' needs the OpenHaptics HD API");
  expectFails(node, "__name:=d3 _backend:=mouse",
              "parameter '/d3/backend' = 'mouse' is not one of fake, interactive, replay, falcon, omni, fake_hand, "
              "pose_source");
  expectFails(node, "__name:=d4 _max_force:=-2", "parameter '/d4/max_force' = -2 is out of range (0, 10000] (N)");
  expectFails(node, "__name:=d5", "parameter '/d5/script' must be a list of [t, x, y, z] waypoints");
  expectFails(node, "__name:=dh _backend:=fake_hand",
              "device 'fake_hand' is a hand (one interface per finger): only the servo loop runs hands; use "
              "topology:=servo");
  expectFails(node, "__name:=d6", "does not come after the previous one");
  expectFails(node, "__name:=d7 _backend:=replay", "parameter '/d7/bag' is required by backend 'replay'");
  expectFails(node, "__name:=d8 _backend:=replay _bag:=/nonexistent/session.bag",
              "bag '/nonexistent/session.bag': cannot be read");
  // Hardware backends check their parameters before looking for the vendor library.
  expectFails(node, "__name:=d9 _backend:=falcon _index:=20", "parameter '/d9/index' = 20 is out of range [0, 15]");
  expectFails(node, "__name:=d10 _backend:=omni _calibration_timeout:=0",
              "parameter '/d10/calibration_timeout' = 0 is out of range (0, 600] (s)");
}
TEST(NodeErrors, DelayNode)
{
  const std::string node = GOD_FINGER_DELAY_NODE;
  expectFails(node, "__name:=l1 _loss:=2", "parameter '/l1/loss' = 2 is out of range [0, 1] (dimensionless)");
  expectFails(node, "__name:=l2 _delay:=-0.01", "parameter '/l2/delay' = -0.01 is out of range [0, 10] (s)");
  expectFails(node, "__name:=l3 _reorder:=yes", "parameter '/l3/reorder'");
}
}  // namespace
}  // namespace god_finger
