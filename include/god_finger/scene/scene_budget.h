// Refuses a scene that cannot fit before anything of it is built, with one line naming the
// limit, instead of a load that runs the machine out of memory or a world too large to step.
//
//  - At most kMaxBodies bodies: Bullet's broadphase and the per-step snapshot grow with the
//    body count, and each body costs about kBytesPerBody (measured: 10,000 boxes took 690 MiB).
//  - A primitive's every dimension (box edges, radii, lengths) in [kMinBodySize, kMaxBodySize]:
//    below, Bullet's margins (4 mm on a box) swallow the body; above, a unit mix-up (a URDF in
//    millimetres) rather than a scene one touches with a finger.
//  - The bodies and their primitives' walk meshes (tessellations, sized by max_walk_edge, m)
//    must fit in the memory limit of support/memory_budget.h. Mesh files are not opened here:
//    each is checked against the then-available memory when it is read (mesh_loader.h), so
//    that what the bodies before it took counts too.
// Errors: ResourceLimitError (an InputError). Not real-time.
#pragma once

#include "god_finger/scene/scene_description.h"

#include <cstdint>

namespace god_finger
{
constexpr int kMaxBodies = 10000;
constexpr std::uint64_t kBytesPerBody = 80 * 1024;
constexpr double kMinBodySize = 1e-4;   // m: 0.1 mm
constexpr double kMaxBodySize = 100.0;  // m
// Joints from a link to the root of its URDF: deeper chains are refused (a cycle-free URDF's
// articulated objects are a few links deep; the bound keeps a hostile file's walk short).
constexpr int kMaxJointDepth = 64;

// Bytes the scene's bodies and primitive walk meshes need (meshes' triangles not included).
std::uint64_t estimatedSceneBytes(const SceneDescription& scene, double max_walk_edge);

// Throws ResourceLimitError when the scene has more than kMaxBodies bodies ("scene 'NAME' has
// 10001 bodies, more than the limit of 10000") or estimatedSceneBytes exceeds the limit.
void checkSceneFits(const SceneDescription& scene, double max_walk_edge);
}  // namespace god_finger
