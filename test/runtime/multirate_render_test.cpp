// The multi-rate renderer on its own (runtime/multirate_render.h): on time it passes the step's
// reaction through bit for bit; a late step makes it pull the device towards an anchor that
// moves to the new proxy by at most delta a tick, the force changing by at most its bound; it
// rejoins the step once the anchor is on the proxy and the reaction within the bound. Between
// steps the anchor is the step's proxy while the hand presses into one of its contact planes
// and the hand itself otherwise: free space stays free, a wall and its friction hold. On a soft contact the anchor
// yields as the body does: the coupling and the body in series, never pulling. The hold's passivity controller keeps
// what it gives the hand within what the coupling stored plus what the hand put in.
#include "god_finger/runtime/multirate_render.h"

#include "god_finger/physics/world_state.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>

namespace god_finger
{
namespace
{
// A coupling of `stiffness` (N/m), `damping` (N s/m) and `max_force` (N).
CouplingProfile couplingOf(double stiffness, double damping, double max_force)
{
  CouplingProfile coupling;
  coupling.stiffness = stiffness;
  coupling.damping = damping;
  coupling.max_force = max_force;
  return coupling;
}

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
  step.step_target = device.target;
  step.plane_count = 1;
  step.plane_normals[0] = Eigen::Vector3d::UnitZ();  // the surface z = 0
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
  // The spring alone: damping acts on the device's velocity, the same either way.
  const CouplingProfile coupling = couplingOf(800.0, 0.0, 20.0);
  const double k_s = 1200.0;  // N/m: a soft block under a pad (InterfaceState::contact_stiffness)
  const double k_series = coupling.stiffness * k_s / (coupling.stiffness + k_s);  // 480 N/m
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  // The last step: the device 10 mm under the proxy, 8 N on the hand along n.
  MultirateStep soft{
      Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 8.0), 0, Eigen::Vector3d(0.0, 0.0, -0.01), k_s, n};
  soft.plane_count = 1;
  soft.plane_normals[0] = n;
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

// A late step in free space: the prediction moves with the hand, so a hand crossing free space
// at 0.2 m/s through a 20 ms stall feels the step's force (none here) and no drag. A fixed
// anchor would have pulled it back by stiffness x its move: 800 N/m x 4 mm = 3.2 N.
TEST(MultirateRender, BetweenStepsFreeSpaceStaysFree)
{
  const CouplingProfile coupling = couplingOf(800.0, 2.0, 8.9);
  MultirateState state;
  MultirateDevice device;
  const Eigen::Vector3d speed(0.2, 0.0, 0.0);  // m/s
  device.target = Eigen::Vector3d(0.0, 0.0, 0.05);
  device.previous_target = device.target - 1e-3 * speed;
  device.velocity = device.previous_velocity = speed;
  MultirateStep step{device.target, Eigen::Vector3d::Zero(), 0, device.target};
  ASSERT_TRUE(renderMultirate(coupling, 8, device, step, &state));
  double largest = 0.0;
  for (int tick = 1; tick <= 20; ++tick)
  {
    step.lag = tick;
    device.previous_target = device.target;
    device.target += 1e-3 * speed;
    EXPECT_FALSE(renderMultirate(coupling, 8, device, step, &state));
    EXPECT_EQ(state.anchor, device.target) << "tick " << tick;
    largest = std::max(largest, state.force.norm());
  }
  std::printf("[ measured ] free space, 20 ticks late at 0.2 m/s: largest force %.3g N (a fixed anchor: %.3g N)\n",
              largest, coupling.stiffness * 0.2 * 0.02 + coupling.damping * 0.2);
  EXPECT_LE(largest, 1e-12);
}

// A late step on a wall (the plane z = 0 through the proxy): while the hand presses into it the
// proxy stays where the step left it (the wall holds, and so does the friction that held it):
// deeper is felt at the coupling's stiffness, a slide as the spring's pull back; out of the wall
// the hand is free again, at once.
TEST(MultirateRender, BetweenStepsAWallHoldsTheProxyAndFreeSpaceIsFreeAgain)
{
  const CouplingProfile coupling = couplingOf(800.0, 0.0, 20.0);
  MultirateState state;
  MultirateDevice device;
  device.target = device.previous_target = Eigen::Vector3d(0.0, 0.0, -0.005);  // 5 mm in
  MultirateStep step{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 4.0), 0, device.target};
  step.plane_count = 1;
  step.plane_normals[0] = Eigen::Vector3d::UnitZ();
  ASSERT_TRUE(renderMultirate(coupling, 8, device, step, &state));
  step.lag = 1;
  for (int tick = 1; tick <= 10; ++tick)  // 1 mm a tick along x, 0.1 mm a tick deeper
  {
    device.previous_target = device.target;
    device.target += Eigen::Vector3d(0.001, 0.0, -0.0001);
    ASSERT_FALSE(renderMultirate(coupling, 8, device, step, &state));
    EXPECT_NEAR(state.force.z(), 4.0 + 800.0 * 0.0001 * tick, 1e-9) << "tick " << tick;
    EXPECT_NEAR(state.force.x(), -800.0 * 0.001 * tick, 1e-9) << "tick " << tick;
    EXPECT_EQ(state.anchor, step.proxy_position) << "tick " << tick;
  }
  for (int tick = 1; tick <= 40; ++tick)  // out by 0.5 mm a tick: 20 mm, past the wall
  {
    device.previous_target = device.target;
    device.target.z() += 0.0005;
    renderMultirate(coupling, 8, device, step, &state);
    EXPECT_GE(state.force.z(), -1e-12) << "tick " << tick;
  }
  EXPECT_NEAR(state.force.norm(), 0.0, 1e-12);
  EXPECT_EQ(state.anchor, device.target);
}

