#include "god_finger/support/denormals.h"

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace god_finger
{
namespace
{
constexpr unsigned kFlushToZero = 0x8000;     // MXCSR bit 15
constexpr unsigned kDenormalsAreZero = 0x40;  // MXCSR bit 6
}  // namespace

void flushDenormalsInThisThread()
{
#if defined(__SSE__)
  _mm_setcsr(_mm_getcsr() | kFlushToZero | kDenormalsAreZero);
#endif
}

bool denormalsFlushedInThisThread()
{
#if defined(__SSE__)
  const unsigned both = kFlushToZero | kDenormalsAreZero;
  return (_mm_getcsr() & both) == both;
#else
  return false;
#endif
}
}  // namespace god_finger
