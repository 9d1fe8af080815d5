// The /diagnostics levels (runtime/diagnostic_levels.h) as pure functions: counts and figures
// in, level out, at and around each threshold of the table; the docs show the table as
// generated; the thresholds are read and checked with the parameter named.
#include "god_finger/runtime/diagnostic_levels.h"
#include "god_finger/support/input_error.h"

#include "docs_text.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
const DiagnosticLevel kOk = DiagnosticLevel::kOk;
const DiagnosticLevel kWarn = DiagnosticLevel::kWarn;
const DiagnosticLevel kError = DiagnosticLevel::kError;

TEST(DiagnosticLevels, TheDocsShowTheTableAsGenerated)
{
  const std::string table = markdownTable(diagnosticThresholdTable());
  EXPECT_NE(test::docsText().find(table), std::string::npos) << "the docs lack the diagnostics thresholds table:\n"
                                                             << table;
}

TEST(DiagnosticLevels, TheLevelsAreDiagnosticMsgsValues)
{
  // diagnostic_msgs/DiagnosticStatus: OK=0, WARN=1, ERROR=2 (the nodes cast the level to it).
  EXPECT_EQ(static_cast<int>(kOk), 0);
  EXPECT_EQ(static_cast<int>(kWarn), 1);
  EXPECT_EQ(static_cast<int>(kError), 2);
  EXPECT_EQ(worst(kOk, kWarn), kWarn);
  EXPECT_EQ(worst(kError, kWarn), kError);
  EXPECT_EQ(worst(kOk, kOk), kOk);
  EXPECT_STREQ(levelName(kWarn), "WARN");
}

TEST(DiagnosticLevels, OverrunsAtAndAroundEachShare)
{
  const DiagnosticThresholds defaults;  // WARN above 5 %, ERROR above 25 %
  ASSERT_EQ(defaults.overrun_warn_share, 0.05);
  ASSERT_EQ(defaults.overrun_error_share, 0.25);
  // One report of the 1 kHz loop: 1000 ticks. Measured on a two-core machine: the servo loop of
  // the default demo 0 to 9 a report; across processes the physics node's own 0 to 10 (0 to 35
  // with both cores kept busy), its steps that waited for a late pose 0 to 14 (0 to 80).
  EXPECT_EQ(overrunLevel(0, 1000, defaults), kOk);
  EXPECT_EQ(overrunLevel(9, 1000, defaults), kOk);
  EXPECT_EQ(overrunLevel(35, 1000, defaults), kOk);
  EXPECT_EQ(overrunLevel(49, 1000, defaults), kOk);
  EXPECT_EQ(overrunLevel(50, 1000, defaults), kOk);  // exactly 5 %: not above it
  EXPECT_EQ(overrunLevel(51, 1000, defaults), kWarn);
  EXPECT_EQ(overrunLevel(80, 1000, defaults), kWarn);
  EXPECT_EQ(overrunLevel(249, 1000, defaults), kWarn);
  EXPECT_EQ(overrunLevel(250, 1000, defaults), kWarn);  // exactly 25 %
  EXPECT_EQ(overrunLevel(251, 1000, defaults), kError);
  // The physics node across processes on two cores: overruns 17884, about a third of
  // the ticks (here a report's share of it).
  EXPECT_EQ(overrunLevel(333, 1000, defaults), kError);
  EXPECT_EQ(overrunLevel(1000, 1000, defaults), kError);
  // A report with no ticks says nothing of overruns (its rate does).
  EXPECT_EQ(overrunLevel(0, 0, defaults), kOk);
  // A slow loop, 937 ticks in a report.
  EXPECT_EQ(overrunLevel(46, 937, defaults), kOk);      // 4.91 %
  EXPECT_EQ(overrunLevel(47, 937, defaults), kWarn);    // 5.02 %
  EXPECT_EQ(overrunLevel(234, 937, defaults), kWarn);   // 24.97 %
  EXPECT_EQ(overrunLevel(235, 937, defaults), kError);  // 25.08 %
  // Shares of 0: any overrun is one too many.
  DiagnosticThresholds strict;
  strict.overrun_warn_share = 0.0;
  strict.overrun_error_share = 0.0;
  EXPECT_EQ(overrunLevel(0, 1000, strict), kOk);
  EXPECT_EQ(overrunLevel(1, 1000, strict), kError);
  // Shares of 1: never.
  DiagnosticThresholds lenient;
  lenient.overrun_warn_share = 1.0;
  lenient.overrun_error_share = 1.0;
  EXPECT_EQ(overrunLevel(1000, 1000, lenient), kOk);
}

TEST(DiagnosticLevels, LatePosesWarnAboveTheShareAndNeverErr)
{
  const DiagnosticThresholds defaults;
  EXPECT_EQ(latePoseLevel(0, 1000, defaults), kOk);
  EXPECT_EQ(latePoseLevel(14, 1000, defaults), kOk);  // across processes, idle (measured)
  EXPECT_EQ(latePoseLevel(50, 1000, defaults), kOk);  // exactly 5 %
  EXPECT_EQ(latePoseLevel(51, 1000, defaults), kWarn);
  EXPECT_EQ(latePoseLevel(647, 1000, defaults), kWarn);   // through a 30 ms link with 5 ms jitter
  EXPECT_EQ(latePoseLevel(1000, 1000, defaults), kWarn);  // the device stalled: its own status errs
  EXPECT_EQ(latePoseLevel(0, 0, defaults), kOk);
}

