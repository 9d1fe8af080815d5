// The finger pad's torque about its normal against soft-finger physics (physics/pad_fidelity.h):
// a flat box on a frictionless table, pressed by one finger with N, turned by a torque.
//
// Measured (this test prints them; mu = 0.8, a from Eq. 1 at N): a point contact (god_object)
// and Bullet's spinning friction (soft_finger) resist almost nothing (the turn a slow ramp needs
// is the box's inertia: 3-18 % of the ring's capacity); the god-finger's ring of 8 points plus
// the centre resists 87-109 % of the ring's (8/9) mu N a over a 12 s ramp, and holds a twist of
// 70 % of it still (< 0.5 mrad in 3 s). Known gap: at 80-90 % it creeps (0.02-0.28 rad in 3 s).
#include "god_finger/physics/pad_fidelity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace god_finger
{
namespace
{
// The ring model's capacity: n points on a ring of radius a plus the centre, equal loads.
double ringTorque(const TwistSetup& setup, const TwistMeasurement& m)
{
  const int n = setup.params.contact.sub_god_objects;
  return static_cast<double>(n) / (n + 1) * setup.friction * m.normal_force * m.contact_radius;
}

TwistMeasurement slowRamp(ContactModel model, double normal_force, TwistSetup* setup)
{
  setup->model = model;
  setup->normal_force = normal_force;
  // 10 % of mu N r_max per second: slow enough that the box's inertia shows as a few per cent.
  const double rate = 0.1 * setup->friction * normal_force * setup->params.contact.max_radius;
  return measureTwistSlip(*setup, rate, 12.0);
}

TEST(PadFidelity, OnlyTheGodFingerResistsATwist)
{
  for (const double normal_force : {0.5, 2.0, 5.0})
  {
    SCOPED_TRACE(normal_force);
    for (const ContactModel model : {ContactModel::kGodObject, ContactModel::kSoftFinger, ContactModel::kGodFinger})
    {
      TwistSetup setup;
      const TwistMeasurement m = slowRamp(model, normal_force, &setup);
      const double ring = ringTorque(setup, m);
      std::printf("[ twist N %.1f %-11s ] a %.4f m, slips at %.5f N m = %.2f x ring, %.2f x uniform disk\n",
                  normal_force, contactModelName(model), m.contact_radius, m.slip_torque, m.slip_torque / ring,
                  m.slip_torque / uniformPadTorque(setup.friction, m.normal_force, m.contact_radius));
      EXPECT_NEAR(m.normal_force, normal_force, 0.1 * normal_force);
      if (model == ContactModel::kGodFinger)
      {
        EXPECT_GT(m.slip_torque, 0.8 * ring);
        EXPECT_LT(m.slip_torque, 1.15 * ring);
      }
      else
      {
        EXPECT_LT(m.slip_torque, 0.2 * ring);
      }
    }
  }
}

TEST(PadFidelity, AGodFingerHoldsATwistUpTo70PercentOfItsCapacityWithoutCreep)
{
  // Before the friction anchors, 17 % of the ring's capacity turned the box 35 mrad in 3 s,
  // linearly in time and torque; with anchors but the points visited around the ring, 50 %
  // still turned it 58-89 mrad.
  for (const double normal_force : {0.5, 2.0, 5.0})
  {
    TwistSetup setup;
    setup.normal_force = normal_force;
    const TwistMeasurement pressed = measureTwistHold(setup, 0.0, 0.01);
    const double ring = ringTorque(setup, pressed);
    for (const double fraction : {0.17, 0.5, 0.7})
    {
      const TwistMeasurement hold = measureTwistHold(setup, fraction * ring, 3.0);
      std::printf("[ twist N %.1f, hold %.0f %% of the ring ] turned %.3g rad in 3 s\n", normal_force, 100 * fraction,
                  hold.rotation);
      EXPECT_LT(std::abs(hold.rotation), 1e-3) << normal_force << " N, " << fraction;
    }
  }
}

}  // namespace
}  // namespace god_finger