// The hold's passivity: steps that keep coming late while the scene pushes the proxy out (a
// body shoving the finger back) under a hand giving way. The coupling's spring, stretched by
// 4 N, stored 1/2 F^2 / k = 10 mJ; without the controller the hold gives the hand far more than
// that (the observer goes below zero), with it the hand gets at most that plus what it put in.
TEST(MultirateRender, TheHoldGivesTheHandNoMoreThanTheCouplingStoredWithItsController)
{
  const CouplingProfile coupling = couplingOf(800.0, 2.0, 20.0);
  double given[2] = {0.0, 0.0};   // J, to the hand: off, on
  double lowest[2] = {0.0, 0.0};  // J, the observer's lowest
  for (int on = 0; on < 2; ++on)
  {
    PassivityParams params;
    params.passivity_damping_limit = on ? 50.0 : 0.0;
    PassivityController hold(params, 1e-3);
    MultirateState state;
    MultirateDevice device;
    device.target = device.previous_target = Eigen::Vector3d(0.0, 0.0, -0.005);
    MultirateStep step{Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 4.0), 0, device.target};
    step.plane_count = 1;
    step.plane_normals[0] = Eigen::Vector3d::UnitZ();
    ASSERT_TRUE(renderMultirate(coupling, 8, device, step, &state, &hold));
    // 200 ticks: the hand gives way at 0.1 m/s; every third tick a late step (lag 2) whose
    // proxy the body pushed out as far, the hand's target 5 mm behind it.
    const Eigen::Vector3d velocity(0.0, 0.0, 0.1);
    for (int tick = 1; tick <= 200; ++tick)
    {
      device.previous_target = device.target;
      device.previous_velocity = device.velocity;
      device.target += 1e-4 * Eigen::Vector3d::UnitZ();
      device.velocity = velocity;
      if (tick % 3 == 0)
      {
        step.step_target = device.previous_target;
        step.proxy_position = step.step_target + Eigen::Vector3d(0.0, 0.0, 0.005);
        step.user_force = Eigen::Vector3d(0.0, 0.0, 4.0);
        step.lag = 2;
      }
      else
      {
        ++step.lag;
      }
      ASSERT_FALSE(renderMultirate(coupling, 8, device, step, &state, &hold));
      given[on] += state.force.dot(device.target - device.previous_target);
    }
    lowest[on] = hold.lowestEnergy();
  }
  std::printf(
      "[ measured ] a late body pushing the finger out, 200 ticks: energy to the hand %.4g J without the hold's "
      "controller (observer's lowest %.4g J), %.4g J with it (lowest %.4g J); the spring stored %.4g J\n",
      given[0], lowest[0], given[1], lowest[1], 0.5 * 16.0 / 800.0);
  EXPECT_LT(lowest[0], -0.01);  // without: the observer sees the hold make energy
  EXPECT_GE(lowest[1], -1e-12);
  EXPECT_LE(given[1], 0.5 * 16.0 / 800.0 + 1e-12);  // the hand put nothing in: it gets what was stored
  EXPECT_GT(given[0], 2.0 * given[1]);
}
// The force a step holds for a position (heldForce), as the physics node's port counts it and
// the haptic node's local coupling settles to: the coupling's spring and damper to the step's
// proxy where the position presses into one of its planes, nothing elsewhere (free space is
// free); the step read whole from the world's interface state (multirateStepOf).
TEST(HeldForce, TheSpringToTheProxyBehindAPlaneAndNothingInFreeSpace)
{
  InterfaceState state;
  state.proxy_position = Eigen::Vector3d(0.1, 0.0, 0.0);
  state.interface_position = Eigen::Vector3d(0.1, 0.0, -0.01);
  state.user_force = Eigen::Vector3d(0.0, 0.0, 4.0);
  state.contact_count = 1;
  state.contacts[0].normal = Eigen::Vector3d::UnitZ();  // a table's top under the proxy
  const MultirateStep step = multirateStepOf(state, 1);
  EXPECT_EQ(step.proxy_position, state.proxy_position);
  EXPECT_EQ(step.step_target, state.interface_position);
  EXPECT_EQ(step.user_force, state.user_force);
  EXPECT_EQ(step.lag, 1);
  ASSERT_EQ(step.plane_count, 1);
  EXPECT_EQ(step.plane_normals[0], Eigen::Vector3d::UnitZ());
  const CouplingProfile coupling;  // 400 N/m, 4 N s/m, 20 N
  // 5 mm into the table, still: 2 N up; pressing on at 0.1 m/s: 0.4 N more of damping.
  EXPECT_TRUE(heldForce(coupling, step, Eigen::Vector3d(0.1, 0.0, -0.005), Eigen::Vector3d::Zero())
                  .isApprox(Eigen::Vector3d(0.0, 0.0, 2.0), 1e-12));
  EXPECT_TRUE(heldForce(coupling, step, Eigen::Vector3d(0.1, 0.0, -0.005), Eigen::Vector3d(0.0, 0.0, -0.1))
                  .isApprox(Eigen::Vector3d(0.0, 0.0, 2.4), 1e-12));
  // Above the table, or beside on its plane's free side: nothing, at any speed.
  EXPECT_EQ(heldForce(coupling, step, Eigen::Vector3d(0.1, 0.0, 0.005), Eigen::Vector3d(0.0, 0.0, -0.1)),
            Eigen::Vector3d::Zero());
  EXPECT_EQ(heldForce(coupling, step, Eigen::Vector3d(0.3, 0.2, 0.001), Eigen::Vector3d(1.0, 0.0, 0.0)),
            Eigen::Vector3d::Zero());
  // 10 cm in: the coupling's 40 N saturated at max_force.
  EXPECT_NEAR(heldForce(coupling, step, Eigen::Vector3d(0.1, 0.0, -0.1), Eigen::Vector3d::Zero()).norm(), 20.0, 1e-12);
  // No contact in the step: free space everywhere.
  state.contact_count = 0;
  EXPECT_EQ(heldForce(coupling, multirateStepOf(state, 1), Eigen::Vector3d(0.1, 0.0, -0.005), Eigen::Vector3d::Zero()),
            Eigen::Vector3d::Zero());
}
}  // namespace
}  // namespace god_finger
