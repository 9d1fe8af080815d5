// The passivity observer and controller at the device's port (haptics/passivity_controller.h),
// on simulated time: a light hand on a handle pressing a virtual wall rendered through a delayed
// link (the package's coupling, 400 N/m and 4 N s/m, against a wall), the force coming back a
// round trip after the position it answers. Without the controller the delay makes energy and
// the handle buzzes on; with it the observer's energy stays above -1e-4 J and the buzz dies.
#include "god_finger/haptics/passivity_controller.h"

#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <deque>

namespace god_finger
{
namespace
{
constexpr double kPeriod = 1e-3;  // s

struct PressResult
{
  double lowest_energy = 0.0;     // J: the observer's lowest E
  double late_amplitude = 0.0;    // m: the handle's peak-to-peak over the last second
  double peak_force = 0.0;        // N: the largest force rendered
  double settled_position = 0.0;  // m: the handle's mean over the last second (wall at 0)
  long active_ticks = 0;
};

// A worst-case passive operator (issue 29): a light handle (0.1 kg) held by a stiff, barely
// damped hand (300 N/m, 0.2 N s/m) whose rest point is 2 cm past a wall at x = 0. The physics
// renders the coupling's spring-damper (400 N/m, 4 N s/m) between the handle and a proxy that
// stops at the wall, on the position it got half a round trip late; its force comes back half a
// round trip later. 4 s of 1 kHz ticks, the controller on or off.
PressResult pressThroughDelay(double round_trip, double damping_limit)
{
  PassivityParams params;
  params.passivity_damping_limit = damping_limit;
  PassivityController controller(params, kPeriod);
  const int half = static_cast<int>(std::lround(0.5 * round_trip / kPeriod));
  std::deque<double> positions_in_flight(half, -0.01);  // the handle starts 1 cm before the wall
  std::deque<double> velocities_in_flight(half, 0.0);
  std::deque<double> forces_in_flight(half, 0.0);
  double x = -0.01;
  double v = 0.0;
  PressResult result;
  double late_low = 1e9;
  double late_high = -1e9;
  double late_sum = 0.0;
  int late_count = 0;
  const int ticks = 4000;
  for (int tick = 0; tick < ticks; ++tick)
  {
    // The physics answers the position it got (half a round trip old).
    positions_in_flight.push_back(x);
    velocities_in_flight.push_back(v);
    const double seen_x = positions_in_flight.front();
    const double seen_v = velocities_in_flight.front();
    positions_in_flight.pop_front();
    velocities_in_flight.pop_front();
    const double proxy = std::min(seen_x, 0.0);
    const double coupling = seen_x > 0.0 ? -(400.0 * (seen_x - proxy) + 4.0 * seen_v) : 0.0;
    forces_in_flight.push_back(coupling);
    const double command = forces_in_flight.front();
    forces_in_flight.pop_front();
    // The device renders the command through the controller (velocity: the last reading).
    const Eigen::Vector3d rendered =
        controller.apply(Eigen::Vector3d(command, 0.0, 0.0), Eigen::Vector3d(v, 0.0, 0.0), 20.0);
    result.peak_force = std::max(result.peak_force, std::abs(rendered.x()));
    const double hand = 300.0 * (0.02 - x) - 0.2 * v;
    v += kPeriod * (hand + rendered.x()) / 0.1;
    x += kPeriod * v;
    if (tick >= ticks - 1000)
    {
      late_low = std::min(late_low, x);
      late_high = std::max(late_high, x);
      late_sum += x;
      ++late_count;
    }
  }
  result.lowest_energy = controller.lowestEnergy();
  result.late_amplitude = late_high - late_low;
  result.settled_position = late_sum / late_count;
  result.active_ticks = controller.activeTicks();
  return result;
}

TEST(PassivityController, ADelayedWallBuzzesWithoutItAndSettlesPassiveWithIt)
{
  for (const double round_trip : {0.01, 0.03, 0.06, 0.1})
  {
    const PressResult off = pressThroughDelay(round_trip, 0.0);
    const PressResult on = pressThroughDelay(round_trip, PassivityParams().passivity_damping_limit);
    std::printf(
        "[ measured ] round trip %3.0f ms: off: lowest energy %+.4f J, late peak-to-peak %.2f mm, peak force %.2f N; "
        "on: %+.6f J, %.3f mm, %.2f N, rests %.2f mm into the wall (%ld ticks damped)\n",
        1e3 * round_trip, off.lowest_energy, 1e3 * off.late_amplitude, off.peak_force, on.lowest_energy,
        1e3 * on.late_amplitude, on.peak_force, 1e3 * on.settled_position, on.active_ticks);
    // Off: the delay makes energy (the observer sees it) and the handle keeps buzzing.
    EXPECT_LT(off.lowest_energy, -1.0) << round_trip;
    EXPECT_GT(off.late_amplitude, 0.1) << round_trip;
    // On: the buzz dies, and the hand rests on the wall (the coupling's equilibrium with the
    // hand: 300 (0.02 - x) = 400 x, x = 8.57 mm). Passive at every round trip: where the first
    // contact asks more damping than the 50 N s/m limit (at 100 ms it went to -0.070 J with the
    // damper alone), the push along the motion is cut.
    EXPECT_LT(on.late_amplitude, 1e-5) << round_trip;
    EXPECT_NEAR(on.settled_position, 0.02 * 300.0 / 700.0, 1e-4) << round_trip;
    EXPECT_GE(on.lowest_energy, -1e-4) << round_trip;
    EXPECT_GT(on.active_ticks, 0) << round_trip;
  }
}

TEST(PassivityController, APassiveLoopIsLeftAlone)
{
  // No delay: the coupling's damper keeps the loop passive; the controller never acts.
  const PressResult none = pressThroughDelay(0.0, PassivityParams().passivity_damping_limit);
  const PressResult off = pressThroughDelay(0.0, 0.0);
  EXPECT_EQ(none.active_ticks, 0);
  EXPECT_EQ(none.late_amplitude, off.late_amplitude);
  EXPECT_EQ(none.peak_force, off.peak_force);
}

TEST(PassivityController, TheDampingIsTheLeastThatRestoresTheEnergyIsCappedAndThePushIsCutBeyondIt)
{
  PassivityParams params;
  params.passivity_damping_limit = 10.0;
  params.passivity_min_damping = 0.0;
  params.passivity_reservoir = 1e-3;
  PassivityController controller(params, kPeriod);
  // The network gives 1 N along a motion of 0.1 m/s: -1e-4 J in one tick, made up.
  Eigen::Vector3d out = controller.apply(Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.1, 0.0, 0.0), 20.0);
  // alpha = 1e-4 / (0.01 * 1e-3) = 10 N s/m: exactly the limit; the force becomes 1 - 10 * 0.1 = 0.
  EXPECT_NEAR(controller.damping(), 10.0, 1e-12);
  EXPECT_NEAR(out.x(), 0.0, 1e-12);
  EXPECT_NEAR(controller.energy(), 0.0, 1e-15);
  // Twice the speed asks 2e-4 J / (0.04 * 1e-3) = 5 N s/m: below the limit; E back to exactly 0.
  out = controller.apply(Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.2, 0.0, 0.0), 20.0);
  EXPECT_NEAR(controller.damping(), 5.0, 1e-9);
  EXPECT_NEAR(controller.energy(), 0.0, 1e-15);
  // The hand pushes against the force: 5e-4 J in a tick; the bank fills to passivity_reservoir,
  // the observer's energy by all that came in.
  for (int i = 0; i < 3; ++i)
  {
    out = controller.apply(Eigen::Vector3d(-5.0, 0.0, 0.0), Eigen::Vector3d(0.1, 0.0, 0.0), 100.0);
    EXPECT_EQ(controller.damping(), 0.0);
  }
  EXPECT_NEAR(controller.energy(), 1.5e-3, 1e-15);
  EXPECT_EQ(controller.bank(), 1e-3);
  // The network gives 20 N along 0.1 m/s (2e-3 J, 1e-3 J beyond the bank): 100 N s/m asked,
  // capped at 10 (19 N, 1.9e-3 J). That would take the observer's energy 4e-4 J below zero, so
  // 4 N more of the push along the motion is taken away: 15 N, the energy exactly 0, and the
  // bank in a debt of 5e-4 J (what it let out beyond what it held).
  out = controller.apply(Eigen::Vector3d(20.0, 0.0, 0.0), Eigen::Vector3d(0.1, 0.0, 0.0), 100.0);
  EXPECT_EQ(controller.damping(), 10.0);
  EXPECT_NEAR(controller.cut(), 4.0, 1e-12);
  EXPECT_NEAR(out.x(), 15.0, 1e-12);
  EXPECT_NEAR(controller.energy(), 0.0, 1e-15);
  EXPECT_NEAR(controller.bank(), -5e-4, 1e-15);
  // No force (the hand moved off the wall), slowly: the debt is still paid by the damper (10 N
  // s/m at 0.03 m/s takes 9e-6 J a tick); a damper never pushes, so nothing is cut.
  out = controller.apply(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.03, 0.0, 0.0), 20.0);
  EXPECT_EQ(controller.damping(), 10.0);
  EXPECT_EQ(controller.cut(), 0.0);
  EXPECT_NEAR(out.x(), -0.3, 1e-12);
  EXPECT_NEAR(controller.bank(), -5e-4 + 9e-6, 1e-15);
  EXPECT_NEAR(controller.energy(), 9e-6, 1e-15);
  // A push along the motion with the bank in debt and the observer's energy at 9e-6 J: the damper
  // capped (-1 N), and the rest of the push cut to what the energy holds (9e-6 J: 0.09 N).
  out = controller.apply(Eigen::Vector3d(5.0, 0.0, 0.0), Eigen::Vector3d(0.1, 0.0, 0.0), 100.0);
  EXPECT_EQ(controller.damping(), 10.0);
  EXPECT_NEAR(out.x(), 0.09, 1e-12);
  EXPECT_NEAR(controller.energy(), 0.0, 1e-15);
  EXPECT_GE(controller.energy(), 0.0);
}

