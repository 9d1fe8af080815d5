// Counts heap allocations (operator new) in the test binary that links allocation_counter.cpp,
// to prove that a real-time path allocates nothing.
#pragma once

namespace god_finger
{
namespace test
{
// Allocations since the program began.
long allocationCount();
}  // namespace test
}  // namespace god_finger
