// A shipped device profile read from its file (config/devices/NAME.yaml: flat
// "key: value  # comment" lines, a value a number or a choice's name) through the one profile table
// (haptics/device_profile.h), as the nodes read it, so that a test uses the file's numbers instead of copies of them.
#pragma once

#include "god_finger/haptics/device_profile.h"
#include "god_finger/support/input_error.h"

#include <fstream>
#include <regex>
#include <string>

namespace god_finger
{
namespace test
{
// The file's rows as parameters, as a launch loads them (lists such as workspace_offset left
// out: they are not the profile table's).
inline MapParameterSource readDeviceProfileSource(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    throw InputError("device profile '" + path + "': cannot be read");
  }
  MapParameterSource source(path + ": ");
  const std::regex row("^(\\w+):\\s*([^\\s#\\[]+)");
  for (std::string line; std::getline(in, line);)
  {
    std::smatch match;
    if (std::regex_search(line, match, row))
    {
      source.set(match[1], parseValueText(match[2]));
    }
  }
  return source;
}

inline DeviceProfile readDeviceProfileFile(const std::string& path)
{
  return readDeviceProfile(readDeviceProfileSource(path));
}

// config/devices/NAME.yaml of the source tree.
inline DeviceProfile shippedDeviceProfile(const std::string& name)
{
  return readDeviceProfileFile(std::string(GOD_FINGER_SOURCE_DIR) + "/config/devices/" + name + ".yaml");
}
}  // namespace test
}  // namespace god_finger
