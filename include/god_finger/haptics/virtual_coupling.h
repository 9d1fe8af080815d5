// The virtual coupling (Colgate et al. 1995): a spring-damper between the interface position
// p_I (where the device puts the finger in the world) and the god-object p_GO. This one
// function is what the world applies to the proxy, what the haptic node renders locally and
// what the stability tests close the loop with, so the hand always feels the reaction of the
// force that pulls the proxy.
//
// Units: N/m, N s/m, N, m, m/s; any one frame for all vectors (the world's).
// Invariants: |on_proxy| <= max_force; the hand feels -on_proxy. Real-time safe (no
// allocation, no lock).
#pragma once

#include "god_finger/support/parameter_table.h"

#include <Eigen/Core>
#include <string>

namespace god_finger
{
// One profile per device: loaded once (config/devices/NAME.yaml) and given to everything that
// renders or simulates the coupling of that device's interface.
struct CouplingProfile
{
  double stiffness = 400.0;  // N/m: stable at 1 kHz with the device
  double damping = 4.0;      // N s/m
  double max_force = 20.0;   // N: the coupling force is saturated here
};
// coupling_stiffness, coupling_damping, max_force: names, units, ranges, meanings.
const ParameterTable<CouplingProfile>& couplingParameterTable();
// Empty on success, else one line naming the first bad value and its range.
std::string validate(const CouplingProfile& profile);

struct CouplingForce
{
  Eigen::Vector3d on_proxy = Eigen::Vector3d::Zero();  // N; the hand feels -on_proxy
  bool saturated = false;                              // the spring-damper exceeded max_force
};

// k (p_I - p_GO) + b (v_I - v_GO), scaled down to max_force if longer (direction kept).
CouplingForce couplingForce(const CouplingProfile& profile, const Eigen::Vector3d& interface_position,
                            const Eigen::Vector3d& interface_velocity, const Eigen::Vector3d& proxy_position,
                            const Eigen::Vector3d& proxy_velocity);
}  // namespace god_finger
