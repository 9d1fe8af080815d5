// The soft block under a pad and under a point, against Boussinesq's w0 (issue 28, item 4).
#include "god_finger/scenarios/soft_press_fidelity.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace god_finger
{
namespace
{
TEST(SoftPressFidelity, Explore)
{
  for (double grading : { 1.0, 1.3, 1.6, 2.0 })
  {
    for (int nodes : { 250, 1000, 4000 })
    {
      SoftPressSetup setup;
      setup.nodes = nodes;
      setup.grading = grading;
      const SoftPressResult result = pressSoftBlock(setup);
      std::printf("%s\n", softPressJson(setup, result).c_str());
    }
  }
}
}  // namespace
}  // namespace god_finger