TEST(PassivityController, WhilePushingTheLoopMustDissipateAsTheLeastDamperWouldAndFreeMotionIsFree)
{
  PassivityParams params;  // b_min 4 N s/m
  PassivityController controller(params, kPeriod);
  // No force (free motion): nothing asked, nothing done, whatever the speed.
  for (int i = 0; i < 100; ++i)
  {
    EXPECT_EQ(controller.apply(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.5, 0.0, 0.0), 20.0).x(), 0.0);
  }
  EXPECT_EQ(controller.activeTicks(), 0);
  EXPECT_EQ(controller.energy(), 0.0);
  // A force across the motion (no power) while moving at 0.2 m/s: the controller adds exactly b_min.
  const Eigen::Vector3d out = controller.apply(Eigen::Vector3d(0.0, 1.0, 0.0), Eigen::Vector3d(0.2, 0.0, 0.0), 20.0);
  EXPECT_NEAR(controller.damping(), 4.0, 1e-12);
  EXPECT_NEAR(out.x(), -0.8, 1e-12);
  EXPECT_NEAR(controller.bank(), 0.0, 1e-15);                 // what b_min asked was taken out
  EXPECT_NEAR(controller.energy(), 0.8 * 0.2 * 1e-3, 1e-15);  // by the damper, from the hand
}

