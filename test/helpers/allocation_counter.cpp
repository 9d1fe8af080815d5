#include "allocation_counter.h"

#include "god_finger/support/contract.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace
{
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size)
{
  // A build without NDEBUG (scripts/sanitize's): a real-time section that completes after an
  // allocation is a bug wherever a test runs one, whether or not that test counts allocations.
  god_finger::support::noteAllocation();
  ++g_allocations;
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr)
  {
    throw std::bad_alloc();
  }
  return p;
}
void operator delete(void* p) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}

namespace god_finger
{
namespace test
{
long allocationCount()
{
  return g_allocations.load();
}
}  // namespace test
}  // namespace god_finger
