// The frames haptic devices and their ROS drivers report in, by name: the one place their axes
// are written. Each is the rotation that takes a vector in that frame to the device frame
// (devices/haptic_device.h: REP-103 as the user sees it, x away from the user, y to the left,
// z up): device = to_device * vendor for a position or a velocity; a force goes back with its
// inverse, vendor = to_device^T * device (a rotation: the inverse is the transpose, never
// written again). The backends (Falcon, Omni/Touch, the ROS driver bridges) and their profiles
// (config/devices/*.yaml, `driver_frame`) name a row; nothing else spells these axes.
// Not real-time: findVendorFrame() allocates its message on failure; toDevice()/toVendor() are
// real-time safe.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace god_finger
{
struct VendorFrame
{
  const char* name;   // as profiles and parameters spell it
  const char* axes;   // the frame's axes as the user sees them, for docs and messages
  const char* users;  // who reports in it
  Eigen::Matrix3d to_device;

  Eigen::Vector3d toDevice(const Eigen::Vector3d& vendor) const
  {
    return to_device * vendor;
  }
  Eigen::Vector3d toVendor(const Eigen::Vector3d& device) const
  {
    return to_device.transpose() * device;
  }
};

const std::vector<VendorFrame>& vendorFrames();
// "device, hd, omni_common, force_dimension".
std::string vendorFrameNames();
// InputError naming `parameter` and the known names when there is no such frame.
const VendorFrame& findVendorFrame(const std::string& name, const std::string& parameter);
// The HD API's and libnifalcon's frame (x to the user's right, y up, z towards the user), which
// the Omni/Touch and Falcon backends read.
const VendorFrame& hdFrame();
}  // namespace god_finger
