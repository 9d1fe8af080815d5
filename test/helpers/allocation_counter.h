// Counts heap allocations (operator new) in the test binary that links allocation_counter.cpp,
// to prove that a real-time path allocates nothing. In a build without NDEBUG, a
// support::RealTimeSection (support/contract.h) that completes after an allocation aborts the test.
#pragma once

namespace god_finger
{
namespace test
{
// Allocations since the program began.
long allocationCount();
}  // namespace test
}  // namespace god_finger
