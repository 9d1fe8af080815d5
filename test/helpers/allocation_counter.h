// Counts heap allocations (operator new) in the test binary that links allocation_counter.cpp,
// to prove that a real-time path allocates nothing. In a build without NDEBUG, an allocation inside
// a support::RealTimeSection (support/contract.h) aborts the test, naming the section's rule.
#pragma once

namespace god_finger
{
namespace test
{
// Allocations since the program began.
long allocationCount();
}  // namespace test
}  // namespace god_finger
