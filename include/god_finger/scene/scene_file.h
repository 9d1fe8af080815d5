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

#include <string>

namespace god_finger
{
SceneDescription loadScene(const std::string& path, const PackageResolver& packages = PackageResolver());

// The table a scene list stands its objects on (support: table): static, 1 m x 1 m x 4 cm, its
// top the plane z = 0, lateral friction 0.6 as the shipped scenes' tables.
BodyDescription supportTable();
}  // namespace god_finger
