#include "god_finger/core/device_profile.h"

#include "god_finger/core/input_error.h"

namespace god_finger
{
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
    rows.push_back(realRow<P>(
        "workspace_radius", "m", openClosed(0.0, 10.0),
        "radius of the device's workspace from its centre: beyond it the proxy stops and a wall pushes the hand back",
        [](P& p) -> double& { return p.workspace_radius; }));
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
