// Articulated objects: bodies on URDF's revolute and prismatic joints (Bullet's hinge and slider
// constraints). A door pushed by a finger near its edge turns about its hinge and nothing else,
// stops at its limit when pushed on, and resists by its damping; a handle-less drawer pressed
// and pulled by a finger slides out on its runners as far as the finger's friction carries it;
// the joints' states read back what the bodies did.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/physics/joint_measure.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace god_finger
{
namespace
{
const std::string kScenes = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/";

// A finger `lever` m from the hinge at the door's mid-height pushes it along its arc at `speed`
// rad/s up to `angle` rad and holds `hold` s; returns the world after it.
struct DoorRun
{
  double opened = 0.0;          // rad, the hinge's position at the end
  double hand_force = 0.0;      // N, mean force on the hand along the motion while turning
  double worst_off_axis = 0.0;  // m, how far the door's hinge line strayed
  double speed = 0.0;           // rad/s, the hinge's mean speed while turning
};

DoorRun pushDoor(const SceneDescription& scene, ContactModel model, double angle, double speed, double hold)
{
  WorldParams params;
  params.model = model;
  GodFingerWorld world(scene, params);
  const double lever = 0.27;
  const double z = 0.208;
  const auto on_arc = [&](double a, double off)
  { return Eigen::Vector3d(lever * std::cos(a) + off * std::sin(a), lever * std::sin(a) - off * std::cos(a), z); };
  const int finger = world.addInterface(on_arc(0.0, 0.04));
  const double inside = 0.0075 + 0.003 - 0.004;
  const int door = scene.find("door");
  DoorRun run;
  int samples = 0;
  const double turning = angle / speed;
  const int steps = static_cast<int>(std::lround((0.5 + turning + hold) * 1000));
  for (int i = 1; i <= steps; ++i)
  {
    const double t = i * 1e-3;
    const double a = t < 0.5 ? 0.0 : std::min(angle, speed * (t - 0.5));
    world.setInterfaceTarget(finger, on_arc(a, t < 0.5 ? 0.04 + (inside - 0.04) * t / 0.5 : inside));
    world.step();
    const BodyState state = world.bodyState(door);
    // The hinge line: the link frame's origin stays on the z axis at z = 0.005.
    run.worst_off_axis = std::max(run.worst_off_axis, (state.pose.translation() - Eigen::Vector3d(0, 0, 0.005)).norm());
    if (t > 0.5 + 0.25 * turning && t < 0.5 + 0.75 * turning)
    {
      const JointState hinge = world.jointState(0);
      const Eigen::Vector3d along(-std::sin(hinge.position), std::cos(hinge.position), 0.0);
      run.hand_force += -world.interfaceState(finger).user_force.dot(along);
      run.speed += hinge.velocity;
      ++samples;
    }
  }
  run.hand_force /= samples;
  run.speed /= samples;
  run.opened = world.jointState(0).position;
  return run;
}

TEST(Articulated, ADoorPushedNearItsEdgeTurnsOnItsHingeAndTheHandFeelsItsDamping)
{
  const SceneDescription scene = loadUrdfScene(kScenes + "door.urdf");
  ASSERT_EQ(scene.joints.size(), 1u);
  const JointDescription& hinge = scene.joints[0];
  EXPECT_EQ(hinge.kind, JointKind::kRevolute);
  EXPECT_EQ(hinge.parent, -1);
  EXPECT_EQ(scene.bodies[hinge.child].name, "door");
  const DoorRun run = pushDoor(scene, ContactModel::kGodFinger, 65.0 * M_PI / 180.0, 0.4, 0.5);
  // Without damping: what remains is the hinge's friction (and the door's inertia).
  SceneDescription free_swinging = scene;
  free_swinging.joints[0].damping = 0.0;
  const DoorRun undamped = pushDoor(free_swinging, ContactModel::kGodFinger, 65.0 * M_PI / 180.0, 0.4, 0.5);
  const double damping_force = hinge.damping * run.speed / 0.27;
  std::printf(
      "articulated: door opened %.3f rad, hinge off its line %.3f mm, hand force %.4f N at %.3f rad/s (%.4f N "
      "without damping; the damping's share %.4f N)\n",
      run.opened, 1e3 * run.worst_off_axis, run.hand_force, run.speed, undamped.hand_force, damping_force);
  // Opened with the finger to 65 degrees; when the finger stops the door swings on, at most by
  // its speed times the hinge's time constant (its inertia about the hinge over the damping).
  const BodyDescription& door = scene.bodies[hinge.child];
  const double arm = door.inertial_origin.translation().head<2>().norm();
  const double inertia = door.inertia(2, 2) + door.mass * arm * arm;
  EXPECT_GT(run.opened, 60.0 * M_PI / 180.0);
  EXPECT_LT(run.opened, 65.0 * M_PI / 180.0 + run.speed * inertia / hinge.damping);
  EXPECT_NEAR(run.speed, 0.4, 0.02) << "the door follows the finger's arc";
  // Turned about the hinge and nothing else: the hinge line stays put.
  EXPECT_LT(run.worst_off_axis, 1e-3);
  // The hand feels the damping: d w / lever more than without it, within 20 %.
  EXPECT_NEAR(run.hand_force - undamped.hand_force, damping_force, 0.2 * damping_force);
  EXPECT_GT(undamped.hand_force, 0.0) << "the hinge's friction still asks a push";
}

TEST(Articulated, ADoorPushedPastItsLimitStopsThere)
{
  const SceneDescription scene = loadUrdfScene(kScenes + "door.urdf");
  // The finger's arc runs to 115 degrees, past the 100-degree (1.75 rad) limit, and pushes on.
  const DoorRun run = pushDoor(scene, ContactModel::kGodFinger, 2.0, 0.8, 1.0);
  std::printf("articulated: door pushed past its limit stands at %.4f rad (limit %.4f)\n", run.opened,
              scene.joints[0].upper);
  EXPECT_NEAR(run.opened, scene.joints[0].upper, 0.01);
}

// Spun open by a torque (2 N m for 0.2 s: about 1.5 rad/s when it reaches the stop), with no
// finger, the door stops at its 100-degree limit and does not bounce back off it.
TEST(Articulated, ADoorSwungIntoItsStopStaysThere)
{
  const SceneDescription scene = loadUrdfScene(kScenes + "door.urdf");
  GodFingerWorld world(scene, WorldParams());
  const int door = scene.find("door");
  double highest = 0.0;
  double lowest_after = 10.0;
  bool reached = false;
  for (int i = 0; i < 2500; ++i)
  {
    if (i < 200)
    {
      world.applyBodyWrench(door, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 2.0));
    }
    world.step();
    const double angle = world.jointState(0).position;
    highest = std::max(highest, angle);
    reached = reached || angle > scene.joints[0].upper - 0.01;
    if (reached)
    {
      lowest_after = std::min(lowest_after, angle);
    }
  }
  std::printf("articulated: door swung into its stop: at most %.4f rad (limit %.4f), at least %.4f rad after\n",
              highest, scene.joints[0].upper, lowest_after);
  ASSERT_TRUE(reached);
  EXPECT_LT(highest, scene.joints[0].upper + 0.05) << "the stop holds";
  // A stop with restitution (Bullet's default relaxation 1.0) throws it back 0.02 rad here.
  EXPECT_GT(lowest_after, scene.joints[0].upper - 0.005) << "no bounce off the stop";
}

// A finger presses the drawer's top with about 3 N (7.5 mm of coupling) and pulls 12 cm along
// the runners in 2 s.
double pullDrawer(const SceneDescription& scene, ContactModel model, double* slip)
{
  WorldParams params;
  params.model = model;
  GodFingerWorld world(scene, params);
  const double press = 0.10 + 0.003 - 0.0075;
  const int finger = world.addInterface(Eigen::Vector3d(0.05, 0.003, 0.14));
  for (int i = 1; i <= 2700; ++i)
  {
    const double t = i * 1e-3;
    const double x = 0.05 + (t < 0.7 ? 0.0 : 0.12 * std::min(1.0, (t - 0.7) / 2.0));
    const double z = t < 0.5 ? 0.14 + (press - 0.14) * t / 0.5 : press;
    world.setInterfaceTarget(finger, Eigen::Vector3d(x, 0.003, z));
    world.step();
  }
  const double pulled = world.jointState(0).position;
  *slip = 0.12 - pulled;
  return pulled;
}

TEST(Articulated, AHandleLessDrawerIsPulledOutByThePadsFriction)
{
  const SceneDescription scene = loadUrdfScene(kScenes + "drawer.urdf");
  ASSERT_EQ(scene.joints.size(), 1u);
  EXPECT_EQ(scene.joints[0].kind, JointKind::kPrismatic);
  EXPECT_EQ(scene.bodies[scene.joints[0].parent].name, "cabinet");
  for (const ContactModel model : {ContactModel::kGodFinger, ContactModel::kGodObject})
  {
    double slip = 0.0;
    const double pulled = pullDrawer(scene, model, &slip);
    std::printf("articulated: drawer pulled %.4f m by %s (the finger slid %.4f m on it)\n", pulled,
                contactModelName(model), slip);
    // Friction carries the drawer with the finger: 12 cm less a millimetre or two of slip. The
    // point does it as well as the pad: Coulomb friction's bound is mu N either way, and the runners
    // ask 0.62 N of the 1.9 N a 3 N press gives (the "a point cannot" does not hold here).
    EXPECT_NEAR(pulled, 0.12, 0.005) << contactModelName(model);
  }
  // Without the finger the drawer stays where it was put (its runners' friction holds it).
  GodFingerWorld alone(scene, WorldParams());
  for (int i = 0; i < 1000; ++i)
  {
    alone.step();
  }
  EXPECT_NEAR(alone.jointState(0).position, 0.0, 1e-4);
}

TEST(Articulated, AJointsStateIsMeasuredFromItsBodies)
{
  JointDescription hinge;
  hinge.kind = JointKind::kRevolute;
  hinge.joint_in_parent.translation() = Eigen::Vector3d(1, 0, 0);
  hinge.axis = Eigen::Vector3d::UnitZ();
  BodyState child;
  child.pose.translation() = Eigen::Vector3d(1, 0, 0);
  child.pose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  child.angular_velocity = Eigen::Vector3d(0.1, 0.0, -0.3);
  const JointState turned = measureJoint(hinge, nullptr, child);
  EXPECT_NEAR(turned.position, 0.7, 1e-12);
  EXPECT_NEAR(turned.velocity, -0.3, 1e-12);
  JointDescription slide = hinge;
  slide.kind = JointKind::kPrismatic;
  slide.axis = Eigen::Vector3d::UnitX();
  BodyState parent;
  parent.pose.translation() = Eigen::Vector3d(0, 2, 0);
  BodyState drawn;
  drawn.pose.translation() = Eigen::Vector3d(1.25, 2, 0);
  drawn.linear_velocity = Eigen::Vector3d(0.5, 0.1, 0);
  const JointState out = measureJoint(slide, &parent, drawn);
  EXPECT_NEAR(out.position, 0.25, 1e-12);
  EXPECT_NEAR(out.velocity, 0.5, 1e-12);
}

TEST(Articulated, JointsThatCannotBeBuiltAreRefusedNamingThem)
{
  SceneDescription scene = loadUrdfScene(kScenes + "door.urdf");
  scene.joints[0].child = scene.find("post");
  try
  {
    GodFingerWorld world(scene, WorldParams());
    FAIL() << "a joint moving a fixed body was accepted";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "joint 'hinge': its child 'post' is fixed: a joint moves a free body");
  }
  scene = loadUrdfScene(kScenes + "door.urdf");
  scene.joints[0].lower = 1.0;
  scene.joints[0].upper = 0.5;
  EXPECT_THROW(GodFingerWorld(scene, WorldParams()), InputError);
  scene = loadUrdfScene(kScenes + "door.urdf");
  scene.joints.push_back(scene.joints[0]);
  scene.joints[1].name = "second";
  try
  {
    GodFingerWorld world(scene, WorldParams());
    FAIL() << "a body on two joints was accepted";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "joint 'second': 'door' is already the child of joint 'hinge'");
  }
}
}  // namespace
}  // namespace god_finger
