#include "diagnostics.h"

#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"
#include "parameters.h"

#include <algorithm>

namespace god_finger
{
void addValue(diagnostic_msgs::DiagnosticStatus* status, const std::string& key, const std::string& value)
{
  diagnostic_msgs::KeyValue pair;
  pair.key = key;
  pair.value = value;
  status->values.push_back(pair);
}

diagnostic_msgs::DiagnosticStatus stepProfileStatus(const std::string& name,
                                                    const std::array<Percentiles, kStepStageCount>& stages)
{
  diagnostic_msgs::DiagnosticStatus status;
  status.name = name;
  status.hardware_id = "god_finger";
  status.level = diagnostic_msgs::DiagnosticStatus::OK;
  status.message = "world step by stage (us)";
  for (int s = 0; s < kStepStageCount; ++s)
  {
    const std::string stage = stepStageName(static_cast<StepStage>(s));
    addValue(&status, stage + "_us_p50", jsonNumber(stages[s].p50));
    addValue(&status, stage + "_us_p99", jsonNumber(stages[s].p99));
  }
  return status;
}

void raiseLevel(diagnostic_msgs::DiagnosticStatus* status, DiagnosticLevel level, const std::string& reason)
{
  static_assert(static_cast<int>(DiagnosticLevel::kWarn) == diagnostic_msgs::DiagnosticStatus::WARN &&
                    static_cast<int>(DiagnosticLevel::kError) == diagnostic_msgs::DiagnosticStatus::ERROR,
                "DiagnosticLevel holds diagnostic_msgs' values");
  status->level = std::max<std::uint8_t>(status->level, static_cast<std::uint8_t>(level));
  if (level == DiagnosticLevel::kOk || reason.empty())
  {
    return;
  }
  status->message = status->message.empty() || status->message == "running" ? reason : status->message + "; " + reason;
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
