// Time-domain passivity of the haptic <-> physics channel as a two-port (Ryu, Artigas and
// Preusche 2010; Artigas et al.'s time-delay power network): the network between the hand's
// port (the device: it takes the hand's velocity, gives a force) and the physics' port (it takes
// the hand's position as the link delivered it, gives the coupling's force) is passive when
// neither port lets out more energy than the other put in, counted across the delay:
//   E_out_device(t) <= E_in_physics(t - T_back),   E_out_physics(t) <= E_in_device(t - T_forward).
// Each port observes the power through it, split by sign into what flows into the channel
// (E_in) and what flows out (E_out), both never decreasing; it sends its E_in to the other side
// in time-stamped packets with the messages it already sends. A packet's figure only grows, so a
// lost, late or reordered one leaves the newest figure received, which is never more than the
// sender's true one: the check stays conservative on any link (RemoteEnergy keeps the largest).
//
// Each side's controller enforces its own inequality with the least action its causality allows:
//  - DevicePortPassivity (impedance type, at the device: F' = F - alpha v): as the one-port
//    controller (haptics/passivity_controller.h) but against the energy the physics gave back,
//    not against what the hand put in: only the channel's share is damped, and energy stored in
//    the world (a spring pressed) flows back to the hand undamped. alpha is capped at
//    passivity_damping_limit; beyond it the push along the motion is cut (never reversed).
//  - PhysicsPortPassivity (admittance type, at the physics: the position the physics uses, x' =
//    x + d): where the force there would let out more than the device put in, the position is
//    pulled back along the tick's move (toward the last one used) by just enough; d, the drift,
//    returns toward 0 at passivity_drift_return (1/s) only as far as the energy margin allows.
//    The margin may go down to -passivity_contact_credit and no lower: in free motion the device
//    renders no force and puts nothing in, so without that credit no contact could start (the
//    wall would never push and the hand never pay); with it the first force reaches the hand,
//    and the hand's push against it pays for the rest.
//    The force is re-evaluated at the pulled-back position (answer()'s force_at), so the check
//    uses the force the physics actually answers with.
// Power signs: at the device, P = -F.v (F the force rendered on the hand, v the handle's
// velocity): > 0 flows into the channel. At the physics, P = F.v' (F the force the physics sends
// for the hand, v' the velocity of the position it used): > 0 flows into the channel (the world
// gives energy back), < 0 out of it (the channel pushes the world).
//
// Units: SI (J, N, m, m/s, s); vectors in the one frame both ports share (the sweep's axis; in
// a package topology the world frame, in which positions and forces are power-conjugate).
// Real-time safety: every call allocates nothing, takes no lock and logs nothing.
#pragma once

