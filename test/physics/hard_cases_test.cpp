// Numerical stability on hard cases (issue 5): every case asserts no NaN, a bounded object
// energy or motion, no penetration beyond a stated tolerance, and that it ends (each runs a
// fixed number of steps). The bounds are physical, stated where they are checked.
#include "device_profile_file.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

namespace god_finger
{
namespace
{
constexpr double kG = 9.81;

BodyDescription tableAt(const Eigen::Vector3d& origin, double half_size = 1.0)
{
  BodyDescription table;
  table.name = "table";
  table.is_static = true;
  table.geometry.kind = GeometryKind::kBox;
  table.geometry.size = Eigen::Vector3d(2.0 * half_size, 2.0 * half_size, 0.05);
  table.pose.translation() = origin + Eigen::Vector3d(0.0, 0.0, -0.025);
  return table;
}

// A free box of edge `size` (m) and `mass` (kg) resting on the table at `origin`.
BodyDescription boxAt(const Eigen::Vector3d& origin, double size, double mass)
{
  BodyDescription box;
  box.name = "box";
  box.geometry.kind = GeometryKind::kBox;
  box.geometry.size = Eigen::Vector3d::Constant(size);
  box.mass = mass;
  box.inertia = Eigen::Matrix3d::Identity() * mass * size * size / 6.0;
  box.pose.translation() = origin + Eigen::Vector3d(0.0, 0.0, 0.5 * size);
  box.material.friction = 0.8;
  return box;
}

// What a run saw, step by step.
struct RunRecord
{
  long nan_steps = 0;
  double deepest = 0.0;         // m, world.counters().deepest_penetration
  double max_speed = 0.0;       // m/s, of body 1's centre of mass
  double max_kinetic = 0.0;     // J, of body 1
  double max_user_force = 0.0;  // N, over all interfaces
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  double max_displacement = 0.0;  // m, of body 1's centre of mass from its start
};

// Steps `world` `steps` times; before each step `targets(i)` sets the interface targets.
RunRecord runChecked(GodFingerWorld* world, long steps, const std::function<void(long)>& targets, int body = 1)
{
  RunRecord record;
  const BodyDescription& description = world->scene().bodies[body];
  record.start = world->bodyState(body).center_of_mass;
  for (long i = 0; i < steps; ++i)
  {
    targets(i);
    world->step();
    const BodyState state = world->bodyState(body);
    bool finite =
        state.pose.matrix().allFinite() && state.linear_velocity.allFinite() && state.angular_velocity.allFinite();
    for (int f = 0; f < world->interfaceCount(); ++f)
    {
      const InterfaceState& finger = world->interfaceState(f);
      finite = finite && finger.proxy_position.allFinite() && finger.user_force.allFinite();
      record.max_user_force = std::max(record.max_user_force, finger.user_force.norm());
    }
    if (!finite)
    {
      ++record.nan_steps;
      continue;
    }
    record.deepest = std::max(record.deepest, world->counters().deepest_penetration);
    record.max_speed = std::max(record.max_speed, state.linear_velocity.norm());
    const Eigen::Vector3d w = state.pose.linear().transpose() * state.angular_velocity;
    const double kinetic =
        0.5 * description.mass * state.linear_velocity.squaredNorm() + 0.5 * w.dot(description.inertia * w);
    record.max_kinetic = std::max(record.max_kinetic, kinetic);
    record.max_displacement = std::max(record.max_displacement, (state.center_of_mass - record.start).norm());
  }
  return record;
}

// Every case runs with either pad solver (world_params.h).
class HardCases : public ::testing::TestWithParam<PadSolver>
{
 protected:
  WorldParams fingerParams() const
  {
    WorldParams params;
    params.pad_solver = GetParam();
    return params;
  }
};

// Presses a finger `press` (m) into the top of body 1 (top at `top`) over 0.3 s, then holds.
std::function<void(long)> pressOnTop(GodFingerWorld* world, int finger, const Eigen::Vector3d& top, double press)
{
  return [=](long i)
  {
    const double s = std::min(1.0, (i + 1) * world->params().time_step / 0.3);
    const double radius = world->params().coupling.proxy_radius;
    world->setInterfaceTarget(finger, top + Eigen::Vector3d(0.0, 0.0, radius + 0.01 * (1.0 - s) - press * s));
  };
}

TEST_P(HardCases, ObjectsOfOneMillimetreAndOfTenMetres)
{
  // 1 mm: a 1 mm cube of 2 mg, touched by a 0.3 mm proxy with a 0.5 mm pad, pressed 0.2 mm.
  {
    WorldParams params = fingerParams();
    params.coupling.proxy_radius = 0.0003;
    params.coupling.proxy_mass = 2e-4;
    params.coupling.damping = 0.04;
    params.coupling.stiffness = 40.0;
    params.contact.max_radius = 0.0005;
    params.contact.distance_constant = 0.0001;
    SceneDescription scene;
    scene.bodies = {tableAt(Eigen::Vector3d::Zero()), boxAt(Eigen::Vector3d::Zero(), 0.001, 2e-6)};
    GodFingerWorld world(scene, params);
    const int finger = world.addInterface(Eigen::Vector3d(0.0, 0.0, 0.02));
    const RunRecord record =
        runChecked(&world, 1000, pressOnTop(&world, finger, Eigen::Vector3d(0.0, 0.0, 0.001), 0.0002));
    std::printf("[ 1 mm cube ] deepest %.3g m, displaced %.3g m, max speed %.3g m/s\n", record.deepest,
                record.max_displacement, record.max_speed);
    EXPECT_EQ(record.nan_steps, 0);
    // Pressed with k * 0.2 mm = 8 mN, 400 times its weight: the cube stays put on the table
    // (moves less than a tenth of its size) and is not pierced deeper than a tenth of it.
    EXPECT_LT(record.max_displacement, 1e-4);
    EXPECT_LT(record.deepest, 1e-4);
    EXPECT_GT(world.interfaceState(finger).contact_count, 0);
  }
  // 10 m: a 10 m cube of 1000 t on a 40 m table, pressed 1 cm by the default finger.
  {
    SceneDescription scene;
    scene.bodies = {tableAt(Eigen::Vector3d::Zero(), 20.0), boxAt(Eigen::Vector3d::Zero(), 10.0, 1e6)};
    GodFingerWorld world(scene, fingerParams());
    const int finger = world.addInterface(Eigen::Vector3d(1.0, 1.0, 10.05));
    const RunRecord record =
        runChecked(&world, 1000, pressOnTop(&world, finger, Eigen::Vector3d(1.0, 1.0, 10.0), 0.01));
    std::printf("[ 10 m cube ] deepest %.3g m, displaced %.3g m, area radius %.4f m\n", record.deepest,
                record.max_displacement, world.interfaceState(finger).contacts[0].radius);
    EXPECT_EQ(record.nan_steps, 0);
    EXPECT_LT(record.max_displacement, 1e-3);  // settles under its 9.8 MN weight by < 1 mm
    EXPECT_LT(record.deepest, 2e-3);           // the finger's 4 N sink the pad < 2 mm
    ASSERT_GT(world.interfaceState(finger).contact_count, 0);
    EXPECT_GT(world.interfaceState(finger).contacts[0].sub_god_object_count, 0);
  }
}

TEST_P(HardCases, SceneTenKilometresFromTheOriginBehavesAsAtTheOrigin)
{
  auto pressAt = [this](const Eigen::Vector3d& origin)
  {
    SceneDescription scene;
    scene.bodies = {tableAt(origin), boxAt(origin, 0.05, 0.2)};
    auto world = std::make_unique<GodFingerWorld>(scene, fingerParams());
    const int finger = world->addInterface(origin + Eigen::Vector3d(0.005, 0.0, 0.07));
    const RunRecord record = runChecked(
        world.get(), 800, pressOnTop(world.get(), finger, origin + Eigen::Vector3d(0.005, 0.0, 0.05), 0.005));
    return std::make_pair(record, world->interfaceState(finger));
  };
  const auto near = pressAt(Eigen::Vector3d::Zero());
  const auto far = pressAt(Eigen::Vector3d(1e4, 1e4, 0.0));
  EXPECT_EQ(far.first.nan_steps, 0);
  std::printf("[ 1e4 m ] user force %.6f N (origin %.6f N), radius %.6f m (origin %.6f m)\n", far.second.user_force.z(),
              near.second.user_force.z(), far.second.contacts[0].radius, near.second.contacts[0].radius);
  // float64 at 1e4 m resolves 2e-12 m: the same press gives the same force and area to well
  // under a per mille.
  EXPECT_NEAR(far.second.user_force.z(), near.second.user_force.z(), 1e-3 * std::abs(near.second.user_force.z()));
  EXPECT_NEAR(far.second.contacts[0].radius, near.second.contacts[0].radius, 1e-6);
  EXPECT_EQ(far.second.contacts[0].sub_god_object_count, near.second.contacts[0].sub_god_object_count);
  EXPECT_LT(far.first.max_displacement, 1e-3);
}

TEST_P(HardCases, ObjectsAThousandTimesHeavierAndLighterThanTheProxy)
{
  // A 5 cm box of ratio x the proxy's 20 g on the table, pressed 5 mm (2 N) from the top, then
  // dragged 3 cm along x at 3 cm/s.
  //
  // Bullet's sequential impulses transfer about one object-mass of momentum per iteration
  // through a proxy -> light object -> table stack: without the support passes
  // (WorldParams::support_passes = 0, src/physics/solver/support_pass.h) an object much lighter
  // than the proxy sank into the table while pressed: 0.14 mm at 1/10, 1.8 mm at 1/100, 7.2 mm
  // at 1/1000. With them it rests within 0.2 mm down to 1/1000, and is still dragged along.
  const double proxy_mass = fingerParams().coupling.proxy_mass;
  for (double ratio : {1000.0, 0.1, 0.01, 0.001})
  {
    SCOPED_TRACE(ratio);
    SceneDescription scene;
    scene.bodies = {tableAt(Eigen::Vector3d::Zero()), boxAt(Eigen::Vector3d::Zero(), 0.05, ratio * proxy_mass)};
    GodFingerWorld world(scene, fingerParams());
    const int finger = world.addInterface(Eigen::Vector3d(0.0, 0.0, 0.07));
    double lowest_centre = INFINITY;
    const RunRecord record =
        runChecked(&world, 2300,
                   [&](long i)
                   {
                     const double t = (i + 1) * 1e-3;
                     const double s = std::min(1.0, t / 0.3);
                     const double x = 0.03 * std::clamp((t - 0.3) / 1.0, 0.0, 1.0);
                     world.setInterfaceTarget(finger, Eigen::Vector3d(x, 0.0, 0.053 + 0.01 * (1.0 - s) - 0.005 * s));
                     lowest_centre = std::min(lowest_centre, world.bodyState(1).center_of_mass.z());
                   });
    std::printf("[ mass ratio %g ] deepest %.3g m, lowest centre %.4f m, max speed %.3g m/s, max kinetic %.3g J\n",
                ratio, record.deepest, lowest_centre, record.max_speed, record.max_kinetic);
    EXPECT_EQ(record.nan_steps, 0);
    // Energy: all the object can get is the work of a saturated coupling (20 N) over the 3 cm
    // the hand moves, 0.6 J.
    EXPECT_LT(record.max_kinetic, 0.6);
    // It ends at most where the hand took it (3 cm), plus its own half size.
    EXPECT_LT(record.max_displacement, 0.03 + 0.025);
    // Never through the table: the centre stays above the table's top by more than a quarter
    // of the box.
    EXPECT_GT(lowest_centre, 0.25 * 0.05);
    EXPECT_LT(record.deepest, 2e-3);
    // The hand drags along +x: the box never goes the other way (without the support passes the
    // 1/1000 box ended 2.9 cm behind its start). A box 100 and 1000 times lighter than the proxy
    // follows the hand all the way (3 cm) under the pad constraint; under the paper's points,
    // whose friction in the stack converges as slowly as the normal did, 2.2-2.5 cm of the 3.
    const double end_x = world.bodyState(1).center_of_mass.x();
    std::printf("[ mass ratio %g ] ends %.4f m along x (the hand: 0.03 m)\n", ratio, end_x);
    EXPECT_GT(end_x, -1e-3);
    if (ratio <= 0.01)
    {
      EXPECT_GT(end_x, GetParam() == PadSolver::kConstraint ? 0.0295 : 0.02);
    }
  }
}

// The proxy in free space (no gravity) after a 1 cm step of the hand, with `coupling`: the
// lowest and highest z it takes over its last 0.2 s of 3 s.
std::pair<double, double> stepResponse(const WorldParams& params, const CouplingProfile& coupling)
{
  GodFingerWorld world(SceneDescription(), params);
  const int finger = world.addInterface(Eigen::Vector3d::Zero(), coupling);
  double low = INFINITY;
  double high = -INFINITY;
  for (int i = 0; i < 3000; ++i)
  {
    world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, 0.01));
    world.step();
    const double z = world.interfaceState(finger).proxy_position.z();
    if (!std::isfinite(z))
    {
      return {NAN, NAN};
    }
    if (i >= 2800)
    {
      low = std::min(low, z);
      high = std::max(high, z);
    }
  }
  return {low, high};
}

