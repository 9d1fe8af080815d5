// Stage "escapees" of the world's step, after sleep: an awake body, or a resting soft body pushed
// off its support, whose centre left the world's bounds (world_bounds.h) goes back to its start, at
// rest, and is counted (BodyState::left_world). Also the soft bodies' supports, set when the world
// is built. Internal to physics.
// Units: SI, world frame. catchEscapees is real-time safe; placeSoftSupports allocates.
#pragma once

namespace god_finger::internal
{
struct WorldCore;

void catchEscapees(WorldCore* core);
// The resting soft bodies' supports end where the static bodies under them do
// (soft_body.h setSoftSupportExtent). When the world is built.
void placeSoftSupports(WorldCore* core);
}  // namespace god_finger::internal
