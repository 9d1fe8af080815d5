// The multi-rate renderer (servo_loop.h, "Two rates, one feel"): the force one haptic tick
// renders for one interface from the last completed physics step; the
// servo loop's haptic side calls it once per interface and tick.
//
// When the step that took this tick's targets is done (lag 0) and the renderer was exact, the
// hand gets the step's coupling reaction, bit for bit. Otherwise the anchor (the proxy position
// the renderer pulls towards) moves to the step's predicted proxy (below) by at most
// delta = max_force / (stiffness recovery_periods) plus the device's move this tick (at once
// where the prediction is the device itself, out of every plane), and the
// force either rejoins the step's reaction (lag 0, the anchor on the proxy, and the reaction
// within this tick's bound of the last force) or is a spring to the anchor with damping on the
// device's velocity relative to the prediction's, saturated, moving from the last force by at
// most the bound stiffness (|target - previous target| + delta) + damping |velocity - previous
// velocity|.
//
// The predicted proxy (predictedProxy), from the planes of the step's contacts (one per contact,
// through the step's proxy with its normal: the intermediate representation of Mark et al.
// 1996): while the device presses into one of them, the step's proxy, fixed (the wall holds,
// and the contact's friction holds the proxy where the step left it, as the physics does until
// it slips); otherwise the device itself (free space stays free: a fixed anchor pulled a hand
// crossing the air back by stiffness x its move, "sticky air"). Nothing of the step's own force
// is held: replayed a round trip late through the haptic node's local coupling, it gave the hand
// energy it never put in (0.05 J in free motion through 30 ms).
//
// The hold's passivity (haptics/passivity_controller.h, the same observer and controller as the
// device driver's port): a non-null `hold` observes every tick not served by a step (a hold),
// from the energy the coupling stored at the step the hold began on (1/2 |F|^2 (1/stiffness +
// 1/k_s), a soft contact's spring in series), and damps or cuts a force that would give the
// hand more than that plus what the hand put in: energy is spent only where it was stored. A
// spring to a fixed anchor is passive; a new step's proxy moving under a stretched spring is
// what it catches.
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

#include "god_finger/haptics/passivity_controller.h"
#include "god_finger/haptics/virtual_coupling.h"

#include <Eigen/Core>
#include <array>
#include <limits>

namespace god_finger
{
struct InterfaceState;  // physics/world_state.h

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
  // The step's contact planes: plane_count normals (world, unit, out of the bodies), each plane
  // through proxy_position (InterfaceState::contacts' normals).
  static constexpr int kMaxPlanes = 4;
  int plane_count = 0;
  std::array<Eigen::Vector3d, kMaxPlanes> plane_normals{};
};

// The proxy a step predicts for the device at `target` (m, world): the step's proxy while
// `target` is behind one of the step's planes, else `target`.
Eigen::Vector3d predictedProxy(const MultirateStep& step, const Eigen::Vector3d& target);

// The step the world left for one interface (its proxy, coupling reaction, target, a soft
// contact's stiffness and normal, the first kMaxPlanes contacts' planes), `lag` ticks old.
MultirateStep multirateStepOf(const InterfaceState& state, long lag);

// The force (N, world, on the hand) a step holds for the device at `target` moving at `velocity`
// (m, m/s, world): the coupling's spring and damper to the predicted proxy, still where the
// device presses into one of the step's planes, the device itself (no force) elsewhere;
// saturated at max_force. What the hold settles to between steps (renderMultirate moves its
// anchor there by bounded steps), and the force the physics port of the channel counts in the
// nodes (ros/channel_port.h). A soft contact's yield is left out (a stiffer spring: more force).
Eigen::Vector3d heldForce(const CouplingProfile& coupling, const MultirateStep& step, const Eigen::Vector3d& target,
                          const Eigen::Vector3d& velocity);

// Decides this tick's force (N, world, on the hand) into state->force and updates the anchor and
// exactness; returns true when the force is the step's reaction (not stale).
// `hold` (may be null): the hold's passivity controller (the device profile's PassivityParams), reset at each hold's
// first tick.
bool renderMultirate(const CouplingProfile& coupling, int recovery_periods, const MultirateDevice& device,
                     const MultirateStep& step, MultirateState* state, PassivityController* hold = nullptr);
}  // namespace god_finger
