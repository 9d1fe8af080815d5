// The finger pad's torques against soft-finger physics (scenarios/pad_fidelity.h): a flat box
// pressed by one finger with N, turned about the normal (twist) or a tangent (tilt). A layout's
// capacity is the largest torque it holds (< 1 mrad in 1 s); each layout that resists holds
// 90 % of its capacity for 3 s and slips at 110 %.
//
// Measured (this test prints them; mu = 0.8, a from Eq. 1 at N = 0.5 / 2 / 5 N), see the README's
// "Pad fidelity": god_object resists neither twist nor tilt; soft_finger the twist its
// configured spinning friction gives and the tilt its configured lever gives; god_finger with the points layout about the
// ring's (8/9) mu N a (0.78-0.85 of it held, creep above 70 %) and an elastic tilt (0.13-0.75
// N a within 1 mrad); with the pad constraint the uniform disk's (2/3) mu N a (1.00) and N a
// (1.00-1.05), held at 90 % without a turn and slipping at 110 %.
#include "god_finger/scenarios/pad_fidelity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace god_finger
{
namespace
{
// kPadLayouts: god_object, soft_finger, god_finger (pad constraint), god_finger/points.
constexpr const PadLayout& kPoints = kPadLayouts[3];
constexpr double kForces[] = {0.5, 2.0, 5.0};

PadLoadSetup setupFor(const PadLayout& layout, PadLoad load, double normal_force)
{
  PadLoadSetup setup;
  setup.load = load;
  setup.model = layout.model;
  setup.params.pad_solver = layout.pad_solver;
  setup.normal_force = normal_force;
  return setup;
}

struct Capacity
{
  PadLoadMeasurement pressed;  // a, N
  double torque = 0.0;         // N m
};

// Bisection up to twice the largest capacity any pad of r_max could have.
Capacity capacityOf(const PadLoadSetup& setup)
{
  const double r_max = setup.params.contact.max_radius;
  const double upper = 2.0 * setup.normal_force * r_max * (setup.load == PadLoad::kTwist ? setup.friction : 1.0);
  return {measurePadHold(setup, 0.0, 0.01), measurePadCapacity(setup, upper)};
}

// Holds 90 % of the capacity for 3 s without a measurable turn, slips at 110 %.
void expectHoldsBelowAndSlipsAbove(const PadLoadSetup& setup, const char* name, double capacity)
{
  const PadLoadMeasurement below = measurePadHold(setup, 0.9 * capacity, 3.0);
  const PadLoadMeasurement above = measurePadHold(setup, 1.1 * capacity, 3.0);
  std::printf("[ %s N %.1f %-21s ] 90 %% of %.5f N m turns %.3g rad in 3 s, 110 %% %.3g rad\n",
              setup.load == PadLoad::kTwist ? "twist" : "tilt", setup.normal_force, name, capacity, below.rotation,
              above.rotation);
  EXPECT_LT(std::abs(below.rotation), 1e-3);
  EXPECT_GT(std::abs(above.rotation), 1e-2);
}

TEST(PadFidelity, EachLayoutHoldsTheTwistItsContactCarries)
{
  for (const double normal_force : kForces)
  {
    for (const PadLayout& layout : kPadLayouts)
    {
      SCOPED_TRACE(std::string(layout.name) + " at " + std::to_string(normal_force) + " N");
      const PadLoadSetup setup = setupFor(layout, PadLoad::kTwist, normal_force);
      const Capacity c = capacityOf(setup);
      const double n = setup.params.contact.sub_god_objects;
      const double mu_n_a = setup.friction * c.pressed.normal_force * c.pressed.contact_radius;
      const double ring = n / (n + 1.0) * mu_n_a;
      const double uniform = uniformPadTorque(setup.friction, c.pressed.normal_force, c.pressed.contact_radius);
      std::printf(
          "[ twist N %.1f %-21s ] a %.4f m, holds %.5f N m = %.2f x ring, %.2f x uniform disk, "
          "%.2f x Hertz\n",
          normal_force, layout.name, c.pressed.contact_radius, c.torque, c.torque / ring, c.torque / uniform,
          c.torque / hertzPadTorque(setup.friction, c.pressed.normal_force, c.pressed.contact_radius));
      EXPECT_NEAR(c.pressed.normal_force, normal_force, 0.1 * normal_force);
      if (layout.model == ContactModel::kGodObject)
      {
        EXPECT_LT(c.torque, 0.01 * ring);
      }
      else if (layout.model == ContactModel::kSoftFinger)
      {
        // Bullet multiplies the proxy's spinning friction by the object's friction.
        const double configured = setup.params.soft_finger.spinning_friction * setup.friction * c.pressed.normal_force;
        EXPECT_NEAR(c.torque / configured, 1.0, 0.1);
        expectHoldsBelowAndSlipsAbove(setup, layout.name, c.torque);
      }
      else if (layout.pad_solver == PadSolver::kPoints)
      {
        EXPECT_GT(c.torque, 0.6 * ring);
        EXPECT_LT(c.torque, 1.15 * ring);
      }
      else
      {
        EXPECT_NEAR(c.torque / uniform, 1.0, 0.15);
        expectHoldsBelowAndSlipsAbove(setup, layout.name, c.torque);
      }
    }
  }
}

TEST(PadFidelity, ThePointsLayoutHoldsATwistOf70PercentOfTheRingsCapacity)
{
  // Before the friction anchors, 17 % of the ring's capacity turned the box 35 mrad in 3 s,
  // linearly in time and torque; with anchors but the points visited around the ring, 50 %
  // still turned it 58-89 mrad. Above 70 % it still creeps (known gap).
  for (const double normal_force : kForces)
  {
    const PadLoadSetup setup = setupFor(kPoints, PadLoad::kTwist, normal_force);
    const PadLoadMeasurement pressed = measurePadHold(setup, 0.0, 0.01);
    const double n = setup.params.contact.sub_god_objects;
    const double ring = n / (n + 1.0) * setup.friction * pressed.normal_force * pressed.contact_radius;
    for (const double fraction : {0.17, 0.5, 0.7})
    {
      const PadLoadMeasurement hold = measurePadHold(setup, fraction * ring, 3.0);
      std::printf("[ twist N %.1f god_finger/points hold %.0f %% of the ring ] turned %.3g rad in 3 s\n", normal_force,
                  100 * fraction, hold.rotation);
      EXPECT_LT(std::abs(hold.rotation), 1e-3) << normal_force << " N, " << fraction;
    }
  }
}

TEST(PadFidelity, APadHoldsATiltAPointDoesNot)
{
  for (const double normal_force : kForces)
  {
    for (const PadLayout& layout : kPadLayouts)
    {
      SCOPED_TRACE(std::string(layout.name) + " at " + std::to_string(normal_force) + " N");
      const PadLoadSetup setup = setupFor(layout, PadLoad::kTilt, normal_force);
      const Capacity c = capacityOf(setup);
      const double n_a = padTiltTorque(c.pressed.normal_force, c.pressed.contact_radius);
      std::printf("[ tilt N %.1f %-21s ] a %.4f m, holds %.5f N m = %.2f x N a\n", normal_force, layout.name,
                  c.pressed.contact_radius, c.torque, c.torque / n_a);
      EXPECT_NEAR(c.pressed.normal_force, normal_force, 0.1 * normal_force);
      if (layout.model == ContactModel::kGodObject)
      {
        EXPECT_LT(c.torque, 0.05 * n_a);
      }
      else if (layout.model == ContactModel::kSoftFinger)
      {
        // The pad's lever, not multiplied by mu (finger_contact_friction.h).
        const double configured = setup.params.soft_finger.rolling_friction * c.pressed.normal_force;
        EXPECT_NEAR(c.torque / configured, 1.0, 0.1);
        expectHoldsBelowAndSlipsAbove(setup, layout.name, c.torque);
      }
      else if (layout.pad_solver == PadSolver::kPoints)
      {
        // The points' compliance (2e4 N/m each on a ring of radius a) lets the box turn
        // elastically, about 1 mrad per 8 mN m at 1 cm, before any point lets go: "held within
        // 1 mrad" reads 0.13-0.75 N a, falling with N as the torque grows.
        EXPECT_GT(c.torque, 0.1 * n_a);
        EXPECT_LT(c.torque, 1.2 * n_a);
      }
      else
      {
        EXPECT_NEAR(c.torque / n_a, 1.0, 0.15);
        expectHoldsBelowAndSlipsAbove(setup, layout.name, c.torque);
      }
    }
  }
}
}  // namespace
}  // namespace god_finger
