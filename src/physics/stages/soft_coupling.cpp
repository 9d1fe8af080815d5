#include "stages/soft_coupling.h"

#include "bullet_helpers.h"
#include "world_core.h"

#include <algorithm>
#include <limits>

namespace god_finger::internal
{
namespace
{
// The fingers' friction anchors on soft body `index` (material points of it, kept in its
// centre-of-mass frame: WarmStart::anchor_on_object) go where its surface took them in the step
// it just made (soft_body.h materialMotion): the anchors of this step, the only ones the next
// step may hold (pad_constraints.cpp, sub_god_object_injection.cpp: step - 1). Left in place, a
// glued body's anchor stays where the surface was: the friction rows then see the material slide
// under the pad by the dimple's own motion.
void carryFrictionAnchors(WorldCore* core, int index)
{
  const SceneBody& body = core->bodies[index];
  const long steps = core->steps;
  const auto carry = [&](WarmStart* warm)
  {
    if (warm->step == steps - 1)
    {
      warm->anchor_on_object += materialMotion(body, warm->anchor_on_object);
    }
  };
  for (Proxy& proxy : core->proxies)
  {
    carry(&proxy.pads[index].linear);
    for (WarmStart& warm : proxy.warm_starts[index])
    {
      carry(&warm);
    }
  }
}

// Proxy `i`'s contact force, reversed, on the soft bodies it touches.
void loadSoftBodies(WorldCore* core, const SoftCoupling& coupling, std::size_t i)
{
  const WorldParams& params = core->params;
  const double dt = params.time_step;
  const bool as_pad = params.model != ContactModel::kGodObject;
  Proxy& proxy = core->proxies[i];
  proxy.state.contact_stiffness = std::numeric_limits<double>::infinity();
  const InterfaceState& state = proxy.state;
  const Eigen::Vector3d on_proxy = params.coupling.proxy_mass *
                                       (toEigen(proxy.rigid->getLinearVelocity()) - coupling.proxy_velocity_before[i]) /
                                       dt -
                                   coupling.proxy_force_before[i];
  bool loaded_soft = false;
  for (int c = 0; c < state.contact_count; ++c)
  {
    const WorldContactArea& area = state.contacts[c];
    SoftVolume* volume = core->bodies[area.body].soft.get();
    if (volume == nullptr)
    {
      continue;
    }
    const double pressing = on_proxy.dot(area.normal);  // > 0: the body pushes the proxy out
    const Eigen::Vector3d measured =
        state.contact_count == 1 ? Eigen::Vector3d(-on_proxy) : Eigen::Vector3d(-std::max(0.0, pressing) * area.normal);
    // One contact: under-relaxed (soft_body.h, kSoftLoadRelaxation), from the last load on the
    // same body (none on another).
    Eigen::Vector3d on_body = measured;
    if (state.contact_count == 1 && measured.allFinite())
    {
      if (proxy.soft_load_body != area.body)
      {
        proxy.soft_load.setZero();
      }
      on_body = proxy.soft_load + kSoftLoadRelaxation * (measured - proxy.soft_load);
      proxy.soft_load = on_body;
      proxy.soft_load_body = area.body;
      loaded_soft = true;
    }
    if (on_body.allFinite() && !on_body.isZero(0.0))
    {
      addSoftContactLoad(area, on_body, as_pad, volume);
      // Before this step's motion: the sink that this force (the last step's, reversed) made.
      proxy.state.contact_stiffness = softContactStiffness(area, on_body, volume);
      proxy.state.contact_normal = area.normal;
    }
  }
  if (!loaded_soft)
  {
    proxy.soft_load.setZero();
    proxy.soft_load_body = -1;
  }
}

// A manifold keeps its points where they were found on a body that does not move, refreshed by
// the bodies' transforms only: on a moved surface they would be points of the old one (a rim that
// holds the proxy above the dimple). The next detection finds them again.
void dropManifoldsOnSoftBodies(WorldCore* core)
{
  btCollisionDispatcher* dispatcher = core->dispatcher.get();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m)
  {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    const btCollisionObject* pair[] = {manifold->getBody0(), manifold->getBody1()};
    for (const btCollisionObject* object : pair)
    {
      if (object->getUserIndex() == kKindBody && core->bodies[object->getUserIndex2()].soft)
      {
        manifold->clearManifold();
        break;
      }
    }
  }
}
}  // namespace

void SoftCoupling::resize(std::size_t proxies)
{
  proxy_velocity_before.assign(proxies, Eigen::Vector3d::Zero());
  proxy_force_before.assign(proxies, Eigen::Vector3d::Zero());
}

void SoftCoupling::beforeSolve(WorldCore* core)
{
  if (core->soft_bodies.empty())
  {
    return;
  }
  for (std::size_t i = 0; i < core->proxies.size(); ++i)
  {
    proxy_velocity_before[i] = toEigen(core->proxies[i].rigid->getLinearVelocity());
    proxy_force_before[i] = toEigen(core->proxies[i].rigid->getTotalForce());
  }
}

void SoftCoupling::loadAndStep(WorldCore* core)
{
  if (core->soft_bodies.empty())
  {
    return;
  }
  for (std::size_t i = 0; i < core->proxies.size(); ++i)
  {
    loadSoftBodies(core, *this, i);
  }
  bool moved = false;
  for (const int index : core->soft_bodies)
  {
    if (stepSoftVolume(core->world.get(), &core->bodies[index]))
    {
      moved = true;
      carryFrictionAnchors(core, index);
    }
  }
  if (moved)
  {
    dropManifoldsOnSoftBodies(core);
  }
}
}  // namespace god_finger::internal
