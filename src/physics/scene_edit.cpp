#include "scene_edit.h"

#include "bullet_helpers.h"
#include "start_overlaps.h"
#include "world_build.h"
#include "world_core.h"
#include "world_queries.h"

#include "god_finger/scene/scene_budget.h"
#include "god_finger/support/input_error.h"

#include <cmath>

namespace god_finger::internal
{
namespace
{
struct Motion
{
  btTransform transform;
  btVector3 linear;
  btVector3 angular;
};

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
}  // namespace

std::string describe(const ProxyInsideAdded& inside, const SceneDescription& scene)
{
  return "finger " + std::to_string(inside.finger) + " starts " + std::to_string(inside.depth) + " m inside '" +
         scene.bodies[inside.body].name + "': the solver pushes its proxy out (the hand feels it)";
}

void changeScene(WorldCore* core, SceneDescription next, const std::vector<int>& old_of_new,
                 std::vector<SceneBody>* made_before)
{
  const double max_edge = walkEdge(*core);
  std::vector<SceneBody> made(next.bodies.size());
  std::size_t taken = 0;
  for (std::size_t i = 0; i < next.bodies.size(); ++i)
  {
    if (old_of_new[i] < 0)
    {
      made[i] = made_before != nullptr ? std::move((*made_before)[taken++]) : makeSceneBody(next.bodies[i], max_edge);
    }
  }
  std::vector<char> kept(core->bodies.size(), 0);
  for (const int old : old_of_new)
  {
    if (old >= 0)
    {
      kept[old] = 1;
    }
  }
  std::vector<Motion> motions;
  for (const SceneBody& body : core->bodies)
  {
    motions.push_back(
        {body.rigid->getWorldTransform(), body.rigid->getLinearVelocity(), body.rigid->getAngularVelocity()});
  }
  // The proxies leave the old world whole, and join the new one as they are.
  for (Proxy& proxy : core->proxies)
  {
    letGoOfRemoved(core->params, kept, &proxy);
    core->world->removeRigidBody(proxy.rigid.get());
  }
  std::vector<Proxy> proxies = std::move(core->proxies);
  core->proxies.clear();
  teardownWorld(core);
  for (std::size_t i = 0; i < next.bodies.size(); ++i)
  {
    if (old_of_new[i] >= 0)
    {
      made[i] = std::move(core->bodies[old_of_new[i]]);
    }
  }
  core->bodies = std::move(made);
  core->scene = std::move(next);
  core->shared_scene = std::make_shared<const SceneDescription>(core->scene);
  buildWorld(core);
  for (std::size_t i = 0; i < core->bodies.size(); ++i)
  {
    if (old_of_new[i] < 0 || core->scene.bodies[i].is_static)
    {
      continue;
    }
    const Motion& motion = motions[old_of_new[i]];
    btRigidBody* rigid = core->bodies[i].rigid.get();
    rigid->setWorldTransform(motion.transform);
    rigid->setInterpolationWorldTransform(motion.transform);
    rigid->setLinearVelocity(motion.linear);
    rigid->setAngularVelocity(motion.angular);
    rigid->setInterpolationLinearVelocity(motion.linear);
    rigid->setInterpolationAngularVelocity(motion.angular);
    core->world->updateSingleAabb(rigid);
  }
  core->proxies = std::move(proxies);
  for (Proxy& proxy : core->proxies)
  {
    remapBodies(old_of_new, &proxy);
    // Its contacts were numbered in the old scene: none until the next step finds them.
    proxy.state.contact_count = 0;
    core->world->addRigidBody(proxy.rigid.get(), kProxyGroup, kBodyGroup);
  }
  sizeProxyScratch(core);
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
