// support/contract.h: a contract is checked, and aborts naming itself, in a build without NDEBUG
// (scripts/sanitize's), and costs nothing, its condition not even evaluated, with NDEBUG (the
// nodes' and the bench's RelWithDebInfo); a real-time section that allocated aborts, when it
// ends, the test binary that links allocation_counter (this one) in the first kind of build,
// unless an exception ends it.
#include "allocation_counter.h"

#include "god_finger/support/contract.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

namespace god_finger
{
namespace
{
int requirePositive(int value)
{
  GOD_FINGER_EXPECTS(value > 0, "the caller gives a positive value");
  return value;
}

#ifndef NDEBUG
TEST(ContractDeathTest, ABrokenContractAbortsNamingWhatItGuards)
{
  EXPECT_EQ(requirePositive(3), 3);
  EXPECT_DEATH(requirePositive(-1),
               "contract_test.cpp:[0-9]+: contract violated: the caller gives a positive value "
               "\\(value > 0\\)");
}

TEST(ContractDeathTest, ARealTimeSectionThatAllocatedAbortsWhenItEnds)
{
  const long before = test::allocationCount();
  auto outside = std::make_unique<int>(1);  // outside any section: counted, allowed
  EXPECT_EQ(test::allocationCount() - before, 1);
  EXPECT_DEATH(
      {
        const support::RealTimeSection real_time;
        auto inside = std::make_unique<int>(2);
        (void)inside;
      },
      "a real-time section allocated");
}

TEST(Contract, ASectionLeftByAnExceptionMayAllocateItsMessage)
{
  // A device fault that stops the loop: its DeviceError's message allocates on the way out.
  EXPECT_THROW(
      {
        const support::RealTimeSection real_time;
        throw std::runtime_error("a device fault, with a message long enough to allocate its text");
      },
      std::runtime_error);
  EXPECT_FALSE(support::inRealTimeSection());
}

TEST(Contract, RealTimeSectionsNestAndEnd)
{
  EXPECT_FALSE(support::inRealTimeSection());
  {
    const support::RealTimeSection outer;
    {
      const support::RealTimeSection inner;
      EXPECT_TRUE(support::inRealTimeSection());
    }
    EXPECT_TRUE(support::inRealTimeSection());
  }
  EXPECT_FALSE(support::inRealTimeSection());
}
#else
TEST(Contract, WithNdebugTheConditionIsNotEvenEvaluated)
{
  int evaluated = 0;
  GOD_FINGER_EXPECTS(++evaluated < 0, "never checked with NDEBUG");
  EXPECT_EQ(evaluated, 0);
  EXPECT_EQ(requirePositive(-1), -1);  // not checked: the contract is the caller's
  const support::RealTimeSection real_time;
  EXPECT_FALSE(support::inRealTimeSection());
}
#endif
}  // namespace
}  // namespace god_finger
