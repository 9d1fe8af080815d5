// Soft bodies as PyBullet's URDF extension writes them (issue 28): a <robot> holding
//   <deformable name="torus">
//     <inertial><mass value="1"/><inertia .../></inertial>
//     <collision_margin value="0.006"/> <repulsion_stiffness value="800"/> <friction value="0.5"/>
//     <neohookean mu="60" lambda="200" damping="0.01"/>   (or <corotated mu lambda [damping]/>)
//     <visual filename="torus.vtk"/> <collision filename="torus.vtk"/>
//   </deformable>
// The volume is the tetrahedral .vtk of <collision> (else of <visual>), read by
// soft/vtk_tet_reader.h; file names resolve as the URDF loader's meshes do (relative, absolute,
// file://, package://). The material's mu and lambda are read as the Lamé parameters of its
// small-strain response (what the linear elements model), damping as Rayleigh's stiffness
// coefficient (s), the density as the mass over the mesh's volume. <spring> (mass-spring
// cloth) is not modelled: a body that has only a spring is refused. <repulsion_stiffness>,
// <gravity_factor> and <cache_barycenter> tune Bullet's solver and are accepted and ignored.
// <origin xyz rpy> places the body (ours: where PyBullet's loadSoftBody takes a base pose).
// <support value="glued|resting"/> (ours) says how it stands on what is under it: glued by its
// lowest nodes (the default: a block that stays put, the fidelity study's half-space), or
// resting, free, on the plane under its lowest point with its <friction> (a ball that can be
// picked up: physics/soft_body.h).
// Any other element in <deformable> is refused (a misspelt <neohooken> would otherwise lose its
// material silently).
//
// Errors: InputError, one line naming the file, the deformable and the problem: a missing
// name, mass, material or volume file; a value that is not a finite number or is out of
// soft_material.h's ranges; an unknown element; then the VTK reader's. Not real-time: reads files.
#pragma once

#include "god_finger/scene/urdf_scene.h"
#include "god_finger/soft/soft_material.h"
#include "god_finger/soft/tet_mesh.h"

#include <string>
#include <vector>

namespace god_finger
{
struct DeformableDescription
{
  std::string name;
  std::string volume_file;  // the .vtk read (resolved path)
  std::string visual_file;  // <visual>'s file as resolved ("" when none)
  std::string model;        // "neohookean" or "corotated"
  TetMesh mesh;             // checked, metres, the body's frame
  SoftMaterial material;    // E and nu from mu and lambda; density = mass / volume
  double mass = 0.0;        // kg
  double friction = ContactMaterial().friction;
  double collision_margin = 0.0;  // m
  // <support>: resting (free on the plane under its lowest point) or glued (the default).
  bool resting = false;
  // <origin xyz rpy> (this package's own, PyBullet places a body when it loads it): the body's
  // frame in the file's (a scene URDF's world, an object file's frame); identity when absent.
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
};

// Whether the URDF text holds a <deformable> element.
bool hasDeformables(const std::string& xml);

// The deformables of URDF text `xml`; `source` names it in errors, `base_directory` anchors
// relative file names.
std::vector<DeformableDescription> parseDeformables(const std::string& xml, const std::string& base_directory,
                                                    const std::string& source,
                                                    const PackageResolver& packages = PackageResolver());

// The deformables of the URDF (or xacro) file at `path`.
std::vector<DeformableDescription> loadDeformables(const std::string& path,
                                                   const PackageResolver& packages = PackageResolver());
}  // namespace god_finger
