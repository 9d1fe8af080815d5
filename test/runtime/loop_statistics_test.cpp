// The servo loop's statistics over a window (runtime/loop_statistics.h): the world step's stages
// (StepProfileStatistics) as percentiles in microseconds, from the profiles' nanoseconds.
#include "god_finger/runtime/loop_statistics.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace god_finger
{
namespace
{
StepProfile profileWith(StepStage stage, std::int64_t ns, long step)
{
  StepProfile profile;
  profile.step = step;
  profile.stage_ns[static_cast<int>(stage)] = ns;
  profile.total_ns = ns;
  return profile;
}

TEST(StepProfileStatistics, PercentilesOfEachStageInMicroseconds)
{
  StepProfileStatistics statistics;
  // 100 steps: the solve takes 1, 2, ..., 100 us; the contact areas 7 us in every step but the
  // last, which takes 500 us.
  for (int k = 1; k <= 100; ++k)
  {
    StepProfile profile = profileWith(StepStage::kSolve, 1000 * k, 16 * k);
    profile.stage_ns[static_cast<int>(StepStage::kContactAreas)] = k == 100 ? 500000 : 7000;
    statistics.add(profile);
  }
  const std::array<Percentiles, kStepStageCount> stages = statistics.summarize();
  const Percentiles& solve = stages[static_cast<int>(StepStage::kSolve)];
  EXPECT_NEAR(solve.p50, 50.5, 0.5);
  EXPECT_NEAR(solve.p99, 99.0, 1.0);
  EXPECT_EQ(solve.max, 100.0);
  const Percentiles& areas = stages[static_cast<int>(StepStage::kContactAreas)];
  EXPECT_EQ(areas.p50, 7.0);
  EXPECT_EQ(areas.max, 500.0);
  EXPECT_EQ(stages[static_cast<int>(StepStage::kWake)].max, 0.0);
  statistics.clear();
  EXPECT_EQ(statistics.summarize()[static_cast<int>(StepStage::kSolve)].max, 0.0);  // empty window
}

TEST(StepProfileStatistics, TheLoopsSummaryCarriesInterfaceZerosStepProfiles)
{
  LoopStatistics statistics;
  for (int interface = 0; interface < 2; ++interface)
  {
    ServoSample sample;
    sample.interface = interface;
    sample.step_profile = profileWith(StepStage::kCollide, interface == 0 ? 3000 : 9000, 1 + interface);
    statistics.add(sample);
  }
  const LoopSummary summary = statistics.summarize();
  EXPECT_EQ(summary.ticks, 1);
  EXPECT_EQ(summary.stage_us[static_cast<int>(StepStage::kCollide)].max, 3.0);  // one step per tick
}

TEST(StepProfileStatistics, EachTimedStepCountsOnce)
{
  // The world keeps a timed step's profile until the next timed one (profile_every): the samples
  // of the steps between carry it again.
  StepProfileStatistics statistics;
  statistics.add(StepProfile());  // no step timed yet
  for (int k = 0; k < 16; ++k)
  {
    statistics.add(profileWith(StepStage::kSolve, 4000, 1));
  }
  statistics.add(profileWith(StepStage::kSolve, 100000, 17));
  statistics.add(profileWith(StepStage::kSolve, 10000, 33));
  const Percentiles solve = statistics.summarize()[static_cast<int>(StepStage::kSolve)];
  EXPECT_EQ(solve.max, 100.0);
  EXPECT_EQ(solve.p50, 10.0);  // of 4, 10 and 100 us (with the copies, 4 would be the median)
  statistics.clear();
  statistics.add(profileWith(StepStage::kSolve, 10000, 33));  // still the same step
  EXPECT_EQ(statistics.summarize()[static_cast<int>(StepStage::kSolve)].max, 0.0);
}

TEST(StepProfileStatistics, StageNamesAreDistinctAndKnown)
{
  std::set<std::string> names;
  for (int s = 0; s < kStepStageCount; ++s)
  {
    names.insert(stepStageName(static_cast<StepStage>(s)));
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(kStepStageCount));
  EXPECT_EQ(names.count("unknown"), 0u);
  EXPECT_STREQ(stepStageName(StepStage::kContactAreas), "contact_areas");
}
}  // namespace
}  // namespace god_finger
