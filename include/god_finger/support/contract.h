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

namespace god_finger::support
{
[[noreturn]] inline void contractViolated(const char* file, int line, const char* condition, const char* what) noexcept
{
  std::fprintf(stderr, "%s:%d: contract violated: %s (%s)\n", file, line, what, condition);
  std::fflush(stderr);
  std::abort();
}

// Marks the calling thread's real-time sections (a haptic tick, a warmed physics step) in a
// build without NDEBUG, so that an allocation inside one is caught (the tests' operator new,
// test/helpers/allocation_counter.cpp, aborts on one). Sections nest. With NDEBUG: nothing.
#ifndef NDEBUG
inline int& realTimeSectionDepth() noexcept
{
  thread_local int depth = 0;
  return depth;
}
#endif
inline bool inRealTimeSection() noexcept
{
#ifndef NDEBUG
  return realTimeSectionDepth() > 0;
#else
  return false;
#endif
}
class RealTimeSection
{
 public:
#ifndef NDEBUG
  RealTimeSection() noexcept
  {
    ++realTimeSectionDepth();
  }
  ~RealTimeSection()
  {
    --realTimeSectionDepth();
  }
#else
  RealTimeSection() noexcept {}  // user-provided: a section is never an "unused variable"
#endif
  RealTimeSection(const RealTimeSection&) = delete;
  RealTimeSection& operator=(const RealTimeSection&) = delete;
};
}  // namespace god_finger::support

#ifndef NDEBUG
#define GOD_FINGER_EXPECTS(condition, what) \
  ((condition) ? static_cast<void>(0) : ::god_finger::support::contractViolated(__FILE__, __LINE__, #condition, what))
#else
#define GOD_FINGER_EXPECTS(condition, what) static_cast<void>(sizeof((condition) ? 1 : 0))
#endif
