// A device that plays a recorded hand motion back: its position follows the recorded device
// positions in time (linear between samples) and ignores the commanded force, so a recorded
// session's interface motion is reproduced exactly, and with it (up to the loop's timing
// jitter) the objects' motion.
//
// Units: s, m. The track's time 0 is its first sample; setScriptStart() says when that is played.
#pragma once

#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/devices/haptic_device.h"

namespace god_finger
{
class ReplayDevice : public HapticDevice
{
 public:
  explicit ReplayDevice(WaypointPath track) : track_(std::move(track)) {}
  std::string name() const override
  {
    return "replay";
  }
  void start() override {}
  // Plays the track's time 0 at `time` of update()'s clock; by default at the first update.
  void setScriptStart(double time) override
  {
    start_ = time;
    start_set_ = true;
  }
  DeviceReading update(double time, const Eigen::Vector3d& force) override;

 private:
  WaypointPath track_;
  double start_ = 0.0;
  bool start_set_ = false;
};
}  // namespace god_finger
