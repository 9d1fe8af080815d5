// Reading a recorded device motion from a bag: the positions of god_finger/DeviceState
// messages on one topic, in recording order, timed by their header stamps (s, relative to the
// first). Throws InputError naming the bag and the problem (missing or unreadable file, no
// such topic, non-finite or out-of-order samples are skipped and counted in the message only
// if nothing usable remains).
#pragma once

#include "god_finger/haptics/waypoint_path.h"

#include <string>

namespace god_finger
{
WaypointPath readBagTrack(const std::string& bag_path, const std::string& topic);
}  // namespace god_finger
