// dynamic_reconfigure of the method's parameters and the contact model (cfg/GodFinger.cfg),
// shared by the physics node and the servo node.
#pragma once

#include "god_finger/GodFingerConfig.h"
#include "god_finger/physics/world_params.h"

#include <string>

namespace god_finger
{
// The configuration that shows `params` (to start the server from what the node runs with).
god_finger::GodFingerConfig configOf(const WorldParams& params);
// `config` applied over `base`: false (and `error` says why) when the model, the walk or the
// whole set of contact parameters is invalid; nothing is to be applied then.
bool contactFromConfig(const god_finger::GodFingerConfig& config, const ContactParams& base, ContactParams* contact,
                       ContactModel* model, std::string* error);
}  // namespace god_finger
