// The physics world against analytic answers: a proxy resting on a plane, the friction cone on
// flat and inclined planes, no tunnelling at 1 m/s, every sub-god-object inside Bullet's
// solver, model switching, determinism, and bad input.
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/mesh_io/mesh_loader.h"
#include "god_finger/scenarios/pad_fidelity.h"
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace god_finger
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

// A static 1 m x 1 m x 0.1 m slab whose top face is the plane through the origin with normal
// R_y(tilt) z.
SceneDescription planeScene(double tilt, double friction, double thickness = 0.1)
{
  BodyDescription slab;
  slab.name = "slab";
  slab.is_static = true;
  slab.geometry.kind = GeometryKind::kBox;
  slab.geometry.size = Eigen::Vector3d(1.0, 1.0, thickness);
  slab.material.friction = friction;
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()).toRotationMatrix();
  slab.pose.linear() = rotation;
  slab.pose.translation() = -0.5 * thickness * rotation.col(2);
  SceneDescription scene;
  scene.name = "plane";
  scene.bodies.push_back(slab);
  return scene;
}

Eigen::Vector3d planeNormal(double tilt)
{
  return Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()) * Eigen::Vector3d::UnitZ();
}

// Steps the world `seconds` long with fixed targets.
void run(GodFingerWorld* world, double seconds)
{
  const long steps = std::lround(seconds / world->params().time_step);
  for (long i = 0; i < steps; ++i)
  {
    world->step();
  }
}

TEST(GodFingerWorld, ProxyRestsOnAPlaneAndTheUserFeelsTheCouplingSpring)
{
  for (ContactModel model : {ContactModel::kGodObject, ContactModel::kGodFinger, ContactModel::kSoftFinger})
  {
    SCOPED_TRACE(contactModelName(model));
    WorldParams params;
    params.model = model;
    GodFingerWorld world(planeScene(0.0, 0.5), params);
    const int finger = world.addInterface(Eigen::Vector3d(0, 0, 0.02));
    world.setInterfaceTarget(finger, Eigen::Vector3d(0, 0, -0.01));
    run(&world, 1.0);
    const InterfaceState& state = world.interfaceState(finger);
    const double radius = params.coupling.proxy_radius;
    // On the surface, sunk no more than the pad's compliance allows (5.2 N on 1 point: 0.26 mm).
    EXPECT_NEAR(state.proxy_position.z(), radius, 3e-4);
    EXPECT_NEAR(state.proxy_position.x(), 0.0, 1e-9);
    // The hand feels k (p_GO - p_I): 400 N/m over 1.3 cm.
    const double expected = params.coupling.stiffness * (state.proxy_position.z() + 0.01);
    EXPECT_NEAR(state.user_force.z(), expected, 1e-3 * expected);
    EXPECT_NEAR(expected, 5.2, 0.15);
    ASSERT_EQ(state.contact_count, 1);
    EXPECT_EQ(state.contacts[0].body, 0);
    EXPECT_NEAR(state.contacts[0].normal.z(), 1.0, 1e-9);
  }
}

// A target at distance L from the resting proxy, at angle phi from the inward normal: the
// proxy sticks when tan(phi) < mu; otherwise it slides until the tangential stretch is mu
// times the normal stretch, i.e. by L (sin(phi) - mu cos(phi)).
struct ConeCase
{
  double tilt;
  double phi;
};

double slideDistance(ContactModel model, double tilt, double phi, double mu)
{
  WorldParams params;
  params.model = model;
  GodFingerWorld world(planeScene(tilt, mu), params);
  const Eigen::Vector3d normal = planeNormal(tilt);
  const Eigen::Vector3d tangent = normal.cross(Eigen::Vector3d::UnitY()).normalized();
  const double radius = params.coupling.proxy_radius;
  const Eigen::Vector3d rest = radius * normal;
  const int finger = world.addInterface(rest);
  // Press first (straight in), so that the contact exists before any tangential pull.
  const double length = 0.01;
  world.setInterfaceTarget(finger, rest - length * std::cos(phi) * normal);
  run(&world, 0.3);
  const Eigen::Vector3d pressed = world.interfaceState(finger).proxy_position;
  // Then the pull, ramped over 0.2 s as a hand moves (a jump would be a velocity spike that
  // the coupling's damper turns into a kick).
  for (int i = 1; i <= 200; ++i)
  {
    world.setInterfaceTarget(finger,
                             rest - length * std::cos(phi) * normal + (i / 200.0) * length * std::sin(phi) * tangent);
    world.step();
  }
  run(&world, 1.3);
  return (world.interfaceState(finger).proxy_position - pressed).dot(tangent);
}

