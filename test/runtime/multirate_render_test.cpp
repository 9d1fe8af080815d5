// The multi-rate renderer on its own (runtime/multirate_render.h): on time it passes the step's
// reaction through bit for bit; a late step makes it pull the device towards an anchor that
// moves to the new proxy by at most delta a tick, the force changing by at most its bound; it
// rejoins the step once the anchor is on the proxy and the reaction within the bound. On a soft
// contact the anchor yields as the body does: the coupling and the body in series, never pulling.
#include "god_finger/runtime/multirate_render.h"

#include <gtest/gtest.h>

#include <limits>

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
TEST(MultirateRender, OnASoftContactTheHandFeelsTheCouplingAndTheBodyInSeriesBetweenSteps)
{
  CouplingProfile coupling;
  coupling.stiffness = 800.0;
  coupling.damping = 0.0;  // the spring alone: damping acts on the device's velocity, the same either way
  coupling.max_force = 20.0;
  const double k_s = 1200.0;  // N/m: a soft block under a pad (InterfaceState::contact_stiffness)
  const double k_series = coupling.stiffness * k_s / (coupling.stiffness + k_s);  // 480 N/m
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  // The last step: the device 10 mm under the proxy, 8 N on the hand along n.
  MultirateStep soft{
      Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 8.0), 0, Eigen::Vector3d(0.0, 0.0, -0.01), k_s, n};
  MultirateStep rigid = soft;
  rigid.contact_stiffness = std::numeric_limits<double>::infinity();
  for (MultirateStep* step : {&soft, &rigid})
  {
    MultirateState state;
    MultirateDevice device;
    device.target = device.previous_target = step->step_target;
    ASSERT_TRUE(renderMultirate(coupling, 8, device, *step, &state));
    EXPECT_EQ(state.force, step->user_force);
    // The physics goes late; the device moves 0.5 mm a tick into the body for 4 ticks.
    step->lag = 1;
    for (int tick = 1; tick <= 4; ++tick)
    {
      device.previous_target = device.target;
      device.target.z() -= 0.0005;
      EXPECT_FALSE(renderMultirate(coupling, 8, device, *step, &state));
      const double expected = 8.0 + (step == &soft ? k_series : coupling.stiffness) * 0.0005 * tick;
      EXPECT_NEAR(state.force.z(), expected, 1e-9) << (step == &soft ? "soft" : "rigid") << " tick " << tick;
      EXPECT_NEAR(state.force.head<2>().norm(), 0.0, 1e-12);
    }
  }
  // Withdrawn past where the body lets go (8 N / 480 N/m = 16.7 mm over the step's target): the
  // proxy leaves the surface at zero force, the hand is not pulled back (the force falls by at
  // most the bound a tick, to zero).
  MultirateState state;
  MultirateDevice device;
  soft.lag = 0;
  device.target = device.previous_target = soft.step_target;
  ASSERT_TRUE(renderMultirate(coupling, 8, device, soft, &state));
  soft.lag = 1;
  for (int tick = 1; tick <= 60; ++tick)
  {
    device.previous_target = device.target;
    device.target.z() += 0.0005;
    renderMultirate(coupling, 8, device, soft, &state);
    EXPECT_GE(state.force.z(), -1e-12) << "tick " << tick;
  }
  EXPECT_NEAR(state.force.z(), 0.0, 1e-12);  // 30 mm out: free space
}
}  // namespace
}  // namespace god_finger
