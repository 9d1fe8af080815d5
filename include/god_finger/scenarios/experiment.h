// The paper's experiments as scripted, deterministic runs (no ROS): a scripted hand moves the
// interfaces, the world steps at a fixed rate, metrics come out.
//
// Scenarios (scenes in urdf/scenes; z is up, REP-103):
//  - kSlide (Fig. 5): a finger presses on the back of a ball (r = 4 cm) resting on the table,
//    a little above its equator, and pushes it 10 cm sideways. Metrics: translation_m,
//    rolled_rad (integral of the horizontal angular speed), rolling_ratio = rolled arc over
//    translation (1: rolls without slipping, 0: slides).
//  - kLiftOne (Fig. 6): a finger comes from under a light plate resting on two rails and lifts
//    it 10 cm in 2 s (fast: in 0.2 s), then holds. Metrics: lift_height_m, held_s,
//    max_tilt_rad, dropped.
//  - kLiftTwo (Fig. 7): the same with two fingers side by side.
//  - kPinchCylinder (Fig. 8): two fingers moving along x press the two flat ends of a lying
//    cylinder 5 mm under its axis, lift it 10 cm in 2 s, then stop; 25 s in all. Metrics:
//    rotation_about_normal_rad, angular_velocity_about_normal_max (after the lift),
//    fz_oscillation_amplitude_N (half the peak-to-peak vertical net force on the centre of
//    mass, last 10 s), held_s (time after the lift with the object more than half the lift
//    height above its start; the same in the lift scenarios), lift_height_m.
//  - kClutter (urdf/scenes/table_clutter.urdf, 108 bodies): two fingers moving along x pinch a
//    5 cm box (100 g) off the top of a small pile, 5 mm under its centre, lift it 6 cm, carry it
//    13 cm sideways (-y), set it down on the table, let go and rise; 9 s in all. Metrics:
//    held (1 if held through the whole carry), held_s (time in the carry with the box more than
//    half the lift height above its start), lift_height_m (at the end of the carry), turn_rad
//    (largest rotation of the box from its start, from the lift to the release),
//    placed_error_m (distance of its centre of mass at the end from the target),
//    disturbed_neighbours (the other dynamic bodies whose centre of mass ends more than 5 mm
//    from its start) and max_neighbour_displacement_m.
//  - kHandGrasp (urdf/scenes/table_mug.urdf): three fingers of a hand close on a 300 g mug's
//    wall from three sides (away from the handle), lift it 10 cm in 2 s, hold 1 s, open and
//    rise; 5.5 s in all. Metrics: held_s (the hold with the mug above half the lift height,
//    until the fingers open), lift_height_m (when they open), max_tilt_rad (of the mug's axis,
//    from the lift to the opening), turn_rad (its largest rotation over the same span) and
//    fell_after_release (1 when, let go, it falls below half the lift height: no glue).
//  - kRollFinger (urdf/scenes/table_box.urdf): an oriented (6-DOF) finger, pulp down and along
//    x, presses the top of a 6 cm box on the table with 4 N, rolls 40 degrees about its own
//    axis (x) in 1 s and holds; 2.5 s in all (ScenarioTimes: lift_start and lift_end are the
//    roll's start and end). Metrics (roll_metrics.h): area_centre_travel_m (how far the contact
//    area's centre moved across the box from the roll's start to the end: about
//    fingertip_radius x 40 degrees), max_force_step_N (the largest change of the force on the
//    hand from one step to the next, from the roll's start on), rolled_rad (the proxy's roll over
//    the same span) and contact_lost_steps (steps from the roll's start without a contact area
//    on the box). --hand fake runs it too: the fake device reports the script's orientation.
//  - kPinchThin (urdf/scenes/holder_plate.urdf): two fingers press the same face of a clamped
//    2 mm plate, 3 cm apart along it, and slide towards each other for 2 s until they meet;
//    3.5 s in all. The paper's overlap of contact areas (Discussion: two fingers' areas on one
//    side of a body), and its push (WorldParams::overlap; ExperimentOptions::overlap_stiffness 0
//    runs without). Metrics (overlap_metrics.h): overlap_area_max_m2, max_force_step_N.
//  - kPinchCard (urdf/scenes/table_card.urdf): two fingers pinch a free 8 mm phone (150 g) across
//    its thickness where it overhangs the table's edge, one above and one below, lift it 10 cm
//    in 1.5 s and hold; 3.5 s in all. Pads on opposite faces are a pinch, never an overlap.
//    Metrics (pinch_metrics.h): held, slip_m, turn_rad.
//  - kDoor (urdf/scenes/door.urdf, an articulated object): a finger comes to the door's face
//    27 cm from the hinge in 0.5 s, then pushes it open along the arc to 65 degrees in 3 s
//    (about 0.38 rad/s) and holds until 4.5 s; the hinge's damping and friction resist.
//    Metrics (joint_metrics.h): opened_rad, beyond_limit, hand_force_N against
//    resistance_force_N (the hinge's damping as the hand should feel it).
//  - kDrawer (urdf/scenes/drawer.urdf): a pad presses the top of a handle-less drawer with about
//    3 N, 5 cm in front of the cabinet, and pulls 12 cm along the runners in 2 s (0.7-2.7 s) by
//    friction alone, then rises; 3.5 s in all. Metrics (joint_metrics.h): pulled_m, slip_m,
//    beyond_limit, hand_force_N against resistance_force_N.
//  - kPressSoft (urdf/scenes/soft_block.urdf: a 10 cm soft cube, E 50 kPa, nu 0.45, glued to the
//    table): a finger comes down onto the block's top centre in 0.5 s, presses its target 1.5 cm
//    past the top by 1.5 s and holds until 3 s. Metrics (soft_contact_metrics.h): sink_m (the
//    dimple) against w0_m (Boussinesq's for the hand's force over the area's radius),
//    hand_force_N, area_radius_m, penetration_max_m and penetration_p99_m (the proxy into the
//    deformed surface).
//  - kStrokeSoft (the same block): the finger presses 1.2 cm past the top by 1.5 s, holds 0.5 s,
//    strokes 3 cm along +x in 2 s (2-4 s), holds 0.5 s and rises by 5 s. Metrics
//    (soft_contact_metrics.h): trace_m, stick_slip_events, friction_ratio_max, hand_force_N,
//    sink_m, penetration_max_m and penetration_p99_m.
//  - kPinchSoft (urdf/scenes/soft_ball.urdf: a soft ball of radius 3 cm, E 100 kPa, nu 0.45,
//    0.1 kg, resting free on the table): two fingers at its equator close along x and squeeze
//    it (0-1.2 s), lift it 5 cm in 1.5-3 s and hold until 4 s. Metrics: the grip's (pinch_metrics.h:
//    held, slip_m, turn_rad) and the soft body's (soft_contact_metrics.h: squash, the largest
//    relative shortening of the ball across the fingers from the squeeze on; lift_height_m, its
//    centre's rise at the end; hand_force_N, the fingers' mean force over the hold;
//    sink_m, penetration_max_m and penetration_p99_m over both fingers).
// Asymmetry: a perfectly symmetric set-up hides every effect (nothing balanced on one point
// ever tips in a deterministic simulation), so every scenario has the small offset a human
// hand makes, the same for every model: a few millimetres of offset or drift (plus up to
// +-0.5 mm drawn from the seed), documented per scenario in experiment.cpp.
// Contact parameters: the core's defaults (ContactParams; D0' = 1 mm).
#pragma once

