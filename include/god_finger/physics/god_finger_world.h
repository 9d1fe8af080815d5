// A Bullet world of rigid objects touched by god-object proxies with god-finger contact areas.
//
// One step (fixed time step, deterministic: the same calls give the same trajectory bit for
// bit) runs the stages step_profile.h lists, each timed (stepProfile()); in short:
//  1. each proxy gets the coupling force k (p_I - p_GO) + b (v_I - v_GO), saturated
//     (haptics/virtual_coupling.h, with its interface's profile);
//  2. Bullet's collision detection finds the proxies' contacts;
//  3. kGodFinger: for the deepest contact of each (proxy, object) pair, the contact area is
//     computed on the object's walk mesh and reaches the solver (WorldParams::pad_solver):
//     by default (constraint) as one pad at its centre of pressure with torsional and tilt rows
//     bounded by the area (src/physics/solver/pad_constraints.h); with `points` (the paper's way) every
//     active sub-god-object is a contact point with the true contact's normal and its
//     tilt-corrected depth, in manifolds of our own (Bullet's keep at most 4 points and merge
//     close ones; src/physics/solver/sub_god_object_injection.h);
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
// Invariants: proxies' Bullet bodies never rotate and ignore gravity; every scene body has a walk mesh
// (its mesh, or a tessellation of its primitive fine enough for r_max); the walk runs on the
// original triangle mesh even where collision uses a convex decomposition.
#pragma once

#include "god_finger/physics/step_profile.h"
#include "god_finger/physics/world_params.h"
#include "god_finger/physics/world_state.h"
#include "god_finger/scene/scene_description.h"
#include "god_finger/support/input_error.h"

#include <Eigen/Geometry>
#include <memory>
#include <vector>

namespace god_finger
{
// Thrown by addInterface when the proxy would start inside a body (the hand starts in the table:
// a workspace offset too low): the message names the body and the position. A caller that
// restarts under a hand pressing an object (the physics node respawning) catches it and adds the
// interface with allow_inside.
class ProxyInsideBodyError : public InputError
{
 public:
  explicit ProxyInsideBodyError(const std::string& message) : InputError(message) {}
};

// An object made ready to add to a world (GodFingerWorld::prepareObject): its bodies' shapes,
// walk meshes, trees and hulls built, the costly part of adding it (a first load decomposes a
// concave mesh), so that it can be done in another thread (a service's) than the world's, whose
// addObject then only adds its bodies to Bullet's world. Opaque.
class PreparedObject
{
 public:
  ~PreparedObject();
  PreparedObject(const PreparedObject&) = delete;
  PreparedObject& operator=(const PreparedObject&) = delete;
  const SceneDescription& object() const;

 private:
  friend class GodFingerWorld;
  PreparedObject();
  struct Impl;
  std::unique_ptr<Impl> impl_;
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
  // ProxyInsideBodyError on a position inside a body (the proxy's centre in it): the message names
  // the body and the position. A proxy never starts inside a body, and is never lifted out silently, unless
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
  // Moves the interface's proxy by `by` (m, world) before the next step when it touched nothing
  // at the last step and its sphere swept along `by` meets nothing (for a caller that skipped
  // targets: the free proxy keeps up with the hand instead of being pulled across the skipped
  // motion by the coupling); returns whether it moved. Real-time safe.
  bool carryFreeProxy(int interface, const Eigen::Vector3d& by);
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

  // Scene edits while running (the spawn_object and delete_object services): the object's bodies
  // join or leave Bullet's world as it runs, every other body and every proxy kept where it is
  // and moving as it moved, with its contacts and their warm starts, and asleep if it slept
  // (what rested on a removed body wakes). The time and step count go on. Not real-time safe: it
  // allocates and makes the new bodies' shapes (src/physics/scene_edit.h).
  //
  // Adds `object` (scene_file.h loadPlacedObject: its joints index its own bodies, parent -1 the
  // world) at its bodies' poses: from now on they are the scene's (a reset puts them back there).
  // Returns one line per body it starts inside of (start_overlaps.h). InputError, the world
  // unchanged: no body, a name the scene has already, a body or joint the world refuses.
  [[nodiscard]] std::vector<std::string> addObject(const SceneDescription& object);
  // The same with its bodies made beforehand (prepareObject, with this world's walk_edge_per_max_radius
  // and contact.max_radius; bodies made with others are made again here). Its bodies are taken:
  // a second add of the same one is refused.
  [[nodiscard]] std::vector<std::string> addObject(PreparedObject* object);
  // Makes `object`'s bodies for a world with `params` (any thread, no world needed; not real-time).
  // InputError: no body, a body no world takes (its geometry, the scene budget, its joints).
  [[nodiscard]] static std::unique_ptr<PreparedObject> prepareObject(const SceneDescription& object,
                                                                     const WorldParams& params);
  // Removes the bodies named `name` or `name/...` (an object added with several links), and the
  // joints that hold them. A finger pressing one lets go over WorldParams::let_go_time. Returns
  // how many bodies went. InputError, nothing removed: no body of that name.
  int removeObject(const std::string& name);

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
  // The scene's joints (SceneDescription::joints), in its order: where each stands now
  // (joint_measure.h). Articulated bodies never sleep.
  int jointCount() const;
  JointState jointState(int joint) const;
  // The scene as it is now (addObject and removeObject change it; the loop's thread only: an
  // observer elsewhere reads WorldSnapshot::scene).
  const SceneDescription& scene() const;
  // Fills `out` with the current state. Allocates only when out's vectors are smaller than
  // the body or interface count (so a snapshot buffer filled once never allocates again).
  void snapshot(WorldSnapshot* out) const;
  const TriangleMesh& walkMesh(int body) const;
  // What the user should know about the scene as the world found it when it was made, one line
  // each: bodies that start inside one another (src/physics/start_overlaps.h). Whoever builds the
  // world prints them, as it prints the scene's own warnings.
  const std::vector<std::string>& startWarnings() const;
  // How `body` collides: the convex hulls its pieces collide with other bodies as (0 when every
  // piece collides exactly: primitives, static meshes), and whether fingers (and free convex
  // bodies) touch its walk mesh itself instead (a hollow or a visual surface the hulls would
  // fill or miss: src/physics/near_callback.h).
  struct BodyCollision
  {
    int convex_hulls = 0;
    bool hulls_as_given = false;  // the mesh's own convex pieces (convex_decomposition.h), not computed
    bool fingers_touch_walk_mesh = false;
  };
  BodyCollision bodyCollision(int body) const;
  // What the last step counted (awake bodies, solver rows and iterations, proxy points, deepest
  // penetration, dropped contacts) and the totals since the world was made (rejected targets).
  WorldCounters counters() const;
  // What the last step spent, stage by stage (step_profile.h). Real-time safe.
  const StepProfile& stepProfile() const;
  double time() const;
  long steps() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
}  // namespace god_finger