TEST(GodFingerWorld, ProxyObeysTheFrictionConeOnFlatAndInclinedPlanes)
{
  const double mu = 0.5;  // the proxy's coefficient is 1: Bullet's product gives the plane's
  const double length = 0.01;
  for (double tilt : {0.0, kPi / 6, kPi / 3})
  {
    for (ContactModel model : {ContactModel::kGodObject, ContactModel::kGodFinger})
    {
      SCOPED_TRACE(std::string(contactModelName(model)) + " tilt " + std::to_string(tilt));
      // Inside the cone (tan phi = 0.8 mu): sticks.
      const double inside = std::atan(0.8 * mu);
      EXPECT_LT(std::abs(slideDistance(model, tilt, inside, mu)), 5e-5);
      // Outside (tan phi = 1.6 mu): slides by L (sin phi - mu cos phi) = 2.4 mm.
      const double outside = std::atan(1.6 * mu);
      const double expected = length * (std::sin(outside) - mu * std::cos(outside));
      EXPECT_NEAR(slideDistance(model, tilt, outside, mu), expected, 0.1 * expected);
    }
  }
}

TEST(GodFingerWorld, ProxyDoesNotTunnelThroughAThinPlateAtOneMetrePerSecond)
{
  WorldParams params;
  params.model = ContactModel::kGodObject;
  for (double thickness : {0.005, 0.002})
  {
    SCOPED_TRACE(thickness);
    GodFingerWorld world(planeScene(0.0, 0.5, thickness), params);
    const int finger = world.addInterface(Eigen::Vector3d(0, 0, 0.1));
    double lowest = 1.0;
    for (int i = 1; i <= 400; ++i)
    {
      // The hand at 1 m/s straight down, through the plate and 20 cm beyond it.
      world.setInterfaceTarget(finger, Eigen::Vector3d(0, 0, 0.1 - 1.0 * std::min(i, 300) * 1e-3));
      world.step();
      lowest = std::min(lowest, world.interfaceState(finger).proxy_position.z());
    }
    // The hand is 20 cm under the plate: the coupling saturates at max_force, and the proxy
    // stays on top, sunk by the pad's compliance: max_force / pad stiffness = 1 mm at rest,
    // at most half as much again while the impact rings down. Tunnelling would put it under
    // the plate (z < -thickness).
    const double sink = params.coupling.max_force / params.pad.stiffness;
    EXPECT_TRUE(world.interfaceState(finger).saturated);
    EXPECT_GT(lowest, params.coupling.proxy_radius - 1.5 * sink);
    EXPECT_NEAR(world.interfaceState(finger).proxy_position.z(), params.coupling.proxy_radius - sink, 1e-4);
  }
}

