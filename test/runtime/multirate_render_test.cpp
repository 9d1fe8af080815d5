// The multi-rate renderer on its own (runtime/multirate_render.h): on time it passes the step's
// reaction through bit for bit; a late step makes it pull the device towards an anchor that
// moves to the new proxy by at most delta a tick, the force changing by at most its bound; it
// rejoins the step once the anchor is on the proxy and the reaction within the bound.
#include "god_finger/runtime/multirate_render.h"

#include <gtest/gtest.h>

namespace god_finger
{
namespace
{
TEST(MultirateRender, OnTimeTheStepsReactionPassesThroughExactly)
{
  const CouplingProfile coupling;
  MultirateState state;
  const MultirateDevice device;
  const MultirateStep step{Eigen::Vector3d(0.0, 0.0, 0.01), Eigen::Vector3d(0.1, -0.2, 0.3), 0};
  EXPECT_TRUE(renderMultirate(coupling, 8, device, step, &state));
  EXPECT_EQ(state.force, step.user_force);
  EXPECT_EQ(state.anchor, step.proxy_position);
  EXPECT_TRUE(state.exact);
}

TEST(MultirateRender, ALateStepIsRenderedAgainstAMovingAnchorWithoutAForceStep)
{
  const CouplingProfile coupling;  // 400 N/m, max_force from the profile
  const int recovery = 8;
  const double delta = coupling.max_force / (coupling.stiffness * recovery);
  MultirateState state;
  MultirateDevice device;
  device.target = device.previous_target = Eigen::Vector3d(0.0, 0.0, -0.005);  // the hand 5 mm in
  // The last step: proxy on the surface, its reaction 2 N up on the hand; then it goes late.
  MultirateStep step{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 2.0), 0};
  ASSERT_TRUE(renderMultirate(coupling, recovery, device, step, &state));
  // The physics is late three ticks while the proxy it will report moved 1 cm sideways.
  step.lag = 1;
  step.proxy_position = Eigen::Vector3d(0.01, 0.0, 0.0);
  step.user_force =
      -couplingForce(coupling, device.target, Eigen::Vector3d::Zero(), step.proxy_position, Eigen::Vector3d::Zero())
           .on_proxy;
  Eigen::Vector3d last_force = state.force;
  Eigen::Vector3d last_anchor = state.anchor;
  for (int tick = 0; tick < 3; ++tick)
  {
    EXPECT_FALSE(renderMultirate(coupling, recovery, device, step, &state));
    EXPECT_FALSE(state.exact);
    EXPECT_LE((state.anchor - last_anchor).norm(), delta + 1e-15);
    // The device does not move: the bound is stiffness delta.
    EXPECT_LE((state.force - last_force).norm(), coupling.stiffness * delta + 1e-12);
    last_force = state.force;
    last_anchor = state.anchor;
  }
  // Caught up (lag 0) with a reaction consistent with the new proxy: rendered until the anchor
  // reaches the proxy, then the step's reaction again.
  step.lag = 0;
  int ticks = 0;
  while (!renderMultirate(coupling, recovery, device, step, &state) && ticks < 1000)
  {
    ++ticks;
  }
  EXPECT_LT(ticks, 1000);
  EXPECT_EQ(state.anchor, step.proxy_position);
  EXPECT_EQ(state.force, step.user_force);
  EXPECT_TRUE(state.exact);
}
}  // namespace
}  // namespace god_finger
