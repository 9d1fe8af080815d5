// The pose source (backend pose_source): N fingertip poses from a hand tracker, a glove or mocap,
// given by the ROS side (a geometry_msgs/PoseArray topic, or one TF frame per finger:
// ros/pose_feed_ros.cpp) through a PoseFeed. Input only: it renders no force (devices/hand_device.h). Real time only.
//
// Frames and units: positions in metres in the device frame (the interface's workspace mapping
// takes them to the world; with the default offset 0 the device frame is the world); stamps
// in seconds on the PoseSource's clock (`now`, steadySeconds() in the servo node).
// Orientations: a pose's orientation (the PoseArray's, the TF frame's rotation) is the finger's
// (an oriented finger, physics/oriented_finger.h): the fingertip frame must follow the finger
// frame's convention (z out of the pulp, x towards the tip; no frame offset is applied yet). An
// all-zero quaternion (a PoseArray that leaves it unset) means none: the finger is 3-DOF. Any
// other is passed on as given; the servo loop ignores and counts one that is not usable.
//
// Lost fingers: a finger whose newest finite pose is older than `pose_timeout`, or that has
// none yet, reads tracked = false at its last known position (`rest` before any): the loop lets
// it go. A non-finite pose or a missing one (an array with fewer poses) does not refresh the
// finger, so a finger the tracker lost lets go pose_timeout later; the others go on.
//
// Threads: PoseFeed::write() from one thread at a time (the subscriber's callback), read() from
// the loop's thread; a lock-free latest-value mailbox between them (support/latest_value.h).
// read() is real-time safe (no allocation, no lock).
#pragma once

#include "god_finger/devices/hand_device.h"
#include "god_finger/support/latest_value.h"
#include "god_finger/support/parameter_source.h"
#include "god_finger/support/parameter_table.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace god_finger
{
struct PoseSourceParams
{
  std::vector<std::string> fingers = {"thumb", "index", "middle"};  // names, in the array's order
  std::string topic = "poses";  // geometry_msgs/PoseArray, the interface's namespace
  // TF frames, one per finger (then no topic): each fingertip's frame, looked up in
  // reference_frame (the device frame's name in TF) at poll_rate.
  std::vector<std::string> frames;
  std::string reference_frame = "world";
  double poll_rate = 500.0;                               // Hz
  double pose_timeout = 0.1;                              // s: older poses let the finger go
  Eigen::Vector3d rest = Eigen::Vector3d(0.0, 0.0, 0.3);  // m, device frame: before a first pose
};

// The numeric parameters' one table (poll_rate, pose_timeout: names, units, ranges, meanings;
// defaults: the struct's initialisers above); the names, topic and frames are read beside it.
const ParameterTable<PoseSourceParams>& poseSourceParameterTable();

// fingers (1 to 10 unique non-empty names), topic, frames (none, or one per finger),
// reference_frame, the table's rows, rest; InputError naming a bad one.
PoseSourceParams readPoseSourceParams(const ParameterSource& source);

struct FingerPose
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m, device frame
  double stamp = -1.0;                                 // s, the source's clock; < 0: none
  bool missing = false;                                // PoseFeed: the newest write had no entry for this finger
  bool has_orientation = false;
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // finger frame, device frame
};

// Sets `pose`'s orientation from a message's quaternion (x, y, z, w): none when all four are
// zero (see above), else as given.
void setPoseOrientation(double x, double y, double z, double w, FingerPose* pose);

class PoseFeed
{
 public:
  explicit PoseFeed(std::size_t fingers) : box_(std::vector<FingerPose>(fingers)), latest_(fingers) {}
  std::size_t fingers() const
  {
    return latest_.size();
  }
  // Writer: the newest poses; entries beyond `poses` or not finite keep their last value (one
  // beyond `poses` is marked missing until a pose for it comes).
  void write(const std::vector<FingerPose>& poses);
  // Reader (the loop): the newest poses written.
  const std::vector<FingerPose>& read();

  std::shared_ptr<void> connection;  // the ROS subscription writing it (DeviceContext::connect_poses)

 private:
  LatestValue<std::vector<FingerPose>> box_;
  std::vector<FingerPose> latest_;  // the writer's merged state
};

// The source, reading `feed`; `now`: its clock (s), what stamps are on.
std::shared_ptr<HandSource> makePoseSource(const PoseSourceParams& params, std::shared_ptr<PoseFeed> feed,
                                           std::function<double()> now);
}  // namespace god_finger
