// A Bullet world of rigid objects touched by god-object proxies with god-finger contact areas.
//
// One step (fixed time step, deterministic: the same calls give the same trajectory bit for
// bit):
//  1. each proxy gets the coupling force k (p_I - p_GO) + b (v_I - v_GO), saturated
//     (core/virtual_coupling.h, with its interface's profile);
//  2. Bullet's collision detection finds the proxies' contacts;
//  3. kGodFinger: for the deepest contact of each (proxy, object) pair, the contact area is
//     computed on the object's walk surface and reaches the solver (WorldParams::pad_solver):
//     by default (constraint) as one pad at its centre of pressure with torsional and tilt rows
//     bounded by the area (src/physics/pad_constraints.h); with `points` (the paper's way) every
//     active sub-god-object is a contact point with the true contact's normal and its
//     tilt-corrected depth, in manifolds of our own (Bullet's keep at most 4 points and merge
//     close ones; src/physics/sub_god_object_injection.h);
//  4. the solver runs; the force on the user is the opposite of the coupling force;
//  5. kGodFinger: where two fingers' contact areas on one body overlap (share surface on one side
//     of it: pads on opposite faces are a pinch, never an overlap), both proxies are pushed apart
//     in the next step, unless a finger holds the body against another (WorldParams::overlap,
//     src/physics/overlap_push.h).
//
// Sleeping (WorldParams::sleep): a dynamic body at rest, out of every proxy's reach, falls asleep
// with its island and costs almost nothing until a proxy or a woken body comes near it.
//
// Oriented fingers (setInterfaceTarget with an orientation, oriented_finger.h): the proxy keeps an
// orientation pulled by a rotational spring-damper; the contact area's radius and centre follow
// how the pulp meets the surface. A finger never given an orientation runs the 3-DOF code bit for
// bit.
//
// Invariants: proxies' Bullet bodies never rotate and ignore gravity; every scene body has a walk surface
// (its mesh, or a tessellation of its primitive fine enough for r_max); the walk runs on the
// original triangle mesh even where collision uses a convex decomposition.
#pragma once

#include "god_finger/core/contact_area.h"
#include "god_finger/scene/scene_description.h"
#include "god_finger/physics/world_params.h"

#include <Eigen/Geometry>
#include <memory>
#include <vector>

namespace god_finger
{
// A contact area in world coordinates, for output (markers, messages, metrics).
struct WorldContactArea
{
  int body = -1;                                      // scene body index
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // c_p (m, world)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // c_n (world, out of the object)
  double depth = 0.0;                                 // m, > 0 when penetrating
  double radius = 0.0;                                // r (m)
  FeatureKind feature = FeatureKind::kFace;
  int sub_god_object_count = 0;                                             // active ones, in positions
  std::array<Eigen::Vector3d, ContactParams::kMaxSubGodObjects> positions;  // world
  // m^2: the overlap with other fingers' areas on this body, summed (core/area_overlap.h; god_finger
  // model only, 0 otherwise)
  double overlap_area = 0.0;
};

struct InterfaceState
{
  Eigen::Vector3d interface_position = Eigen::Vector3d::Zero();  // p_I (m, world)
  Eigen::Vector3d proxy_position = Eigen::Vector3d::Zero();      // p_GO (m, world)
  Eigen::Vector3d proxy_velocity = Eigen::Vector3d::Zero();      // m/s
  Eigen::Vector3d user_force = Eigen::Vector3d::Zero();          // N on the hand (world)
  bool saturated = false;                                        // coupling force hit max_force
  // An oriented (6-DOF) finger (oriented_finger.h: the finger frame has z out of the pulp, x
  // towards the tip): false until the interface is given an orientation, and then the three
  // below are the device's and the proxy's orientation and the rotational coupling's torque on
  // the hand (N m, world). A 3-DOF finger keeps identities and zero.
  bool oriented = false;
  Eigen::Quaterniond interface_orientation = Eigen::Quaterniond::Identity();
  Eigen::Quaterniond proxy_orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d user_torque = Eigen::Vector3d::Zero();
  int contact_count = 0;                  // entries used in contacts
  static constexpr int kMaxContacts = 4;  // bodies touched at once
  std::array<WorldContactArea, kMaxContacts> contacts;
  // The overlap of this finger's areas with the other fingers' (m^2, the sum of its contacts'
  // overlap_area), and the push it brings on the proxy in the next step (N, world; WorldParams::
  // overlap, src/physics/overlap_push.h): both zero when no area overlaps.
  double overlap_area = 0.0;
  Eigen::Vector3d overlap_push = Eigen::Vector3d::Zero();
};

struct BodyState
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // link frame in world
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
  Eigen::Vector3d linear_velocity = Eigen::Vector3d::Zero();   // of the centre of mass
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, world
  Eigen::Vector3d net_force =
      Eigen::Vector3d::Zero();  // N on the centre of mass, m dv/dt over the last step (gravity included)
  bool asleep = false;          // sleeping (WorldParams::sleep): not simulated until woken
  // Times it left the world's bounds (WorldParams::world_margin) and was put back at its initial
  // pose, at rest, since the world was made (a reset does not clear them); the world time (s)
  // of the last, -1 if never.
  int left_world = 0;
  double left_world_at = -1.0;
};

