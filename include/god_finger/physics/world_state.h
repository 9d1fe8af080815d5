// What a world shows of itself at one step, for output (markers, messages, metrics, the servo
// loop's snapshots): the contact areas in world coordinates, each interface's and each body's
// state. Plain data, no Bullet; the world (god_finger_world.h) fills them. Units SI, frame world.
#pragma once

#include "god_finger/contact/contact_area.h"
#include "god_finger/contact/contact_params.h"
#include "god_finger/physics/contact_model.h"
#include "god_finger/scene/scene_description.h"

#include <Eigen/Geometry>
#include <array>
#include <limits>
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
  // m^2: the overlap with other fingers' areas on this body, summed (contact/area_overlap.h; god_finger
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
  // below are the device's and the proxy's orientation and the torque on the hand (N m, world):
  // the rotational coupling's, plus what its pads' rows gave the objects it holds, turned back
  // on it (physics/solver/pad_state.h). A 3-DOF finger keeps identities and zero.
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
  // A soft contact's stiffness (N/m) along contact_normal (world, out of the body): the force the
  // finger presses the soft body with over how deep the surface sank under it (its linear
  // elements make this the same for any force), what the hand should feel between two steps
  // when the physics is slower than the device (runtime/multirate_render.h). Infinity for rigid
  // bodies, no contact, or a press too light to measure it.
  double contact_stiffness = std::numeric_limits<double>::infinity();
  Eigen::Vector3d contact_normal = Eigen::Vector3d::UnitZ();
};

struct BodyState
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // link frame in world
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
  Eigen::Vector3d linear_velocity = Eigen::Vector3d::Zero();   // of the centre of mass
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, world
  Eigen::Vector3d net_force =
      Eigen::Vector3d::Zero();  // N on the centre of mass, m dv/dt over the last step (gravity included)
  bool asleep = false;          // sleeping (WorldParams::sleep; a soft body: its volume at rest, soft/elastic_body.h)
  // Times it left the world's bounds (WorldParams::world_margin) and was put back at its initial
  // pose, at rest, since the world was made (a reset does not clear them); the world time (s)
  // of the last, -1 if never.
  int left_world = 0;
  double left_world_at = -1.0;
};

// Everything an observer shows of a world at one step (markers, TF, contact-area messages),
// copied out so that it can be read in another thread while the world steps on.
// An articulated object's joint (SceneDescription::joints): the child's position relative to
// its parent, 0 where the scene placed it, and its speed: rad and rad/s about the axis
// (revolute, continuous), m and m/s along it (prismatic).
struct JointState
{
  double position = 0.0;
  double velocity = 0.0;
};

// A soft body's surface as it is now (BodyDescription::soft: its walk mesh, deformed), for
// markers and recordings.
struct SoftSurfaceState
{
  int body = -1;                                                  // scene body index
  std::shared_ptr<const std::vector<Eigen::Vector3i>> triangles;  // into vertices, outward; never changes
  std::vector<Eigen::Vector3d> vertices;                          // m, world
  std::vector<float> sink;  // m, by vertex: how far it is from where it rests untouched
};

struct WorldSnapshot
{
  // The scene these bodies are (their names, shapes, joints), by body index: the world's scene
  // when the snapshot was taken (it changes when objects are added or removed). Shared, never
  // changed: an observer reads it in its own thread.
  std::shared_ptr<const SceneDescription> scene;
  double time = 0.0;  // s, world time of the step
  long steps = 0;
  ContactModel model = ContactModel::kGodFinger;
  std::vector<BodyState> bodies;                // by scene body index
  std::vector<InterfaceState> interfaces;       // by interface index
  std::vector<SoftSurfaceState> soft_surfaces;  // one per soft body, in scene order
};

}  // namespace god_finger
