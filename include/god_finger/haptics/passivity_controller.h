// Time-domain passivity at a haptic device's port (Hannaford and Ryu 2002): a passivity observer
// counts the energy the hand has put into everything behind the port (the link to the physics,
// its delay, jitter, loss and hold, the virtual coupling, the world), and a passivity controller
// adds the least damping that keeps that energy from going below zero, capped at what the device
// can render. A loop that stays passive without it is left untouched: the controller acts only
// on the energy the rest of the loop made up (a stiff wall rendered through a delayed link gives
// energy back on the way out that the hand never put in: the buzz).
//
// Per tick of period dt, with F the force command (N, device frame) and v the device's velocity
// (m/s, the last reading's):
//   d = b_min |v|^2 dt if F != 0, else 0: the dissipation asked of the loop this tick (J);
//   if B - F.v dt - d < 0:              alpha = min(passivity_damping_limit, -(B - F.v dt - d) / (|v|^2 dt)),
//                                       F' = F - alpha v;
//   if F'.v dt > E:                     c = (F'.v dt - E) / (|v| dt) (cut()), F' = F' - c v/|v|;
//   F' saturated at max_force;
//   B = min(E_max, B - F'.v dt - d)     the controller's bank, B(0) = 0;
//   E = E - F'.v dt                     the observer's energy (energy()): what the hand put in.
// E >= 0 after every tick (the cut: a push along the motion taken away, never reversed, so a
// device can always render it), E >= B always, and B >= 0 unless alpha was capped or F'
// saturated: the bank's debt is then paid by the damper over the next ticks. Choices beyond
// Hannaford and Ryu's observer, each measured in passivity_controller_test (a light, barely
// damped hand on a wall behind a 10-100 ms round trip):
//  - E_max (passivity_reservoir): the bank holds at most this much. Unbounded, a press banks
//    what the coupling's damper dissipates, and a delayed loop then spends it making the hand
//    ring (Kim and Ryu's energy bounding has the same bound);
//  - b_min (passivity_min_damping): while it pushes, the loop behind the port must dissipate at
//    least as a damper b_min would (strictly passive): at B = 0 a merely passive loop neither
//    feeds nor drains the hand's own ringing, and a barely damped hand rings on;
//  - free motion (F = 0) is not charged (d = 0), so it stays free, unless the bank is in debt
//    (a capped alpha left B < 0): then it is damped until the debt is paid (measured: without
//    that, the 100 ms round trip's handle bounced on the wall, 70 mm peak to peak);
//  - the cut (Ryu and Preusche's force bounding, in spirit): the damper alone, capped at 50 N s/m,
//    let a first contact through a 60-100 ms round trip make up to 0.028 J (delay sweep, report
//    section 13); cutting on the bank instead of E left no debt, so nothing paid it: a passive
//    but undamped 25 Hz limit cycle on the wall (measured, 0.6 N rms). Cutting only what would
//    take E below zero keeps both: E >= 0 and the bank's debt damped;
//  - the damper opposes the motion (-alpha v). It acts after the force guard
//    (haptics/force_guard.h): the guard's stop, watchdog and soft start zero F and with it the
//    damper (the device driver then resets the controller); the guard's rate and budget limits
//    do not bound the damper's own change, max_force does.
//
// Units: SI, the device frame. passivity_damping_limit 0 turns the controller off (the
// observer still counts). Real-time safety: apply() and the readers allocate nothing, take no
// lock and log nothing.
#pragma once

#include "god_finger/support/parameter_table.h"

#include <Eigen/Core>
#include <string>

namespace god_finger
{
struct PassivityParams
{
  double passivity_damping_limit = 50.0;  // N s/m: the most damping added (0: controller off)
  double passivity_min_damping = 4.0;     // N s/m: b_min, the dissipation asked while pushing
  double passivity_reservoir = 0.1;       // J: E_max, the most energy the observer banks
  // 1/s: how fast the two-port's physics side returns its position drift (two_port_passivity.h)
  double passivity_drift_return = 10.0;
  // J: what the two-port's physics side may let out ahead of the device's energy, so that a
  // contact can start (two_port_passivity.h): its margin never goes below minus this
  double passivity_contact_credit = 1e-4;
};
// passivity_damping_limit, passivity_min_damping, passivity_reservoir, passivity_drift_return,
// passivity_contact_credit:
// names, units, ranges, meanings.
const ParameterTable<PassivityParams>& passivityParameterTable();
// Empty on success, else one line naming the first bad value and its range.
std::string validate(const PassivityParams& params);

class PassivityController
{
 public:
  // `period` (s): the device loop's tick. Throws InputError on bad parameters or period.
  PassivityController(const PassivityParams& params, double period);

  // The force to render this tick for the command `force`, the device moving at `velocity`;
  // |result| <= max_force. Non-finite input: the command is returned unchanged and not counted.
  Eigen::Vector3d apply(const Eigen::Vector3d& force, const Eigen::Vector3d& velocity, double max_force);
  // Forgets the observed energy (a new session: the device's force was off).
  void reset();
  // Starts again from `stored` J (>= 0) that the loop behind the port already holds for the hand
  // (a spring's stretch): the observer's energy is `stored`, the bank min(E_max, stored).
  void reset(double stored);

  // J: the energy the hand put in through the port since the last reset, sum of -F'.v dt (the
  // passivity observer's figure: >= 0 while the controller is on).
  double energy() const
  {
    return energy_;
  }
  double lowestEnergy() const  // J: the lowest energy() since the last reset
  {
    return lowest_energy_;
  }
  double bank() const  // J: the controller's E (what it lets the loop give back), <= E_max
  {
    return bank_;
  }
  double damping() const  // N s/m: the damping added at the last tick
  {
    return damping_;
  }
  double cut() const  // N: the push along the motion taken away at the last tick (beyond the damper)
  {
    return cut_;
  }
  double dissipated() const  // J: the energy the controller took out since the last reset
  {
    return dissipated_;
  }
  long activeTicks() const  // ticks the controller added damping at, since the last reset
  {
    return active_ticks_;
  }
  const PassivityParams& params() const
  {
    return params_;
  }

 private:
  PassivityParams params_;
  double period_;
  double bank_ = 0.0;
  double energy_ = 0.0;
  double lowest_energy_ = 0.0;
  double damping_ = 0.0;
  double cut_ = 0.0;
  double dissipated_ = 0.0;
  long active_ticks_ = 0;
};
}  // namespace god_finger
