#include "god_finger/runtime/diagnostic_levels.h"

#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"

#include <algorithm>
#include <cmath>

namespace god_finger
{
DiagnosticLevel worst(DiagnosticLevel a, DiagnosticLevel b)
{
  return static_cast<std::uint8_t>(a) >= static_cast<std::uint8_t>(b) ? a : b;
}

const char* levelName(DiagnosticLevel level)
{
  switch (level)
  {
    case DiagnosticLevel::kOk:
      return "OK";
    case DiagnosticLevel::kWarn:
      return "WARN";
    case DiagnosticLevel::kError:
      return "ERROR";
  }
  return "ERROR";
}

const ParameterTable<DiagnosticThresholds>& diagnosticThresholdTable()
{
  using P = DiagnosticThresholds;
  static const ParameterTable<P> table = {
      realRow<P>("overrun_warn_share", "dimensionless", closed(0.0, 1.0),
                 "a loop's /diagnostics status is WARN when more than this share of its ticks since the last "
                 "report overran (servo loop, physics loop, device loop; and the physics loop's when more than "
                 "this share of its steps waited for a late pose)",
                 [](P& p) -> double& { return p.overrun_warn_share; }),
      realRow<P>("overrun_error_share", "dimensionless", closed(0.0, 1.0),
                 "a loop's /diagnostics status is ERROR when more than this share of its ticks since the last "
                 "report overran (at least overrun_warn_share)",
                 [](P& p) -> double& { return p.overrun_error_share; }),
      realRow<P>("margin_error", "J", closed(0.0, 1000.0),
                 "a channel port's energy margin below minus its contact credit (passivity_contact_credit) is "
                 "WARN, and ERROR more than this below it",
                 [](P& p) -> double& { return p.margin_error; }),
      realRow<P>("device_state_timeout", "s", openClosed(0.0, 10.0),
                 "the haptic node's status is ERROR (device stale) when its newest device state is older than this",
                 [](P& p) -> double& { return p.device_state_timeout; }),
  };
  return table;
}

std::string validate(const DiagnosticThresholds& thresholds)
{
  const std::string rows = validateRows(diagnosticThresholdTable(), thresholds);
  if (!rows.empty())
  {
    return rows;
  }
  if (thresholds.overrun_warn_share > thresholds.overrun_error_share)
  {
    return "parameter 'overrun_warn_share' = " + formatNumber(thresholds.overrun_warn_share) +
           " is above 'overrun_error_share' = " + formatNumber(thresholds.overrun_error_share);
  }
  return std::string();
}

DiagnosticThresholds readDiagnosticThresholds(const ParameterSource& source)
{
  DiagnosticThresholds thresholds;
  readRows(source, diagnosticThresholdTable(), &thresholds);
  if (thresholds.overrun_warn_share > thresholds.overrun_error_share)
  {
    throw InputError("parameter '" + source.fullName("overrun_warn_share") +
                     "' = " + formatNumber(thresholds.overrun_warn_share) + " is above '" +
                     source.fullName("overrun_error_share") + "' = " + formatNumber(thresholds.overrun_error_share));
  }
  return thresholds;
}

DiagnosticLevel overrunLevel(long overruns, long ticks, const DiagnosticThresholds& thresholds)
{
  if (ticks <= 0 || overruns <= 0)
  {
    return DiagnosticLevel::kOk;
  }
  // Compared as overruns > share * ticks: exact at the threshold (no rounding of a quotient).
  const double late = static_cast<double>(overruns);
  const double all = static_cast<double>(ticks);
  if (late > thresholds.overrun_error_share * all)
  {
    return DiagnosticLevel::kError;
  }
  if (late > thresholds.overrun_warn_share * all)
  {
    return DiagnosticLevel::kWarn;
  }
  return DiagnosticLevel::kOk;
}

DiagnosticLevel latePoseLevel(long late, long ticks, const DiagnosticThresholds& thresholds)
{
  return overrunLevel(late, ticks, thresholds) == DiagnosticLevel::kOk ? DiagnosticLevel::kOk : DiagnosticLevel::kWarn;
}

DiagnosticLevel marginLevel(double margin, double credit, const DiagnosticThresholds& thresholds)
{
  if (!std::isfinite(margin))
  {
    return DiagnosticLevel::kError;
  }
  const double floor = -std::max(0.0, credit);
  if (margin >= floor)
  {
    return DiagnosticLevel::kOk;
  }
  return margin < floor - thresholds.margin_error ? DiagnosticLevel::kError : DiagnosticLevel::kWarn;
}

DiagnosticLevel streamLevel(bool received, double age, double timeout)
{
  if (!received)
  {
    return DiagnosticLevel::kWarn;
  }
  return std::isfinite(age) && age <= timeout ? DiagnosticLevel::kOk : DiagnosticLevel::kError;
}

namespace
{
// "33.3 % of ticks WHAT (333 of 1000; BOUNDS)".
std::string shareClause(long count, long ticks, const std::string& what, const std::string& bounds)
{
  return roundedNumber(100.0 * static_cast<double>(count) / static_cast<double>(ticks)) + " % of ticks " + what + " (" +
         std::to_string(count) + " of " + std::to_string(ticks) + "; " + bounds + ")";
}
}  // namespace

std::string overrunText(long overruns, long ticks, const DiagnosticThresholds& thresholds)
{
  if (overrunLevel(overruns, ticks, thresholds) == DiagnosticLevel::kOk)
  {
    return std::string();
  }
  return shareClause(overruns, ticks, "overran",
                     "WARN above " + roundedNumber(100.0 * thresholds.overrun_warn_share) + " %, ERROR above " +
                         roundedNumber(100.0 * thresholds.overrun_error_share) + " %");
}

std::string latePoseText(long late, long ticks, const DiagnosticThresholds& thresholds)
{
  if (latePoseLevel(late, ticks, thresholds) == DiagnosticLevel::kOk)
  {
    return std::string();
  }
  return shareClause(late, ticks, "waited until their deadline for a late pose",
                     "WARN above " + roundedNumber(100.0 * thresholds.overrun_warn_share) + " %");
}

std::string marginText(double margin, double credit, const DiagnosticThresholds& thresholds)
{
  if (marginLevel(margin, credit, thresholds) == DiagnosticLevel::kOk)
  {
    return std::string();
  }
  const double floor = std::max(0.0, credit);
  return "energy margin " + roundedNumber(margin) + " J, beyond its credit of " + roundedNumber(floor) +
         " J: this port let out more than the other put in (ERROR below " +
         roundedNumber(-(floor + thresholds.margin_error)) + " J)";
}
}  // namespace god_finger
