// What the nodes share for reporting: a key/value on a diagnostic status, a status's level
// raised by a decision of runtime/diagnostic_levels.h, and the per-tick timing file the bench
// asks for (~timing_csv). Not real-time (they allocate and write).
#pragma once

#include "god_finger/runtime/diagnostic_levels.h"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/node_handle.h>

#include <cstdio>
#include <string>

namespace god_finger
{
void addValue(diagnostic_msgs::DiagnosticStatus* status, const std::string& key, const std::string& value);

// Raises `status`'s level to `level` (never lowers it) and, when that is not OK, says `reason`
// in its message: it replaces "running" and follows anything else after "; ".
void raiseLevel(diagnostic_msgs::DiagnosticStatus* status, DiagnosticLevel level, const std::string& reason);

// The file named by `pnh`'s timing_csv with `header` as its first line; nullptr when the
// parameter is empty or unset. InputError naming the parameter when it cannot be written.
std::FILE* openTimingCsv(const ros::NodeHandle& pnh, const std::string& header);
}  // namespace god_finger
