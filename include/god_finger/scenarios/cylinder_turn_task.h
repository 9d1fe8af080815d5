// Pinch and turn a cylinder 90 degrees: two fingers pinch a standing cylinder across its
// mantle, lift it and turn it about its own (vertical) axis by moving in opposite tangential
// directions, as a hand turns a knob or a jar: each finger's target goes a quarter circle about
// the axis. A task of the operator benchmark (bench/operator_bench.cpp) by a perfect or a
// human-like hand (human_operator.h: tremor on both fingers, the second finger's misalignment
// turning with the hand, the squeeze fluctuating, the reflex squeezing harder on a slip).
//
// Scene (cylinderTurnScene): a static table (top at z = 0) and a solid cylinder of radius 3 cm,
// 12 cm long, 150 g, mu 0.8, standing on it (axis z, centre at (0, 0, 0.06)). The fingers close
// along y at the centre's height; the squeeze s is the coupling stretch into the mantle
// (N = k s, k = 400 N/m by default). Script (s; every move a minimum-jerk profile): close in 1,
// wait 0.5, lift 5 cm in 1, turn the fingers 90 degrees about the axis (counter-clockwise seen
// from above) in 2, hold until 5.5. With the fingers stuck on the mantle the cylinder turns 90
// degrees with them (a point contact, a ball that does not turn, rolls on the mantle: the
// cylinder turns kTurnAngle (r + proxy radius) / r); a slip turns it less, and a point contact lets
// it swing about the pinch line. The fingers are 3-DOF unless `oriented`: they keep their
// orientation, so the mantle rolls under each pad, and a pad that resists a tilt (god_finger's tilt rows, up to N a,
// and its centre of pressure shifted against the pull: N a_eff) resists the turn. What turns it
// is the hand's pull, not friction: the target circles at R - s from the axis (R = r + proxy
// radius), so a pad stuck on the mantle, lagging its target by `lag`, is pulled along it with
// k (R - s) sin(lag) <= k (R - s); the turn stops where k (R - s) sin(lag) r = N a_eff. A harder
// squeeze raises N and shortens R - s: the harder, the less it turns (god_finger at 20 mm:
// a_eff 12 mm, far under mu r = 24 mm; cylinder_turn_test). Oriented fingers turn with the hand:
// their pads turn with them (pad_state.h), and nothing resists the turn but the cylinder's inertia.
// Deterministic: the same options give the same result, bit for bit. Units SI, frames world
// (z up). Not real-time (builds a world).
#pragma once

#include "god_finger/physics/contact_model.h"
#include "god_finger/physics/world_params.h"
#include "god_finger/scenarios/human_operator.h"
#include "god_finger/scene/scene_description.h"

namespace god_finger
{
constexpr double kTurnCylinderRadius = 0.03;  // m
constexpr double kTurnCylinderLength = 0.12;  // m, along the axis (z)
constexpr double kTurnCylinderMass = 0.15;    // kg
constexpr double kTurnCylinderFriction = 0.8;
constexpr double kTurnLift = 0.05;                 // m
constexpr double kTurnAngle = 1.5707963267948966;  // rad, about +z
constexpr double kTurnTolerance = 0.2;             // rad, on the final turn for success
constexpr double kTurnTiltTolerance = 0.1;         // rad, on the final tilt for success

SceneDescription cylinderTurnScene();

struct CylinderTurnOptions
{
  ContactModel model = ContactModel::kGodFinger;
  double squeeze = 0.01;  // m, nominal
  OperatorTraits hand = perfectOperator();
  WorldParams params;  // the world's (its pad solver too); the model above is set on it
  // Oriented (6-DOF) fingers (physics/oriented_finger.h): each finger's pulp faces the axis, its
  // tip points down, and the hand turns it about z with its target (a hand turning a knob).
  // False: 3-DOF fingers that keep their orientation.
  bool oriented = false;
};

struct CylinderTurnResult
{
  bool held = false;               // above half the lift height from the lift's end to the end
  bool turned = false;             // held, the final turn within kTurnTolerance of kTurnAngle, the
                                   // final tilt within kTurnTiltTolerance
  double turn_rad = 0.0;           // about the cylinder's axis (signed, + counter-clockwise), at the end:
                                   // the heading of its x axis, unwrapped (no turn once it has tipped over)
  double final_tilt_rad = 0.0;     // the axis's angle from vertical at the end
  double max_tilt_rad = 0.0;       // the same, largest from the lift's start to the end
  double max_slip_m = 0.0;         // a finger's sliding on the mantle (m, its path against the surface
                                   // under it, from the lift's start; rolling is none), the larger one
  double mean_grip_force_N = 0.0;  // the fingers' coupling force towards the axis, mean from the lift's end
};

// Throws InputError on a squeeze outside (0, 0.05] m or bad world parameters.
CylinderTurnResult runCylinderTurn(const CylinderTurnOptions& options);
}  // namespace god_finger
