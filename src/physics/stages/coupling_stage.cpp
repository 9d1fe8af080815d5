#include "stages/coupling_stage.h"

#include "bullet_helpers.h"
#include "scene_joints.h"
#include "world_core.h"
#include "world_queries.h"

#include "god_finger/physics/oriented_finger.h"
#include "god_finger/support/contract.h"

#include <array>

namespace god_finger::internal
{
namespace
{
// The oriented proxy's body cannot turn through what its tip touched at the last step
// (oriented_finger.h, limitFingerByContacts).
void limitByLastContacts(Proxy* proxy)
{
  std::array<Eigen::Vector3d, InterfaceState::kMaxContacts> normals;
  const int count = proxy->state.contact_count;
  for (int c = 0; c < count; ++c)
  {
    normals[c] = proxy->state.contacts[c].normal;
  }
  limitFingerByContacts(normals.data(), count, &proxy->orientation);
}

void coupleProxy(const WorldParams& params, Proxy* proxy)
{
  const double dt = params.time_step;
  const Eigen::Vector3d position = toEigen(proxy->rigid->getWorldTransform().getOrigin());
  const Eigen::Vector3d velocity = toEigen(proxy->rigid->getLinearVelocity());
  GOD_FINGER_EXPECTS(proxy->target.allFinite() && proxy->previous_target.allFinite(),
                     "setInterfaceTarget keeps only finite targets (non-finite ones are counted, not stored)");
  const Eigen::Vector3d target_velocity = (proxy->target - proxy->previous_target) / dt;
  const CouplingForce coupled = couplingForce(proxy->coupling, proxy->target, target_velocity, position, velocity);
  const Eigen::Vector3d& force = coupled.on_proxy;
  proxy->state.saturated = coupled.saturated;
  proxy->state.user_force = -force;
  if (proxy->let_go_steps > 0)
  {
    // Letting go of a removed object: the proxy follows a target that reaches the hand over
    // let_go_time, the hand feels the coupling to its own target (above).
    const double left = double(proxy->let_go_steps--) / proxy->let_go_total;
    const Eigen::Vector3d pull = proxy->target + left * proxy->let_go_offset;
    proxy->rigid->applyCentralForce(
        toBullet(couplingForce(proxy->coupling, pull, target_velocity, position, velocity).on_proxy));
  }
  else
  {
    proxy->rigid->applyCentralForce(toBullet(force));
  }
  proxy->state.interface_position = proxy->target;
  proxy->previous_target = proxy->target;
  if (proxy->orientation.oriented)
  {
    proxy->state.interface_orientation = proxy->orientation.target;
    proxy->state.user_torque = -stepFingerOrientation(params.finger, dt, &proxy->orientation);
    limitByLastContacts(proxy);
    proxy->state.proxy_orientation = proxy->orientation.proxy;
  }
}
}  // namespace

void applyCouplings(WorldCore* core)
{
  for (Proxy& proxy : core->proxies)
  {
    coupleProxy(core->params, &proxy);
  }
  for (std::size_t i = 0; i < core->proxies.size(); ++i)
  {
    const Eigen::Vector3d& push = core->overlap.push(static_cast<int>(i));
    if (!push.isZero(0.0))
    {
      core->proxies[i].rigid->applyCentralForce(toBullet(push));
    }
  }
  for (std::size_t i = 0; i < core->joints.size(); ++i)
  {
    resistJointMotion(core->scene.joints[i], jointState(*core, static_cast<int>(i)), core->params.time_step,
                      core->joints[i].get());
  }
}
}  // namespace god_finger::internal
