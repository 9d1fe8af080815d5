// The shipped device profiles (config/devices/*.yaml) set only rows of the one profile table
// (haptics/device_profile.h; the fake device's own rows for fake.yaml), each in its range, and the
// README shows the fake device's table as generated.
#include "god_finger/devices/driver_bridge.h"
#include "god_finger/devices/fake_device.h"
#include "god_finger/devices/falcon_device.h"
#include "god_finger/devices/omni_device.h"
#include "god_finger/haptics/device_profile.h"
#include "god_finger/support/input_error.h"

#include "docs_text.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace god_finger
{
namespace
{
TEST(DeviceProfiles, ShippedDeviceProfilesSetOnlyRowsOfTheProfileTable)
{
  const std::regex key("^(\\w+):");
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(GOD_FINGER_SOURCE_DIR) + "/config/devices"))
  {
    std::ifstream in(entry.path());
    MapParameterSource source(entry.path().filename().string() + ": ");
    for (std::string line; std::getline(in, line);)
    {
      std::smatch match;
      if (!std::regex_search(line, match, key))
      {
        continue;
      }
      if (match[1] == "workspace_offset")
      {
        // The workspace mapping's vector (ros/interface_parameters.h), in the profile so that
        // each device has one offset whichever launch starts it: three finite numbers.
        const std::regex vector3(
            "^workspace_offset:\\s*\\[\\s*[-+.0-9eE]+\\s*,\\s*[-+.0-9eE]+\\s*,\\s*[-+.0-9eE]+\\s*\\]");
        EXPECT_TRUE(std::regex_search(line, vector3)) << entry.path() << ": " << line;
        continue;
      }
      bool known = false;
      for (const auto& row : deviceProfileTable())
      {
        known = known || match[1] == row.name;
      }
      for (const auto& row : fakeDeviceParameterTable())
      {
        // The fake handle's own rows: its profile and the interactive handle's.
        known = known || (match[1] == row.name &&
                          (entry.path().filename() == "fake.yaml" || entry.path().filename() == "interactive.yaml"));
      }
      EXPECT_TRUE(known) << entry.path() << ": '" << match[1]
                         << "' is no row of deviceProfileTable() (or, for the fake device, of its own table)";
      // The value: a number, or a choice's name (torque_axes), up to the comment.
      const std::regex value("^\\w+:\\s*([^\\s#]+)");
      std::smatch text;
      ASSERT_TRUE(std::regex_search(line, text, value)) << entry.path() << ": " << line;
      source.set(match[1], parseValueText(text[1]));
    }
    EXPECT_NO_THROW(readDeviceProfile(source)) << entry.path();
    EXPECT_NO_THROW(readFakeDeviceParams(source)) << entry.path();
    ++files;
  }
  EXPECT_EQ(files, 4);
}

TEST(DeviceProfiles, TheOmniAndTheFalconRenderForceOnly)
{
  for (const char* name : {"omni.yaml", "falcon.yaml"})
  {
    std::ifstream in(std::string(GOD_FINGER_SOURCE_DIR) + "/config/devices/" + name);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NE(text.str().find("\ntorque_axes: none"), std::string::npos) << name;
  }
  EXPECT_EQ(DeviceProfile().torque_axes, 0u);  // and a profile that says nothing renders none
}

TEST(DeviceProfiles, TorqueAxesReadByNameAndRenderableTorqueMasksThenSaturates)
{
  MapParameterSource source("test: ");
  source.set("torque_axes", ParameterValue::of(std::string("xz")));
  source.set("max_torque", ParameterValue::of(0.05));
  const DeviceProfile profile = readDeviceProfile(source);
  EXPECT_EQ(profile.torque_axes, kTorqueX | kTorqueZ);
  EXPECT_EQ(torqueAxesName(profile.torque_axes), "xz");
  // 0.03 on x, 0.04 on z: length 0.05, at the limit; y dropped.
  Eigen::Vector3d torque = renderableTorque(profile, Eigen::Vector3d(0.03, 0.7, 0.04));
  EXPECT_DOUBLE_EQ(torque.x(), 0.03);
  EXPECT_EQ(torque.y(), 0.0);
  EXPECT_DOUBLE_EQ(torque.z(), 0.04);
  // Twice as much: saturated to length 0.05, direction kept.
  torque = renderableTorque(profile, Eigen::Vector3d(0.06, 0.0, 0.08));
  EXPECT_NEAR(torque.norm(), 0.05, 1e-15);
  EXPECT_NEAR(torque.x() / torque.z(), 0.75, 1e-12);
  EXPECT_TRUE(renderableTorque(profile, Eigen::Vector3d(NAN, 0.0, 0.0)).isZero());
  EXPECT_TRUE(renderableTorque(DeviceProfile(), Eigen::Vector3d(1.0, 2.0, 3.0)).isZero());  // none
  source.set("torque_axes", ParameterValue::of(std::string("w")));
  EXPECT_THROW(readDeviceProfile(source), InputError);
}

TEST(DeviceProfiles, TheDocsShowTheBackendTablesAsGenerated)
{
  const std::string docs = test::docsText();
  const std::pair<const char*, std::string> tables[] = {
      {"fake device's", markdownTable(fakeDeviceParameterTable())},
      {"Falcon's", markdownTable(falconParameterTable())},
      {"Omni's", markdownTable(omniParameterTable())},
      {"ROS driver bridges'", markdownTable(driverBridgeParameterTable())},
  };
  for (const auto& [what, table] : tables)
  {
    EXPECT_NE(docs.find(table), std::string::npos) << "the docs lack the " << what << " table:\n" << table;
  }
}
}  // namespace
}  // namespace god_finger
