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
#include "god_finger/scenarios/human_operator.h"
#include "god_finger/scene/scene_description.h"
#include "god_finger/physics/world_params.h"

#include <Eigen/Geometry>

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

// The pieces runGripTask is made of, for a simulator other than GodFingerWorld (the MuJoCo
// baseline of bench/operator_mujoco_bench.cpp) to run the same hand and measure it the same way.
// The script's length (s).
double gripTaskDuration(const GripTaskOptions& options);
// The two fingers' targets (m, world) at time t (s) with the squeeze's factor on its nominal
// value (fluctuation and reflex): the near finger at -y, the far one at +y with the misalignment;
// each touches its face with a proxy of options.params.coupling.proxy_radius.
void gripTargets(const GripTaskOptions& options, double t, double squeeze_factor, Eigen::Vector3d* near,
                 Eigen::Vector3d* far);

// Measures a run step by step: the result's fields and the operator's reflex.
class GripTaskMeter
{
 public:
  // `start` is the bar's pose and centre of mass before the first step.
  GripTaskMeter(const GripTaskOptions& options, const Eigen::Isometry3d& start_pose, const Eigen::Vector3d& start_com);
  // The squeeze's factor to command at time t: the fluctuation plus the reflex so far.
  double squeezeFactor(double t) const;
  // After the step that ended at time t, commanded with `squeeze_factor`: the bar's pose and
  // centre of mass, the proxies' positions and the fingers' coupling forces (N, world, either
  // sign).
  void add(double t, double squeeze_factor, const Eigen::Isometry3d& bar_pose, const Eigen::Vector3d& bar_com,
           const Eigen::Vector3d& near_proxy, const Eigen::Vector3d& far_proxy, const Eigen::Vector3d& near_force,
           const Eigen::Vector3d& far_force);
  // After the last step: the bar's final pose and centre of mass.
  GripTaskResult finish(const Eigen::Isometry3d& bar_pose, const Eigen::Vector3d& bar_com);

 private:
  GripTaskOptions options_;
  GripReflex reflex_;
  Eigen::Matrix3d start_rotation_;
  double start_z_ = 0.0;
  GripTaskResult result_;
  Eigen::Vector3d grip_on_bar_ = Eigen::Vector3d::Zero();  // bar frame, fixed at the lift's start
  Eigen::Vector3d previous_slip_ = Eigen::Vector3d::Zero();
  double extra_ = 0.0;
  double force_sum_ = 0.0;
  long force_samples_ = 0;
  bool lifting_ = false;
};
}  // namespace god_finger
