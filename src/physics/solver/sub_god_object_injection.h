// Sub-god-objects into Bullet's solver (the god_finger response): each kept sub-god-object of
// a contact area becomes a manifold point beside the true contact, with the true contact's
// normal, friction and pad compliance, its tilt-corrected distance
// (contact/sub_god_object_distance.h), and the impulses it had in the previous step as warm start
// (warm_start.h). pad_solver: points only; the pad constraint's one point is pad_constraints.h's.
// Internal to physics.
//
// Lifetime: points are injected between collision detection and the solver, their impulses are
// recorded after the solver, and the manifolds are released before the next collision
// detection. Allocation: the manifold and point lists grow to the largest contact seen, then
// are reused.
#pragma once

#include "area_solver_input.h"
#include "proxy.h"

#include <btBulletDynamicsCommon.h>

#include <Eigen/Core>
#include <vector>

namespace god_finger::internal
{
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
  void inject(const AreaSolverInput& contact, const Proxy& proxy, long step);
  // After the solver of step `step`: each injected point's impulses into its proxy's record.
  void recordImpulses(std::vector<Proxy>* proxies, long step);
  // Gives the injected manifolds back to the dispatcher.
  void release();

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
};
}  // namespace god_finger::internal
