// The multi-rate renderer (servo_loop.h, "Two rates, one feel"): the force one haptic tick
// renders for one interface from the last completed physics step; the
// servo loop's haptic side calls it once per interface and tick.
//
// When the step that took this tick's targets is done (lag 0) and the renderer was exact, the
// hand gets the step's coupling reaction, bit for bit. Otherwise the anchor (the proxy position
// the renderer pulls towards) moves to the step's proxy by at most
// delta = max_force / (stiffness recovery_periods) per tick, and the force either rejoins the
// step's reaction (lag 0, the anchor on the proxy, and the reaction within this tick's bound of
// the last force) or is a spring to the anchor with damping on the device's own velocity,
// saturated, moving from the last force by at most the bound
// stiffness (|target - previous target| + delta) + damping |velocity - previous velocity|.
//
// A soft contact (a finite contact stiffness k_s): between steps the proxy is not a wall but
// yields along the contact's normal n as the body would, linearised at the step (SOFA's
// LCPForceFeedback re-solves its constraints with the last compliance the same way): with the
// device dx along n past the step's target, the proxy moves k_c dx / (k_c + k_s), so the hand's
// force along n changes by -k_c k_s / (k_c + k_s) dx (the coupling and the body in series), and
// never pulls (the proxy leaves the surface at zero force). The spring pulls to the anchor moved
// by that yield; the anchor itself, the bound and the return to exactness are as above. A rigid
// contact (k_s infinite) is rendered as before, bit for bit.
//
// Units: SI, world frame. Real-time safe (no allocation).
#pragma once

#include "god_finger/haptics/virtual_coupling.h"

#include <Eigen/Core>
#include <limits>

namespace god_finger
{
struct MultirateState
{
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();  // m
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N on the hand, the last decided
  bool exact = true;                                 // the force is the step's reaction
};

// This tick's device: its mapped target and velocity, and the previous tick's (m, m/s, world).
struct MultirateDevice
{
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  Eigen::Vector3d previous_target = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d previous_velocity = Eigen::Vector3d::Zero();
};

// The last completed step's proxy (m, world) and coupling reaction on the hand (N, world), and
// how many ticks it lags this one (0: it took this tick's targets).
struct MultirateStep
{
  Eigen::Vector3d proxy_position = Eigen::Vector3d::Zero();
  Eigen::Vector3d user_force = Eigen::Vector3d::Zero();
  long lag = 0;
  // A soft contact (InterfaceState::contact_stiffness finite): the device target the step took
  // (m, world), the contact's stiffness k_s (N/m) along its normal n (world, out of the body).
  Eigen::Vector3d step_target = Eigen::Vector3d::Zero();
  double contact_stiffness = std::numeric_limits<double>::infinity();
  Eigen::Vector3d contact_normal = Eigen::Vector3d::UnitZ();
};

// Decides this tick's force (N, world, on the hand) into state->force and updates the anchor and
// exactness; returns true when the force is the step's reaction (not stale).
bool renderMultirate(const CouplingProfile& coupling, int recovery_periods, const MultirateDevice& device,
                     const MultirateStep& step, MultirateState* state);
}  // namespace god_finger
