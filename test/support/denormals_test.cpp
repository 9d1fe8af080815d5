// support/denormals.h: a thread that flushes turns subnormal results into 0; one that does not
// (the default) keeps them; flushTiny ends a decay at exactly 0.
#include "god_finger/support/denormals.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <thread>

namespace god_finger
{
namespace
{
volatile double g_small = 1e-300;  // volatile: computed at run time, in the thread under test
volatile double g_factor = 1e-10;

TEST(Denormals, AFlushingThreadTurnsSubnormalResultsIntoZero)
{
  // Without the flush (this thread): 1e-310 is subnormal.
  const double unflushed = g_small * g_factor;
  EXPECT_EQ(std::fpclassify(unflushed), FP_SUBNORMAL);
  double flushed = -1.0;
  bool flag = false;
  std::thread thread(
      [&flushed, &flag]()
      {
        flushDenormalsInThisThread();
        flag = denormalsFlushedInThisThread();
        flushed = g_small * g_factor;
      });
  thread.join();
#if defined(__SSE__)
  EXPECT_TRUE(flag);
  EXPECT_EQ(flushed, 0.0);
#else
  GTEST_SKIP() << "no SSE: the flush is a no-op";
#endif
  EXPECT_FALSE(denormalsFlushedInThisThread());  // only the calling thread's
}

TEST(Denormals, FlushTinyEndsADecayAtZero)
{
  Eigen::Vector3d v(1e-201, -1e-250, 1e-199);
  flushTiny(&v);
  EXPECT_EQ(v, Eigen::Vector3d(0.0, 0.0, 1e-199));
  Eigen::Vector3d physical(1e-12, -3.0, DBL_MIN * 1e120);
  const Eigen::Vector3d before = physical;
  flushTiny(&physical);
  EXPECT_EQ(physical, before);
}
}  // namespace
}  // namespace god_finger
