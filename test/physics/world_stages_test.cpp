// The world step's stages (src/physics/stages, src/physics/sleep/world_sleep.h), each called on
// its own on a world's state (world_core.h) built by world_build.h: what each does to the state,
// with real numbers. The whole step's order is GodFingerWorld::step (god_finger_world_test and
// the experiments check it end to end); its profile is checked last.
#include "scene_edit.h"
#include "stages/contact_area_stage.h"
#include "stages/coupling_stage.h"
#include "stages/escapees.h"
#include "stages/impulse_record.h"
#include "world_build.h"
#include "world_core.h"

#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace god_finger::internal
{
namespace
{
const std::string kScenes = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";

// `core` built for `scene` as a GodFingerWorld builds it.
void build(const SceneDescription& scene, const WorldParams& params, WorldCore* core)
{
  core->params = params;
  core->scene = scene;
  core->shared_scene = std::make_shared<const SceneDescription>(scene);
  buildBodies(core);
  buildWorld(core);
}

int addProxy(const Eigen::Vector3d& at, WorldCore* core)
{
  Proxy proxy;
  proxy.initial = at;
  proxy.coupling = core->params.coupling;
  core->proxies.push_back(std::move(proxy));
  const int index = static_cast<int>(core->proxies.size()) - 1;
  addProxyToWorld(core, index);
  return index;
}

void moveProxy(WorldCore* core, int proxy, const Eigen::Vector3d& to)
{
  btRigidBody* rigid = core->proxies[proxy].rigid.get();
  rigid->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(to.x(), to.y(), to.z())));
  core->world->updateSingleAabb(rigid);
}

bool inWorld(const WorldCore& core, const btCollisionObject* object)
{
  const btCollisionObjectArray& objects = core.world->getCollisionObjectArray();
  return objects.findLinearSearch(const_cast<btCollisionObject*>(object)) < objects.size();
}

// table_box: a 1 m table whose top is z = 0, a 6 cm cube of 100 g resting on it centred at z = 3 cm.
class TableBox : public ::testing::Test
{
 protected:
  void SetUp() override
  {
    scene_ = loadUrdfScene(kScenes + "/table_box.urdf");
    build(scene_, WorldParams(), &core_);
    cube_ = scene_.find("cube");
    ASSERT_GE(cube_, 0);
    radius_ = core_.params.coupling.proxy_radius;
  }
  SceneDescription scene_;
  WorldCore core_;
  int cube_ = -1;
  double radius_ = 0.0;
};

TEST_F(TableBox, CouplingPullsTheProxyTowardsItsTargetAndTheHandFeelsTheOpposite)
{
  const Eigen::Vector3d start(0.2, 0.2, 0.3);  // in the air
  const int finger = addProxy(start, &core_);
  Proxy& proxy = core_.proxies[finger];
  proxy.target = start + Eigen::Vector3d(0.0, 0.0, -0.004);
  const Eigen::Vector3d target_velocity = (proxy.target - start) / core_.params.time_step;
  const CouplingForce expected =
      couplingForce(proxy.coupling, proxy.target, target_velocity, start, Eigen::Vector3d::Zero());
  applyCouplings(&core_);
  const btVector3 applied = proxy.rigid->getTotalForce();
  EXPECT_EQ(Eigen::Vector3d(applied.x(), applied.y(), applied.z()), expected.on_proxy);
  EXPECT_LT(expected.on_proxy.z(), -1.0);  // 4 mm of spring at the default stiffness: newtons
  EXPECT_EQ(proxy.state.user_force, -expected.on_proxy);
  EXPECT_EQ(proxy.previous_target, proxy.target);
  EXPECT_EQ(proxy.state.interface_position, proxy.target);
}

TEST_F(TableBox, ASleepingCubeLeavesTheWorldAndAFingerNearItWakesIt)
{
  const int finger = addProxy(Eigen::Vector3d(0.4, 0.4, 0.3), &core_);
  btRigidBody* cube = core_.bodies[cube_].rigid.get();
  cube->setActivationState(ISLAND_SLEEPING);
  putSleepersAway(&core_);
  EXPECT_TRUE(core_.sleep.dormant.dormant(cube_));
  EXPECT_FALSE(inWorld(core_, cube));
  EXPECT_TRUE(core_.sleep.awake.empty());
  EXPECT_TRUE(bodyAsleep(core_, cube_));
  // A finger 30 cm away wakes nothing.
  wakeNearFingersAndMovers(&core_);
  EXPECT_TRUE(core_.sleep.dormant.dormant(cube_));
  // One 0.5 mm above its top face (z = 6 cm) wakes it.
  moveProxy(&core_, finger, Eigen::Vector3d(0.0, 0.0, 0.06 + radius_ + 0.0005));
  wakeNearFingersAndMovers(&core_);
  EXPECT_FALSE(core_.sleep.dormant.dormant(cube_));
  EXPECT_TRUE(inWorld(core_, cube));
  EXPECT_EQ(core_.sleep.awake, std::vector<int>{cube_});
  EXPECT_TRUE(cube->isActive());
  EXPECT_EQ(awakeBodyCount(core_), 1);
}