// The points layout: every sub-god-object is a solver point beside the true contact; the pad
// constraint: the true contact alone. On a static plane.
TEST(GodFingerWorld, EverySubGodObjectReachesTheSolver)
{
  for (const PadSolver solver : {PadSolver::kPoints, PadSolver::kConstraint})
  {
    for (int n_sgo : {3, 8, 32, 64})
    {
      SCOPED_TRACE(std::string(padSolverName(solver)) + ", " + std::to_string(n_sgo));
      WorldParams params;
      params.pad_solver = solver;
      params.contact.sub_god_objects = n_sgo;
      GodFingerWorld world(planeScene(0.0, 0.5), params);
      const int finger = world.addInterface(Eigen::Vector3d(0.01, 0.02, 0.003));
      world.setInterfaceTarget(finger, Eigen::Vector3d(0.01, 0.02, -0.01));
      run(&world, 0.3);
      // One true contact and n_sgo sub-god-objects, although a Bullet manifold holds 4 points.
      const int points = solver == PadSolver::kPoints ? 1 + n_sgo : 1;
      EXPECT_EQ(world.counters().solver_proxy_points, points);
      const InterfaceState& state = world.interfaceState(finger);
      ASSERT_EQ(state.contact_count, 1);
      EXPECT_EQ(state.contacts[0].sub_god_object_count, n_sgo);
      // Eq. 1: r = r_max (1 - exp(-s / D0')), s the coupling stretch into the object.
      const double stretch = state.proxy_position.z() - state.interface_position.z();
      const double radius = params.contact.max_radius * (1.0 - std::exp(-stretch / params.contact.distance_constant));
      EXPECT_NEAR(state.contacts[0].radius, radius, 1e-6);
      for (int i = 0; i < n_sgo; ++i)
      {
        // On the plane, at the radius from the contact point.
        EXPECT_NEAR(state.contacts[0].positions[i].z(), 0.0, 1e-9);
        EXPECT_NEAR((state.contacts[0].positions[i] - state.contacts[0].point).norm(), radius, 1e-6);
      }

      // Switching the model while running: the single point again.
      world.setContactModel(ContactModel::kGodObject);
      world.step();
      EXPECT_EQ(world.counters().solver_proxy_points, 1);
      world.setContactModel(ContactModel::kGodFinger);
      world.step();
      EXPECT_EQ(world.counters().solver_proxy_points, points);
    }
  }
}

// Pressed at rest on a static plane, every model's solve converges before its 60 iterations
// (solver_tolerance). A torsional row between the non-turning proxy and a static body has no
// effective mass: kept, its 0 / 0 residual made soft_finger run all 60 every step.
TEST(GodFingerWorld, RestingContactsStopIteratingEarly)
{
  for (const ContactModel model : contactModels())
  {
    SCOPED_TRACE(contactModelName(model));
    WorldParams params;
    params.model = model;
    GodFingerWorld world(planeScene(0.0, 0.5), params);
    const int finger = world.addInterface(Eigen::Vector3d(0.0, 0.0, 0.003));
    world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, -0.005));
    run(&world, 0.5);
    ASSERT_EQ(world.interfaceState(finger).contact_count, 1);
    EXPECT_LT(world.counters().solver_iterations, params.solver_iterations);
  }
}

// One finger pressing a free box on a table: the solver rows the finger adds beyond a
// god-object's three (normal, two friction): 3 per sub-god-object with the points layout (24
// for n_SGO = 8: 27 in all), the three torsional rows with the pad constraint (6 in all).
TEST(GodFingerWorld, ThePadConstraintIsSixRowsPerFinger)
{
  auto rows = [](ContactModel model, PadSolver solver)
  {
    const SceneDescription scene = padLoadScene(PadLoad::kTwist, 0.8);
    WorldParams params;
    params.model = model;
    params.pad_solver = solver;
    GodFingerWorld world(scene, params);
    const int finger = world.addInterface(Eigen::Vector3d(0.0, 0.0, 0.03));
    world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, 0.015));
    run(&world, 0.3);
    EXPECT_EQ(world.interfaceState(finger).contact_count, 1);
    return world.counters().solver_contact_rows;
  };
  const int point = rows(ContactModel::kGodObject, PadSolver::kPoints);
  EXPECT_EQ(rows(ContactModel::kGodFinger, PadSolver::kPoints) - point, 3 * 8);
  EXPECT_EQ(rows(ContactModel::kGodFinger, PadSolver::kConstraint) - point, 3);
}

