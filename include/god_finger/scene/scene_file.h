// The one loader of every scene file a user gives (the physics' `scene` parameter, the tools):
//  - FILE.urdf: a URDF scene, or an object file whose root link is the body (urdf_scene.h);
//  - FILE.yaml / FILE.yml: a scene list, objects from their own files, each at a pose:
//
//      support: table        # table (default): a 1 m x 1 m table whose top is z = 0; none: nothing
//      objects:
//        - file: objects/mug.urdf   # relative to the list, absolute, file://, or package://NAME/...
//          name: mug                # optional: default the file's body name (several: NAME/BODY)
//          xyz: [0.0, 0.0, 0.0]     # m, optional: where the file's frame goes in `world`
//          rpy: [0.0, 0.0, 0.0]     # rad, optional (URDF's roll, pitch, yaw)
//          fixed: false             # optional: default the file's own (an object file's mass 0: fixed)
//
//    Each listed file may itself be either URDF form; its bodies are moved by the pose. Body
//    names must be unique across the list.
//
// Errors: InputError with one line naming the file (and the list's entry, or the URDF's link) and
// the problem: unknown keys, a missing or unreadable file, a pose that is not three finite
// numbers, a free body without mass, a name given twice, YAML syntax (with its line).
// Not real-time: reads files.
#pragma once

#include "god_finger/scene/scene_description.h"
#include "god_finger/scene/urdf_scene.h"

#include <optional>
#include <string>

namespace god_finger
{
// Where and how one object file goes into a scene: a scene list's entry, the spawn_object
// service's request.
struct ObjectPlacement
{
  std::string name;                                        // empty: the file's body names (several: NAME/BODY)
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // the file's frame in `world`
  std::optional<bool> fixed;                               // none: the file's own
};

SceneDescription loadScene(const std::string& path, const PackageResolver& packages = PackageResolver());

// Appends `object` (one URDF as loadUrdfScene gives it: its joints index its bodies, parent -1
// the world) to `scene`, placed: bodies moved by the pose and renamed (NAME, or NAME/BODY when
// the object has several; joints NAME/JOINT), `fixed` applied to the bodies no joint moves, the
// object's warnings added. InputError (no file name in it) when a fixed body without mass is made
// free. Names are not checked against the scene's.
void placeObject(const SceneDescription& object, const ObjectPlacement& placement, SceneDescription* scene);
// One object file (a URDF of either form) placed alone: the scene a spawn adds
// (GodFingerWorld::addObject). InputError naming the file: a scene list, a pose that is not finite,
// and every refusal of loadUrdfScene.
SceneDescription loadPlacedObject(const std::string& path, const ObjectPlacement& placement,
                                  const PackageResolver& packages = PackageResolver());

// URDF's roll, pitch, yaw (rad, about the fixed x, y, z axes in that order) as a rotation: a scene
// list's rpy, a spawned object's.
Eigen::Matrix3d rpyRotation(const Eigen::Vector3d& rpy);

// The table a scene list stands its objects on (support: table): static, 1 m x 1 m x 4 cm, its
// top the plane z = 0, lateral friction 0.6 as the shipped scenes' tables.
BodyDescription supportTable();
}  // namespace god_finger
