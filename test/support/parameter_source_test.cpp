// The typed parameter readers every node, the servo loop and the tools share: defaults, types,
// ranges, lists and tables, each bad value named with its full name; layered sources.
#include "god_finger/support/parameter_source.h"
#include "god_finger/haptics/device_profile.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

namespace god_finger
{
namespace
{
std::string errorOf(const std::function<void()>& read)
{
  try
  {
    read();
  }
  catch (const InputError& error)
  {
    return error.what();
  }
  return "";
}

TEST(ParameterSource, TypedReadersCheckTypeAndRange)
{
  MapParameterSource source("/finger/");
  source.set("rate", ParameterValue::of(5.0));
  source.set("count", ParameterValue::of(2.5));
  source.set("name", ParameterValue::ofInteger(3));
  source.set("offset", ParameterValue::of(std::vector<double>{1, 2}));
  EXPECT_EQ(readDouble(source, "missing", 7.0, 0.0, 10.0, "m"), 7.0);
  EXPECT_EQ(errorOf([&] { readDouble(source, "rate", 1000.0, 10.0, 1e4, "Hz"); }),
            "parameter '/finger/rate' = 5 is out of range [10, 10000] (Hz)");
  EXPECT_EQ(errorOf([&] { readInt(source, "count", 1, 0, 10); }), "parameter '/finger/count' must be an integer");
  EXPECT_EQ(errorOf([&] { readString(source, "name", ""); }), "parameter '/finger/name' must be a string");
  EXPECT_EQ(errorOf([&] { readVector(source, "offset", Eigen::Vector3d::Zero()); }),
            "parameter '/finger/offset' must be a list of 3 numbers");
}

TEST(ParameterSource, TablesAreRowsOfNumbers)
{
  MapParameterSource source;
  ParameterValue table;
  table.kind = ParameterValue::Kind::kList;
  table.items.push_back(ParameterValue::of(std::vector<double>{0, 0, 0, 0.1}));
  table.items.push_back(ParameterValue::of(std::vector<double>{1, 0, 0}));
  source.set("script", table);
  std::vector<std::vector<double>> rows;
  EXPECT_EQ(errorOf([&] { readTable(source, "script", 4, "a list of [t, x, y, z] waypoints", &rows); }),
            "parameter 'script' must be a list of [t, x, y, z] waypoints (row 1)");
  EXPECT_FALSE(readTable(source, "none", 4, "rows", &rows));
}

TEST(ParameterSource, LayeredSourcePrefersTheFirstAndNamesWhereItFoundTheValue)
{
  MapParameterSource node("/finger/haptic/");
  MapParameterSource interface("/finger/");
  node.set("max_force", ParameterValue::of(-2.0));
  interface.set("coupling_stiffness", ParameterValue::of(800.0));
  interface.set("max_force", ParameterValue::of(8.9));
  const LayeredParameterSource both(node, interface);
  EXPECT_EQ(errorOf([&] { readDeviceProfile(both); }),
            "parameter '/finger/haptic/max_force' = -2 is out of range (0, 10000] (N)");
  const DeviceProfile profile = readDeviceProfile(interface);
  EXPECT_EQ(profile.coupling.stiffness, 800.0);
  EXPECT_EQ(profile.coupling.max_force, 8.9);
}
}  // namespace
}  // namespace god_finger
