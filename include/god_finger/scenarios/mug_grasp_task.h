// A three-finger hand lifts a mug mesh and holds it: the hand_grasp scenario's scene and hand
// (experiment.h) as a task of the operator benchmark (bench/operator_bench.cpp), by a perfect or
// a human-like hand (human_operator.h: tremor on every finger, the misalignment on the finger at
// 180 degrees, the squeeze fluctuating, the reflex squeezing harder on a slip).
//
// Scene: urdf/scenes/table_mug.urdf, the mug (urdf/meshes/mug.obj: a cup of outer radius 4 cm,
// 9 cm high, the handle on +x, 300 g, mu 0.8; a concave mesh colliding as its convex
// decomposition) standing on the table at the origin. Three fingers at 60, 180 and 300 degrees
// about z, 5 cm up, close on the wall from 7 cm off the axis; the squeeze s is the coupling
// stretch into the wall (N = k s each, k = 400 N/m by default). Script (s; every move a
// minimum-jerk profile): close in 1, wait 0.5, lift 10 cm in 2, hold until 4.5. Deterministic.
// Units SI, frames world (z up). Not real-time (loads a scene, builds a world).
#pragma once

#include "god_finger/physics/contact_model.h"
#include "god_finger/scenarios/human_operator.h"
#include "god_finger/physics/world_params.h"

#include <string>

namespace god_finger
{
constexpr double kMugLift = 0.1;           // m
constexpr double kMugTiltTolerance = 0.1;  // rad, on the largest tilt for success

struct MugGraspOptions
{
  std::string scenes_dir;  // the folder of table_mug.urdf (urdf/scenes)
  ContactModel model = ContactModel::kGodFinger;
  double squeeze = 0.01;  // m, nominal
  OperatorTraits hand = perfectOperator();
  WorldParams params;  // the world's (its pad solver too); the model above is set on it
};

struct MugGraspResult
{
  bool held = false;               // above half the lift height from the lift's end to the end
  bool lifted = false;             // held, tilting at most kMugTiltTolerance
  double lift_height_m = 0.0;      // the centre of mass's rise at the end
  double max_tilt_rad = 0.0;       // the mug's axis from vertical, from the lift's start to the end
  double max_slip_m = 0.0;         // a finger's grip point on the mug against the finger, along the wall
  double mean_grip_force_N = 0.0;  // a finger's coupling force towards the axis, mean over the fingers
                                   // from the lift's end
};

// Throws InputError on a squeeze outside (0, 0.03] m, a missing scene or bad world parameters.
MugGraspResult runMugGrasp(const MugGraspOptions& options);
}  // namespace god_finger
