// Where the haptic loop goes unstable (issue 5, hard cases): the fake device of the shipped
// profile (config/devices/fake.yaml: handle mass and damping, the hand's grip) pushed 1 cm
// into a rigid virtual wall rendered with a coupling stiffness k (and the profile's coupling
// damping), at 1 kHz, the force computed from a device reading `delay` ticks old (the loop's
// round trip: 1-2 ticks with nodelets, more over a network). A run is stable when the handle
// settles (peak-to-peak over the last 0.3 s under 10 um). The test finds the first unstable k
// for each delay and checks that the profile's k stays a factor of 4 below it.
#include "device_profile_file.h"
#include "god_finger/devices/fake_device.h"
#include "god_finger/haptics/device_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <fstream>
#include <map>
#include <string>

namespace god_finger
{
namespace
{
// The wall is a proxy held at z = 0 by the one coupling function (haptics/virtual_coupling.h),
// unsaturated so that only the loop's dynamics limit the stiffness.
bool settles(const FakeDeviceParams& params, double stiffness, double damping, int delay)
{
  // The hand moves from 1 cm outside the wall (z > 0) to 1 cm inside in 0.2 s, then holds.
  FakeDevice device(params, WaypointPath({{0.0, Eigen::Vector3d(0, 0, 0.01)},
                                          {0.2, Eigen::Vector3d(0, 0, -0.01)},
                                          {3.0, Eigen::Vector3d(0, 0, -0.01)}}));
  device.setScriptStart(0.0);
  device.start();
  std::deque<DeviceReading> readings(delay, DeviceReading());
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  double low = INFINITY;
  double high = -INFINITY;
  for (int tick = 0; tick < 2000; ++tick)
  {
    const double time = tick * 1e-3;
    const DeviceReading reading = device.update(time, force);
    if (!reading.position.allFinite() || std::abs(reading.position.z()) > 1.0)
    {
      return false;
    }
    readings.push_back(reading);
    // What the loop knows `delay` ticks later: a copy, as pop_front frees the element.
    const DeviceReading seen = readings.front();
    readings.pop_front();
    CouplingProfile wall;
    wall.stiffness = stiffness;
    wall.damping = damping;
    wall.max_force = INFINITY;
    const Eigen::Vector3d on_wall = Eigen::Vector3d(seen.position.x(), seen.position.y(), 0.0);
    force = seen.position.z() < 0.0
                ? Eigen::Vector3d(
                      -couplingForce(wall, seen.position, seen.velocity, on_wall, Eigen::Vector3d::Zero()).on_proxy)
                : Eigen::Vector3d::Zero();
    if (time >= 1.7)
    {
      low = std::min(low, reading.position.z());
      high = std::max(high, reading.position.z());
    }
  }
  return high - low < 1e-5;
}

TEST(CouplingStability, ProfileStiffnessStaysAFactorOfFourBelowTheLimit)
{
  const MapParameterSource profile =
      test::readDeviceProfileSource(std::string(GOD_FINGER_SOURCE_DIR) + "/config/devices/fake.yaml");
  const FakeDeviceParams params = readFakeDeviceParams(profile);
  const DeviceProfile device = readDeviceProfile(profile);
  const double profile_k = device.coupling.stiffness;
  const double profile_c = device.coupling.damping;
  ASSERT_TRUE(settles(params, profile_k, profile_c, 2));
  double previous_limit = INFINITY;
  for (int delay : {1, 2, 5})
  {
    double limit = 0.0;
    for (double k = profile_k; k <= 1e6; k *= 1.25)
    {
      if (!settles(params, k, profile_c, delay))
      {
        limit = k;
        break;
      }
    }
    std::printf("[ fake device, %d ms round trip ] unstable from k = %.0f N/m (profile: %.0f N/m, %.1fx margin)\n",
                delay, limit, profile_k, limit / profile_k);
    ASSERT_GT(limit, 0.0) << "no instability up to 1e6 N/m: the sweep shows nothing";
    EXPECT_GE(limit, 4.0 * profile_k) << delay;
    // A longer round trip can only lower the limit.
    EXPECT_LE(limit, previous_limit * 1.0001) << delay;
    previous_limit = limit;
  }
}
}  // namespace
}  // namespace god_finger
