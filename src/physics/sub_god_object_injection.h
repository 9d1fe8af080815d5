// Sub-god-objects into Bullet's solver (the god_finger response): each kept sub-god-object of
// a contact area becomes a manifold point beside the true contact, with the true contact's
// normal, friction and pad compliance, its tilt-corrected distance
// (core/sub_god_object_distance.h), and the impulses it had in the previous step as warm start.
// Internal to physics.
//
// Lifetime: points are injected between collision detection and the solver, their impulses are
// recorded after the solver, and the manifolds are released before the next collision
// detection. Allocation: the manifold and point lists grow to the largest contact seen, then
// are reused.
#pragma once

#include "pad_constraint.h"
#include "proxy.h"

#include <btBulletDynamicsCommon.h>

#include <Eigen/Core>
#include <vector>

namespace god_finger
{
// One contact area of one (proxy, body) pair, as a contact response sees it.
struct AreaContact
{
  btPersistentManifold* manifold = nullptr;  // Bullet's manifold holding the true contact
  btManifoldPoint* contact = nullptr;        // the true contact (the deepest point)
  bool proxy_is_a = false;                   // the proxy is the manifold's body 0
  int proxy_index = 0;
  int body_index = 0;
  Eigen::Vector3d point_world = Eigen::Vector3d::Zero();        // the contact point on the object
  Eigen::Vector3d normal_world = Eigen::Vector3d::Zero();       // out of the object
  Eigen::Matrix3d object_to_pad = Eigen::Matrix3d::Identity();  // the object's turn since the contact began
  const WorldContactArea* area = nullptr;                       // the kept sub-god-objects (world)
  const int* radial_index = nullptr;                            // per kept sub-god-object, its radial vector's index
};

class SubGodObjectInjector
{
 public:
  explicit SubGodObjectInjector(btCollisionDispatcher* dispatcher) : dispatcher_(dispatcher) {}
  ~SubGodObjectInjector()
  {
    release();
  }
  // Adds the area's sub-god-objects as solver points, warm-started from `proxy`'s record of
  // step `step - 1` (pad_solver: points).
  void inject(const AreaContact& contact, const Proxy& proxy, long step);
  // Makes the true contact the pad (pad_constraint.h; pad_solver: constraint), warm-started and
  // anchored from `proxy`'s record of step `step - 1`.
  void injectPad(const AreaContact& contact, Proxy* proxy, long step);
  // After the solver of step `step`: each injected point's impulses into its proxy's record;
  // the pads' points back to plain contacts.
  void recordImpulses(std::vector<Proxy>* proxies, long step);
  // Gives the injected manifolds back to the dispatcher.
  void release();
  // This step's pads, for the solver's torsional rows (support_pass_solver.h).
  std::vector<PadRows>* padRows()
  {
    return &pads_;
  }

 private:
  struct InjectedPoint
  {
    btPersistentManifold* manifold = nullptr;
    int point = 0;
    int proxy = 0;
    int body = 0;
    int sub_god_object = 0;
    Eigen::Vector3d anchor_on_proxy;   // m, proxy frame
    Eigen::Vector3d anchor_on_object;  // m, object frame
  };
  btCollisionDispatcher* dispatcher_;
  std::vector<btPersistentManifold*> manifolds_;
  std::vector<InjectedPoint> points_;
  std::vector<PadRows> pads_;
};
}  // namespace god_finger
