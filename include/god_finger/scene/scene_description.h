// A physics scene as plain data, independent of where it came from (URDF, code) and of
// Bullet: rigid bodies with their collision geometry, mass properties and contact materials,
// and the joints of articulated objects between them. Units SI; frames per REP-103 (z up); poses are of the body's link
// frame in `world`.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace god_finger
{
struct DeformableDescription;  // scene/deformable_object.h

enum class GeometryKind
{
  kBox,       // size = full extents (m)
  kSphere,    // radius (m)
  kCylinder,  // radius, length (m), axis = z of the geometry frame (URDF convention)
  kMesh,      // mesh_path, scale
};

struct Geometry
{
  GeometryKind kind = GeometryKind::kBox;
  Eigen::Vector3d size = Eigen::Vector3d::Ones();
  double radius = 0.0;
  double length = 0.0;
  std::string mesh_path;  // absolute, resolved
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
};

// Contact material of a body. Bullet combines two bodies' values by multiplication for
// friction, rolling and spinning friction, and by multiplication for restitution.
struct ContactMaterial
{
  double friction = 0.8;           // Coulomb coefficient (1)
  double rolling_friction = 0.0;   // (m), Bullet's rolling resistance
  double spinning_friction = 0.0;  // (m), Bullet's torsional friction
  double restitution = 0.0;        // (1)
};

// One more piece of a compound body (a link with several <collision>s): its geometry and where
// it sits in the link frame.
struct BodyPart
{
  Geometry geometry;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // geometry in link frame
};

struct BodyDescription
{
  std::string name;
  Geometry geometry;                                       // the first piece; a compound's others are in more_parts
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // link frame in world
  Eigen::Isometry3d collision_origin = Eigen::Isometry3d::Identity();  // geometry in link frame
  bool is_static = false;                                              // fixed to world
  double mass = 0.0;                                                   // kg, > 0 unless static
  Eigen::Isometry3d inertial_origin = Eigen::Isometry3d::Identity();   // centre of mass in link frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();                   // kg m^2 at the centre of mass
  ContactMaterial material;
  // A compound body's pieces after the first (empty for one piece): one rigid body colliding
  // as all of them, its walk surface the union of their surfaces.
  std::vector<BodyPart> more_parts;
  // The true surface, when the link's <visual> is a mesh other than its collision geometry (a
  // scanned or modelled surface over coarse collision hulls): the pad walks on it and rviz shows
  // it; the <collision>s are for collision only.
  std::optional<BodyPart> visual_mesh;
  // A soft body (a URDF <deformable>, issue 28): its volume, material and mass. It is static in
  // the rigid world and glued to what it rests on by its lowest nodes; its surface deforms under
  // the fingers (physics/soft_body.h). geometry is then kMesh naming its .vtk volume, for names
  // only. Shared and never changed: scenes are copied freely.
  std::shared_ptr<const DeformableDescription> soft;
};

// A joint between two bodies of an articulated object (URDF's revolute, continuous and
// prismatic joints): a door's hinge, a drawer's runners, a knob. The child is a free body; the
// parent another body or the world.
enum class JointKind
{
  kRevolute,    // about `axis`, limited to [lower, upper] rad
  kContinuous,  // about `axis`, unlimited
  kPrismatic,   // along `axis`, limited to [lower, upper] m
};
// "revolute", "continuous", "prismatic": URDF's names.
const char* jointKindName(JointKind kind);

struct JointDescription
{
  std::string name;
  JointKind kind = JointKind::kRevolute;
  int parent = -1;  // body index; -1: the world
  int child = -1;   // body index, a free body
  // The joint frame at position 0 in the parent's link frame (in the world for -1); the child's
  // link frame is the joint frame moved by the joint's position (URDF's convention).
  Eigen::Isometry3d joint_in_parent = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // unit, in the joint frame
  double lower = 0.0;                               // rad or m (revolute, prismatic)
  double upper = 0.0;
  // URDF's <limit effort velocity>: kept for the user; nothing drives the joint, so the world
  // applies neither.
  double effort = 0.0;
  double velocity = 0.0;
  // URDF's <dynamics>: viscous damping (N m s/rad or N s/m) and dry friction (N m or N).
  double damping = 0.0;
  double friction = 0.0;
};

struct SceneDescription
{
  std::string name;
  std::vector<BodyDescription> bodies;
  std::vector<JointDescription> joints;  // an articulated object's, between its bodies
  // What the loader passed over and the user should know, one line each naming the file and the
  // link (a visual mesh that cannot be read, visuals beyond the first): the loaders print them.
  std::vector<std::string> warnings;
  // Index of a body by name, -1 if absent.
  int find(const std::string& body_name) const
  {
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
      if (bodies[i].name == body_name)
      {
        return static_cast<int>(i);
      }
    }
    return -1;
  }
};
// Throws InputError when a joint of `scene` cannot be built: a body index out of range, a child
// that is static, its own parent or the child of another joint, a zero or non-finite axis,
// lower > upper, a negative damping or friction.
void checkJoints(const SceneDescription& scene);

// A solid box body: `size` (m, full edges), `mass` (kg) spread uniformly (its inertia at the
// centre of mass), its link frame at `centre` (m, world), axis-aligned. With mass 0: static.
BodyDescription boxBody(const std::string& name, const Eigen::Vector3d& size, double mass,
                        const Eigen::Vector3d& centre);
// A solid cylinder body of `radius` and `length` (m), its axis z (URDF convention), `mass` (kg)
// spread uniformly (inertia m r^2 / 2 about the axis, m (3 r^2 + l^2) / 12 across it), its link
// frame at `centre` (m, world), the axis vertical. With mass 0: static.
BodyDescription cylinderBody(const std::string& name, double radius, double length, double mass,
                             const Eigen::Vector3d& centre);
}  // namespace god_finger
