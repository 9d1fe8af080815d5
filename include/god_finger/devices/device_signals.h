// Signal handling shared by the hardware backends (Falcon, Omni): what every backend does to
// a force before it reaches the motors, and how it estimates velocity from positions.
//
// Units: forces in newtons, positions in metres, times in seconds, velocities in m/s.
// Invariants: a motor command is finite and its magnitude never exceeds the limit given;
// the velocity is zero until two readings with increasing times have been seen.
#pragma once

#include <Eigen/Core>
#include <array>

namespace god_finger
{
// The Falcon's and the Omni's own frames share their axes (devices/vendor_frames.h, hdFrame():
// x to the user's right, y up, z towards the user): a force in the device frame in theirs.
std::array<double, 3> deviceForceToVendorAxes(const Eigen::Vector3d& force);

// `force` scaled down to `max_force` if longer (direction kept); non-finite forces become zero.
Eigen::Vector3d motorCommand(const Eigen::Vector3d& force, double max_force);

// Backward difference of successive positions (the devices report no velocity of their own).
class VelocityEstimator
{
 public:
  Eigen::Vector3d update(double time, const Eigen::Vector3d& position);

 private:
  bool have_last_ = false;
  double last_time_ = 0.0;
  Eigen::Vector3d last_position_ = Eigen::Vector3d::Zero();
};

// Counts consecutive failed I/O cycles; `failed()` is true once more than `allowed` failed in a row.
class IoFailureCounter
{
 public:
  explicit IoFailureCounter(int allowed) : allowed_(allowed) {}
  // Records one cycle; returns true when the device must be given up.
  bool record(bool cycle_ok)
  {
    failures_ = cycle_ok ? 0 : failures_ + 1;
    return failures_ > allowed_;
  }
  int consecutive() const
  {
    return failures_;
  }

 private:
  int allowed_;
  int failures_ = 0;
};
}  // namespace god_finger