TEST_F(TableBox, ContactAreasAreComputedBetweenCollisionAndTheSolver)
{
  const int finger = addProxy(Eigen::Vector3d(0.0, 0.0, 0.06 + radius_ - 0.001), &core_);  // 1 mm into the top
  // The hand 5 mm below: Eq. 1's radius grows with the coupling force.
  core_.proxies[finger].target = Eigen::Vector3d(0.0, 0.0, 0.055 + radius_);
  core_.world->performDiscreteCollisionDetection();  // the hook runs the stage
  const InterfaceState& state = core_.proxies[finger].state;
  ASSERT_EQ(state.contact_count, 1);
  const WorldContactArea& area = state.contacts[0];
  EXPECT_EQ(area.body, cube_);
  EXPECT_NEAR(area.normal.z(), 1.0, 1e-9);
  EXPECT_NEAR(area.point.z(), 0.06, 1e-6);
  EXPECT_NEAR(area.depth, 0.001, 1e-6);
  EXPECT_GT(area.radius, 0.0);
  EXPECT_LE(area.radius, core_.params.contact.max_radius);
  EXPECT_NEAR(core_.counters.deepest_penetration, 0.001, 1e-6);
  EXPECT_EQ(core_.counters.dropped_contacts, 0);
}

TEST(WorldStages, AFingerTouchingFiveBodiesKeepsFourAreasAndCountsTheFifth)
{
  // Five static 2 cm cubes around a proxy at the origin, each 0.5 mm into its sphere: below it
  // and on its four sides.
  WorldParams params;
  const double radius = params.coupling.proxy_radius;
  const double centre = radius + 0.01 - 0.0005;
  const Eigen::Vector3d places[] = {{0, 0, -centre}, {centre, 0, 0}, {-centre, 0, 0}, {0, centre, 0}, {0, -centre, 0}};
  SceneDescription scene;
  for (int i = 0; i < 5; ++i)
  {
    BodyDescription block;
    block.name = "block" + std::to_string(i);
    block.geometry.size = Eigen::Vector3d::Constant(0.02);
    block.is_static = true;
    block.pose.translation() = places[i];
    scene.bodies.push_back(block);
  }
  WorldCore core;
  build(scene, params, &core);
  const int finger = addProxy(Eigen::Vector3d::Zero(), &core);
  core.world->performDiscreteCollisionDetection();
  const InterfaceState& state = core.proxies[finger].state;
  EXPECT_EQ(state.contact_count, InterfaceState::kMaxContacts);
  EXPECT_EQ(core.counters.dropped_contacts, 1);
  EXPECT_EQ(core.counters.dropped_contacts_total, 1);
  std::set<int> touched;
  for (int c = 0; c < state.contact_count; ++c)
  {
    touched.insert(state.contacts[c].body);
  }
  EXPECT_EQ(touched.size(), 4u);
  core.world->performDiscreteCollisionDetection();
  EXPECT_EQ(core.counters.dropped_contacts, 1);  // per step
  EXPECT_EQ(core.counters.dropped_contacts_total, 2);
}

TEST_F(TableBox, TheNetForceIsMassTimesTheChangeOfVelocityOverTheStep)
{
  btRigidBody* cube = core_.bodies[cube_].rigid.get();
  cube->setLinearVelocity(btVector3(0.0, 0.0, 0.02));
  beforeSolve(&core_);
  EXPECT_EQ(core_.bodies[cube_].previous_velocity, Eigen::Vector3d(0.0, 0.0, 0.02));
  cube->setLinearVelocity(btVector3(0.0, 0.0, 0.01));
  recordNetForces(&core_);
  const double dt = core_.params.time_step;
  EXPECT_DOUBLE_EQ(core_.bodies[cube_].net_force.z(), 0.1 * (0.01 - 0.02) / dt);
  EXPECT_EQ(core_.bodies[cube_].net_force.x(), 0.0);
}

