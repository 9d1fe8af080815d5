// A shipped device profile read from its file (config/devices/NAME.yaml: flat
// "key: number  # comment" lines) through the one profile table (core/device_profile.h), as
// the nodes read it, so that a test uses the file's numbers instead of copies of them.
#pragma once

#include "god_finger/core/device_profile.h"
#include "god_finger/core/input_error.h"

#include <fstream>
#include <regex>
#include <string>

namespace god_finger
{
namespace test
{
inline DeviceProfile readDeviceProfileFile(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    throw InputError("device profile '" + path + "': cannot be read");
  }
  MapParameterSource source(path + ": ");
  const std::regex row("^(\\w+):\\s*([-+0-9.eE]+)");
  for (std::string line; std::getline(in, line);)
  {
    std::smatch match;
    if (std::regex_search(line, match, row))
    {
      source.set(match[1], ParameterValue::of(std::stod(match[2])));
    }
  }
  return readDeviceProfile(source);
}

// config/devices/NAME.yaml of the source tree.
inline DeviceProfile shippedDeviceProfile(const std::string& name)
{
  return readDeviceProfileFile(std::string(GOD_FINGER_SOURCE_DIR) + "/config/devices/" + name + ".yaml");
}
}  // namespace test
}  // namespace god_finger
