// GodFingerWorld's private state is a WorldCore (world_core.h): one definition for the files that
// implement its calls (god_finger_world.cpp, god_finger_world_reads.cpp). Internal to physics.
#pragma once

#include "world_core.h"

#include "god_finger/physics/god_finger_world.h"

namespace god_finger
{
struct GodFingerWorld::Impl : internal::WorldCore
{
};
}  // namespace god_finger
