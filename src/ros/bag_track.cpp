#include "bag_track.h"

#include "god_finger/DeviceState.h"
#include "god_finger/support/input_error.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <exception>

namespace god_finger
{
WaypointPath readBagTrack(const std::string& bag_path, const std::string& topic)
{
  rosbag::Bag bag;
  try
  {
    bag.open(bag_path, rosbag::bagmode::Read);
  }
  catch (const std::exception& error)
  {
    throw InputError("bag '" + bag_path + "': cannot be read (" + error.what() + ")");
  }
  std::vector<Waypoint> waypoints;
  ros::Time first;
  long skipped = 0;
  for (const rosbag::MessageInstance& message : rosbag::View(bag, rosbag::TopicQuery(topic)))
  {
    const god_finger::DeviceState::ConstPtr state = message.instantiate<god_finger::DeviceState>();
    if (!state)
    {
      throw InputError("bag '" + bag_path + "': topic '" + topic + "' does not hold god_finger/DeviceState");
    }
    const Eigen::Vector3d position(state->position.x, state->position.y, state->position.z);
    if (waypoints.empty())
    {
      first = state->header.stamp;
    }
    // In whole nanoseconds first: a simulated-time session's stamps are exact ticks, and so
    // are these times.
    const double t = (state->header.stamp - first).toSec();
    if (!position.allFinite() || (!waypoints.empty() && !(t > waypoints.back().time)))
    {
      ++skipped;
      continue;
    }
    waypoints.push_back({t, position});
  }
  if (waypoints.empty())
  {
    throw InputError("bag '" + bag_path + "': no device states on topic '" + topic + "'" +
                     (skipped ? " (" + std::to_string(skipped) + " unusable)" : ""));
  }
  return WaypointPath(std::move(waypoints));
}
}  // namespace god_finger
