// Parameters of the physics world and of the god-object proxies, with units, defaults and
// ranges; validate() names the first bad one.
#pragma once

#include "god_finger/core/contact_params.h"
#include "god_finger/physics/contact_model.h"

#include <Eigen/Core>
#include <string>

namespace god_finger
{
// The virtual coupling (Colgate et al. 1995): a spring-damper between the interface position
// p_I and the god-object p_GO. The god-object is a small sphere with locked rotation.
struct CouplingParams
{
  double stiffness = 400.0;     // N/m, range (0, 1e5]; the device profile's stable value
  double damping = 4.0;         // N s/m, range [0, 1e3]; near critical for the proxy mass
  double proxy_mass = 0.02;     // kg, range (0, 10]
  double proxy_radius = 0.003;  // m, range (0, 0.1]
  double max_force = 20.0;      // N, range (0, 1e4]: the coupling force is saturated here
};

// The soft-finger baseline: Bullet's torsional and rolling friction at the single point.
// Bullet multiplies the proxy's coefficient with the object's friction, and its sequential
// impulse solver only adds spinning friction when the rolling friction is non-zero.
struct SoftFingerParams
{
  double spinning_friction = 0.01;  // m, range [0, 1]
  double rolling_friction = 1e-4;   // m, range (0, 1]: must be > 0 for spinning to act
};

struct WorldParams
{
  double time_step = 1e-3;                                 // s, range [1e-5, 0.1]
  int solver_iterations = 30;                              // range [1, 1000]
  Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);  // m/s^2, finite
  ContactModel model = ContactModel::kGodFinger;
  ContactParams contact;
  CouplingParams coupling;
  SoftFingerParams soft_finger;
  // Largest edge of the walk surface of a sphere or cylinder, as a fraction of r_max: the
  // tessellation is refined until its edges are no longer (capped at 81920 triangles).
  double walk_edge_per_max_radius = 0.5;  // range (0, 10]
};

std::string validate(const WorldParams& params);
void validateOrThrow(const WorldParams& params);
}  // namespace god_finger
