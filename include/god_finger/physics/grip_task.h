// A two-finger pinch of a bar across its parallel faces, gripped off its centre: lifted and
// held, or picked and placed, by a perfect or a human-like hand (human_operator.h). The
// operator benchmark's pick and place (bench/operator_bench.cpp) and pinch_grip_test run it.
//
// Scene (gripBarScene): a static table (top at z = 0) and a bar of 0.2 x 0.03 x 0.04 m (150 g,
// mu 0.8) lying on it, centred at the origin, long axis x. The fingers close along y on the
// 3 cm faces at x = kGripOffset (3 cm off the centre, so gravity twists the bar about the pinch
// normal by m g x = 44 mN m), z = 2 cm; the squeeze s is the coupling stretch across the pinch
// (N = k s, k = 400 N/m by default). Script (s; every move a minimum-jerk profile): close in 1, wait 0.5, lift 10 cm
// in 1.5 (lift and hold: in 2, then hold until 6); pick and place: carry 15 cm along -x in 2, lower 10.2 cm in 1.5,
// wait 0.5, open in 0.5, rise 5 cm in 0.5, end at 8.5; the target is the bar's centre at (-0.15, 0, 0.02).
// Deterministic: the same options give the same result, bit for bit. Units SI, frames world (z up). Not real-time
// (builds a world).
#pragma once

#include "god_finger/physics/contact_model.h"
#include "god_finger/physics/human_operator.h"
#include "god_finger/physics/scene_description.h"
#include "god_finger/physics/world_params.h"

namespace god_finger
{
constexpr double kGripBarMass = 0.15;   // kg
constexpr double kGripOffset = 0.03;    // m, along x from the bar's centre
constexpr double kGripBarWidth = 0.03;  // m, between the pinched faces (y)
constexpr double kGripLift = 0.1;       // m
constexpr double kGripBarFriction = 0.8;

SceneDescription gripBarScene();

struct GripTaskOptions
{
  ContactModel model = ContactModel::kGodFinger;
  double squeeze = 0.02;  // m, nominal
  OperatorTraits hand = perfectOperator();
  bool carry = false;  // false: lift and hold; true: pick and place
  WorldParams params;  // the world's (its pad solver too); the model above is set on it
};

struct GripTaskResult
{
  bool held = false;                // above half the lift height through the hold (the carry)
  bool placed = false;              // pick and place: held, ended within 2 cm of the target, lying as it started
  double placed_error_m = 0.0;      // pick and place: the centre's distance from the target at the end
  double final_rotation_rad = 0.0;  // the bar\'s rotation from its start at the end (any axis)
  double max_turn_rad = 0.0;        // about the pinch normal (y), from the lift's start to the release
  double final_turn_rad = 0.0;      // the same, at the end of the hold (at the release)
  double max_tilt_rad = 0.0;        // about the other axes, same span
  double max_slip_m = 0.0;          // the grip point on the bar against the fingers, across the pinch
  double mean_grip_force_N = 0.0;   // the fingers' coupling force along the pinch, mean over the hold
  double min_squeeze_m = 0.0;       // the smallest squeeze commanded in the hold
};

// Throws InputError on a bad option (a squeeze outside (0, 0.1] m, bad world parameters).
GripTaskResult runGripTask(const GripTaskOptions& options);
}  // namespace god_finger