// Started from stored energy (a stretched spring the loop behind the port already holds, the
// multi-rate hold's start): a push along the motion is let through until the hand has had that
// much, then cut; the observer never goes below zero.
TEST(PassivityController, StartedFromStoredEnergyGivesBackNoMoreThanThat)
{
  PassivityParams params;
  params.passivity_min_damping = 0.0;
  PassivityController controller(params, 1e-3);
  controller.reset(0.002);  // J
  EXPECT_EQ(controller.energy(), 0.002);
  EXPECT_EQ(controller.bank(), 0.002);
  const Eigen::Vector3d velocity(0.0, 0.0, 0.1);  // m/s: the hand moving along the push
  double given = 0.0;                             // J
  int whole = 0;                                  // ticks the 4 N push went through unchanged
  for (int tick = 0; tick < 100; ++tick)
  {
    const Eigen::Vector3d rendered = controller.apply(Eigen::Vector3d(0.0, 0.0, 4.0), velocity, 10.0);
    given += rendered.dot(velocity) * 1e-3;
    whole += rendered.z() == 4.0 ? 1 : 0;
  }
  EXPECT_EQ(whole, 5);  // 4 N x 0.1 mm a tick = 0.4 mJ: five ticks of the 2 mJ stored
  EXPECT_NEAR(given, 0.002, 1e-12);
  EXPECT_GE(controller.lowestEnergy(), -1e-15);
  controller.reset(-1.0);  // nothing stored: as reset()
  EXPECT_EQ(controller.energy(), 0.0);
  EXPECT_EQ(controller.bank(), 0.0);
}

TEST(PassivityController, RefusesBadParameters)
{
  PassivityParams params;
  params.passivity_damping_limit = -1.0;
  EXPECT_THROW(PassivityController(params, kPeriod), InputError);
  params = PassivityParams();
  params.passivity_reservoir = NAN;
  EXPECT_THROW(PassivityController(params, kPeriod), InputError);
  params = PassivityParams();
  params.passivity_min_damping = -0.5;
  EXPECT_THROW(PassivityController(params, kPeriod), InputError);
  EXPECT_THROW(PassivityController(PassivityParams(), 0.0), InputError);
  try
  {
    params = PassivityParams();
    params.passivity_damping_limit = 2000.0;
    PassivityController controller(params, kPeriod);
    FAIL();
  }
  catch (const InputError& error)
  {
    EXPECT_NE(std::string(error.what()).find("passivity_damping_limit"), std::string::npos) << error.what();
  }
}
}  // namespace
}  // namespace god_finger