TEST_F(TableBox, ABodyPastTheBoundsIsPutBackAtItsStartAndCounted)
{
  btRigidBody* cube = core_.bodies[cube_].rigid.get();
  const btTransform start = cube->getWorldTransform();
  core_.time = 2.5;
  catchEscapees(&core_);
  EXPECT_EQ(core_.bodies[cube_].left_world, 0);  // inside: untouched
  cube->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0.0, 0.0, -5.0)));
  cube->setLinearVelocity(btVector3(0.0, 0.0, -9.0));
  catchEscapees(&core_);
  EXPECT_EQ(core_.bodies[cube_].left_world, 1);
  EXPECT_EQ(core_.bodies[cube_].left_world_at, 2.5);
  EXPECT_EQ(cube->getWorldTransform().getOrigin(), start.getOrigin());
  EXPECT_EQ(cube->getLinearVelocity(), btVector3(0, 0, 0));
}

TEST(WorldStages, AFingerPressingASoftBodyLoadsItWithTheSolversForceReversed)
{
  // soft_block: a 10 cm soft cube on the table, settled under its weight (its top near z = 0.1 m).
  const SceneDescription scene = loadUrdfScene(kScenes + "/soft_block.urdf");
  WorldCore core;
  build(scene, WorldParams(), &core);
  const int block = scene.find("soft_block");
  ASSERT_GE(block, 0);
  SoftSurfaceState surface;
  snapshotSoftSurface(core.bodies[block], block, &surface);
  double top = -1.0;
  for (const Eigen::Vector3d& vertex : surface.vertices)
  {
    top = std::max(top, vertex.z());
  }
  ASSERT_GT(top, 0.09);
  const int finger = addProxy(Eigen::Vector3d(0.0, 0.0, top + core.params.coupling.proxy_radius - 0.0005), &core);
  core.proxies[finger].target = Eigen::Vector3d(0.0, 0.0, top + core.params.coupling.proxy_radius - 0.005);
  core.world->performDiscreteCollisionDetection();
  Proxy& proxy = core.proxies[finger];
  ASSERT_EQ(proxy.state.contact_count, 1);
  ASSERT_EQ(proxy.state.contacts[0].body, block);
  core.soft.beforeSolve(&core);  // at rest, no force applied
  // The solver pushed the proxy up by 0.1 m/s in one step: the block felt m dv/dt down.
  proxy.rigid->setLinearVelocity(btVector3(0.0, 0.0, 0.1));
  core.soft.loadAndStep(&core);
  const double on_proxy = core.params.coupling.proxy_mass * 0.1 / core.params.time_step;
  EXPECT_GT(on_proxy, 0.5);  // N
  EXPECT_EQ(proxy.soft_load_body, block);
  // The first load on a body: under-relaxed from zero (kSoftLoadRelaxation).
  EXPECT_NEAR(proxy.soft_load.z(), -kSoftLoadRelaxation * on_proxy, 1e-12);
  EXPECT_NEAR(proxy.soft_load.head<2>().norm(), 0.0, 1e-12);
  // No dimple yet under the first load: no stiffness to measure.
  EXPECT_EQ(proxy.state.contact_stiffness, std::numeric_limits<double>::infinity());
  // The same push again: the load relaxes further towards it, and the dimple the first one made
  // gives the contact's stiffness.
  core.soft.beforeSolve(&core);
  proxy.rigid->setLinearVelocity(btVector3(0.0, 0.0, 0.2));
  core.soft.loadAndStep(&core);
  const double relaxed = -kSoftLoadRelaxation * on_proxy;
  EXPECT_NEAR(proxy.soft_load.z(), relaxed + kSoftLoadRelaxation * (-on_proxy - relaxed), 1e-12);
  EXPECT_TRUE(std::isfinite(proxy.state.contact_stiffness));
  EXPECT_GT(proxy.state.contact_stiffness, 0.0);
}

TEST(WorldStages, ProxiesCarryTheirPerBodyStateToTheBodiesNewIndices)
{
  Proxy proxy;
  proxy.reference_tangents = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
  proxy.warm_starts.resize(3);
  proxy.pads.resize(3);
  for (int body = 0; body < 3; ++body)
  {
    proxy.warm_starts[body][0].step = 10 + body;
    proxy.pads[body].linear.step = 20 + body;
  }
  proxy.soft_load = Eigen::Vector3d(0.0, 0.0, -1.5);
  proxy.soft_load_body = 2;
  // Body 1 removed, a new body appended: 0 -> 0, 2 -> 1, new -> 2.
  remapBodies({0, 2, -1}, &proxy);
  ASSERT_EQ(proxy.pads.size(), 3u);
  EXPECT_EQ(proxy.reference_tangents[1], Eigen::Vector3d::UnitZ());
  EXPECT_EQ(proxy.warm_starts[0][0].step, 10);
  EXPECT_EQ(proxy.warm_starts[1][0].step, 12);
  EXPECT_EQ(proxy.pads[1].linear.step, 22);
  EXPECT_EQ(proxy.pads[2].linear.step, PadState().linear.step);  // fresh
  EXPECT_EQ(proxy.reference_tangents[2], Eigen::Vector3d::Zero());
  EXPECT_EQ(proxy.soft_load_body, 1);
  EXPECT_EQ(proxy.soft_load.z(), -1.5);
  // The body it loaded goes: so does the load.
  remapBodies({0, 2}, &proxy);
  EXPECT_EQ(proxy.soft_load_body, -1);
  EXPECT_EQ(proxy.soft_load, Eigen::Vector3d::Zero());
}

