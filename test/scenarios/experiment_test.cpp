// The paper's claims, held to account with identical scripted input for each contact model
// (docs/experiments.md has the numbers these runs print).
#include "god_finger/scenarios/experiment.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace god_finger
{
namespace
{
constexpr PadSolver kPadSolvers[] = {PadSolver::kPoints, PadSolver::kConstraint};

ExperimentResult run(Scenario scenario, ContactModel model, PadSolver pad_solver = PadSolver::kPoints,
                     double push_height = ExperimentOptions().push_height)
{
  ExperimentOptions options;
  options.scenario = scenario;
  options.model = model;
  options.pad_solver = pad_solver;
  options.push_height = push_height;
  options.scenes_dir = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";
  const ExperimentResult result = runExperiment(options);
  EXPECT_EQ(result.nan, 0);
  return result;
}

// Fig. 5: pushed a little above its equator, the ball rolls under a god-object (its rolled arc
// equals its translation) and slides under a god-finger, with either pad solver.
TEST(Experiment, SlideBallRollsUnderGodObjectAndSlidesUnderGodFinger)
{
  const ExperimentResult object = run(Scenario::kSlide, ContactModel::kGodObject);
  const ExperimentResult soft = run(Scenario::kSlide, ContactModel::kSoftFinger);
  EXPECT_GT(object.metrics.at("rolling_ratio"), 0.9);
  for (const PadSolver solver : kPadSolvers)
  {
    SCOPED_TRACE(padSolverName(solver));
    const ExperimentResult finger = run(Scenario::kSlide, ContactModel::kGodFinger, solver);
    EXPECT_LT(finger.metrics.at("rolling_ratio"), 0.2);
    EXPECT_LT(finger.metrics.at("rolled_rad"), 0.2 * object.metrics.at("rolled_rad"));
    // Both moved the ball: the god-finger one along with the hand (10 cm), the rolling one
    // until the finger rode over it.
    EXPECT_GT(finger.metrics.at("translation_m"), 0.09);
  }
  EXPECT_GT(object.metrics.at("translation_m"), 0.05);
  // The soft finger's pad resists the ball rolling under it up to its tilt lever times N
  // (SoftFingerParams): the ball slides, as under a god-finger.
  EXPECT_LT(soft.metrics.at("rolling_ratio"), 0.2);
  EXPECT_GT(soft.metrics.at("translation_m"), 0.09);
}

// The paper: the god-finger "makes it easier to let it slide". Over a sweep of push heights,
// wherever the god-object slides the god-finger slides too, and there are heights where only
// the god-finger slides.
TEST(Experiment, SlideGodFingerSlidesWhereverGodObjectDoesAndMore)
{
  for (const PadSolver solver : kPadSolvers)
  {
    SCOPED_TRACE(padSolverName(solver));
    int only_finger_slides = 0;
    for (double height : {0.0075, 0.01, 0.0125, 0.015, 0.02})
    {
      SCOPED_TRACE(height);
      const double object =
          run(Scenario::kSlide, ContactModel::kGodObject, PadSolver::kPoints, height).metrics.at("rolling_ratio");
      const double finger = run(Scenario::kSlide, ContactModel::kGodFinger, solver, height).metrics.at("rolling_ratio");
      EXPECT_LE(finger, object + 0.02);
      if (object > 0.9 && finger < 0.2)
      {
        ++only_finger_slides;
      }
    }
    EXPECT_GE(only_finger_slides, 1);
  }
}

// Fig. 6: one finger under a light plate, 2 mm off its centre: held by a god-finger, dropped by
// a god-object (and by the soft finger: its rolling resistance, 8e-5 m x 0.25 N, is twenty
// times smaller than the tipping torque, 0.25 N x 2 mm).
TEST(Experiment, LiftOneHeldByGodFingerDroppedByGodObject)
{
  for (const PadSolver solver : kPadSolvers)
  {
    SCOPED_TRACE(padSolverName(solver));
    const ExperimentResult finger = run(Scenario::kLiftOne, ContactModel::kGodFinger, solver);
    EXPECT_EQ(finger.metrics.at("dropped"), 0.0);
    EXPECT_NEAR(finger.metrics.at("lift_height_m"), 0.1, 0.005);
    EXPECT_GE(finger.metrics.at("held_s"), 1.5);
    EXPECT_LT(finger.metrics.at("max_tilt_rad"), 0.02);
  }
  const ExperimentResult point = run(Scenario::kLiftOne, ContactModel::kGodObject);
  EXPECT_EQ(point.metrics.at("dropped"), 1.0);
  EXPECT_EQ(point.metrics.at("held_s"), 0.0);
  EXPECT_GT(point.metrics.at("max_tilt_rad"), 0.5);
  // The soft finger's pad holds the plate's tilt (2 mm off centre: 0.5 mN m per 25 g) far
  // below its lever times N.
  const ExperimentResult soft = run(Scenario::kLiftOne, ContactModel::kSoftFinger);
  EXPECT_EQ(soft.metrics.at("dropped"), 0.0);
  EXPECT_NEAR(soft.metrics.at("lift_height_m"), 0.1, 0.005);
  EXPECT_LT(soft.metrics.at("max_tilt_rad"), 0.02);
}

// Fig. 7: two fingers side by side under the plate, both 2 mm off its centre line: the plate
// tips about the line through two points, not about two areas.
TEST(Experiment, LiftTwoHeldByGodFingersDroppedByGodObjects)
{
  for (const PadSolver solver : kPadSolvers)
  {
    SCOPED_TRACE(padSolverName(solver));
    const ExperimentResult finger = run(Scenario::kLiftTwo, ContactModel::kGodFinger, solver);
    EXPECT_EQ(finger.metrics.at("dropped"), 0.0);
    EXPECT_NEAR(finger.metrics.at("lift_height_m"), 0.1, 0.005);
    EXPECT_LT(finger.metrics.at("max_tilt_rad"), 0.02);
  }
  EXPECT_EQ(run(Scenario::kLiftTwo, ContactModel::kGodObject).metrics.at("dropped"), 1.0);
}

// Fig. 8: pinched by its flat ends 5 mm under its axis and lifted, the cylinder swings about the
// contact normal without end between two god-objects, and the vertical force on its centre of
// mass keeps oscillating; between two god-fingers it stays still, without creep, for the whole
// run.
TEST(Experiment, PinchCylinderStillUnderGodFingerOscillatesUnderGodObject)
{
  const ExperimentResult object = run(Scenario::kPinchCylinder, ContactModel::kGodObject);
  EXPECT_GT(object.metrics.at("rotation_about_normal_rad"), 1.0);
  EXPECT_GT(object.metrics.at("angular_velocity_about_normal_max"), 5.0);
  EXPECT_GT(object.metrics.at("fz_oscillation_amplitude_N"), 0.1);
  for (const PadSolver solver : kPadSolvers)
  {
    SCOPED_TRACE(padSolverName(solver));
    const ExperimentResult finger = run(Scenario::kPinchCylinder, ContactModel::kGodFinger, solver);
    // Friction anchors on the sub-god-objects (warm_start.h): 1.1 mrad without
    // them (a creep that grew with time), 1e-10 rad with them; the pad constraint's anchored
    // torsional rows hold it to 0.
    EXPECT_LT(finger.metrics.at("rotation_about_normal_rad"), 1e-5);
    EXPECT_LT(finger.metrics.at("angular_velocity_about_normal_max"), 0.002);
    EXPECT_LT(finger.metrics.at("fz_oscillation_amplitude_N"), 0.001);
    // Lifted from the end of the lift (3.5 s) to the end of the run (25 s).
    EXPECT_GE(finger.metrics.at("held_s"), 21.5 - 1e-9);
    EXPECT_NEAR(finger.metrics.at("lift_height_m"), 0.1, 0.005);
  }
}

std::string readFile(const std::string& path)
{
  std::ifstream file(path);
  std::stringstream content;
  content << file.rdbuf();
  return content.str();
}

// hand_grasp: three fingers lift a 300 g mug mesh (its handle moves the centre of mass 4 mm off
// the axis) and let go. Three god-fingers hold it level; three points let it tilt; every model
// drops it when the fingers open (no glue).
TEST(Experiment, HandGraspHoldsTheMugLevelAndLetsItFall)
{
  const ExperimentResult points = run(Scenario::kHandGrasp, ContactModel::kGodObject);
  for (const PadSolver solver : kPadSolvers)
  {
    SCOPED_TRACE(padSolverName(solver));
    const ExperimentResult finger = run(Scenario::kHandGrasp, ContactModel::kGodFinger, solver);
    EXPECT_NEAR(finger.metrics.at("held_s"), 1.0, 1e-6);
    EXPECT_NEAR(finger.metrics.at("lift_height_m"), 0.1, 0.005);
    EXPECT_LT(finger.metrics.at("max_tilt_rad"), 0.1 * points.metrics.at("max_tilt_rad"));
    EXPECT_EQ(finger.metrics.at("fell_after_release"), 1.0);
  }
  EXPECT_GT(points.metrics.at("max_tilt_rad"), 0.01);
  EXPECT_EQ(points.metrics.at("fell_after_release"), 1.0);
  EXPECT_EQ(run(Scenario::kHandGrasp, ContactModel::kSoftFinger).metrics.at("fell_after_release"), 1.0);
}

// pinch_thin: two god-fingers press the same face of a 2 mm plate and slide until they meet.
// Without the overlap push their areas come to cover each other; with it (the default) they are
// kept apart, the overlap at most a fifth of that, and the push adds no force step over 0.5 N.
// Point contacts (god_object) have no areas to overlap.
TEST(Experiment, PinchThinOverlapPushKeepsTheFingersApart)
{
  for (const PadSolver solver : kPadSolvers)
  {
    SCOPED_TRACE(padSolverName(solver));
    ExperimentOptions options;
    options.scenario = Scenario::kPinchThin;
    options.model = ContactModel::kGodFinger;
    options.pad_solver = solver;
    options.scenes_dir = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";
    const ExperimentResult pushed = runExperiment(options);
    options.overlap_stiffness = 0.0;
    const ExperimentResult unpushed = runExperiment(options);
    EXPECT_EQ(pushed.nan, 0);
    EXPECT_EQ(unpushed.nan, 0);
    // Without the push, half of a pad of r = 9.8 mm (3.0e-4 m^2) or more: the proxies lag their
    // hands by friction and end 4.6 mm apart.
    EXPECT_GT(unpushed.metrics.at("overlap_area_max_m2"), 1.5e-4);
    EXPECT_LE(pushed.metrics.at("overlap_area_max_m2"), 0.2 * unpushed.metrics.at("overlap_area_max_m2"));
    EXPECT_GT(pushed.metrics.at("overlap_area_max_m2"), 0.0);
    EXPECT_LE(pushed.metrics.at("max_force_step_N"), 0.5);
  }
  EXPECT_EQ(run(Scenario::kPinchThin, ContactModel::kGodObject).metrics.at("overlap_area_max_m2"), 0.0);
}

// pinch_card: two fingers pinch a free 8 mm phone across its thickness where it overhangs the
// table, and lift it 10 cm. Every model holds it (a pinch is no overlap, however thin); the pads
// hold it level against its weight's 0.05 N m about the pinch (the pad constraint within 1 mrad,
// the paper's points within 0.05 rad, soft_finger's tilt lever within 0.02), while two points,
// which resist no tilt, let it swing down about the pinch.
TEST(Experiment, PinchCardHoldsAPhoneLevelWithPadsAndLetsItSwingOnPoints)
{
  for (const PadSolver solver : kPadSolvers)
  {
    SCOPED_TRACE(padSolverName(solver));
    const ExperimentResult finger = run(Scenario::kPinchCard, ContactModel::kGodFinger, solver);
    EXPECT_EQ(finger.nan, 0);
    EXPECT_EQ(finger.metrics.at("held"), 1.0);
    EXPECT_LT(finger.metrics.at("slip_m"), 0.002);
    EXPECT_LT(finger.metrics.at("turn_rad"), solver == PadSolver::kConstraint ? 0.001 : 0.05);
  }
  const ExperimentResult soft = run(Scenario::kPinchCard, ContactModel::kSoftFinger);
  EXPECT_EQ(soft.metrics.at("held"), 1.0);
  EXPECT_LT(soft.metrics.at("slip_m"), 0.002);
  EXPECT_LT(soft.metrics.at("turn_rad"), 0.02);
  const ExperimentResult object = run(Scenario::kPinchCard, ContactModel::kGodObject);
  EXPECT_GT(object.metrics.at("turn_rad"), 0.5);
}

TEST(Experiment, TwoRunsGiveIdenticalCsv)
{
  ExperimentOptions options;
  options.scenario = Scenario::kLiftTwo;
  options.model = ContactModel::kGodFinger;
  options.duration = 1.5;
  options.scenes_dir = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";
  const std::string first = testing::TempDir() + "/determinism_first.csv";
  const std::string second = testing::TempDir() + "/determinism_second.csv";
  options.csv = first;
  runExperiment(options);
  options.csv = second;
  runExperiment(options);
  const std::string a = readFile(first);
  const std::string b = readFile(second);
  // Header plus one row per step, and the plate moved (not two identical resting states): the
  // hands rise 10.5 cm in 2 s from t = 0.5 s, so by t = 1.5 s the plate (column z) has risen
  // about half of its 10 cm lift.
  EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), 1501);
  EXPECT_EQ(a, b);
  EXPECT_NE(a.find("f1_sgo"), std::string::npos);
  std::istringstream rows(a);
  std::string header;
  std::getline(rows, header);
  ASSERT_EQ(header.rfind("t,x,y,z,", 0), 0u) << header;
  const auto z_of = [](const std::string& row)
  {
    std::istringstream fields(row);
    std::string field;
    for (int column = 0; column < 4; ++column)
    {
      std::getline(fields, field, ',');
    }
    return std::stod(field);
  };
  std::string row;
  std::getline(rows, row);
  const double first_z = z_of(row);
  std::string last;
  while (std::getline(rows, row))
  {
    last = row;
  }
  const double rise = z_of(last) - first_z;
  std::printf("[ plate ] rose %.4f m in 1.5 s\n", rise);
  EXPECT_NEAR(rise, 0.05, 0.005);
  std::remove(first.c_str());
  std::remove(second.c_str());
}

TEST(Experiment, BadOptionsAreRejected)
{
  ExperimentOptions options;
  options.scenes_dir = "/nonexistent";
  EXPECT_THROW(runExperiment(options), InputError);
  options.scenes_dir = std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/scenes";
  options.time_step = 0.0;
  EXPECT_EQ(validateRows(experimentOptionTable(), options), "parameter 'dt' = 0 is out of range [1e-05, 0.1] (s)");
  EXPECT_THROW(runExperiment(options), InputError);
  options.time_step = 1e-3;
  options.duration = -1.0;
  EXPECT_THROW(runExperiment(options), InputError);
  options.duration = 0.0;
  options.push_height = 0.1;
  EXPECT_THROW(runExperiment(options), InputError);
  options.push_height = 0.01;
  options.csv = "/nonexistent/dir/out.csv";
  EXPECT_THROW(runExperiment(options), InputError);
}
}  // namespace
}  // namespace god_finger
