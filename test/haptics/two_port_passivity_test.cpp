// The two-port passivity observer and controllers (haptics/two_port_passivity.h), tick by tick:
// the energy split by direction, packets that arrive late or never, the device side's damper
// against the physics' returned energy, the physics side's drift out of a contact and its return.
#include "god_finger/haptics/two_port_passivity.h"

#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace god_finger
{
namespace
{
constexpr double kPeriod = 1e-3;  // s

TEST(TwoPortPassivity, TheObserverCountsEachDirectionApartAndNeverDecreases)
{
  PortEnergyObserver observer;
  for (int i = 0; i < 500; ++i)
  {
    observer.observe(2.0, kPeriod);  // 2 W into the channel for 0.5 s
  }
  for (int i = 0; i < 250; ++i)
  {
    observer.observe(-1.0, kPeriod);  // 1 W out for 0.25 s
  }
  observer.observe(std::numeric_limits<double>::quiet_NaN(), kPeriod);
  EXPECT_NEAR(observer.in(), 1.0, 1e-12);
  EXPECT_NEAR(observer.out(), 0.25, 1e-12);
}

TEST(TwoPortPassivity, ALateOrLostPacketLeavesTheNewestLargestFigure)
{
  RemoteEnergy remote;
  EXPECT_EQ(remote.energyIn(), 0.0);
  remote.receive({0.002, 0.3});
  remote.receive({0.001, 0.1});  // sent earlier, arrived later: it says less, and changes nothing
  EXPECT_EQ(remote.energyIn(), 0.3);
  EXPECT_EQ(remote.stamp(), 0.002);
  remote.receive({0.003, std::numeric_limits<double>::infinity()});
  EXPECT_EQ(remote.energyIn(), 0.3);
  remote.receive({0.004, 0.5});
  EXPECT_EQ(remote.energyIn(), 0.5);
}

TEST(TwoPortPassivity, AnObservedPortCountsWorkAndTakesANewSessionsFigureInsteadOfTheOldLarger)
{
  ObservedPort port;
  port.observeWork(0.02);   // J into the channel
  port.observeWork(-0.05);  // out
  port.observeWork(std::numeric_limits<double>::quiet_NaN());
  EXPECT_NEAR(port.observer().in(), 0.02, 1e-15);
  EXPECT_NEAR(port.observer().out(), 0.05, 1e-15);
  EXPECT_NEAR(port.lowestMargin(), -0.05, 1e-15);  // nothing received yet
  port.receive({1.0, 0.08}, 100.0);
  port.receive({0.9, 0.06}, 100.0);  // late: changes nothing
  EXPECT_NEAR(port.margin(), 0.03, 1e-15);
  port.receive({0.1, 0.01}, 200.0);  // the other side started again: its new count, not the old 0.08
  EXPECT_EQ(port.remote().energyIn(), 0.01);
  EXPECT_NEAR(port.margin(), -0.04, 1e-15);
  EXPECT_EQ(port.packets(), 3);
  port.reset();
  EXPECT_EQ(port.observer().out(), 0.0);
  EXPECT_EQ(port.remote().energyIn(), 0.0);
  EXPECT_EQ(port.packets(), 0);
}

TEST(TwoPortPassivity, TheDeviceLetsOutNoMoreThanThePhysicsGaveBack)
{
  PassivityParams params;
  DevicePortPassivity device(params, kPeriod);
  // The handle moves at 0.1 m/s along a 5 N push: 0.5 W would leave the channel for the hand.
  const Eigen::Vector3d push(5.0, 0.0, 0.0);
  const Eigen::Vector3d velocity(0.1, 0.0, 0.0);
  // Nothing given back yet: the damper (0.5 W / 0.01 = 50 N s/m, at the cap) takes it all.
  const Eigen::Vector3d rendered = device.apply(push, velocity, 20.0);
  EXPECT_NEAR(rendered.x(), 0.0, 1e-12);
  EXPECT_NEAR(device.damping(), 50.0, 1e-9);
  EXPECT_EQ(device.observer().out(), 0.0);
  EXPECT_GE(device.margin(), 0.0);
  // The physics gave back 0.2 mJ: 0.4 ticks' worth passes, the rest is damped.
  device.remote().receive({0.001, 2e-4});
  const Eigen::Vector3d partly = device.apply(push, velocity, 20.0);
  EXPECT_NEAR(device.observer().out(), 2e-4, 1e-12);
  EXPECT_NEAR(partly.x(), 2.0, 1e-9);  // 2 N x 0.1 m/s x 1 ms = 0.2 mJ
  EXPECT_NEAR(device.margin(), 0.0, 1e-15);
  // Plenty given back: the force passes untouched; a force against the motion is never touched.
  device.remote().receive({0.002, 1.0});
  EXPECT_EQ(device.apply(push, velocity, 20.0), push);
  EXPECT_EQ(device.apply(-push, velocity, 20.0), -push);
  EXPECT_EQ(device.damping(), 0.0);
  // Free motion: nothing to render, nothing added.
  EXPECT_EQ(device.apply(Eigen::Vector3d::Zero(), velocity, 20.0), Eigen::Vector3d::Zero());
}

TEST(TwoPortPassivity, BeyondTheDampersCapThePushIsCutNeverReversed)
{
  PassivityParams params;
  params.passivity_damping_limit = 10.0;
  DevicePortPassivity device(params, kPeriod);
  const Eigen::Vector3d velocity(0.1, 0.0, 0.0);
  // 10 N along the motion, nothing given back: the capped damper takes 1 N, the cut the rest.
  const Eigen::Vector3d rendered = device.apply(Eigen::Vector3d(10.0, 0.0, 0.0), velocity, 20.0);
  EXPECT_NEAR(rendered.x(), 0.0, 1e-12);
  EXPECT_GE(device.margin(), -1e-15);
  // Off (damping limit 0): the observer counts what leaves, and the margin shows the breach.
  params.passivity_damping_limit = 0.0;
  DevicePortPassivity observer_only(params, kPeriod);
  EXPECT_EQ(observer_only.apply(Eigen::Vector3d(10.0, 0.0, 0.0), velocity, 20.0).x(), 10.0);
  EXPECT_NEAR(observer_only.lowestMargin(), -1e-3, 1e-15);
}

// A spring wall at x = 0 behind the physics port (400 N/m on the hand's side past it): the force
// the physics answers the position it is given with.
Eigen::Vector3d wall(const Eigen::Vector3d& x, const Eigen::Vector3d& /*v*/)
{
  return Eigen::Vector3d(x.x() > 0.0 ? -400.0 * x.x() : 0.0, 0.0, 0.0);
}

TEST(TwoPortPassivity, ThePhysicsTakesInNoMoreThanTheDevicePutInAndTheCreditAndTheDriftReturns)
{
  PassivityParams params;
  const double credit = params.passivity_contact_credit;
  EXPECT_EQ(credit, 1e-4);
  PhysicsPortPassivity physics(params, kPeriod);
  Eigen::Vector3d used_x, used_v;
  // The hand is seen moving 1 cm into the wall over 100 ticks, while the device's packets say it
  // put in only 2 mJ (the spring would store 400 x 0.01^2 / 2 = 20 mJ).
  physics.remote().receive({0.0, 2e-3});
  for (int tick = 0; tick <= 100; ++tick)
  {
    const Eigen::Vector3d seen(-0.002 + 1.2e-4 * tick, 0.0, 0.0);
    const Eigen::Vector3d force = physics.answer(seen, Eigen::Vector3d(0.12, 0.0, 0.0), wall, &used_x, &used_v);
    EXPECT_EQ(force, wall(used_x, used_v));
    EXPECT_GE(physics.margin(), -credit);
  }
  // The spring holds what went in and the credit, counted with each tick's end force (an upper
  // bound on the spring's work): at 400 N/m, 2.1 mJ is a depth of sqrt(2 x 2.1e-3 / 400) = 3.24
  // mm, less a tick.
  const double depth = std::sqrt(2.0 * (2e-3 + credit) / 400.0);
  EXPECT_NEAR(used_x.x(), depth, 1.2e-4);
  EXPECT_LT(used_x.x(), depth);
  EXPECT_NEAR(physics.observer().out(), 2e-3 + credit, 1e-9);
  EXPECT_NEAR(physics.drift().x(), used_x.x() - 0.01, 1e-15);  // the 1 cm seen less what was used
  EXPECT_LT(physics.drift().x(), -0.006);
  const double drift = physics.drift().x();
  // The device puts in 20 mJ more: the drift returns, passivity_drift_return x 1 ms of it a tick.
  const double rate = params.passivity_drift_return;
  EXPECT_EQ(rate, 10.0);
  physics.remote().receive({0.2, 0.022});
  const Eigen::Vector3d seen(0.01, 0.0, 0.0);
  physics.answer(seen, Eigen::Vector3d::Zero(), wall, &used_x, &used_v);
  EXPECT_NEAR(physics.drift().x(), drift * (1.0 - rate * kPeriod), 1e-12);
  EXPECT_NEAR(used_v.x(), -rate * drift, 1e-9);  // (d' - d) / dt
  for (int tick = 0; tick < 1200; ++tick)        // 0.99^1200: 6e-6 of it is left
  {
    physics.answer(seen, Eigen::Vector3d::Zero(), wall, &used_x, &used_v);
  }
  EXPECT_NEAR(physics.drift().x(), 0.0, 1e-6);
  EXPECT_NEAR(used_x.x(), 0.01, 1e-6);
  EXPECT_GE(physics.margin(), 0.0);
}

// The two-port form's first contact: in free motion the device renders no force and puts no
// energy in, so without the credit the physics may let none out, the wall never pushes and the
// device never pays (measured before the credit: no force at all with no link). On the credit
// the wall takes 0.1 mJ, its force reaches the hand, and what the hand then puts in against it
// lets the contact go deeper.
TEST(TwoPortPassivity, AContactStartsOnTheCreditAndGoesOnOnWhatTheDevicePutsIn)
{
  PassivityParams params;
  const double credit = params.passivity_contact_credit;
  PhysicsPortPassivity physics(params, kPeriod);
  params.passivity_contact_credit = 0.0;
  PhysicsPortPassivity without(params, kPeriod);
  Eigen::Vector3d used_x, used_v;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (int tick = 0; tick <= 100; ++tick)  // 1 cm into the wall over 100 ticks, nothing put in
  {
    const Eigen::Vector3d seen(1e-4 * tick, 0.0, 0.0);
    force = physics.answer(seen, Eigen::Vector3d(0.1, 0.0, 0.0), wall, &used_x, &used_v);
    EXPECT_GE(physics.margin(), -credit);
    Eigen::Vector3d held_x, held_v;
    EXPECT_EQ(without.answer(seen, Eigen::Vector3d(0.1, 0.0, 0.0), wall, &held_x, &held_v).x(), 0.0);
    EXPECT_LE(held_x.x(), 0.0);  // held at the surface
  }
  EXPECT_NEAR(physics.observer().out(), credit, 1e-12);
  // Each 0.1 mm move counted with its end force, 400 x_k 0.1 mm, summing to the credit: 0.66 mm
  // (6 moves and part of the 7th), 0.264 N; between a single move's 400 x^2 = 0.1 mJ (0.5 mm)
  // and the spring's own 200 x^2 (0.71 mm).
  EXPECT_NEAR(used_x.x(), (0.24 + std::sqrt(0.24 * 0.24 + 4.0 * 400.0 * 1.6e-5)) / 800.0, 1e-9);
  EXPECT_NEAR(force.x(), -0.26422, 1e-5);
  const Eigen::Vector3d on_credit = used_x;
  EXPECT_EQ(without.observer().out(), 0.0);
  // The hand pushes 2 mm further against that force: 0.2 N x 2 mm = 0.4 mJ in, told by packet.
  // The drift returns as far as that pays: the spring takes 0.5 mJ in all (the credit stays
  // lent), 1.58 mm deep at most (counted with the end force, a little less).
  const double paid = -force.x() * 0.002;
  physics.remote().receive({0.1, paid});
  for (int tick = 0; tick < 1000; ++tick)
  {
    force = physics.answer(Eigen::Vector3d(0.01, 0, 0), Eigen::Vector3d::Zero(), wall, &used_x, &used_v);
    EXPECT_GE(physics.margin(), -credit);
  }
  EXPECT_NEAR(physics.observer().out(), paid + credit, 1e-9);
  EXPECT_LT(used_x.x(), std::sqrt(2.0 * (paid + credit) / 400.0));
  EXPECT_GT(used_x.x(), 0.95 * std::sqrt(2.0 * (paid + credit) / 400.0));
  std::printf("[ measured ] on the credit alone: %.4f N at %.4f mm; after %.2g J paid: %.4f N at %.4f mm\n",
              400.0 * on_credit.x(), 1e3 * on_credit.x(), paid, -force.x(), 1e3 * used_x.x());
}

TEST(TwoPortPassivity, AJumpDeepIntoAContactIsHeldToWhatTheDevicePutIn)
{
  // A late burst of messages: the hand seen 2 mm out, then 15 mm in at once (jitter). With 1 mJ
  // put in, the physics lets the spring take 1 mJ and the credit, no more.
  PassivityParams params;
  const double allowed = 1e-3 + params.passivity_contact_credit;
  PhysicsPortPassivity physics(params, kPeriod);
  Eigen::Vector3d used_x, used_v;
  physics.remote().receive({0.0, 1e-3});
  physics.answer(Eigen::Vector3d(-0.002, 0, 0), Eigen::Vector3d::Zero(), wall, &used_x, &used_v);
  physics.answer(Eigen::Vector3d(0.015, 0, 0), Eigen::Vector3d::Zero(), wall, &used_x, &used_v);
  EXPECT_GE(physics.margin(), -params.passivity_contact_credit);
  EXPECT_NEAR(physics.observer().out(), allowed, 1e-9);
  // The end force times the move from -2 mm: 400 x (x + 0.002) = 1.1 mJ at x = 0.92 mm.
  EXPECT_NEAR(400.0 * used_x.x() * (used_x.x() + 0.002), allowed, 1e-9);
  EXPECT_NEAR(used_x.x(), 0.5 * (std::sqrt(4e-6 + 4.0 * allowed / 400.0) - 0.002), 1e-9);
  // Off, it takes the whole jump: 400 x 0.015 x 0.017 = 102 mJ out, 101 mJ beyond what came in.
  params.passivity_damping_limit = 0.0;
  PhysicsPortPassivity off(params, kPeriod);
  off.remote().receive({0.0, 1e-3});
  off.answer(Eigen::Vector3d(-0.002, 0, 0), Eigen::Vector3d::Zero(), wall, &used_x, &used_v);
  off.answer(Eigen::Vector3d(0.015, 0, 0), Eigen::Vector3d::Zero(), wall, &used_x, &used_v);
  EXPECT_EQ(used_x.x(), 0.015);
  EXPECT_NEAR(off.lowestMargin(), 1e-3 - 0.102, 1e-12);
}

TEST(TwoPortPassivity, WithTheControllerOffThePhysicsIsGivenThePositionSeen)
{
  PassivityParams params;
  params.passivity_damping_limit = 0.0;
  PhysicsPortPassivity physics(params, kPeriod);
  Eigen::Vector3d used_x, used_v;
  for (int tick = 0; tick <= 100; ++tick)
  {
    const Eigen::Vector3d seen(1e-4 * tick, 0.0, 0.0);
    physics.answer(seen, Eigen::Vector3d(0.1, 0.0, 0.0), wall, &used_x, &used_v);
    EXPECT_EQ(used_x, seen);
    EXPECT_EQ(used_v, Eigen::Vector3d(0.1, 0.0, 0.0));
  }
  // 1 cm into the wall, the force taken at each tick's end: 400 x sum of (k 1e-4) 1e-4, k to 100.
  EXPECT_NEAR(physics.observer().out(), 400.0 * 1e-8 * 5050.0, 1e-12);
  EXPECT_LT(physics.lowestMargin(), -0.02);
}

TEST(TwoPortPassivity, ANonFinitePositionOrVelocityIsPassedOnAndForgotten)
{
  PassivityParams params;
  PhysicsPortPassivity physics(params, kPeriod);
  Eigen::Vector3d used_x, used_v;
  physics.remote().receive({0.0, 1e-3});
  physics.answer(Eigen::Vector3d(-0.002, 0, 0), Eigen::Vector3d::Zero(), wall, &used_x, &used_v);
  physics.answer(Eigen::Vector3d::Constant(NAN), Eigen::Vector3d::Zero(), wall, &used_x, &used_v);
  EXPECT_TRUE(physics.drift().allFinite());
  EXPECT_EQ(physics.observer().out(), 0.0);
  // Then the same jump as above, a velocity NaN: held to the 1 mJ, the drift finite.
  physics.answer(Eigen::Vector3d(0.015, 0, 0), Eigen::Vector3d::Constant(NAN), wall, &used_x, &used_v);
  EXPECT_TRUE(used_x.allFinite());
  EXPECT_TRUE(used_v.allFinite());
  EXPECT_NEAR(physics.observer().out(), 1e-3 + params.passivity_contact_credit, 1e-9);
  EXPECT_TRUE(physics.drift().allFinite());
}

// As the nodes send them: the physics port takes the device port's packets by session (the
// haptic node restarted: its new, smaller count replaces the old one, which would otherwise let
// the physics let out what the new session never put in).
TEST(TwoPortPassivity, ThePhysicsPortTakesANewSessionsFigureInsteadOfTheOldLarger)
{
  PhysicsPortPassivity physics(PassivityParams{}, kPeriod);
  physics.receive({1.0, 0.08}, 100.0);
  physics.receive({0.9, 0.06}, 100.0);  // late: changes nothing
  EXPECT_EQ(physics.remote().energyIn(), 0.08);
  physics.receive({0.1, 0.01}, 200.0);
  EXPECT_EQ(physics.remote().energyIn(), 0.01);
  EXPECT_EQ(physics.packets(), 3);
  physics.reset();
  EXPECT_EQ(physics.packets(), 0);
  EXPECT_EQ(physics.remote().energyIn(), 0.0);
}

TEST(TwoPortPassivity, BadParametersOrPeriodsAreRefused)
{
  PassivityParams params;
  params.passivity_drift_return = -1.0;
  EXPECT_THROW(PhysicsPortPassivity(params, kPeriod), InputError);
  EXPECT_THROW(DevicePortPassivity(params, kPeriod), InputError);
  EXPECT_THROW(DevicePortPassivity(PassivityParams{}, 0.0), InputError);
  EXPECT_THROW(PhysicsPortPassivity(PassivityParams{}, std::nan("")), InputError);
}
}  // namespace
}  // namespace god_finger
