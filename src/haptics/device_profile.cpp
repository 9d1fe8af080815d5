#include "god_finger/haptics/device_profile.h"

#include "god_finger/support/input_error.h"

#include <array>
#include <cmath>

namespace god_finger
{
namespace
{
// Indexed by the bit mask.
const std::array<const char*, 8> kTorqueAxesNames = {"none", "x", "y", "xy", "z", "xz", "yz", "xyz"};
}  // namespace

std::string torqueAxesName(unsigned axes)
{
  return kTorqueAxesNames.at(axes & 7u);
}

bool parseTorqueAxes(const std::string& name, unsigned* axes)
{
  for (unsigned mask = 0; mask < kTorqueAxesNames.size(); ++mask)
  {
    if (name == kTorqueAxesNames[mask])
    {
      *axes = mask;
      return true;
    }
  }
  return false;
}

Eigen::Vector3d renderableTorque(const DeviceProfile& profile, const Eigen::Vector3d& torque)
{
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < 3; ++axis)
  {
    if (profile.torque_axes & (1u << axis))
    {
      out[axis] = torque[axis];
    }
  }
  const double length = out.norm();
  if (!(length <= profile.max_torque))  // also a non-finite torque: none
  {
    out = std::isfinite(length) && length > 0.0 ? Eigen::Vector3d(out * (profile.max_torque / length))
                                                : Eigen::Vector3d::Zero();
  }
  return out;
}

const ParameterTable<DeviceProfile>& deviceProfileTable()
{
  using P = DeviceProfile;
  static const ParameterTable<P> table = []
  {
    ParameterTable<P> rows =
        liftRows<P, CouplingProfile>(couplingParameterTable(), [](P& p) -> CouplingProfile& { return p.coupling; });
    const ParameterTable<P> guard =
        liftRows<P, ForceGuardParams>(forceGuardParameterTable(), [](P& p) -> ForceGuardParams& { return p.guard; });
    rows.insert(rows.end(), guard.begin(), guard.end());
    const ParameterTable<P> passivity =
        liftRows<P, PassivityParams>(passivityParameterTable(), [](P& p) -> PassivityParams& { return p.passivity; });
    rows.insert(rows.end(), passivity.begin(), passivity.end());
    rows.push_back(realRow<P>(
        "workspace_radius", "m", openClosed(0.0, 10.0),
        "radius of the device's workspace from its centre: beyond it the proxy stops and a wall pushes the hand back",
        [](P& p) -> double& { return p.workspace_radius; }));
    rows.push_back(choiceRow<P>(
        "torque_axes", "none, x, y, z, xy, xz, yz, xyz",
        "device-frame axes on which the device renders an oriented finger's torque (none: force only)",
        [](const P& p) -> std::string { return torqueAxesName(p.torque_axes); },
        [](P* p, const std::string& text) { return parseTorqueAxes(text, &p->torque_axes); }));
    rows.push_back(realRow<P>("max_torque", "N m", closed(0.0, 10.0),
                              "the torque's limit on the torque axes (its length is saturated there)",
                              [](P& p) -> double& { return p.max_torque; }));
    return rows;
  }();
  return table;
}

DeviceProfile readDeviceProfile(const ParameterSource& source)
{
  DeviceProfile profile;
  readRows(source, deviceProfileTable(), &profile);
  return profile;
}
}  // namespace god_finger
