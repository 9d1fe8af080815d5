// A god-object proxy: the sphere the virtual coupling pulls towards the interface, what it keeps
// from one step to the next per touched body (the radial basis, the warm-start impulses of its
// sub-god-objects, its pad), and how its Bullet body is built. Internal to physics.
//
// Units: SI; positions in the world frame. Not real-time to build; reading and writing its
// members is.
#pragma once

#include "god_finger/contact/contact_params.h"
#include "god_finger/haptics/virtual_coupling.h"
#include "god_finger/physics/oriented_finger.h"
#include "god_finger/physics/world_params.h"
#include "god_finger/physics/world_state.h"
#include "solver/pad_state.h"
#include "solver/warm_start.h"

#include <btBulletDynamicsCommon.h>

#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

namespace god_finger::internal
{
struct Proxy
{
  std::unique_ptr<btSphereShape> shape;
  std::unique_ptr<btRigidBody> rigid;
  Eigen::Vector3d initial = Eigen::Vector3d::Zero();
  CouplingProfile coupling;
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  Eigen::Vector3d previous_target = Eigen::Vector3d::Zero();
  // The device's and the proxy's orientation: an oriented (6-DOF) finger once given one.
  FingerOrientation orientation;
  InterfaceState state;
  // Per touched body: the last first radial vector (a continuous basis in time).
  std::vector<Eigen::Vector3d> reference_tangents;
  // Per touched body and sub-god-object index: the impulses of the last step, to warm-start
  // the next one as Bullet does for its own persistent points.
  std::vector<std::array<WarmStart, ContactParams::kMaxSubGodObjects>> warm_starts;
  // Per touched body: its finger pad (pad_state.h).
  std::vector<PadState> pads;
  // Letting go of a removed object (WorldParams::let_go_time): for let_go_steps more steps of
  // let_go_total, the coupling pulls the proxy toward target + let_go_steps / let_go_total *
  // let_go_offset (m, world: where the proxy was from the hand when its object went), while the
  // hand feels the coupling to the target itself.
  Eigen::Vector3d let_go_offset = Eigen::Vector3d::Zero();
  int let_go_steps = 0;
  int let_go_total = 0;
  // N, world: the load this proxy last gave the one soft body it touches (under-relaxed,
  // soft_body.h kSoftLoadRelaxation); zero while it touches none.
  Eigen::Vector3d soft_load = Eigen::Vector3d::Zero();
  int soft_load_body = -1;  // the body soft_load was given to (scene index), -1: none
};

// The pad's frame on the proxy, at the proxy body's origin (`proxy_object`'s), for a contact of
// normal `normal` (unit, world, out of the object): the body's own (it never turns) for a 3-DOF
// finger. For an oriented finger, the finger's orientation swung by the shortest arc that
// turns its pulp (z) onto -normal: it turns with the finger's twist about the normal and with
// the normal itself, not with the finger's roll on the surface (the pulp rolls there,
// pad_state.h). An oriented pad's material points are kept in this frame. Real-time safe.
inline btTransform padFrame(const Proxy& proxy, const btCollisionObject& proxy_object, const Eigen::Vector3d& normal)
{
  if (!proxy.orientation.oriented)
  {
    return proxy_object.getWorldTransform();
  }
  const Eigen::Quaterniond& finger = proxy.orientation.proxy;
  const Eigen::Quaterniond pad =
      Eigen::Quaterniond::FromTwoVectors(finger * Eigen::Vector3d::UnitZ(), -normal) * finger;
  return btTransform(btQuaternion(pad.x(), pad.y(), pad.z(), pad.w()), proxy_object.getWorldTransform().getOrigin());
}

// Builds the proxy's sphere and rigid body at `proxy.initial` (index `index`, touching
// `body_count` bodies) and resets its per-step state; the caller adds it to the world.
void buildProxyBody(const CouplingParams& coupling, const FingerPadParams& pad, int index, int body_count,
                    Proxy* proxy);

// The proxy's per-body state (radial basis, warm starts, pads, soft load) carried to a scene whose
// body i was body old_of_new[i] (-1: a new body, fresh state); a removed body's state goes.
void remapBodies(const std::vector<int>& old_of_new, Proxy* proxy);

// Whether carryFreeProxy may move it by `by`: no contact at its last step, not letting go, `by`
// finite and not zero.
bool carriable(const Proxy& proxy, const Eigen::Vector3d& by);
// Moves a carriable proxy by `by` (m, world) when its sphere touches nothing in `world` where it
// is (Bullet's shapes: inside a hollow object's hull, whose true surface the near callback
// keeps, it is never moved) and its sweep along `by` meets no body, keeping its velocity;
// returns whether it moved. Real-time safe (Bullet's tests allocate nothing).
bool carryFreeProxy(btCollisionWorld* world, const Eigen::Vector3d& by, Proxy* proxy);
}  // namespace god_finger::internal
