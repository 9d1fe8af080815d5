// The human-like operator (scenarios/human_operator.h): its draws stay in their ranges and repeat
// per seed, its tremor and fluctuation have the drawn amplitudes, and its grip reflex answers a
// slip exactly one reaction delay later.
#include "god_finger/scenarios/human_operator.h"

#include <gtest/gtest.h>

#include <cmath>

namespace god_finger
{
namespace
{
TEST(HumanOperator, DrawsStayInTheirRangesAndRepeatPerSeed)
{
  const Eigen::Vector3d pinch = Eigen::Vector3d::UnitY();
  for (std::uint64_t seed = 1; seed <= 200; ++seed)
  {
    const OperatorTraits traits = drawOperator(seed, pinch);
    EXPECT_GE(traits.tremor_amplitude, 1e-4);
    EXPECT_LE(traits.tremor_amplitude, 1e-3);
    EXPECT_GE(traits.tremor_frequency, 8.0);
    EXPECT_LE(traits.tremor_frequency, 12.0);
    EXPECT_LE(traits.misalignment.norm(), 0.003);
    EXPECT_NEAR(traits.misalignment.dot(pinch), 0.0, 1e-15);  // across the pinch only
    EXPECT_EQ(traits.grip_fluctuation, 0.25);
    EXPECT_GE(traits.reaction_delay, 0.1);
    EXPECT_LE(traits.reaction_delay, 0.15);
    const OperatorTraits again = drawOperator(seed, pinch);
    EXPECT_EQ(traits.misalignment, again.misalignment);
    EXPECT_EQ(traits.reaction_delay, again.reaction_delay);
  }
  EXPECT_NE(drawOperator(1, pinch).misalignment, drawOperator(2, pinch).misalignment);
}

TEST(HumanOperator, TremorAndFluctuationHaveTheDrawnAmplitudes)
{
  const OperatorTraits traits = drawOperator(7, Eigen::Vector3d::UnitY());
  double largest_tremor = 0.0;
  double lowest = INFINITY;
  double highest = 0.0;
  for (int i = 0; i < 20000; ++i)
  {
    const double t = i * 1e-4;
    largest_tremor = std::max(largest_tremor, tremorAt(traits, t, 0).cwiseAbs().maxCoeff());
    lowest = std::min(lowest, fluctuationAt(traits, t));
    highest = std::max(highest, fluctuationAt(traits, t));
  }
  EXPECT_NEAR(largest_tremor, traits.tremor_amplitude, 0.01 * traits.tremor_amplitude);
  EXPECT_NEAR(lowest, 0.75, 1e-3);
  EXPECT_NEAR(highest, 1.25, 1e-3);
  EXPECT_TRUE(perfectOperator().misalignment.isZero());
  EXPECT_EQ(fluctuationAt(perfectOperator(), 0.3), 1.0);
}

TEST(HumanOperator, TheGripReflexAnswersASlipOneReactionDelayLater)
{
  GripReflex reflex(0.12);
  const double dt = 1e-3;
  double first_rise = -1.0;
  for (int i = 0; i <= 1000; ++i)
  {
    const double t = i * dt;
    // Slips from 0.2 s on, for ever.
    const double extra = reflex.update(t, t >= 0.2 ? 0.01 : 0.0);
    if (first_rise < 0.0 && extra > 0.0)
    {
      first_rise = t;
      EXPECT_DOUBLE_EQ(extra, GripReflex::kReflexStep);
    }
    EXPECT_LE(extra, GripReflex::kReflexMax + 1e-12);
  }
  EXPECT_NEAR(first_rise, 0.32, 1.5 * dt);
  EXPECT_DOUBLE_EQ(reflex.update(2.0, 0.01), GripReflex::kReflexMax);
  GripReflex none(0.0);
  EXPECT_EQ(none.update(1.0, 1.0), 0.0);
  EXPECT_EQ(none.update(2.0, 1.0), 0.0);
}
}  // namespace
}  // namespace god_finger
