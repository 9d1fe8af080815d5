// What the nodes share for reporting: a key/value on a diagnostic status, and the per-tick
// timing file the bench asks for (~timing_csv). Not real-time (they allocate and write).
#pragma once

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/node_handle.h>

#include <cstdio>
#include <string>

namespace god_finger
{
void addValue(diagnostic_msgs::DiagnosticStatus* status, const std::string& key, const std::string& value);

// The file named by `pnh`'s timing_csv with `header` as its first line; nullptr when the
// parameter is empty or unset. InputError naming the parameter when it cannot be written.
std::FILE* openTimingCsv(const ros::NodeHandle& pnh, const std::string& header);
}  // namespace god_finger
