// How much torque a finger pad resists, measured in the world, against soft-finger physics.
//
// A pad of contact radius a under normal force N resists a torque about its normal up to
// (2/3) mu N a for uniform pressure and (3 pi / 16) mu N a for Hertzian pressure; n points on a
// ring of radius a plus the centre, each carrying N / (n + 1), resist (n / (n + 1)) mu N a.
//
// The twist set-up: a flat box (0.1 x 0.1 x 0.02 m, 0.2 kg, friction mu) lying on a frictionless
// static table, one finger pressing its centre from above with N; after 0.5 s of settling, a
// torque about the vertical grows on the box (or is held). Only the finger resists it.
// Units: SI; rotations in rad about the table's normal. Not real-time (builds a world).
#pragma once

#include "god_finger/physics/world_params.h"

namespace god_finger
{
struct TwistSetup
{
  ContactModel model = ContactModel::kGodFinger;
  double normal_force = 2.0;  // N, pressed by the coupling (target below the proxy's rest)
  double friction = 0.8;      // mu of the box (the proxy's is 1; Bullet multiplies them)
  WorldParams params;         // the world's; model and time step are taken from here too
};

struct TwistMeasurement
{
  double contact_radius = 0.0;  // a (m), the contact area's radius after settling
  double normal_force = 0.0;    // N measured on the hand after settling
  // Ramp: the torque (N m) at which the box had turned by `slip_angle`; infinite if never.
  double slip_torque = 0.0;
  // Hold: the box's turn (rad) after the hold.
  double rotation = 0.0;
};

// Analytic limits of a pad of radius `radius` (m) under `normal_force` (N), friction `mu`.
double uniformPadTorque(double mu, double normal_force, double radius);
double hertzPadTorque(double mu, double normal_force, double radius);

// Ramps the torque at `torque_rate` (N m / s) for up to `duration` (s) and reports the torque
// at which the box had turned by `slip_angle` (rad).
TwistMeasurement measureTwistSlip(const TwistSetup& setup, double torque_rate, double duration = 4.0,
                                  double slip_angle = 0.05);
// Holds `torque` (N m) for `duration` (s) and reports the box's turn.
TwistMeasurement measureTwistHold(const TwistSetup& setup, double torque, double duration);
}  // namespace god_finger
