// The solver's input from one contact area of one (proxy, body) pair, as a contact response
// (contact_response.h) sees it between collision detection and the solver (the area itself is
// contact/contact_area.h's ContactAreaResult; its output, world_state.h's WorldContactArea). Internal to
// physics.
//
// Units: SI, world frame. Valid for one step: the pointers are into Bullet's manifolds and the
// proxy's interface state of that step.
#pragma once

#include "god_finger/physics/world_state.h"

#include <btBulletDynamicsCommon.h>

#include <Eigen/Core>

namespace god_finger::internal
{
struct AreaSolverInput
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
}  // namespace god_finger::internal
