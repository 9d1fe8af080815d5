#include "god_finger/devices/vendor_frames.h"

#include "god_finger/support/input_error.h"

namespace god_finger
{
namespace
{
// Rows of the rotation: device x, y, z in the vendor's axes.
Eigen::Matrix3d rows(double a, double b, double c, double d, double e, double f, double g, double h, double i)
{
  Eigen::Matrix3d m;
  m << a, b, c, d, e, f, g, h, i;
  return m;
}
}  // namespace

const std::vector<VendorFrame>& vendorFrames()
{
  static const std::vector<VendorFrame> frames = {
      {"device", "x away from the user, y to the left, z up (REP-103)", "god_finger's own device frame",
       Eigen::Matrix3d::Identity()},
      // device = (-z, -x, y)
      {"hd", "x to the user's right, y up, z towards the user",
       "the OpenHaptics HD API, libnifalcon (ros_falcon), ros_geomagic, sawSensablePhantom (CRTK)",
       rows(0, 0, -1, -1, 0, 0, 0, 1, 0)},
      // device = (y, -x, z)
      {"omni_common", "x to the user's right, y away from the user, z up",
       "the Geomagic Touch / Phantom Omni driver omni_common (omni_msgs)", rows(0, 1, 0, -1, 0, 0, 0, 0, 1)},
      // device = (-x, -y, z)
      {"force_dimension", "x towards the user, y to the user's right, z up",
       "Force Dimension's SDK (sawForceDimensionSDK, CRTK)", rows(-1, 0, 0, 0, -1, 0, 0, 0, 1)},
  };
  return frames;
}

std::string vendorFrameNames()
{
  std::string names;
  for (const VendorFrame& frame : vendorFrames())
  {
    names += (names.empty() ? "" : ", ") + std::string(frame.name);
  }
  return names;
}

const VendorFrame& findVendorFrame(const std::string& name, const std::string& parameter)
{
  for (const VendorFrame& frame : vendorFrames())
  {
    if (name == frame.name)
    {
      return frame;
    }
  }
  throw InputError("parameter '" + parameter + "' = '" + name + "' is not one of " + vendorFrameNames());
}

const VendorFrame& hdFrame()
{
  return vendorFrames()[1];
}
}  // namespace god_finger