TEST_P(HardCases, CouplingIsStableUpToItsAnalyticLimitAndRefusedBeyond)
{
  // The proxy in free space (no gravity) follows a 1 cm step of the hand. The explicit
  // coupling is stable iff (k dt + 2 c) dt / m < 4: at 90 % of that stiffness it settles, and
  // a world beyond it is refused with a message naming the limit. Every shipped device
  // profile's coupling (config/devices/*.yaml) is accepted and settles too.
  WorldParams params = fingerParams();
  params.gravity = Eigen::Vector3d::Zero();
  params.coupling.max_force = 1e4;
  const double dt = params.time_step;
  const double m = params.coupling.proxy_mass;
  const double c = params.coupling.damping;
  const double limit = (4.0 * m / dt - 2.0 * c) / dt;  // N/m
  std::printf("[ coupling ] stable below %.0f N/m (proxy %.3f kg, damping %.1f N s/m, dt %.4f s)\n", limit, m, c, dt);
  for (double fraction : {0.001, 0.1, 0.5, 0.9})
  {
    params.coupling.stiffness = fraction * limit;
    const auto [low, high] = stepResponse(params, params.coupling);
    ASSERT_TRUE(std::isfinite(high)) << fraction;
    std::printf("[ coupling %8.0f N/m ] last 0.2 s peak-to-peak %.3g m, rests at %.6f m\n", params.coupling.stiffness,
                high - low, high);
    EXPECT_LT(high - low, 1e-6) << fraction;
    EXPECT_NEAR(high, 0.01, 1e-6) << fraction;
  }
  params.coupling.stiffness = 1.01 * limit;
  EXPECT_NE(validate(params).find("coupling unstable at this time step"), std::string::npos) << validate(params);
  EXPECT_THROW(GodFingerWorld(SceneDescription(), params), InputError);
  params.coupling.stiffness = WorldParams().coupling.stiffness;
  for (const char* device : {"fake", "falcon", "omni"})
  {
    const CouplingProfile coupling = test::shippedDeviceProfile(device).coupling;
    EXPECT_EQ(couplingStabilityError(coupling, m, dt), "") << device;
    const auto [low, high] = stepResponse(params, coupling);
    ASSERT_TRUE(std::isfinite(high)) << device;
    std::printf("[ coupling %s, %.0f N/m, %.1f N s/m, %.1f N ] last 0.2 s peak-to-peak %.3g m, rests at %.6f m\n",
                device, coupling.stiffness, coupling.damping, coupling.max_force, high - low, high);
    EXPECT_LT(high - low, 1e-6) << device;
    EXPECT_NEAR(high, 0.01, 1e-6) << device;
  }
}

