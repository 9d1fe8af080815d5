// An oriented finger (6-DOF): a finger whose source reports an orientation (an Omni/Touch
// gimbal, an interactive marker's rotation, a fake script with orientation, a pose from TF).
//
// The finger frame: z points out of the pulp (the pad's outward normal, the side that
// presses), x runs along the finger towards its tip, y = z x x. An orientation is the finger
// frame in the world.
//
// Two things follow from it (GodFingerWorld::setInterfaceTarget with an orientation):
//  1. The proxy keeps its own orientation, pulled towards the device's by a rotational
//     spring-damper (the 6-DOF god-object, Ortega et al. 2007), integrated as the linear
//     coupling is (the torque from the state at the start of the step, then symplectic Euler):
//       tau = k_r rotvec(q_I q_GO^-1) + b_r (w_I - w_GO)  (N m, world, on the proxy),
//       the hand feels -tau. Stable in free space iff (k_r dt + 2 b_r) dt / I < 4.
//     The proxy's orientation is limited by its contacts (limitFingerByContacts): behind the
//     tip runs the finger's body (the distal phalanx, along -x, as wide as the tip), which
//     cannot pass through a surface the tip touches. So the proxy turns towards the device's
//     orientation only as far as x . c_n <= sin(kFingerBodyClearance) for each contact normal
//     c_n (the surface's plane at the contact, less the body's taper): neither the finger's body
//     nor its nail turns through the surface. A
//     finger reaches nail-down by curling its tip down, through pointing straight in, never by
//     lifting its tip and sweeping its body through the object. Held at that bound, the
//     spring above is stretched and the hand feels it (-tau), as a god-object's hand feels its
//     stopped proxy.
//     The pads the proxy holds turn with it
//     (src/physics/solver/pad_state.h), and what resists them (their rows' torque on the
//     objects, turned back) is added to the hand's torque, InterfaceState::user_torque; the
//     servo loop sends it to a device on its profile's torque_axes, saturated at max_torque (haptics/device_profile.h;
//     the Omni/Touch and the Falcon render force only: none).
//  2. The pad sits on the pulp: with phi the angle between the pulp normal (finger z) and the
//     inward surface normal (-c_n), the contact radius is the Eq. 1 radius times
//     cos(pi/2 phi / nail_angle) (1 when the pulp faces the surface, smaller on the side, 0 from
//     the nail angle on: the nail gives a point, the god-object), and the area's centre moves
//     along the surface by the arc R_f phi towards the side the pulp turned to (a fingertip of
//     radius R_f rolling on the surface): rolling by theta moves the area by R_f theta. From the
//     nail angle on the point is the true contact (no offset).
// A finger never given an orientation is a 3-DOF finger and none of this runs.
//
// Units SI, angles in radians, vectors in the world frame. Every function here is real-time
// safe (no allocation, no lock, no throw).
#pragma once

#include <Eigen/Geometry>
#include <string>

namespace god_finger
{
// The oriented finger's parameters (rows in worldParameterTable(), world_params.cpp).
struct OrientedFingerParams
{
  double fingertip_radius = 0.008;         // m, R_f: a fingertip's radius across the finger
  double nail_angle = 2.0943951023931957;  // rad (120 deg): from this tilt of the pulp on, a point
  double orientation_stiffness = 0.05;     // N m/rad, k_r
  double orientation_damping = 2e-4;       // N m s/rad, b_r (damping ratio 0.45 with the inertia)
  double proxy_inertia = 1e-6;             // kg m^2, I: the proxy's rotational inertia
};

// An interface's orientation state: the device's (target) and the proxy's.
struct FingerOrientation
{
  bool oriented = false;  // given an orientation once: a 6-DOF finger from then on
  Eigen::Quaterniond initial = Eigen::Quaterniond::Identity();  // where a reset restarts it
  Eigen::Quaterniond target = Eigen::Quaterniond::Identity();   // q_I, the device's, unit
  Eigen::Quaterniond previous_target = Eigen::Quaterniond::Identity();
  Eigen::Quaterniond proxy = Eigen::Quaterniond::Identity();   // q_GO, unit
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // w_GO (rad/s, world)
  // Back to `initial`, at rest (a reset).
  void restart();
};

// One step of the rotational coupling (dt s): returns tau on the proxy (N m, world) and
// advances the proxy's orientation and angular velocity; the previous target becomes the
// current one.
Eigen::Vector3d stepFingerOrientation(const OrientedFingerParams& params, double dt, FingerOrientation* state);

// The contact limit of item 1: for each of `count` contact normals (unit, world, out of the
// objects the tip touches), turns the proxy by the least rotation that brings its finger axis x
// back to kFingerBodyClearance past the surface's plane (x . n <= sin kFingerBodyClearance) when
// it went further, and stops its angular velocity's part that would turn it further in. A few
// passes for several normals (corners); returns whether it turned the proxy. Real-time safe.
// The clearance: a finger's body narrows behind the tip (about 1 mm over a 2.5 cm distal
// phalanx), so it meets a plane its tip touches only once tilted about 0.04 rad into it. It
// also keeps the limit away from a finger laid along what it holds: with none, the cylinder
// turn's fingers (tips down along the mantle, x . n = 0) sat on the bound, the wrist's tremor
// hit it every few steps, and a finger laid back on a tilting cylinder turned it further
// through its pad (measured: 30 % of 20 mm squeezes turned it 90 degrees, median tilt 0.82 rad,
// against 100 % and 0.007 rad without the limit).
constexpr double kFingerBodyClearance = 0.05;  // rad
bool limitFingerByContacts(const Eigen::Vector3d* normals, int count, FingerOrientation* state);

// How the finger meets a surface (item 2 above).
struct PulpContact
{
  double tilt = 0.0;                                 // phi (rad), in [0, pi]
  double radius_scale = 1.0;                         // in [0, 1], times the Eq. 1 radius
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // m, world, tangent to the surface
};
// `finger`: the proxy's orientation; `surface_normal`: c_n, unit, out of the object.
PulpContact pulpContact(const Eigen::Quaterniond& finger, const Eigen::Vector3d& surface_normal,
                        const OrientedFingerParams& params);

// Empty when the rotational coupling is stable at `time_step` (s); else one line naming the
// parameters.
std::string orientationStabilityError(const OrientedFingerParams& params, double time_step);
}  // namespace god_finger
