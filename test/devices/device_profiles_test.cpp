// The shipped device profiles (config/devices/*.yaml) set only rows of the one profile table
// (core/device_profile.h; the fake device's own rows for fake.yaml), each in its range, and the
// README shows the fake device's table as generated.
#include "god_finger/core/device_profile.h"
#include "god_finger/core/input_error.h"
#include "god_finger/devices/fake_device.h"
#include "god_finger/devices/falcon_device.h"
#include "god_finger/devices/omni_device.h"

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
        known = known || (match[1] == row.name && entry.path().filename() == "fake.yaml");
      }
      EXPECT_TRUE(known) << entry.path() << ": '" << match[1]
                         << "' is no row of deviceProfileTable() (or, for the fake device, of its own table)";
      source.set(match[1], ParameterValue::of(std::stod(line.substr(line.find(':') + 1))));
    }
    EXPECT_NO_THROW(readDeviceProfile(source)) << entry.path();
    EXPECT_NO_THROW(readFakeDeviceParams(source)) << entry.path();
    ++files;
  }
  EXPECT_EQ(files, 3);
}

TEST(DeviceProfiles, TheReadmeShowsTheBackendTablesAsGenerated)
{
  std::ifstream in(std::string(GOD_FINGER_SOURCE_DIR) + "/README.md");
  std::stringstream readme;
  readme << in.rdbuf();
  const std::pair<const char*, std::string> tables[] = {
      {"fake device's", markdownTable(fakeDeviceParameterTable())},
      {"Falcon's", markdownTable(falconParameterTable())},
      {"Omni's", markdownTable(omniParameterTable())},
  };
  for (const auto& [what, table] : tables)
  {
    EXPECT_NE(readme.str().find(table), std::string::npos) << "README.md lacks the " << what << " table:\n" << table;
  }
}
}  // namespace
}  // namespace god_finger