TEST_P(HardCases, HandAtTwoMetresPerSecondIntoATwoMillimetrePlateDoesNotTunnel)
{
  for (ContactModel model : {ContactModel::kGodObject, ContactModel::kGodFinger})
  {
    SCOPED_TRACE(contactModelName(model));
    WorldParams params = fingerParams();
    params.model = model;
    SceneDescription scene;
    BodyDescription plate = tableAt(Eigen::Vector3d::Zero());
    plate.geometry.size.z() = 0.002;
    plate.pose.translation().z() = -0.001;
    scene.bodies = {plate};
    GodFingerWorld world(scene, params);
    const int finger = world.addInterface(Eigen::Vector3d(0.0, 0.0, 0.1));
    double lowest = 1.0;
    for (int i = 1; i <= 300; ++i)
    {
      // 2 mm per 1 ms step: the hand goes from 10 cm above to 30 cm below in 0.2 s.
      world.setInterfaceTarget(finger, Eigen::Vector3d(0.0, 0.0, 0.1 - 2.0 * std::min(i, 200) * 1e-3));
      world.step();
      lowest = std::min(lowest, world.interfaceState(finger).proxy_position.z());
      ASSERT_TRUE(world.interfaceState(finger).proxy_position.allFinite());
    }
    // Tunnelling would put the proxy under the plate (z < -2 mm); it sinks only by the pad's
    // compliance, max_force / pad stiffness = 1 mm, half as much again while ringing.
    const double sink = params.coupling.max_force / params.pad.stiffness;
    EXPECT_GT(lowest, params.coupling.proxy_radius - 1.5 * sink);
  }
}

