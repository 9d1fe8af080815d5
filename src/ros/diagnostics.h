// What the nodes share for reporting: a key/value on a diagnostic status, and the per-tick
// timing file the bench asks for (~timing_csv). Not real-time (they allocate and write).
#pragma once

#include "god_finger/runtime/loop_statistics.h"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/node_handle.h>

#include <cstdio>
#include <string>

namespace god_finger
{
void addValue(diagnostic_msgs::DiagnosticStatus* status, const std::string& key, const std::string& value);

// The world step's stages over a window as one status named `name` (level OK): for each stage
// (step_profile.h), <stage>_us_p50 and <stage>_us_p99.
diagnostic_msgs::DiagnosticStatus stepProfileStatus(const std::string& name,
                                                    const std::array<Percentiles, kStepStageCount>& stages);

// The file named by `pnh`'s timing_csv with `header` as its first line; nullptr when the
// parameter is empty or unset. InputError naming the parameter when it cannot be written.
std::FILE* openTimingCsv(const ros::NodeHandle& pnh, const std::string& header);
}  // namespace god_finger
