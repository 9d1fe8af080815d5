// The sleeping bodies out of Bullet's world (src/physics/sleep/dormant_bodies.h), a private piece of the
// physics tested on its own: a group sleeps and wakes together, a box query wakes exactly the
// groups it overlaps, each woken body is reported once, and a reset forgets everything.
#include "sleep/dormant_bodies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace god_finger
{
using namespace internal;  // the private pieces under test
namespace
{
btVector3 v(double x, double y, double z)
{
  return btVector3(x, y, z);
}

// A 2 cm box centred at x (m) on the x axis.
void addBox(DormantBodies* bodies, int body, double x, int group)
{
  bodies->add(body, v(x - 0.01, -0.01, -0.01), v(x + 0.01, 0.01, 0.01), group);
}

TEST(DormantBodies, AQueryWakesTheGroupsItOverlapsAndEachBodyOnce)
{
  DormantBodies bodies;
  bodies.reset(6);
  // Group {0, 1, 2} (a stack: 1 and 2 sleep in 0's group), 3 alone, {4, 5} far away.
  addBox(&bodies, 0, 0.0, -1);
  addBox(&bodies, 1, 0.03, 0);
  addBox(&bodies, 2, 0.06, 1);
  addBox(&bodies, 3, 0.2, -1);
  addBox(&bodies, 4, 1.0, -1);
  addBox(&bodies, 5, 1.03, 4);
  for (int body = 0; body < 6; ++body)
  {
    EXPECT_TRUE(bodies.dormant(body)) << body;
  }
  // A finger's box over body 2 only: the whole stack wakes, each body reported once.
  std::vector<int> woken;
  bodies.wakeOverlapping(v(0.055, -0.005, -0.005), v(0.065, 0.005, 0.005),
                         [&woken](int body) { woken.push_back(body); });
  std::sort(woken.begin(), woken.end());
  EXPECT_EQ(woken, (std::vector<int>{0, 1, 2}));
  EXPECT_FALSE(bodies.dormant(0));
  EXPECT_TRUE(bodies.dormant(3));
  // A query between the boxes wakes nothing; the same query again wakes nothing either.
  woken.clear();
  bodies.wakeOverlapping(v(0.1, -0.005, -0.005), v(0.15, 0.005, 0.005), [&woken](int body) { woken.push_back(body); });
  bodies.wakeOverlapping(v(0.055, -0.005, -0.005), v(0.065, 0.005, 0.005),
                         [&woken](int body) { woken.push_back(body); });
  EXPECT_TRUE(woken.empty());
  // A query over 3 and 4 at once wakes 3 and the group {4, 5}.
  bodies.wakeOverlapping(v(0.19, -0.005, -0.005), v(1.001, 0.005, 0.005),
                         [&woken](int body) { woken.push_back(body); });
  std::sort(woken.begin(), woken.end());
  EXPECT_EQ(woken, (std::vector<int>{3, 4, 5}));
}

TEST(DormantBodies, WakeAllAndResetLeaveNoBodyDormant)
{
  DormantBodies bodies;
  bodies.reset(3);
  addBox(&bodies, 0, 0.0, -1);
  addBox(&bodies, 2, 0.5, -1);
  EXPECT_FALSE(bodies.dormant(1));
  int count = 0;
  bodies.wakeAll([&count](int) { ++count; });
  EXPECT_EQ(count, 2);
  addBox(&bodies, 1, 0.0, -1);
  bodies.reset(3);
  for (int body = 0; body < 3; ++body)
  {
    EXPECT_FALSE(bodies.dormant(body)) << body;
  }
  // After a reset a query finds nothing of before.
  bodies.wakeOverlapping(v(-1, -1, -1), v(1, 1, 1), [&count](int) { ++count; });
  EXPECT_EQ(count, 2);
}
}  // namespace
}  // namespace god_finger
