#include "scene_edit.h"

#include "bullet_helpers.h"
#include "stages/escapees.h"
#include "start_overlaps.h"
#include "world_bounds.h"
#include "world_build.h"
#include "world_core.h"
#include "world_queries.h"

#include "god_finger/scene/scene_budget.h"
#include "god_finger/support/input_error.h"

#include <algorithm>
#include <cmath>

namespace god_finger::internal
{
namespace
{
// A proxy that pressed a body that goes lets go over let_go_time: its proxy is pulled from where
// it is to the hand.
void letGoOfRemoved(const WorldParams& params, const std::vector<char>& kept, Proxy* proxy)
{
  const Eigen::Vector3d position = toEigen(proxy->rigid->getWorldTransform().getOrigin());
  for (int c = 0; c < proxy->state.contact_count; ++c)
  {
    if (!kept[proxy->state.contacts[c].body] && params.let_go_time > 0.0)
    {
      proxy->let_go_total = std::max(1, int(std::lround(params.let_go_time / params.time_step)));
      proxy->let_go_steps = proxy->let_go_total;
      proxy->let_go_offset = position - proxy->target;
    }
  }
}

// Body `index`, which goes, is taken out of Bullet's world with what rests on it: a dormant one's
// group wakes first (with it, what it slept on and what slept on it), then every other dormant
// body within Bullet's contact threshold of it, so that nothing stays asleep in the air.
void takeOut(WorldCore* core, int index)
{
  btRigidBody* rigid = core->bodies[index].rigid.get();
  const auto woken = [core](int body) { wakeBody(core, body, false); };
  if (core->sleep.dormant.dormant(index))
  {
    core->sleep.dormant.wakeGroupOf(index, woken);
  }
  core->world->updateSingleAabb(rigid);  // its broadphase box, with Bullet's contact threshold
  const btBroadphaseProxy* handle = rigid->getBroadphaseHandle();
  core->sleep.dormant.wakeOverlapping(handle->m_aabbMin, handle->m_aabbMax, woken);
  // Bullet drops its pairs and returns their manifolds (btCollisionWorld::removeCollisionObject,
  // cleanProxyFromPairs); no other pair's manifold changes.
  core->world->removeRigidBody(rigid);
}

// The world's bounds for the scene as edited: each body's box at its initial pose, as a build
// computes them (a moving body's from its description, not from where it is now).
Eigen::AlignedBox3d startBox(const WorldCore& core)
{
  Eigen::AlignedBox3d box;
  for (std::size_t i = 0; i < core.bodies.size(); ++i)
  {
    const SceneBody& body = core.bodies[i];
    const BodyDescription& description = core.scene.bodies[i];
    btVector3 min;
    btVector3 max;
    if (description.is_static || body.soft)
    {
      body.rigid->getAabb(min, max);
    }
    else
    {
      body.rigid->getCollisionShape()->getAabb(toBullet(description.pose * body.com_in_link), min, max);
    }
    box.extend(toEigen(min)).extend(toEigen(max));
  }
  return box;
}

bool staticRigid(const SceneDescription& scene, const std::vector<SceneBody>& bodies, int index)
{
  return scene.bodies[index].is_static && !bodies[index].soft;
}
}  // namespace

std::string describe(const ProxyInsideAdded& inside, const SceneDescription& scene)
{
  return "finger " + std::to_string(inside.finger) + " starts " + std::to_string(inside.depth) + " m inside '" +
         scene.bodies[inside.body].name + "': the solver pushes its proxy out (the hand feels it)";
}

void changeScene(WorldCore* core, SceneDescription next, const std::vector<int>& old_of_new,
                 std::vector<SceneBody>* made_before)
{
  // The new bodies' shapes and Bullet bodies first: an InputError here changes nothing.
  const double max_edge = walkEdge(*core);
  std::vector<SceneBody> made(next.bodies.size());
  std::size_t taken = 0;
  for (std::size_t i = 0; i < next.bodies.size(); ++i)
  {
    if (old_of_new[i] < 0)
    {
      made[i] = made_before != nullptr ? std::move((*made_before)[taken++]) : makeSceneBody(next.bodies[i], max_edge);
      buildBody(core->params, next.bodies[i], static_cast<int>(i), &made[i]);  // a soft one may throw
    }
  }
  const int old_count = static_cast<int>(core->bodies.size());
  std::vector<char> kept(old_count, 0);
  std::vector<int> new_of_old(old_count, -1);
  for (std::size_t i = 0; i < old_of_new.size(); ++i)
  {
    if (old_of_new[i] >= 0)
    {
      kept[old_of_new[i]] = 1;
      new_of_old[old_of_new[i]] = static_cast<int>(i);
    }
  }
  // The last step's injected manifolds and pads point at the proxies' per-body state and may
  // hold a body that goes; the next step makes them anew.
  core->injector->release();
  core->pads.clear();
  core->touches.clear();
  bool statics_changed = false;
  for (Proxy& proxy : core->proxies)
  {
    letGoOfRemoved(core->params, kept, &proxy);
  }
  // The joints that hold a body that goes go first (Bullet's constraints hold their bodies).
  std::vector<std::unique_ptr<btTypedConstraint>> joints;
  for (std::size_t j = 0; j < core->joints.size(); ++j)
  {
    const JointDescription& joint = core->scene.joints[j];
    if (kept[joint.child] && (joint.parent < 0 || kept[joint.parent]))
    {
      joints.push_back(std::move(core->joints[j]));
    }
    else
    {
      core->world->removeConstraint(core->joints[j].get());
    }
  }
  std::vector<const btCollisionObject*> removed;
  for (int old = 0; old < old_count; ++old)
  {
    if (!kept[old])
    {
      statics_changed = statics_changed || staticRigid(core->scene, core->bodies, old);
      takeOut(core, old);
      removed.push_back(core->bodies[old].rigid.get());
    }
  }
  // The bodies that stay keep their Bullet bodies (in the world, or dormant), renumbered.
  std::vector<char> was_jointed(next.bodies.size(), 0);
  for (std::size_t i = 0; i < next.bodies.size(); ++i)
  {
    const int old = old_of_new[i];
    if (old >= 0)
    {
      made[i] = std::move(core->bodies[old]);
      made[i].rigid->setUserIndex2(static_cast<int>(i));
      was_jointed[i] = core->jointed[old];
    }
  }
  remapSleep(core, old_of_new, removed);
  std::vector<SceneBody> gone = std::move(core->bodies);  // destroyed once nothing refers to them
  core->bodies = std::move(made);
  core->scene = std::move(next);
  core->shared_scene = std::make_shared<const SceneDescription>(core->scene);
  core->joints = std::move(joints);
  markJointed(core);
  for (std::size_t i = 0; i < core->bodies.size(); ++i)
  {
    if (old_of_new[i] < 0 || was_jointed[i] == core->jointed[i] || core->scene.bodies[i].is_static)
    {
      continue;
    }
    // Its joint went (or it got one): it may sleep now (or never again).
    btRigidBody* rigid = core->bodies[i].rigid.get();
    if (core->sleep.dormant.dormant(static_cast<int>(i)))
    {
      core->sleep.dormant.wakeGroupOf(static_cast<int>(i), [core](int body) { wakeBody(core, body, false); });
    }
    rigid->forceActivationState(ACTIVE_TAG);
    rigid->setDeactivationTime(0.0);
    prepareSleep(*core, rigid);
  }
  bool soft_added = false;
  for (std::size_t i = 0; i < core->bodies.size(); ++i)
  {
    if (old_of_new[i] >= 0)
    {
      continue;
    }
    const int index = static_cast<int>(i);
    addBodyToWorld(core, index);
    soft_added = soft_added || core->bodies[i].soft != nullptr;
    statics_changed = statics_changed || staticRigid(core->scene, core->bodies, index);
    if (!core->scene.bodies[i].is_static)
    {
      core->sleep.awake.push_back(index);
    }
  }
  for (std::size_t j = core->joints.size(); j < core->scene.joints.size(); ++j)
  {
    addJointToWorld(core, static_cast<int>(j));
  }
  core->bounds = worldBounds(startBox(*core), core->params.world_margin);
  if (statics_changed || soft_added)
  {
    placeSoftSupports(core);
  }
  core->soft_bodies.clear();
  for (std::size_t i = 0; i < core->bodies.size(); ++i)
  {
    if (core->bodies[i].soft)
    {
      core->soft_bodies.push_back(static_cast<int>(i));
    }
  }
  for (Proxy& proxy : core->proxies)
  {
    remapBodies(old_of_new, &proxy);
    // Its contacts were numbered in the old scene: none until the next step finds them.
    proxy.state.contact_count = 0;
  }
  sizeProxyScratch(core);
  gone.clear();
}

SceneDescription sceneWithObject(const WorldCore& core, const SceneDescription& object, std::vector<int>* old_of_new)
{
  SceneDescription next = core.scene;
  old_of_new->resize(next.bodies.size());
  for (std::size_t i = 0; i < old_of_new->size(); ++i)
  {
    (*old_of_new)[i] = static_cast<int>(i);
  }
  const int first = static_cast<int>(next.bodies.size());
  for (const BodyDescription& body : object.bodies)
  {
    if (next.find(body.name) >= 0)
    {
      throw InputError("the scene has a body named '" + body.name + "' already (give the object another name)");
    }
    next.bodies.push_back(body);
    old_of_new->push_back(-1);
  }
  for (JointDescription joint : object.joints)
  {
    for (const JointDescription& existing : next.joints)
    {
      if (existing.name == joint.name)
      {
        throw InputError("the scene has a joint named '" + joint.name + "' already (give the object a name)");
      }
    }
    joint.child += first;
    joint.parent = joint.parent < 0 ? -1 : joint.parent + first;
    next.joints.push_back(joint);
  }
  checkSceneFits(next, walkEdge(core));
  checkJoints(next);
  next.warnings.insert(next.warnings.end(), object.warnings.begin(), object.warnings.end());
  return next;
}

SceneDescription sceneWithout(const WorldCore& core, const std::string& name, std::vector<int>* old_of_new)
{
  const auto named = [&name](const std::string& body)
  { return body == name || (body.size() > name.size() && body.compare(0, name.size() + 1, name + "/") == 0); };
  SceneDescription next;
  next.name = core.scene.name;
  next.warnings = core.scene.warnings;
  old_of_new->clear();
  std::vector<int> new_of_old(core.scene.bodies.size(), -1);
  for (std::size_t i = 0; i < core.scene.bodies.size(); ++i)
  {
    if (!named(core.scene.bodies[i].name))
    {
      new_of_old[i] = static_cast<int>(next.bodies.size());
      old_of_new->push_back(static_cast<int>(i));
      next.bodies.push_back(core.scene.bodies[i]);
    }
  }
  if (next.bodies.size() == core.scene.bodies.size() || name.empty())
  {
    throw InputError("the scene has no body named '" + name + "'");
  }
  for (JointDescription joint : core.scene.joints)
  {
    if (new_of_old[joint.child] < 0 || (joint.parent >= 0 && new_of_old[joint.parent] < 0))
    {
      continue;  // a joint holding a body that goes goes with it
    }
    joint.child = new_of_old[joint.child];
    joint.parent = joint.parent < 0 ? -1 : new_of_old[joint.parent];
    next.joints.push_back(joint);
  }
  return next;
}

std::vector<ProxyInsideAdded> proxiesInsideAdded(const WorldCore& core, int first)
{
  std::vector<ProxyInsideAdded> inside;
  for (std::size_t i = 0; i < core.proxies.size(); ++i)
  {
    const std::pair<int, double> deepest = deepestOverlap(core, core.proxies[i].state.proxy_position);
    if (deepest.first >= first && deepest.second > kStartOverlapDepth)
    {
      inside.push_back({static_cast<int>(i), deepest.first, deepest.second});
    }
  }
  return inside;
}
}  // namespace god_finger::internal