TEST_F(TableBox, ASceneEditKeepsEveryProxyWhole)
{
  const int finger = addProxy(Eigen::Vector3d(0.0, 0.0, 0.06 + radius_), &core_);
  Proxy& before = core_.proxies[finger];
  const btRigidBody* rigid = before.rigid.get();
  before.rigid->setLinearVelocity(btVector3(0.01, 0.0, -0.02));
  before.pads[cube_].linear.step = 41;  // a warm start of its pad on the cube
  before.let_go_steps = 0;
  before.state.overlap_area = 3e-5;
  SceneDescription ball;
  BodyDescription body;
  body.name = "ball";
  body.geometry.kind = GeometryKind::kSphere;
  body.geometry.radius = 0.02;
  body.mass = 0.05;
  body.inertia = Eigen::Matrix3d::Identity() * 8e-6;
  body.pose.translation() = Eigen::Vector3d(0.3, 0.0, 0.02);
  ball.bodies.push_back(body);
  std::vector<int> old_of_new;
  SceneDescription next = sceneWithObject(core_, ball, &old_of_new);
  changeScene(&core_, std::move(next), old_of_new, nullptr);
  ASSERT_EQ(core_.bodies.size(), 3u);
  const Proxy& after = core_.proxies[finger];
  EXPECT_EQ(after.rigid.get(), rigid);  // the same Bullet body, in the new world
  EXPECT_TRUE(inWorld(core_, rigid));
  EXPECT_EQ(after.rigid->getLinearVelocity(), btVector3(0.01, 0.0, -0.02));
  EXPECT_EQ(after.pads[cube_].linear.step, 41);
  EXPECT_EQ(after.state.overlap_area, 3e-5);
  EXPECT_EQ(after.state.contact_count, 0);  // found again by the next step
  EXPECT_EQ(after.pads.size(), 3u);
  EXPECT_EQ(after.let_go_steps, 0);  // it pressed nothing that went
}

TEST(WorldStages, EveryStepIsProfiledStageByStage)
{
  WorldParams params;
  params.profile_every = 1;
  GodFingerWorld world(loadUrdfScene(kScenes + "/table_box.urdf"), params);
  world.addInterface(Eigen::Vector3d(0.0, 0.0, 0.06 + world.params().coupling.proxy_radius));
  world.setInterfaceTarget(0, Eigen::Vector3d(0.0, 0.0, 0.05));
  std::set<std::string> names;
  for (int k = 0; k < 20; ++k)
  {
    world.step();
    const StepProfile& profile = world.stepProfile();
    std::int64_t sum = 0;
    for (int s = 0; s < kStepStageCount; ++s)
    {
      EXPECT_GE(profile.stage_ns[s], 0);
      sum += profile.stage_ns[s];
      names.insert(stepStageName(static_cast<StepStage>(s)));
    }
    EXPECT_EQ(sum, profile.total_ns);
    EXPECT_EQ(profile.step, world.steps());
    EXPECT_GT(profile[StepStage::kContactAreas], 0);  // the finger presses the cube
    EXPECT_GT(profile[StepStage::kSolve], 0);
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(kStepStageCount));
  EXPECT_EQ(names.count("unknown"), 0u);
  EXPECT_EQ(world.interfaceState(0).contact_count, 1);
}
TEST(WorldStages, OneStepInProfileEveryIsTimed)
{
  WorldParams params;
  params.profile_every = 4;
  GodFingerWorld world(loadUrdfScene(kScenes + "/table_box.urdf"), params);
  EXPECT_EQ(world.stepProfile().step, -1);
  std::vector<long> timed;
  for (int k = 0; k < 10; ++k)
  {
    world.step();
    if (timed.empty() || timed.back() != world.stepProfile().step)
    {
      timed.push_back(world.stepProfile().step);
    }
  }
  EXPECT_EQ(timed, (std::vector<long>{1, 5, 9}));  // the steps that began at 0, 4 and 8
  params.profile_every = 0;
  GodFingerWorld untimed(loadUrdfScene(kScenes + "/table_box.urdf"), params);
  untimed.step();
  EXPECT_EQ(untimed.stepProfile().step, -1);
  EXPECT_EQ(untimed.stepProfile().total_ns, 0);
}
}  // namespace
}  // namespace god_finger::internal
