// How much torque a finger pad resists, measured in the world, against soft-finger physics.
//
// A pad of contact radius a under normal force N resists a torque about its normal up to
// (2/3) mu N a for uniform pressure and (3 pi / 16) mu N a for Hertzian pressure; n points on a
// ring of radius a plus the centre, each carrying N / (n + 1), resist (n / (n + 1)) mu N a. It
// resists a torque about a tangent (tilt) while the centre of pressure stays inside the area:
// up to N a for either pressure.
//
// The set-up: a flat box (0.1 x 0.1 x 0.02 m, 0.2 kg, friction mu), one finger pressing its
// centre from above with N; after 0.5 s of settling, a torque is held on the box.
// Twist: the box lies on a frictionless static table and the torque is about the vertical.
// Tilt: no table and no gravity; a force N up at the box's centre holds it against the finger
// and the torque is about a horizontal axis (x). Only the finger resists either.
// Units: SI; rotations in rad about the torque's axis. Not real-time (builds a world).
#pragma once

#include "god_finger/scene/scene_description.h"
#include "god_finger/physics/world_params.h"

namespace god_finger
{
enum class PadLoad
{
  kTwist,  // torque about the contact normal
  kTilt,   // torque about a tangent
};

// The contact layouts the fidelity set-ups compare, in the report's order: a point, Bullet's
// soft finger, the god-finger with its default pad solver (the pad constraint) and with the
// paper's points.
struct PadLayout
{
  const char* name;
  ContactModel model;
  PadSolver pad_solver;
};
inline constexpr PadLayout kPadLayouts[] = {
    {"god_object", ContactModel::kGodObject, PadSolver::kConstraint},
    {"soft_finger", ContactModel::kSoftFinger, PadSolver::kConstraint},
    {"god_finger", ContactModel::kGodFinger, PadSolver::kConstraint},
    {"god_finger/points", ContactModel::kGodFinger, PadSolver::kPoints},
};

// The set-up's scene: the box (and, for a twist, the frictionless table under it); the box's
// friction is `friction`.
SceneDescription padLoadScene(PadLoad load, double friction);

struct PadLoadSetup
{
  PadLoad load = PadLoad::kTwist;
  ContactModel model = ContactModel::kGodFinger;
  double normal_force = 2.0;  // N, pressed by the coupling (target below the proxy's rest)
  double friction = 0.8;      // mu of the box (the proxy's is 1; Bullet multiplies them)
  // The world's (time step, pad solver, coupling, ...), except its model, which is `model`, and,
  // for a tilt, its gravity, which is zero.
  WorldParams params;
};

struct PadLoadMeasurement
{
  double contact_radius = 0.0;  // a (m), the contact area's radius after settling
  double normal_force = 0.0;    // N measured on the hand after settling
  double rotation = 0.0;        // the box's turn (rad) at the end of the hold
};

// Analytic limits of a pad of radius `radius` (m) under `normal_force` (N), friction `mu`.
double uniformPadTorque(double mu, double normal_force, double radius);
double hertzPadTorque(double mu, double normal_force, double radius);
double padTiltTorque(double normal_force, double radius);  // N a, either pressure

// Holds `torque` (N m) for `duration` (s) and reports the box's turn.
PadLoadMeasurement measurePadHold(const PadLoadSetup& setup, double torque, double duration);
// The pad's static capacity (N m): the largest torque that, held for `duration` (s), turns the
// box less than `tolerance` (rad); bisection over [0, upper] (N m), `bisections` times. (A
// slow ramp read 5-16 % higher: once it slips, the box needs time to turn a visible angle.)
double measurePadCapacity(const PadLoadSetup& setup, double upper, double duration = 1.0, double tolerance = 1e-3,
                          int bisections = 10);
}  // namespace god_finger
