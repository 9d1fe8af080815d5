// Issue 29's delay sweep: a haptic device talking to the physics across a delayed link (the
// delay line's own schedule, runtime/delay_line.h: delay, Gaussian jitter, loss), with the
// passivity controller at the device's port (haptics/passivity_controller.h) on or off, for four
// tasks and two operators, on simulated time (1 kHz ticks, deterministic).
//
// The model, along one axis (x, m; forces N; the handle's own dynamics integrated at each tick):
//  - The haptic side sends the handle's position and velocity every tick; the physics answers
//    every tick with the coupling's force (haptics/virtual_coupling.h couplingForce, the package's
//    default CouplingProfile) between the newest position it received and a god-object proxy
//    that stops at the surface; the device renders the newest force it received through the
//    controller, saturated at the profile's max_force. A lost message is never seen; with
//    jitter, the newest stamp received wins.
//  - Tasks: kPress (a stiff wall at x = 0; the operator's rest point ramps from 1 cm before it to
//    2 cm past it in 0.5-2 s and holds until 4 s), kTap (the rest point strikes from 2 cm before
//    the wall to 1.5 cm past it and back in 0.2 s, at 1 s and at 2.5 s), kGrasp (two devices on
//    their own links squeeze a free 50 g block 4 cm wide from both sides, each rest point 1.5 cm
//    past its face by 1.5 s, and hold), kFree (the rest point swings +-3 cm at 1 Hz in free space).
//  - Operators: kWorstCase, a light handle held by a stiff, barely damped hand (0.1 kg, 300 N/m,
//    0.2 N s/m: the passive operator that shows a delayed wall's energy best); kHumanLike, a
//    finger and arm (0.15 kg, 300 N/m, 3 N s/m) with a physiological tremor (0.1 mm at 9 Hz)
//    that stops 1.5 s before the run's end (4 s). A tremor is a forcing, and the loop answers it
//    as long as it goes on, more so through a delay: through 10 ms the press's and the grasp's
//    9 Hz answer is 1.3-3.1 times the no-link run's (the delayed loop's resonance, near 11 Hz, is
//    less damped). The last second, the hand still, shows whether the loop oscillates on its own.
//    With the tremor to the end, that stronger answer counted as sustained in 8 of the sweep's
//    settings (10 ms, jitter 20-50 %); stopped, it dies: the worst of them keeps 0.28 of its first
//    second's content.
// Metrics per trial (the worst of the ports for the grasp): lowest_energy_J, the device port's
// one-port observer's lowest energy (the hand's net input) (passive: >= -1e-4 J, the bound);
// early/late_hf_rms_N, the rendered force's content above about 5 Hz (the force less its 0.2 s centred moving mean)
// over the first second after the first contact and over the run's last second; sustained, whether late_hf_rms_N is
// over kSustainedHfRms (an oscillation that does not die); tremor_hf_rms_N, the same content over the tremor's last 0.4
// s (2.1-2.5 s: what the hand feels of its own tremor, the link's transparency to it, against the no-link run's);
// peak_force_N against the device's max_force; felt_stiffness_N_per_m, the slope of the rendered force against the
// handle's position over the contact while pressing (kPress, kGrasp; 0 otherwise): transparency
// against the zero-delay run's; damped_ticks; lost_messages; the two-port's margins (below).
// Not real-time (vectors grow). Units SI.
#pragma once

#include <string>
#include <vector>

namespace god_finger
{
enum class DelayTask
{
  kPress,
  kTap,
  kGrasp,
  kFree
};
enum class DelayOperator
{
  kWorstCase,
  kHumanLike
};
// Where the passivity controllers act (haptics/passivity_controller.h, two_port_passivity.h):
// kDevicePort, at the device alone, against the energy the hand put in (the package's one-port
// controller); kTwoPort, that and the two-port's physics side, which holds the position the
// physics uses to what the device's packets say it put into the link (delayed, jittered and lost
// with the link's messages), less the contact's credit. The two-port's device side only counts
// (its controller, tried in this sweep, kept both margins but left a press ringing:
// docs/decisions.md). Either way every port's observer counts, so that every row reports every
// port. kTwoPort acts on forwarded forces only (local_coupling false); with the local coupling it
// is the device port's form.
enum class PassivityForm
{
  kDevicePort,
  kTwoPort
};
const char* delayTaskName(DelayTask task);
const char* passivityFormName(PassivityForm form);
const char* delayOperatorName(DelayOperator op);

// An oscillation whose force content above 5 Hz stays over the no-link run's by more than this
// (N rms) in the last second, and over half its first second's, is sustained.
constexpr double kSustainedHfRms = 0.01;

struct DelayTrial
{
  DelayTask task = DelayTask::kPress;
  DelayOperator op = DelayOperator::kWorstCase;
  double round_trip = 0.0;       // s: both ways' delay together (half each way)
  double jitter_fraction = 0.0;  // each way's jitter's standard deviation over its delay
  double loss = 0.0;             // each message's probability of being lost
  bool controller = true;        // the passivity controller (its defaults), where `form` puts it
  PassivityForm form = PassivityForm::kDevicePort;
  // false: the physics sends the coupling's force and the device renders the newest received
  // (the haptic node's local_coupling:=false; every row of delaySweep()). true: the physics sends
  // its god-object (position; the device side takes its velocity from the last two received, as
  // the haptic node does) and the device renders the coupling between its own handle, now, and
  // that god-object (the haptic node's default, local_coupling:=true), through couplingForce.
  bool local_coupling = false;
  int seed = 1;
};

struct DelayTrialResult
{
  double lowest_energy_J = 0.0;
  double early_hf_rms_N = 0.0;
  double late_hf_rms_N = 0.0;
  double baseline_late_hf_rms_N = 0.0;
  bool sustained = false;
  double tremor_hf_rms_N = 0.0;  // N rms above 5 Hz over the tremor's last 0.4 s (above)
  double baseline_tremor_hf_rms_N = 0.0;
  double peak_force_N = 0.0;
  double max_force_N = 0.0;  // the device's limit (the coupling profile's max_force)
  double felt_stiffness_N_per_m = 0.0;
  long damped_ticks = 0;
  long lost_messages = 0;
  // The two-port's observers (the worst port for the grasp), J: the device's margin, the physics'
  // E_in received less the device's E_out (>= 0: the device lets out no more than the physics
  // gave back), and the physics' margin, the device's E_in received less the physics' E_out; their
  // lowest over the run. max_drift_m: the largest position drift the physics side used (0 unless
  // the two-port controller acts).
  double device_margin_J = 0.0;
  double physics_margin_J = 0.0;
  double max_drift_m = 0.0;
};

DelayTrialResult runDelayTrial(const DelayTrial& trial);

// The sweep of the issue: round trips 10, 30, 60, 100 ms x jitter 0, 20, 50 % x loss 0, 2 % x
// every task x every operator x controller off, on at the device port, on at both ports (the
// two-port rows follow the others: the first rows are as before the two-port form).
std::vector<DelayTrial> delaySweep();

// One JSON object (one line) of a trial and its result.
std::string delayTrialJson(const DelayTrial& trial, const DelayTrialResult& result);
}  // namespace god_finger