TEST(DiagnosticLevels, OverrunTextSaysTheShareAndTheThresholds)
{
  const DiagnosticThresholds defaults;
  EXPECT_EQ(overrunText(50, 1000, defaults), "");
  EXPECT_EQ(overrunText(333, 1000, defaults),
            "33.3 % of ticks overran (333 of 1000; WARN above 5 %, ERROR above 25 %)");
  // Late poses are WARN at most: their clause names no ERROR bound.
  EXPECT_EQ(latePoseText(1000, 1000, defaults),
            "100 % of ticks waited until their deadline for a late pose (1000 of 1000; WARN above 5 %)");
  EXPECT_EQ(latePoseText(50, 1000, defaults), "");
}

TEST(DiagnosticLevels, MarginAtAndAroundTheCreditAndTheErrorBound)
{
  const DiagnosticThresholds defaults;  // ERROR 0.1 J beyond the credit
  ASSERT_EQ(defaults.margin_error, 0.1);
  const double credit = 1e-4;  // passivity_contact_credit's default
  EXPECT_EQ(marginLevel(0.5, credit, defaults), kOk);
  EXPECT_EQ(marginLevel(0.0, credit, defaults), kOk);
  EXPECT_EQ(marginLevel(-0.5e-4, credit, defaults), kOk);
  EXPECT_EQ(marginLevel(-1e-4, credit, defaults), kOk);  // at the credit: what the physics port's controller holds
  EXPECT_EQ(marginLevel(std::nextafter(-1e-4, -1.0), credit, defaults), kWarn);
  EXPECT_EQ(marginLevel(-1.1e-4, credit, defaults), kWarn);
  // The haptic node: channel_margin_J -0.022, beyond the credit.
  EXPECT_EQ(marginLevel(-0.022, credit, defaults), kWarn);
  const double error_bound = -(credit + defaults.margin_error);  // -0.1001 J
  EXPECT_EQ(marginLevel(error_bound, credit, defaults), kWarn);
  EXPECT_EQ(marginLevel(std::nextafter(error_bound, -1.0), credit, defaults), kError);
  EXPECT_EQ(marginLevel(-0.1002, credit, defaults), kError);
  EXPECT_EQ(marginLevel(-1.6, credit, defaults), kError);
  // No credit (passivity_contact_credit: 0): any deficit warns.
  EXPECT_EQ(marginLevel(0.0, 0.0, defaults), kOk);
  EXPECT_EQ(marginLevel(-1e-12, 0.0, defaults), kWarn);
  EXPECT_EQ(marginLevel(-0.1, 0.0, defaults), kWarn);
  EXPECT_EQ(marginLevel(-0.10001, 0.0, defaults), kError);
  // A broken count.
  EXPECT_EQ(marginLevel(NAN, credit, defaults), kError);
  EXPECT_EQ(marginLevel(-INFINITY, credit, defaults), kError);
  EXPECT_EQ(marginLevel(INFINITY, credit, defaults), kError);
}

TEST(DiagnosticLevels, MarginTextSaysTheMarginAndTheBounds)
{
  const DiagnosticThresholds defaults;
  EXPECT_EQ(marginText(-1e-4, 1e-4, defaults), "");
  EXPECT_EQ(marginText(-0.022, 1e-4, defaults),
            "energy margin -0.022 J, beyond its credit of 0.0001 J: this port let out more than the other put in "
            "(ERROR below -0.1 J)");
}

TEST(DiagnosticLevels, StreamsWaitingFreshAndStale)
{
  const double timeout = DiagnosticThresholds().device_state_timeout;
  ASSERT_EQ(timeout, 0.25);
  EXPECT_EQ(streamLevel(false, INFINITY, timeout), kWarn);  // none yet: waiting
  EXPECT_EQ(streamLevel(true, 0.001, timeout), kOk);        // a 1 kHz device
  EXPECT_EQ(streamLevel(true, 0.25, timeout), kOk);         // at the timeout
  EXPECT_EQ(streamLevel(true, 0.2501, timeout), kError);
  EXPECT_EQ(streamLevel(true, 3.0, timeout), kError);  // the driver was killed 3 s ago
  EXPECT_EQ(streamLevel(true, NAN, timeout), kError);
}

TEST(DiagnosticLevels, ThresholdsAreReadAndCheckedWithTheParameterNamed)
{
  EXPECT_EQ(validate(DiagnosticThresholds{}), "");
  MapParameterSource source("/physics/");
  source.set("overrun_warn_share", ParameterValue::of(0.02));
  source.set("margin_error", ParameterValue::of(0.5));
  const DiagnosticThresholds read = readDiagnosticThresholds(source);
  EXPECT_EQ(read.overrun_warn_share, 0.02);
  EXPECT_EQ(read.overrun_error_share, 0.25);
  EXPECT_EQ(read.margin_error, 0.5);
  EXPECT_EQ(overrunLevel(20, 1000, read), kOk);
  EXPECT_EQ(overrunLevel(21, 1000, read), kWarn);

  MapParameterSource out_of_range("/physics/");
  out_of_range.set("overrun_error_share", ParameterValue::of(1.5));
  try
  {
    readDiagnosticThresholds(out_of_range);
    FAIL() << "accepted";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "parameter '/physics/overrun_error_share' = 1.5 is out of range [0, 1] (dimensionless)");
  }
  MapParameterSource crossed("/servo/");
  crossed.set("overrun_warn_share", ParameterValue::of(0.3));
  try
  {
    readDiagnosticThresholds(crossed);
    FAIL() << "accepted";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(),
                 "parameter '/servo/overrun_warn_share' = 0.3 is above '/servo/overrun_error_share' = 0.25");
  }
  DiagnosticThresholds bad;
  bad.device_state_timeout = 0.0;
  EXPECT_EQ(validate(bad), "parameter 'device_state_timeout' = 0 is out of range (0, 10] (s)");
}
}  // namespace
}  // namespace god_finger
