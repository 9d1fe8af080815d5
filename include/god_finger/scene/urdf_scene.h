// Scenes from URDF (through urdfdom).
//
// Two forms:
//  - A scene: the root link is `world` (or any link without geometry): every link joined to it
//    by a `fixed` joint is static; by a `floating` joint, a free rigid body starting at the
//    joint origin.
//  - An object file, as PyBullet and Gazebo ship them: the root link has a <collision> and is
//    the body, at the origin (scene_file.h's scene lists place it); free with a positive
//    <inertial> mass, fixed without one or with mass 0 (PyBullet's fixed base).
//  - In both, an articulated object: a link joined to the root or to another body by a
//    `revolute`, `continuous` or `prismatic` joint is a free body moving on that joint
//    (SceneDescription::joints, with <axis>, <limit lower upper effort velocity> and <dynamics
//    damping friction>; a revolute joint's limits within [-pi, pi]), placed with every joint
//    at 0. A link on a `fixed` joint to another body's link (to an object file's root, or to any
//    body of a scene) is a piece of that body: its <collision>s join the body's parts, its mass
//    the body's (centre of mass and inertia combined by the parallel-axis theorem), a joint on it
//    joins the body; the body then walks on its pieces' collision surfaces (a visual mesh stands
//    for one link). A `floating` joint between two bodies is refused, as are `planar` joints and
//    chains deeper than kMaxJointDepth.
//  - Each body has one <collision> (box, sphere, cylinder, or mesh with scale), or several: a
//    compound body (BodyDescription::more_parts), one rigid body colliding as all its pieces;
//    a link's first <visual> mesh, when it is not its collision mesh, is the true surface
//    (BodyDescription::visual_mesh: the pad walks on it, rviz shows it; other visuals are
//    ignored); dynamic bodies need an <inertial> with mass > 0 and a positive-definite inertia. Every
//    number of a mass, an inertia, a mesh scale or an origin must be finite, and every
//    primitive's size within [kMinBodySize, kMaxBodySize] (scene_budget.h): each refusal
//    names the link, the element and its text.
//  - Contact materials come from PyBullet's URDF extension, the documented source Bullet
//    users already know: <link><contact><lateral_friction value=".."/>
//    <rolling_friction value=".."/><spinning_friction value=".."/>
//    <restitution value=".."/></contact></link>. Missing values keep ContactMaterial's defaults.
//  - Mesh file names: absolute, relative to the URDF file, file://..., or package://NAME/...
//    (NAME found by the PackageResolver given: the ROS layer passes ros::package::getPath;
//    without one, the folders above the URDF file whose package.xml names NAME).
//
// Errors: InputError with one line naming the file, the link and the problem; a
// ResourceLimitError (support/memory_budget.h) for more than kMaxBodies bodies (scene_budget.h).
#pragma once

#include "god_finger/scene/scene_description.h"

#include <functional>
#include <string>

namespace god_finger
{
// The folder of package `name`, or "" when it is not known.
using PackageResolver = std::function<std::string(const std::string& name)>;

// A file name as URDF writes it (absolute, file://..., package://NAME/..., or relative to
// `base_directory`) as a path; "" when its package is not known (then `package` names it).
// Whether the file exists is the caller's question.
std::string resolveFileName(const std::string& filename, const std::string& base_directory,
                            const PackageResolver& packages, std::string* package);
// The folder a file is in ("." for a bare name).
std::string folderOf(const std::string& path);

// The text of the URDF file at `urdf_path`, xacro expanded (xacro.h) when it is xacro. Throws
// InputError when it cannot be read.
std::string readUrdfText(const std::string& urdf_path, const PackageResolver& packages = PackageResolver());

SceneDescription loadUrdfScene(const std::string& urdf_path, const PackageResolver& packages = PackageResolver());
// Same, from a string; relative mesh paths are resolved against `base_directory`.
SceneDescription parseUrdfScene(const std::string& urdf_xml, const std::string& base_directory,
                                const std::string& source_name = "<string>",
                                const PackageResolver& packages = PackageResolver());
}  // namespace god_finger