TEST_P(HardCases, LateLoopJumpOfTheHandIsAbsorbed)
{
  // The hand pushes a 200 g box along the table by its side at 0.2 m/s; in one run the loop is
  // late for 20 ms (no new target), then the target jumps 4 mm to catch up. The late run must
  // end where the smooth one does (the box was pushed 8 cm) and the jump must not kick the box.
  auto push = [this](bool late)
  {
    SceneDescription scene;
    scene.bodies = {tableAt(Eigen::Vector3d::Zero()), boxAt(Eigen::Vector3d::Zero(), 0.05, 0.2)};
    auto world = std::make_unique<GodFingerWorld>(scene, fingerParams());
    const int finger = world->addInterface(Eigen::Vector3d(-0.04, 0.0, 0.02));
    GodFingerWorld* w = world.get();
    const RunRecord record = runChecked(
        w, 1000,
        [=](long i)
        {
          if (late && i >= 400 && i < 420)
          {
            return;  // the loop is late: the physics steps on the old target
          }
          const double t = (i + 1) * 1e-3;
          w->setInterfaceTarget(finger, Eigen::Vector3d(-0.04 + 0.2 * std::clamp(t - 0.1, 0.0, 0.5), 0.0, 0.02));
        });
    return std::make_pair(record, world->bodyState(1).center_of_mass);
  };
  const auto smooth = push(false);
  const auto late = push(true);
  std::printf("[ late loop ] end x %.5f m (smooth %.5f m), max speed %.3f m/s (smooth %.3f m/s)\n", late.second.x(),
              smooth.second.x(), late.first.max_speed, smooth.first.max_speed);
  EXPECT_GT(smooth.second.x(), 0.05);  // the box was pushed, so the case means something
  EXPECT_EQ(late.first.nan_steps, 0);
  EXPECT_LE(late.first.max_user_force, fingerParams().coupling.max_force + 1e-9);  // saturated, never more
  EXPECT_NEAR(late.second.x(), smooth.second.x(), 0.002);
  // The catch-up may push the box at most as fast as the jump asks: 4 mm in one 1 ms step.
  EXPECT_LT(late.first.max_speed, 4.0);
  EXPECT_LT(late.first.max_speed, 2.0 * smooth.first.max_speed + 0.05);
  EXPECT_LT(late.first.deepest, 2e-3);
}