// A pad that held a twist (warm-started torsional rows, an orientation anchor pulling the box
// back) lets go of it without a kick when the twist ends and the finger lifts off.
TEST(GodFingerWorld, APadThatHeldATwistLetsGoWithoutAKick)
{
  const SceneDescription scene = padLoadScene(PadLoad::kTwist, 0.8);  // a 2 cm box, 0.2 kg
  WorldParams params;
  GodFingerWorld world(scene, params);
  const double rest = 0.02 + params.coupling.proxy_radius;
  const int finger = world.addInterface(Eigen::Vector3d(0.0, 0.0, rest));
  world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, rest - 0.005));  // 2 N
  run(&world, 0.5);
  // 80 % of the uniform disk's (2/3) mu N a, held 0.5 s, then the hand goes up 1 cm per step.
  const InterfaceState& state = world.interfaceState(finger);
  ASSERT_EQ(state.contact_count, 1);
  const double torque = 0.8 * 2.0 / 3.0 * 0.8 * state.user_force.norm() * state.contacts[0].radius;
  for (int i = 0; i < 500; ++i)
  {
    world.applyBodyWrench(1, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, torque));
    world.step();
  }
  EXPECT_LT(std::abs(world.bodyState(1).angular_velocity.z()), 1e-6);
  double fastest = 0.0;
  for (int i = 0; i < 200; ++i)
  {
    world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, rest + 0.01 * (i + 1)));
    world.step();
    fastest = std::max(fastest, std::abs(world.bodyState(1).angular_velocity.z()));
  }
  std::printf("[ let go ] held %.4f N m; fastest turn after %.3g rad/s\n", torque, fastest);
  EXPECT_EQ(world.interfaceState(finger).contact_count, 0);
  // The held impulse would turn the box at 0.8 torque dt / I = 0.01-0.02 rad/s.
  EXPECT_LT(fastest, 1e-3);
}

// A ball on a table, pushed by a finger along a fixed script.
std::vector<double> ballTrajectory(GodFingerWorld* world, int finger)
{
  std::vector<double> trajectory;
  for (int i = 0; i < 800; ++i)
  {
    const double t = (i + 1) * 1e-3;
    world->setInterfaceTarget(finger, Eigen::Vector3d(-0.06 + 0.1 * t, 0.001, 0.05));
    world->step();
    const BodyState state = world->bodyState(1);
    for (int k = 0; k < 3; ++k)
    {
      trajectory.push_back(state.center_of_mass[k]);
      trajectory.push_back(state.angular_velocity[k]);
    }
  }
  return trajectory;
}

SceneDescription ballScene()
{
  SceneDescription scene = planeScene(0.0, 0.6);
  BodyDescription ball;
  ball.name = "ball";
  ball.geometry.kind = GeometryKind::kSphere;
  ball.geometry.radius = 0.04;
  ball.mass = 0.1;
  ball.inertia = Eigen::Matrix3d::Identity() * 6.4e-5;
  ball.pose.translation() = Eigen::Vector3d(0, 0, 0.04);
  scene.bodies.push_back(ball);
  return scene;
}

TEST(GodFingerWorld, SameInputsGiveTheSameTrajectoryBitForBit)
{
  WorldParams params;
  GodFingerWorld first(ballScene(), params);
  GodFingerWorld second(ballScene(), params);
  const int a = first.addInterface(Eigen::Vector3d(-0.06, 0.001, 0.05));
  const int b = second.addInterface(Eigen::Vector3d(-0.06, 0.001, 0.05));
  const std::vector<double> one = ballTrajectory(&first, a);
  const std::vector<double> two = ballTrajectory(&second, b);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)), 0);
  // The finger did move the ball: the comparison is not of two resting states.
  EXPECT_GT(one[one.size() - 6], 0.005);
  // After reset the same run repeats exactly.
  first.reset();
  const std::vector<double> three = ballTrajectory(&first, a);
  EXPECT_EQ(std::memcmp(one.data(), three.data(), one.size() * sizeof(double)), 0);
}

// Issue 18: a hand that starts inside the table (a workspace offset too low) is refused with the
// body and the position named, not given a proxy inside it (nor one lifted out silently); the
// error has its own type (ProxyInsideBodyError, an InputError), which the physics node catches
// to respawn under a pressing hand, and other bad input does not throw it.
TEST(GodFingerWorld, AProxyNeverStartsInsideABody)
{
  GodFingerWorld world(planeScene(0.0, 0.5), WorldParams());
  EXPECT_THROW(world.addInterface(Eigen::Vector3d(0.1, -0.2, -0.03)), ProxyInsideBodyError);
  try
  {
    world.addInterface(Eigen::Vector3d(NAN, 0.0, 0.1));
    FAIL() << "a non-finite position";
  }
  catch (const ProxyInsideBodyError&)
  {
    FAIL() << "a non-finite position is no proxy inside a body";
  }
  catch (const InputError&)
  {
  }
  try
  {
    world.addInterface(Eigen::Vector3d(0.1, -0.2, -0.03));
    FAIL() << "a proxy inside the slab";
  }
  catch (const InputError& error)
  {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("interface 0 would start inside body 'slab': its proxy at (0.1, -0.2, -0.03) m", 0), 0u)
        << message;
    EXPECT_NE(message.find("workspace_offset"), std::string::npos) << message;
  }
  EXPECT_EQ(world.interfaceCount(), 0);
  // Touching (the sphere dips into the top face, its centre above it) and above are fine.
  EXPECT_EQ(world.addInterface(Eigen::Vector3d(0.0, 0.0, 0.5 * world.params().coupling.proxy_radius)), 0);
  EXPECT_EQ(world.addInterface(Eigen::Vector3d(0.0, 0.0, 0.1)), 1);
  run(&world, 0.1);
  EXPECT_GT(world.interfaceState(0).proxy_position.z(), 0.0);
}

