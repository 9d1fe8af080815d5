// The contracts the headers state, in code: GOD_FINGER_EXPECTS(condition, what) at the top of a
// function says what its caller must give it (an index in range, a finite value, a thread that
// may allocate). A build without NDEBUG (scripts/sanitize's, a Debug build) checks it and, when
// it fails, prints the file, line, condition and `what`, then aborts; a build with NDEBUG
// (RelWithDebInfo: the nodes, the bench) compiles it away, condition and all (it must have no
// side effect).
//
// What a caller can get wrong at run time (a user's value, a message) is not a contract: it is
// an InputError or a counted rejection, in every build. A contract is what only a bug in the
// calling code breaks.
//
// Real-time safe: the check is a branch; a failure writes to stderr and aborts.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>

namespace god_finger::support
{
[[noreturn]] inline void contractViolated(const char* file, int line, const char* condition, const char* what) noexcept
{
  std::fprintf(stderr, "%s:%d: contract violated: %s (%s)\n", file, line, what, condition);
  std::fflush(stderr);
  std::abort();
}

// Marks the calling thread's real-time sections (a haptic tick) in a build without NDEBUG: a
// section that completes must have allocated nothing. A test binary's operator new
// (test/helpers/allocation_counter.cpp) reports each allocation with noteAllocation(); the
// section checks the count when it ends, unless it ends by an exception (a device fault that
// stops the loop may allocate its message). Sections nest. With NDEBUG: nothing.
#ifndef NDEBUG
struct RealTimeThreadState
{
  int depth = 0;
  long allocations = 0;  // in any section of this thread, since it started
};
inline RealTimeThreadState& realTimeThreadState() noexcept
{
  thread_local RealTimeThreadState state;
  return state;
}
#endif
inline bool inRealTimeSection() noexcept
{
#ifndef NDEBUG
  return realTimeThreadState().depth > 0;
#else
  return false;
#endif
}
// An allocation on the calling thread (operator new's hook); counted only inside a section.
inline void noteAllocation() noexcept
{
#ifndef NDEBUG
  RealTimeThreadState& state = realTimeThreadState();
  state.allocations += state.depth > 0 ? 1 : 0;
#endif
}
class RealTimeSection
{
 public:
#ifndef NDEBUG
  RealTimeSection() noexcept : allocations_(realTimeThreadState().allocations), exceptions_(std::uncaught_exceptions())
  {
    ++realTimeThreadState().depth;
  }
  ~RealTimeSection()
  {
    RealTimeThreadState& state = realTimeThreadState();
    --state.depth;
    if (std::uncaught_exceptions() == exceptions_ && state.allocations != allocations_)
    {
      contractViolated(__FILE__, __LINE__, "no allocation in a completed real-time section",
                       "a real-time section allocated");
    }
  }
#else
  RealTimeSection() noexcept {}  // user-provided: a section is never an "unused variable"
#endif
  RealTimeSection(const RealTimeSection&) = delete;
  RealTimeSection& operator=(const RealTimeSection&) = delete;

 private:
#ifndef NDEBUG
  long allocations_;
  int exceptions_;
#endif
};
}  // namespace god_finger::support

#ifndef NDEBUG
#define GOD_FINGER_EXPECTS(condition, what) \
  ((condition) ? static_cast<void>(0) : ::god_finger::support::contractViolated(__FILE__, __LINE__, #condition, what))
#else
#define GOD_FINGER_EXPECTS(condition, what) static_cast<void>(sizeof((condition) ? 1 : 0))
#endif
