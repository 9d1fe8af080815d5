// Parameters of the physics world and of the god-object proxies: the structs with their
// defaults, and worldParameterTable(), the one table of their names, units, ranges and
// meanings (support/parameter_table.h); validate() names the first bad one.
#pragma once

#include "god_finger/contact/contact_params.h"
#include "god_finger/haptics/virtual_coupling.h"
#include "god_finger/physics/contact_model.h"
#include "god_finger/physics/oriented_finger.h"

#include <Eigen/Core>
#include <string>

namespace god_finger
{
// The virtual coupling's default profile (haptics/virtual_coupling.h: stiffness, damping,
// max_force; an interface may bring its device's own) and the god-object it pulls: a small
// sphere with locked rotation.
struct CouplingParams : CouplingProfile
{
  double proxy_mass = 0.02;     // kg
  double proxy_radius = 0.003;  // m
};

// The soft-finger baseline: one contact point carrying a pad's torques through Bullet's
// torsional rows. About the normal (spinning), Bullet multiplies the proxy's coefficient with
// the object's friction: up to spinning_friction mu N. About a tangent (a tilt, or an object
// rolling under the finger), the pad's centre of pressure stays inside the pad: up to
// rolling_friction N, whatever mu (finger_contact_friction.h). Bullet's solver adds spinning
// friction only where the rolling friction is non-zero.
// Without the tilt lever (Bullet's 1e-4 m times mu) the point resists no tilt, and a pinch of
// parallel faces by misaligned fingers is unstable: the couple N d of an offset d is held by
// friction only by dragging the coupled proxies apart, which grows d by 2 s / w per round for
// a coupling stretch s and a width w; beyond s = w / 2 the object turns over and squirts out
// (pinch_grip_test).
struct SoftFingerParams
{
  double spinning_friction = 0.01;  // m
  double rolling_friction = 0.008;  // m: the pad's tilt lever, a fingertip's contact radius
};

// The finger pad's compliance at each contact point of a proxy (the true one and every
// sub-god-object): Bullet's per-point contact stiffness and damping. With rigid contacts the
// load on several points at one depth is indeterminate, and the sequential impulse solver
// puts it all on the first point it visits, so the sub-god-objects carry no normal force and
// hence no friction: no torque about the normal. A compliant pad shares the load evenly, as a
// real pad does. Stiff enough (per point) that 4 N on one point sinks 0.2 mm; the felt
// stiffness stays the coupling's, which is 50 times softer.
struct FingerPadParams
{
  double stiffness = 2e4;  // N/m per contact point
  double damping = 20.0;   // N s/m per contact point
};

// How a god_finger contact area reaches the solver (src/physics/solver/pad_constraints.h):
// kPoints, the paper's way, a contact point per sub-god-object (about 3 (1 + n_SGO) rows per
// finger); kConstraint, one pad per area at its centre of pressure with torsional and tilt rows
// bounded by the area (6 rows per finger).
enum class PadSolver
{
  kPoints,
  kConstraint,
};
const char* padSolverName(PadSolver solver);
std::string padSolverNames();  // "points, constraint"
// False (and `solver` unchanged) if `text` names none.
bool parsePadSolver(const std::string& text, PadSolver* solver);

// Sleeping (Bullet's deactivation, with our own time): a dynamic body slower than `speed` and
// `angular_speed` for `time` falls asleep with its island (the bodies whose bounding boxes
// overlap, through dynamic bodies). A sleeping body costs no collision detection with other
// sleeping or static bodies and no solver rows; it keeps its pose and has zero velocity. It wakes
// when a proxy or a woken body comes within Bullet's contact margin (2 cm) of its bounding box,
// when a wrench is applied to it, and on a reset or a change of contact model or parameters.
// Bodies placed at rest start falling asleep at once: their timer starts full, less the time a
// free fall takes to exceed `speed` twice over, so a body placed in the air falls.
struct SleepParams
{
  double time = 0.5;           // s, 0: no body ever sleeps
  double speed = 0.01;         // m/s, of the centre of mass
  double angular_speed = 0.1;  // rad/s
};

// The overlap push (paper, Discussion; src/physics/overlap_push.h): where two fingers' contact
// areas on one body overlap (contact/area_overlap.h: on one side of it; pads on opposite faces never
// do), both proxies are pushed apart with stiffness times the overlap area, the push changing by
// at most force_rate per second; a finger that holds the body against another is never pushed.
// The default stiffness holds the pinch_thin scenario's fingers (1.6 N each on one face of a 2 mm
// plate, hands sliding together until they meet) to less than a fifth of their overlap without it
// (experiment_test; docs/experiments.md): at 1e5 N/m^2 a full overlap of two 1 cm pads
// (3.1e-4 m^2) would push with 31 N (capped at the coupling's max_force), and the push balances
// the couplings' sideways pull and friction (about 3 N) at a few 1e-5 m^2, a tenth of a full
// overlap. The rate keeps the hand's force steps small: on a 20 g proxy, a push change of F per
// 1 ms step changes the coupling's damping force by about b dt F / m = 0.2 F.
struct OverlapParams
{
  double stiffness = 1e5;     // N/m^2, 0: no push
  double force_rate = 100.0;  // N/s
};

struct WorldParams
{
  // s, timeStepRange(): the one definition of the period and its default. The servo loop's
  // `rate` (Hz) defaults to its inverse, the experiment's dt to it.
  double time_step = 1e-3;
  // Sequential-impulse iterations per step. A pinched object slowly creeps about the contact
  // normal when they are too few (README, "Solver iterations"): 30 gives 0.086 rad in the 21.5 s
  // after the pinch_cylinder lift, 50 gives 0.010 rad, 60 gives 0.0035 rad.
  int solver_iterations = 60;
  // The iterations stop early once an iteration corrects no row's velocity by more than this
  // (m/s): 10 um/s, 10 nm of drift per 1 ms step. It halves the step of every model and changes
  // no scenario's outcome (bench/REPORT.md, "Physics step"); 0 runs every iteration.
  double solver_tolerance = 1e-5;
  // Passes after them that hold an object resting on something static while a proxy presses it
  // (src/physics/solver/support_pass.h): without them an object 1000 times lighter than the
  // proxy sank 7 mm into its support. 0: Bullet's solver alone.
  int support_passes = 2;
  Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);  // m/s^2, finite
  ContactModel model = ContactModel::kGodFinger;
  PadSolver pad_solver = PadSolver::kConstraint;
  ContactParams contact;
  CouplingParams coupling;
  SoftFingerParams soft_finger;
  FingerPadParams pad;
  SleepParams sleep;
  // An oriented (6-DOF) finger: its pulp and its rotational coupling (oriented_finger.h).
  OrientedFingerParams finger;
  OverlapParams overlap;
  // Largest edge of the walk mesh of a sphere or cylinder, as a fraction of r_max: the
  // tessellation is refined until its edges are no longer (capped at 81920 triangles).
  double walk_edge_per_max_radius = 0.5;
  // The world's bounds (m): the box around the scene as loaded (every body at its initial pose),
  // grown by this on every side. A dynamic body whose centre of mass leaves them (off the table,
  // falling) is put back at its initial pose, at rest, and counted (BodyState::left_world): the
  // scene stays whole however long it runs. 1 m: far from anything a finger does on a table.
  double world_margin = 1.0;
  // s: a finger pressing an object that is removed (GodFingerWorld::removeObject) lets go over
  // this time: its proxy is pulled toward the hand through a target that starts where the proxy
  // was and reaches the hand linearly, so the force on the hand falls to zero with it instead of
  // in one step. 0: at once.
  double let_go_time = 0.1;
  // One step in this many is timed stage by stage (GodFingerWorld::stepProfile, step_profile.h):
  // timing every step would cost 5 % of a 4 us step (eleven clock reads, about 0.26 us), one in
  // 16 costs 0.4 %. 0: none; 1: every step.
  int profile_every = 16;
};

// The one table of the parameters of WorldParams read by name (its rows are the list; the
// README's table is generated from it). Not in it: time_step comes from the loop's rate, gravity
// from the scene, and the coupling profile per interface from its device (deviceProfileTable()).
const ParameterTable<WorldParams>& worldParameterTable();
// The range of any fixed step of the world, time_step (s): [1e-5, 0.1]. validate() checks
// time_step by it, the experiment's dt row is it.
ParameterRange timeStepRange();

std::string validate(const WorldParams& params);
// Empty when `profile` pulling a proxy of `proxy_mass` (kg) is stable at `time_step` (s): the
// coupling is explicit, stable in free space iff (k dt + 2 b) dt / m < 4; else one line saying so.
std::string couplingStabilityError(const CouplingProfile& profile, double proxy_mass, double time_step);
void validateOrThrow(const WorldParams& params);
}  // namespace god_finger
