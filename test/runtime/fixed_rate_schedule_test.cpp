// FixedRateSchedule on a simulated clock: on time it sleeps to the grid, late it catches up
// without drifting, more than 10 periods behind it restarts, bad periods are refused, and a
// tick allocates nothing.
#include "god_finger/runtime/fixed_rate_schedule.h"
#include "god_finger/support/input_error.h"

#include "allocation_counter.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
// A period that binary floating point holds exactly, so that the boundaries below are exact.
constexpr double kPeriod = 0.5;

TEST(FixedRateSchedule, OnTimeSleepsToTheGrid)
{
  FixedRateSchedule schedule(kPeriod, 2.0);
  EXPECT_EQ(schedule.deadline(), 2.5);
  EXPECT_EQ(schedule.tickEnded(2.1), 2.5);
  EXPECT_EQ(schedule.deadline(), 3.0);
  EXPECT_EQ(schedule.tickEnded(3.0), 3.0);  // ending exactly at the deadline is on time
  EXPECT_EQ(schedule.deadline(), 3.5);
  EXPECT_EQ(schedule.overruns(), 0);
}

TEST(FixedRateSchedule, LateTicksStartAtOnceAndCatchUp)
{
  FixedRateSchedule schedule(kPeriod, 0.0);
  EXPECT_EQ(schedule.tickEnded(1.75), 1.75);  // due 0.5: late, the next starts now
  EXPECT_EQ(schedule.deadline(), 1.0);        // still on the grid
  EXPECT_EQ(schedule.tickEnded(1.8), 1.8);    // due 1.0: late
  EXPECT_EQ(schedule.tickEnded(1.9), 1.9);    // due 1.5: late
  EXPECT_EQ(schedule.tickEnded(1.95), 2.0);   // due 2.0: caught up, sleeps to the grid
  EXPECT_EQ(schedule.overruns(), 3);
}

TEST(FixedRateSchedule, TenPeriodsBehindKeepsTheGridMoreRestarts)
{
  FixedRateSchedule exactly(kPeriod, 0.0);
  EXPECT_EQ(exactly.tickEnded(0.5 + 10 * kPeriod), 5.5);  // 10 periods late: catches up
  EXPECT_EQ(exactly.deadline(), 1.0);
  FixedRateSchedule beyond(kPeriod, 0.0);
  EXPECT_EQ(beyond.tickEnded(5.75), 5.75);  // 10.5 periods late: restarts from now
  EXPECT_EQ(beyond.deadline(), 6.25);
  EXPECT_EQ(beyond.tickEnded(6.0), 6.25);  // and keeps the new grid
  EXPECT_EQ(beyond.overruns(), 1);
}

TEST(FixedRateSchedule, DoesNotDrift)
{
  FixedRateSchedule schedule(1e-3, 0.0);
  for (long k = 0; k < 1000000; ++k)
  {
    schedule.tickEnded(schedule.deadline() - 1e-4);
  }
  EXPECT_NEAR(schedule.deadline(), 1000.001, 1e-9);
  EXPECT_EQ(schedule.overruns(), 0);
}

TEST(FixedRateSchedule, RefusesBadPeriods)
{
  for (const double period : {0.0, -1e-3, double(NAN), double(INFINITY)})
  {
    try
    {
      FixedRateSchedule schedule(period, 0.0);
      ADD_FAILURE() << "period " << period << " was taken";
    }
    catch (const InputError& error)
    {
      EXPECT_NE(std::string(error.what()).find("period must be finite and > 0 (s)"), std::string::npos) << error.what();
    }
  }
  EXPECT_THROW(FixedRateSchedule(1e-3, NAN), InputError);
}

TEST(FixedRateSchedule, TicksAllocateNothing)
{
  FixedRateSchedule schedule(1e-3, 0.0);
  const long before = test::allocationCount();
  for (int k = 0; k < 100; ++k)
  {
    schedule.tickEnded(k % 3 == 0 ? schedule.deadline() + 0.05 : schedule.deadline());
  }
  EXPECT_EQ(test::allocationCount(), before);
  EXPECT_EQ(schedule.overruns(), 34);
}
}  // namespace
}  // namespace god_finger
