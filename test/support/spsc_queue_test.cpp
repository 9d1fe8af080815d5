// The lock-free queue between the servo loop and its publishers: bounded, in order, never
// overwriting, and correct with a producer and a consumer in two threads.
#include "god_finger/support/spsc_queue.h"

#include <gtest/gtest.h>

#include <thread>

namespace god_finger
{
namespace
{
TEST(SpscQueue, BoundedInOrderAndNeverOverwrites)
{
  SpscQueue<int> queue(3);
  EXPECT_TRUE(queue.empty());
  EXPECT_TRUE(queue.tryPush(1));
  EXPECT_TRUE(queue.tryPush(2));
  EXPECT_TRUE(queue.tryPush(3));
  EXPECT_FALSE(queue.tryPush(4));
  EXPECT_EQ(queue.reserve(), nullptr);
  int value = 0;
  EXPECT_TRUE(queue.tryPop(&value));
  EXPECT_EQ(value, 1);
  int* slot = queue.reserve();
  ASSERT_NE(slot, nullptr);
  *slot = 5;
  queue.commit();
  for (int expected : {2, 3, 5})
  {
    ASSERT_TRUE(queue.tryPop(&value));
    EXPECT_EQ(value, expected);
  }
  EXPECT_FALSE(queue.tryPop(&value));
}

TEST(SpscQueue, TwoThreadsPassAMillionValuesInOrder)
{
  SpscQueue<long> queue(64);
  constexpr long kCount = 1000000;
  std::thread producer(
      [&queue]()
      {
        for (long i = 0; i < kCount;)
        {
          if (queue.tryPush(i))
          {
            ++i;
          }
        }
      });
  long next = 0;
  long value = 0;
  while (next < kCount)
  {
    if (queue.tryPop(&value))
    {
      ASSERT_EQ(value, next);
      ++next;
    }
  }
  producer.join();
  EXPECT_TRUE(queue.empty());
}
}  // namespace
}  // namespace god_finger