TEST_P(HardCases, FourFingersWithOverlappingContactAreasHoldABoxStill)
{
  SceneDescription scene;
  scene.bodies = {tableAt(Eigen::Vector3d::Zero()), boxAt(Eigen::Vector3d::Zero(), 0.1, 0.5)};
  WorldParams params = fingerParams();
  GodFingerWorld world(scene, params);
  const Eigen::Vector3d spots[] = {
      {0.003, 0.003, 0.0}, {-0.003, 0.003, 0.0}, {-0.003, -0.003, 0.0}, {0.003, -0.003, 0.0}};
  for (const Eigen::Vector3d& spot : spots)
  {
    world.addInterface(spot + Eigen::Vector3d(0.0, 0.0, 0.12));
  }
  const RunRecord record = runChecked(
      &world, 1500,
      [&](long i)
      {
        const double s = std::min(1.0, (i + 1) * 1e-3 / 0.3);
        for (int f = 0; f < 4; ++f)
        {
          world.setInterfaceTarget(f, spots[f] + Eigen::Vector3d(0.0, 0.0, 0.103 + 0.01 * (1.0 - s) - 0.005 * s));
        }
      });
  double total_push = 0.0;
  for (int f = 0; f < 4; ++f)
  {
    const InterfaceState& finger = world.interfaceState(f);
    ASSERT_EQ(finger.contact_count, 1) << f;
    // Each area (radius ~ r_max) overlaps the others (hands 6-8.5 mm apart).
    EXPECT_GT(finger.contacts[0].radius, 0.0085) << f;
    // The overlap push (overlap_push.h) spreads the proxies out from under their hands, each
    // away from the middle (about 7 mm out along its diagonal), and the areas still overlap.
    EXPECT_GT(finger.overlap_area, 0.0) << f;
    EXPECT_GT(finger.overlap_push.dot(spots[f]), 0.0) << f;
    total_push += finger.user_force.z();
  }
  std::printf("[ four fingers ] hands feel %.3f N up in all (4 x k x 5 mm = %.3f N), box moved %.3g m\n", total_push,
              4.0 * params.coupling.stiffness * 0.005, record.max_displacement);
  EXPECT_EQ(record.nan_steps, 0);
  EXPECT_NEAR(total_push, 4.0 * params.coupling.stiffness * 0.005, 0.1 * 4.0 * params.coupling.stiffness * 0.005);
  EXPECT_LT(record.max_displacement, 5e-4);
  EXPECT_LT(record.deepest, 2e-3);
  // Energy: the box's kinetic energy stays under 1 % of what the four coupling springs hold
  // (4 x k x (5 mm)^2 / 2 = 0.02 J): the overlapping areas add none.
  EXPECT_LT(record.max_kinetic, 0.01 * 4.0 * 0.5 * params.coupling.stiffness * 0.005 * 0.005);
}
INSTANTIATE_TEST_SUITE_P(PadSolvers, HardCases, ::testing::Values(PadSolver::kPoints, PadSolver::kConstraint),
                         [](const ::testing::TestParamInfo<PadSolver>& info)
                         { return std::string(padSolverName(info.param)); });
}  // namespace
}  // namespace god_finger