TEST(GodFingerWorld, BadInputIsRejectedAndLosesNothing)
{
  WorldParams params;
  params.pad.stiffness = -1.0;
  try
  {
    GodFingerWorld world(planeScene(0.0, 0.5), params);
    FAIL() << "no error";
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("parameter 'pad_stiffness' = -1"), std::string::npos) << error.what();
  }

  GodFingerWorld world(planeScene(0.0, 0.5), WorldParams());
  const int finger = world.addInterface(Eigen::Vector3d(0, 0, 0.05));
  EXPECT_THROW(world.addInterface(Eigen::Vector3d(NAN, 0, 0)), InputError);
  world.setInterfaceTarget(finger, Eigen::Vector3d(0, 0, 0.04));
  world.setInterfaceTarget(finger, Eigen::Vector3d(INFINITY, 0, 0));
  world.setInterfaceTarget(finger, Eigen::Vector3d(0, NAN, 0));
  EXPECT_EQ(world.counters().rejected_targets, 2);
  run(&world, 0.5);
  // The last good target stands.
  EXPECT_NEAR(world.interfaceState(finger).proxy_position.z(), 0.04, 1e-4);

  ContactParams bad = world.params().contact;
  bad.alpha = 0.5;
  EXPECT_THROW(world.setContactParams(bad), InputError);
  EXPECT_DOUBLE_EQ(world.params().contact.alpha, ContactParams().alpha);
}
}  // namespace
}  // namespace god_finger

namespace god_finger
{
namespace
{
// The concave scene: the torus collides through its convex decomposition, its contact areas
// walk on the original mesh, and it rests on the table instead of falling through its hole.
TEST(GodFingerWorld, ConcaveMeshObjectRestsAndTakesContactAreas)
{
  const SceneDescription scene = loadUrdfScene(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes/table_torus.urdf");
  GodFingerWorld world(scene, WorldParams());
  const int torus = scene.find("torus");
  ASSERT_GE(torus, 0);
  const BodyState start = world.bodyState(torus);
  // A finger presses down on the top of the ring (R = 6 cm, r = 2 cm).
  const Eigen::Vector3d top = start.center_of_mass + Eigen::Vector3d(0.06, 0, 0.02);
  const int finger = world.addInterface(top + Eigen::Vector3d(0, 0, 0.01));
  world.setInterfaceTarget(finger, top - Eigen::Vector3d(0, 0, 0.005));
  run(&world, 1.0);
  const BodyState end = world.bodyState(torus);
  EXPECT_NEAR(end.center_of_mass.z(), start.center_of_mass.z(), 1e-3);
  const InterfaceState& state = world.interfaceState(finger);
  ASSERT_EQ(state.contact_count, 1);
  EXPECT_EQ(state.contacts[0].body, torus);
  EXPECT_EQ(state.contacts[0].sub_god_object_count, world.params().contact.sub_god_objects);
  EXPECT_GT(state.contacts[0].radius, 0.005);
  // The walk ran on the original mesh, not on the decomposition's hulls.
  const TriangleMesh original = loadTriangleMesh(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/meshes/torus.dae");
  EXPECT_EQ(world.walkMesh(torus).triangleCount(), original.triangleCount());
  EXPECT_GT(original.triangleCount(), 500);
}
}  // namespace
}  // namespace god_finger
