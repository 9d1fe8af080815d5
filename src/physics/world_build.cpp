#include "world_build.h"

#include "bullet_helpers.h"
#include "near_callback.h"
#include "scene_joints.h"
#include "sphere_mesh_algorithm.h"
#include "stages/contact_area_stage.h"
#include "stages/escapees.h"
#include "world_bounds.h"
#include "world_core.h"

namespace god_finger::internal
{
namespace
{
// Bullet's world, its solver's settings, and the hook where contact areas join the solver.
void buildBulletWorld(WorldCore* core)
{
  const WorldParams& params = core->params;
  core->configuration = std::make_unique<btDefaultCollisionConfiguration>();
  core->dispatcher = std::make_unique<btCollisionDispatcher>(core->configuration.get());
  core->dispatcher->setNearCallback(&worldNearCallback);
  registerSphereMeshAlgorithm(core->dispatcher.get());
  core->broadphase = std::make_unique<btDbvtBroadphase>();
  core->solver = std::make_unique<ContactSolver>(params.support_passes, &core->pads);
  core->world = std::make_unique<HookedWorld>(core->dispatcher.get(), core->broadphase.get(), core->solver.get(),
                                              core->configuration.get());
  HookedWorld& world = *core->world;
  world.setGravity(toBullet(params.gravity));
  world.getSolverInfo().m_numIterations = params.solver_iterations;
  // Bullet stops iterating once an iteration's largest velocity correction (squared) is below
  // this.
  world.getSolverInfo().m_leastSquaresResidualThreshold = params.solver_tolerance * params.solver_tolerance;
  // Two friction directions per point: an area resists twisting only if each of its points
  // resists sliding in every tangential direction (Bullet's default is one direction, along the
  // sliding velocity).
  world.getSolverInfo().m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
  // Stages "collide" and "contact_areas" end here (step_profile.h).
  world.after_collision = [core]()
  {
    core->clock.mark(StepStage::kCollide);
    computeContactAreas(core);
    core->clock.mark(StepStage::kContactAreas);
  };
  world.sleep_time = params.sleep.time;
  // Sleeping bodies keep their bounding boxes (static ones never move).
  world.setForceUpdateAllAabbs(false);
  core->injector = std::make_unique<SubGodObjectInjector>(core->dispatcher.get());
}

Eigen::AlignedBox3d sceneBox(const WorldCore& core)
{
  Eigen::AlignedBox3d box;
  for (const SceneBody& body : core.bodies)
  {
    btVector3 min;
    btVector3 max;
    body.rigid->getAabb(min, max);
    box.extend(toEigen(min)).extend(toEigen(max));
  }
  return box;
}

}  // namespace

void markJointed(WorldCore* core)
{
  core->jointed.assign(core->bodies.size(), 0);
  for (const JointDescription& joint : core->scene.joints)
  {
    core->jointed[joint.child] = 1;
    if (joint.parent >= 0 && !core->scene.bodies[joint.parent].is_static)
    {
      core->jointed[joint.parent] = 1;  // a static parent (a cabinet) is never simulated anyway
    }
  }
}

void addJointToWorld(WorldCore* core, int index)
{
  const JointDescription& joint = core->scene.joints[index];
  core->joints.push_back(makeJointConstraint(joint, joint.parent < 0 ? nullptr : &core->bodies[joint.parent],
                                             core->bodies[joint.child], core->world_anchor.get()));
  core->world->addConstraint(core->joints.back().get(), true);  // no contacts between a joint's two bodies
}

void buildBody(const WorldParams& params, const BodyDescription& description, int index, SceneBody* body)
{
  buildRigidBody(description, index, body);
  if (body->soft)
  {
    makeSoftVolume(description, params.time_step, params.gravity, body);
  }
}

void addBodyToWorld(WorldCore* core, int index)
{
  SceneBody& body = core->bodies[index];
  prepareSleep(*core, body.rigid.get());
  core->world->addRigidBody(body.rigid.get(), kBodyGroup, btBroadphaseProxy::AllFilter);
  body.previous_velocity = Eigen::Vector3d::Zero();
  body.net_force = Eigen::Vector3d::Zero();
}

void sizeProxyScratch(WorldCore* core)
{
  core->soft.resize(core->proxies.size());
  core->sleep.group_of_tag.assign(core->bodies.size() + core->proxies.size(), -1);
}

double walkEdge(const WorldCore& core)
{
  return core.params.walk_edge_per_max_radius * core.params.contact.max_radius;
}

void buildBodies(WorldCore* core)
{
  const double max_edge = walkEdge(*core);
  for (const BodyDescription& description : core->scene.bodies)
  {
    core->bodies.push_back(makeSceneBody(description, max_edge));
  }
}

void chooseResponse(WorldCore* core)
{
  if (core->responses.empty())
  {
    for (const ContactModel model : contactModels())
    {
      core->responses.emplace_back(model, makeContactResponse(model));
    }
  }
  for (const auto& [model, candidate] : core->responses)
  {
    core->response = model == core->params.model ? candidate.get() : core->response;
  }
}

void buildWorld(WorldCore* core)
{
  buildBulletWorld(core);
  chooseResponse(core);
  markJointed(core);
  for (std::size_t i = 0; i < core->bodies.size(); ++i)
  {
    buildBody(core->params, core->scene.bodies[i], static_cast<int>(i), &core->bodies[i]);
    addBodyToWorld(core, static_cast<int>(i));
  }
  for (std::size_t j = 0; j < core->scene.joints.size(); ++j)
  {
    addJointToWorld(core, static_cast<int>(j));
  }
  core->bounds = worldBounds(sceneBox(*core), core->params.world_margin);
  placeSoftSupports(core);
  for (std::size_t i = 0; i < core->proxies.size(); ++i)
  {
    addProxyToWorld(core, static_cast<int>(i));
  }
  resetSleep(core);
  core->soft_bodies.clear();
  for (std::size_t i = 0; i < core->bodies.size(); ++i)
  {
    if (core->bodies[i].soft)
    {
      core->soft_bodies.push_back(static_cast<int>(i));
    }
  }
  sizeProxyScratch(core);
}

void addProxyToWorld(WorldCore* core, int index)
{
  Proxy& proxy = core->proxies[index];
  buildProxyBody(core->params.coupling, core->params.pad, index, static_cast<int>(core->bodies.size()), &proxy);
  core->world->addRigidBody(proxy.rigid.get(), kProxyGroup, kBodyGroup);
  proxy.rigid->setGravity(btVector3(0, 0, 0));
  sizeProxyScratch(core);
  core->response->configureProxy(core->params, proxy.rigid.get());
  core->overlap.resize(static_cast<int>(core->proxies.size()));
}

WorldCore::~WorldCore()
{
  teardownWorld(this);
}

void teardownWorld(WorldCore* core)
{
  if (!core->world)
  {
    return;
  }
  core->injector->release();
  core->pads.clear();
  for (const std::unique_ptr<btTypedConstraint>& joint : core->joints)
  {
    core->world->removeConstraint(joint.get());
  }
  core->joints.clear();
  for (Proxy& proxy : core->proxies)
  {
    core->world->removeRigidBody(proxy.rigid.get());
    proxy.rigid.reset();
    proxy.shape.reset();
  }
  for (std::size_t i = 0; i < core->bodies.size(); ++i)
  {
    SceneBody& body = core->bodies[i];
    if (!core->sleep.dormant.dormant(static_cast<int>(i)))
    {
      core->world->removeRigidBody(body.rigid.get());
    }
    body.rigid.reset();
    body.placed.reset();
  }
  core->sleep.dormant.reset(static_cast<int>(core->bodies.size()));
  core->world.reset();
  core->solver.reset();
  core->broadphase.reset();
  core->dispatcher.reset();
  core->configuration.reset();
}
}  // namespace god_finger::internal
