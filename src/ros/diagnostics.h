// What the nodes share for reporting: a key/value on a diagnostic status, a status's level
// raised by a decision of runtime/diagnostic_levels.h, the world step's profile as a status, and
// the per-tick timing file the bench asks for (~timing_csv). Not real-time (they allocate and write).
#pragma once

#include "god_finger/runtime/diagnostic_levels.h"
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

// Raises `status`'s level to `level` (never lowers it) and, when that is not OK, says `reason`
// in its message: it replaces "running" and follows anything else after "; ".
void raiseLevel(diagnostic_msgs::DiagnosticStatus* status, DiagnosticLevel level, const std::string& reason);

// The file named by `pnh`'s timing_csv with `header` as its first line; nullptr when the
// parameter is empty or unset. InputError naming the parameter when it cannot be written.
std::FILE* openTimingCsv(const ros::NodeHandle& pnh, const std::string& header);
}  // namespace god_finger