// Everything an observer shows of a world at one step (markers, TF, contact-area messages),
// copied out so that it can be read in another thread while the world steps on.
struct WorldSnapshot
{
  double time = 0.0;  // s, world time of the step
  long steps = 0;
  ContactModel model = ContactModel::kGodFinger;
  std::vector<BodyState> bodies;           // by scene body index
  std::vector<InterfaceState> interfaces;  // by interface index
};

class GodFingerWorld
{
 public:
  // Throws InputError on bad parameters or scene (naming the body and the problem).
  GodFingerWorld(const SceneDescription& scene, const WorldParams& params);
  ~GodFingerWorld();
  GodFingerWorld(const GodFingerWorld&) = delete;
  GodFingerWorld& operator=(const GodFingerWorld&) = delete;

  // Adds a finger: a proxy at `position` (m, world) pulled with the world's coupling profile
  // (params().coupling) or the device's own. Returns its index. Throws InputError on a
  // non-finite position, a bad profile, or one unstable at this time step and proxy mass, and
  // on a position inside a body (the proxy's centre in it): the message names the body and the
  // position. A proxy never starts inside a body, and is never lifted out silently, unless
  // `allow_inside` (the physics node respawning under a hand that presses an object: the solver
  // pushes the proxy out, and the device's guard ramps the force in after its watchdog tripped).
  int addInterface(const Eigen::Vector3d& position);
  int addInterface(const Eigen::Vector3d& position, const CouplingProfile& coupling, bool allow_inside = false);
  // The profile that pulls this interface's proxy (the hand must feel the same).
  const CouplingProfile& coupling(int interface) const;
  // The device's position in the world for the next step; non-finite values are ignored
  // (and counted), the previous target stays.
  void setInterfaceTarget(int interface, const Eigen::Vector3d& position);
  // As above, with the target's velocity (m/s, world) for the coupling's damping instead of
  // the difference from the previous target over one step: for a caller that skipped targets
  // (the servo loop's physics when it runs late), whose difference would put several periods'
  // motion into one step. Non-finite position or velocity: ignored and counted.
  void setInterfaceTarget(int interface, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity);
  // As the first, with the device's orientation (the finger frame in the world,
  // oriented_finger.h): the interface becomes an oriented (6-DOF) finger. The first orientation
  // given places the proxy's orientation there at rest (a reset restarts it there). A
  // non-finite position or a quaternion that is non-finite or of a norm outside [0.5, 2]: the
  // whole target is ignored and counted; others are normalised. Real-time safe.
  void setInterfaceTarget(int interface, const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation);
  // An external force (N, world, at the centre of mass) and torque (N m, world) on a dynamic
  // body during the next step only (a disturbance, a test's load). Ignored for static bodies;
  // InputError for a bad index or non-finite values.
  void applyBodyWrench(int body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque);
  void step();
  // Back to the scene's initial state, proxies where they started, time 0 (a reset run repeats
  // the first one bit for bit).
  void reset();
  // The same, but each proxy restarts at its interface's current target, which becomes its
  // start: a hand holding a device feels no jump (the servo loop's reset).
  void resetAtInterfaces();

  void setContactModel(ContactModel model);
  ContactModel contactModel() const;
  // Throws InputError on invalid parameters; keeps the old ones then.
  void setContactParams(const ContactParams& params);
  // god_finger's pad solver (WorldParams::pad_solver), from the next step; wakes every body.
  // Throws InputError on a value that names none.
  void setPadSolver(PadSolver solver);
  const WorldParams& params() const;

  int interfaceCount() const;
  const InterfaceState& interfaceState(int interface) const;
  int bodyCount() const;
  BodyState bodyState(int body) const;
  const SceneDescription& scene() const;
  // Fills `out` with the current state. Allocates only when out's vectors are smaller than
  // the body or interface count (so a snapshot buffer filled once never allocates again).
  void snapshot(WorldSnapshot* out) const;
  const TriangleMesh& walkSurface(int body) const;
  // Dynamic bodies awake now (simulated in the next step); static bodies never count.
  int awakeBodyCount() const;
  // Contact points between a proxy and an object the solver received in the last step (test
  // hook for the Bullet manifold limits).
  int solverProxyContactPoints() const;
  // Contact rows (normal, friction, torsional) the solver solved in the last step, all pairs.
  int solverContactRows() const;
  // Sequential-impulse iterations the last step ran (WorldParams::solver_tolerance may stop
  // them before solver_iterations).
  int solverIterationsUsed() const;
  // Deepest penetration (m, >= 0) among all contacts found in the last step, before the solver.
  double deepestPenetration() const;
  double time() const;
  long steps() const;
  long rejectedTargets() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
}  // namespace god_finger
