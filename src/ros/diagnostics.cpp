#include "diagnostics.h"

#include "god_finger/support/input_error.h"
#include "parameters.h"

namespace god_finger
{
void addValue(diagnostic_msgs::DiagnosticStatus* status, const std::string& key, const std::string& value)
{
  diagnostic_msgs::KeyValue pair;
  pair.key = key;
  pair.value = value;
  status->values.push_back(pair);
}

std::FILE* openTimingCsv(const ros::NodeHandle& pnh, const std::string& header)
{
  const std::string path = readString(pnh, "timing_csv", "");
  if (path.empty())
  {
    return nullptr;
  }
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (!file)
  {
    throw InputError("parameter '" + pnh.resolveName("timing_csv") + "' = '" + path + "': cannot be written");
  }
  std::fprintf(file, "%s\n", header.c_str());
  return file;
}
}  // namespace god_finger