#include "god_finger/haptics/orientation_path.h"
#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/physics/world_params.h"
#include "god_finger/scene/scene_description.h"

#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace god_finger
{
enum class Scenario
{
  kSlide,
  kLiftOne,
  kLiftTwo,
  kPinchCylinder,
  kClutter,
  kHandGrasp,
  kRollFinger,
  kPinchThin,
  kPinchCard,
  kDoor,
  kDrawer,
  kPressSoft,
  kStrokeSoft,
  kPinchSoft,
};
// Every scenario, in the order tools and scripts list them: the one list (scenarioNames()).
constexpr Scenario kAllScenarios[] = {
    Scenario::kSlide,     Scenario::kLiftOne,    Scenario::kLiftTwo,    Scenario::kPinchCylinder, Scenario::kClutter,
    Scenario::kHandGrasp, Scenario::kRollFinger, Scenario::kPinchThin,  Scenario::kPinchCard,     Scenario::kDoor,
    Scenario::kDrawer,    Scenario::kPressSoft,  Scenario::kStrokeSoft, Scenario::kPinchSoft};
const char* scenarioName(Scenario scenario);
// The names of kAllScenarios joined by `separator` ("slide, lift_one, ...").
std::string scenarioNames(const std::string& separator = ", ");
bool parseScenario(const std::string& text, Scenario* scenario);

struct ExperimentOptions
{
  Scenario scenario = Scenario::kSlide;
  ContactModel model = ContactModel::kGodFinger;
  double duration = 0.0;                       // s, [0, 3600]; 0: the scenario's own length
  double time_step = WorldParams().time_step;  // s, timeStepRange(): the world's fixed step (the tool's --dt)
  bool fast = false;                           // lift scenarios: lift ten times faster
  // slide: height of the hand above the ball's centre (m), range [0, 0.04]. The default
  // touches the ball 17 degrees above its equator.
  double push_height = 0.0125;
  std::uint64_t seed = 1;
  std::string csv;         // time series path, empty for none
  bool series = false;     // the same time series kept in ExperimentResult::series
  std::string scenes_dir;  // folder of the scene URDFs (urdf/scenes of the package)
  // The world's (world_params.h) unless a caller sets them.
  int solver_iterations = WorldParams().solver_iterations;
  PadSolver pad_solver = WorldParams().pad_solver;
  double overlap_stiffness = WorldParams().overlap.stiffness;  // N/m^2, 0: no overlap push
  // > 0: the watched object's pose is sampled every sample_period (s; rounded to whole steps)
  // into ExperimentResult::trajectory, for comparing runs of different settings.
  double sample_period = 0.0;
};
// dt (time_step), duration and push_height: names, units, ranges and meanings, the one
// definition the tool's flags (--dt, --duration, --push-height) and the check of
// runExperiment / measureScenario come from.
const ParameterTable<ExperimentOptions>& experimentOptionTable();

struct PoseSample
{
  double time = 0.0;                                   // s
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m, centre of mass, world
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

struct ExperimentResult
{
  std::string scenario;
  std::string model;
  double duration_s = 0.0;
  long steps = 0;
  double step_us_median = 0.0;
  double step_us_p99 = 0.0;
  double max_penetration_m = 0.0;
  long nan = 0;
  double step_us_total = 0.0;  // compute time of all steps (us)
  std::map<std::string, double> metrics;
  std::vector<PoseSample> trajectory;  // see ExperimentOptions::sample_period
  // ExperimentOptions::series: the CSV's columns (t, the object's x y z, qx qy qz qw, vx vy vz,
  // wx wy wz, fx fy fz, then per finger i: fi_ix.. target, fi_px.. proxy, fi_ux.. force on the
  // hand, fi_contacts, fi_sgo), and its rows one after another (steps x series_names.size()).
  std::vector<std::string> series_names;
  std::vector<double> series;
};

// The world parameters a scenario runs with: the defaults (WorldParams), with the options'
// time step, solver iterations, pad solver, model and overlap stiffness.
WorldParams scenarioParams(const ExperimentOptions& options);

// A script's times: its own length, when the lift ends (metrics "after the lift" start there)
// and the height it commands.
struct ScenarioTimes
{
  double duration = 0.0;     // s
  double lift_end = 0.0;     // s
  double lift_height = 0.0;  // m (0 for the slide)
  // A pick and place (clutter): the lift starts, the set-down starts (the carry is
  // [lift_end, carry_end]), the fingers open; where the object's centre of mass should end
  // (m, world).
  double lift_start = 0.0;  // s
  double carry_end = 0.0;   // s
  double release = 0.0;     // s
  Eigen::Vector3d place_target = Eigen::Vector3d::Zero();
};

// A scenario's set-up without running it (benchmarks step it themselves): its scene, the
// watched object, the hand's path per finger (device targets in world, m, against time, s),
// and its own length (s).
struct ScenarioSetup
{
  SceneDescription scene;
  int object = -1;
  std::vector<WaypointPath> fingers;
  // Per finger, its orientation (oriented_finger.h) against time; empty: 3-DOF fingers.
  std::vector<OrientationPath> orientations;
  double duration = 0.0;
  ScenarioTimes times;
};
ScenarioSetup loadScenario(const ExperimentOptions& options);
// Throws InputError on a bad scene or option. The ideal hand: every interface is where the
// script puts it (scenarios/servo_experiment.h runs the same scenario through the servo loop and
// the fake device's handle instead).
ExperimentResult runExperiment(const ExperimentOptions& options);
// Measures a scenario's world (the scenario's object, metrics, CSV, trajectory samples) over
// the scenario's steps, each taken by `step(i)`, which advances `world` by one step by whatever
// drives its interfaces. Throws InputError on a bad option.
ExperimentResult measureScenario(const ExperimentOptions& options, const GodFingerWorld& world,
                                 const std::function<void(long step)>& step);
std::string toJson(const ExperimentResult& result);
}  // namespace god_finger
