// dynamic_reconfigure of the method's parameters and the contact model (cfg/GodFinger.cfg),
// shared by the physics node and the servo node. Not real-time (called from ROS callbacks).
#pragma once

#include "god_finger/GodFingerConfig.h"
#include "god_finger/physics/world_params.h"

#include <string>

namespace god_finger
{
// The configuration that shows `params` (to start the server from what the node runs with).
// The cfg's entries are rows of worldParameterTable(), matched by name.
god_finger::GodFingerConfig configOf(const WorldParams& params);
// `config` applied over `base` through worldParameterTable(): false (and `error` says why,
// naming the parameter) when any value or the whole set is invalid; nothing is to be applied then.
bool worldFromConfig(const god_finger::GodFingerConfig& config, const WorldParams& base, WorldParams* params,
                     std::string* error);
}  // namespace god_finger