#include "god_finger/haptics/passivity_controller.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace god_finger
{
// One side's count of the energy through its port (J): into the channel and out of it.
class PortEnergyObserver
{
 public:
  // `power` (W, > 0 into the channel) held for `dt` (s). Non-finite: not counted.
  void observe(double power, double dt);
  double in() const
  {
    return in_;
  }
  double out() const
  {
    return out_;
  }
  void reset()
  {
    in_ = out_ = 0.0;
  }

 private:
  double in_ = 0.0;
  double out_ = 0.0;
};

// What one port tells the other: its E_in (J) as of `stamp` (s, the sender's clock).
struct EnergyPacket
{
  double stamp = -1.0;
  double energy_in = 0.0;
};

// The other port's E_in as the newest packets tell it: the largest figure received (packets
// only grow; an older one arriving late changes nothing). Before any packet: 0.
class RemoteEnergy
{
 public:
  void receive(const EnergyPacket& packet);
  double energyIn() const
  {
    return energy_in_;
  }
  double stamp() const
  {
    return stamp_;
  }
  void reset()
  {
    energy_in_ = 0.0;
    stamp_ = -1.0;
  }

 private:
  double energy_in_ = 0.0;
  double stamp_ = -1.0;
};

// What each side keeps and tells: its observer, the other side's energy in as received, its
// margin's lowest and the ticks its controller acted at.
class PortSide
{
 public:
  RemoteEnergy& remote()
  {
    return remote_;
  }
  const RemoteEnergy& remote() const
  {
    return remote_;
  }
  const PortEnergyObserver& observer() const
  {
    return observer_;
  }
  // The packet to send with this tick's message.
  EnergyPacket packet(double stamp) const
  {
    return {stamp, observer_.in()};
  }
  // J: E_in received - E_out here (>= 0: this side's inequality holds); its lowest since reset.
  double margin() const
  {
    return remote_.energyIn() - observer_.out();
  }
  double lowestMargin() const
  {
    return lowest_margin_;
  }
  long activeTicks() const  // ticks the controller acted at, since the last reset
  {
    return active_ticks_;
  }
  // The other side's packet of `session` (s, any clock, compared for equality only), as the
  // nodes send them: a packet of another session (the other side restarted) replaces the remote
  // figure instead of being compared with the old session's larger one.
  void receive(const EnergyPacket& packet, double session)
  {
    if (session != session_)
    {
      remote_.reset();
      session_ = session;
    }
    remote_.receive(packet);
    ++packets_;
  }
  long packets() const  // received through receive(packet, session) since the last reset
  {
    return packets_;
  }

 protected:
  void noteMargin()
  {
    lowest_margin_ = std::min(lowest_margin_, margin());
  }
  void resetSide()
  {
    observer_.reset();
    remote_.reset();
    lowest_margin_ = 0.0;
    active_ticks_ = 0;
    packets_ = 0;
    session_ = std::numeric_limits<double>::quiet_NaN();
  }
  PortEnergyObserver observer_;
  RemoteEnergy remote_;
  double lowest_margin_ = 0.0;
  long active_ticks_ = 0;
  long packets_ = 0;
  double session_ = std::numeric_limits<double>::quiet_NaN();  // NaN: none yet (never equal)
};

// The work (J) of a force over a position's moves, one move per call: what the physics port
// counts (PhysicsPortPassivity: the force it answered with over the move of the position it
// used), in the delay sweep and in the physics node (ros/channel_port.h).
class MoveWork
{
 public:
  // `force` . (`position` - the last kept position) into `joules`, true; false at the first
  // call (nothing to move from). A non-finite position or force: false, and not kept.
  bool work(const Eigen::Vector3d& position, const Eigen::Vector3d& force, double* joules)
  {
    if (!force.allFinite() || !position.allFinite())
    {
      return false;
    }
    const bool moved = has_last_;
    if (moved)
    {
      *joules = force.dot(position - last_);
    }
    last_ = position;
    has_last_ = true;
    return moved;
  }
  bool hasLast() const
  {
    return has_last_;
  }
  const Eigen::Vector3d& last() const  // m: the last position kept
  {
    return last_;
  }
  void reset()
  {
    last_.setZero();
    has_last_ = false;
  }

 private:
  Eigen::Vector3d last_ = Eigen::Vector3d::Zero();
  bool has_last_ = false;
};

// A port observed and not controlled: the haptic node's device port across processes (its
// packets god_finger/PortEnergy on the link's topics, its figures on /diagnostics). The sides
// count from `session` (the sender's start; PortSide::receive).
class ObservedPort : public PortSide
{
 public:
  // J through the port this sample (> 0 into the channel; non-finite: not counted).
  void observeWork(double work)
  {
    observer_.observe(work, 1.0);
    noteMargin();
  }
  void reset()
  {
    resetSide();
  }
};

// The device's side. Parameters: passivity_damping_limit (0: observer only, the force passes).
class DevicePortPassivity : public PortSide
{
 public:
  // `period` (s): the device loop's tick. InputError on bad parameters or period.
  DevicePortPassivity(const PassivityParams& params, double period);
  // The force to render this tick for the command `force` (N), the handle moving at `velocity`
  // (m/s), against the physics' E_in received so far; |result| <= max_force.
  Eigen::Vector3d apply(const Eigen::Vector3d& force, const Eigen::Vector3d& velocity, double max_force);
  double damping() const  // N s/m: added at the last tick
  {
    return damping_;
  }
  void reset();

 private:
  PassivityParams params_;
  double period_;
  double damping_ = 0.0;
};

// The physics' side. Parameters: passivity_damping_limit (0: observer only, no drift),
// passivity_drift_return and passivity_contact_credit.
class PhysicsPortPassivity : public PortSide
{
 public:
  PhysicsPortPassivity(const PassivityParams& params, double period);
  // This tick's answer for the hand seen at `position` moving at `velocity` (m, m/s): the force
  // (N, on the hand) `force_at(x, v)` gives at the position used, which it also returns in
  // `used_position` and `used_velocity`. The position used is the one seen plus the drift (the
  // drift returning first); where the force there would let out more than the device put in,
  // it is pulled back along this tick's move toward the last one used until it does not (the
  // largest fraction of the move that fits, by bisection: kSettleIterations calls of force_at,
  // which must depend on nothing but its arguments). Not moving lets nothing out, so a fit is
  // always found. Call once a tick; RT-safe if force_at is.
  template <class ForceAt>
  Eigen::Vector3d answer(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, ForceAt&& force_at,
                         Eigen::Vector3d* used_position, Eigen::Vector3d* used_velocity)
  {
    const Eigen::Vector3d last_drift = drift_;
    // A non-finite position is passed on untouched and leaves the drift as it was; a non-finite
    // velocity is taken as still (the move's own velocity is added below).
    const bool finite = position.allFinite();
    const Eigen::Vector3d seen_velocity = velocity.allFinite() ? velocity : Eigen::Vector3d::Zero();
    const bool acting = params_.passivity_damping_limit > 0.0 && finite;
    if (acting)
    {
      drift_ *= 1.0 - std::min(1.0, params_.passivity_drift_return * period_);
    }
    const auto at = [&](double fraction, Eigen::Vector3d* x, Eigen::Vector3d* v) -> Eigen::Vector3d
    {
      *x = moves_.hasLast() && fraction < 1.0
               ? Eigen::Vector3d(moves_.last() + fraction * (position + drift_ - moves_.last()))
               : Eigen::Vector3d(position + drift_);
      *v = seen_velocity + ((*x - position) - last_drift) / period_;
      return force_at(*x, *v);
    };
    Eigen::Vector3d force = at(1.0, used_position, used_velocity);
    if (acting && moves_.hasLast() && leaving(force, *used_position) > allowance())
    {
      double fits = 0.0;
      double fails = 1.0;
      for (int i = 0; i < kSettleIterations; ++i)
      {
        const double half = 0.5 * (fits + fails);
        Eigen::Vector3d x, v;
        (leaving(at(half, &x, &v), x) > allowance() ? fails : fits) = half;
      }
      force = at(fits, used_position, used_velocity);
      ++active_ticks_;
    }
    if (finite)
    {
      drift_ = *used_position - position;
    }
    observe(*used_position, force);
    return force;
  }
  static constexpr int kSettleIterations = 30;
  // m: the drift, the position used less the position seen.
  const Eigen::Vector3d& drift() const
  {
    return drift_;
  }
  void reset();

 private:
  PassivityParams params_;
  double period_;
  Eigen::Vector3d drift_ = Eigen::Vector3d::Zero();
  MoveWork moves_;  // from the position used last tick

  // J: what this tick may let out: the margin and the contact's credit (a breach past is not
  // paid by holding still).
  double allowance() const
  {
    return std::max(0.0, margin() + params_.passivity_contact_credit);
  }
  // J: what answering `force` at `position` would let out of the channel this tick (a
  // non-finite force: everything, so that the bisection moves back).
  double leaving(const Eigen::Vector3d& force, const Eigen::Vector3d& position) const
  {
    const double out = -force.dot(position - moves_.last());
    return std::isfinite(out) ? std::max(0.0, out) : std::numeric_limits<double>::infinity();
  }
  void observe(const Eigen::Vector3d& position, const Eigen::Vector3d& force);
};
}  // namespace god_finger
