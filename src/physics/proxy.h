// A god-object proxy: the sphere the virtual coupling pulls towards the interface, what it keeps
// from one step to the next per touched body (the radial basis, the warm-start impulses of its
// sub-god-objects, the pad's shape), and how its Bullet body is built. Internal to physics.
//
// Units: SI; positions in the world frame. Not real-time to build; reading and writing its
// members is.
#pragma once

#include "god_finger/core/contact_params.h"
#include "god_finger/core/virtual_coupling.h"
#include "god_finger/physics/god_finger_world.h"

#include <btBulletDynamicsCommon.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <vector>

namespace god_finger
{
// What one sub-god-object keeps from one step to the next: the impulses the solver gave it (to
// warm-start the next step) and its friction anchor, the material points of the pad and of the
// object it held when it began to stick (the friction rows pull them back together, so that a
// held object does not creep).
struct WarmStart
{
  long step = -1;  // the step the impulses and the anchor are from
  double normal = 0.0;
  double lateral1 = 0.0;
  double lateral2 = 0.0;
  double friction = 0.0;                                       // the point's combined friction
  Eigen::Vector3d anchor_on_proxy = Eigen::Vector3d::Zero();   // m, in the proxy's frame
  Eigen::Vector3d anchor_on_object = Eigen::Vector3d::Zero();  // m, in the object's (centre of mass) frame
};

// What the pad constraint of one (proxy, body) pair keeps from one step to the next
// (pad_constraint.h): its point's impulses and friction anchor, as a sub-god-object's, and its
// orientation anchor: the object's world orientation when the pad began to stick (the proxy
// never turns), let go when a torsional row reached its bound (slip).
struct PadState
{
  WarmStart linear;
  bool twist_slipped = true;
  Eigen::Quaterniond object_at_anchor = Eigen::Quaterniond::Identity();
  Eigen::Vector3d torque_impulse = Eigen::Vector3d::Zero();  // N m s on the manifold's body B, world
};

// The pad: the shape the finger took when a contact began. It moves with the proxy and never
// rotates; `orientation` is the object's (world) when the contact began, `last_step` the last
// step the contact existed.
struct PadShape
{
  long last_step = -2;
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
};

struct Proxy
{
  std::unique_ptr<btSphereShape> shape;
  std::unique_ptr<btRigidBody> rigid;
  Eigen::Vector3d initial = Eigen::Vector3d::Zero();
  CouplingProfile coupling;
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  Eigen::Vector3d previous_target = Eigen::Vector3d::Zero();
  InterfaceState state;
  // Per touched body: the last first radial vector (a continuous basis in time).
  std::vector<Eigen::Vector3d> reference_tangents;
  // Per touched body and sub-god-object index: the impulses of the last step, to warm-start
  // the next one as Bullet does for its own persistent points.
  std::vector<std::array<WarmStart, ContactParams::kMaxSubGodObjects>> warm_starts;
  // Per touched body.
  std::vector<PadShape> pads;
  std::vector<PadState> pad_states;

  Eigen::Vector3d position() const
  {
    return Eigen::Vector3d(rigid->getWorldTransform().getOrigin().x(), rigid->getWorldTransform().getOrigin().y(),
                           rigid->getWorldTransform().getOrigin().z());
  }
};

// Builds the proxy's sphere and rigid body at `proxy.initial` (index `index`, touching
// `body_count` bodies) and resets its per-step state; the caller adds it to the world.
void buildProxyBody(const CouplingParams& coupling, const FingerPadParams& pad, int index, int body_count,
                    Proxy* proxy);
}  // namespace god_finger
