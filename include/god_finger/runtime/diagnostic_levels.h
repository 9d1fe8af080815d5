// When a node's /diagnostics status is OK, WARN or ERROR: the thresholds, one table that every
// node reads from its private namespace, and the decisions as pure functions of counts and
// figures (numbers in, level out), so that a test can check each threshold with real numbers.
//  - A fixed-rate loop (the servo loop, the physics node's, the device driver's): the share of
//    its ticks since the last report that overran (ended past their deadline,
//    runtime/fixed_rate_schedule.h). Above overrun_warn_share it is WARN, above
//    overrun_error_share ERROR. The physics node judges apart its steps that waited until their
//    deadline for a late pose: WARN above overrun_warn_share, never ERROR (the lateness is the
//    link's or the device side's, whose own statuses say how bad: the haptic node's device
//    stale; the physics answers the last pose, and the local coupling renders the hand's spring).
//  - A channel port's energy margin (J; haptics/two_port_passivity.h, ros/channel_port.h): at or
//    above minus the contact's credit (the device profile's passivity_contact_credit) it is OK,
//    below it WARN, more than margin_error below it ERROR. A non-finite margin is ERROR.
//  - A stream a node renders from (the haptic node's device states and proxy states): none yet
//    is WARN (waiting), newest older than its timeout ERROR (stale). The device states' timeout
//    is device_state_timeout; the proxy's is the node's proxy_timeout (ros/node_parameters.h),
//    past which the haptic node stops rendering it.
// Levels are diagnostic_msgs/DiagnosticStatus's values (OK 0, WARN 1, ERROR 2), without ROS.
// Not real-time: the nodes decide once a report (1 Hz), in their publisher threads.
#pragma once

#include "god_finger/support/parameter_table.h"

#include <cstdint>
#include <string>

namespace god_finger
{
enum class DiagnosticLevel : std::uint8_t
{
  kOk = 0,
  kWarn = 1,
  kError = 2,
};

// The more severe of the two.
DiagnosticLevel worst(DiagnosticLevel a, DiagnosticLevel b);
const char* levelName(DiagnosticLevel level);  // "OK", "WARN", "ERROR"

struct DiagnosticThresholds
{
  double overrun_warn_share = 0.05;    // dimensionless: of a report's ticks, overran
  double overrun_error_share = 0.25;   // dimensionless: of a report's ticks, overran
  double margin_error = 0.1;           // J: below minus the contact credit by more than this
  double device_state_timeout = 0.25;  // s: the haptic node's newest device state older than this
};

// overrun_warn_share, overrun_error_share, margin_error, device_state_timeout.
const ParameterTable<DiagnosticThresholds>& diagnosticThresholdTable();
// "" when every row is in range and overrun_warn_share <= overrun_error_share; else one line.
std::string validate(const DiagnosticThresholds& thresholds);
// Every row `source` sets; InputError naming the first bad one (or the two shares out of order).
DiagnosticThresholds readDiagnosticThresholds(const ParameterSource& source);

// `overruns` of `ticks` ticks (both since the last report, >= 0) overran. No ticks: OK (a loop
// that made none is reported by its rate).
DiagnosticLevel overrunLevel(long overruns, long ticks, const DiagnosticThresholds& thresholds);
// `late` of `ticks` steps (since the last report) waited until their deadline for a late pose:
// WARN above overrun_warn_share, else OK.
DiagnosticLevel latePoseLevel(long late, long ticks, const DiagnosticThresholds& thresholds);
// A port's energy margin (J) against its contact credit (J, >= 0).
DiagnosticLevel marginLevel(double margin, double credit, const DiagnosticThresholds& thresholds);
// A stream: `received` whether any message came; `age` (s) of the newest; `timeout` (s).
DiagnosticLevel streamLevel(bool received, double age, double timeout);

// The status message's clause for a loop's overruns: "" when OK, else e.g. "33.3 % of ticks
// overran (333 of 1000; WARN above 5 %, ERROR above 25 %)".
std::string overrunText(long overruns, long ticks, const DiagnosticThresholds& thresholds);
// For the physics' late poses: "" when OK, else e.g. "100 % of ticks waited until their deadline
// for a late pose (1000 of 1000; WARN above 5 %)".
std::string latePoseText(long late, long ticks, const DiagnosticThresholds& thresholds);
// For a margin: "" when OK, else e.g. "energy margin -0.022 J, below the credit -0.0001 J".
std::string marginText(double margin, double credit, const DiagnosticThresholds& thresholds);
}  // namespace god_finger
