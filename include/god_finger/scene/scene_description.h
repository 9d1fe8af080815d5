// A physics scene as plain data, independent of where it came from (URDF, code) and of
// Bullet: rigid bodies with one collision geometry each, mass properties and contact
// materials. Units SI; frames per REP-103 (z up); poses are of the body's link frame in
// `world`.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace god_finger
{
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
};

struct SceneDescription
{
  std::string name;
  std::vector<BodyDescription> bodies;
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
