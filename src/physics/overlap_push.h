// The overlap push (paper, Discussion): when two fingers' contact areas on one body overlap
// (contact/area_overlap.h: they share surface on one side of the body; pads on opposite faces never
// overlap), both proxies are pushed apart, equal and opposite, in the common plane from one
// area's centre towards the other's, with a force of WorldParams::overlap.stiffness times the
// overlap area (N/m^2 x m^2), capped at the coupling's max_force.
// The push never opens a grasp: a finger whose area on the body is pressed against by another
// finger's area on the same body (normals more than 90 degrees apart: the body is squeezed
// between them) gets no push from that overlap, whatever the stiffness; the other finger of the
// overlapping pair still does, when it holds nothing. The hands feel it
// through their couplings (scripted hands do not react: the push moves the proxies). Each proxy's
// push moves towards its target by at most overlap.force_rate * dt per step (N), so that it adds
// no force step.
//
// Per step, after the solver: update() writes every area's and interface's overlap area
// (WorldContactArea::overlap_area, InterfaceState::overlap_area: m^2, summed over the other
// fingers' areas) and the push of the next step (InterfaceState::overlap_push, N on the proxy,
// world). The areas are measured whatever the stiffness (god_finger model only: the other
// models' contacts are points, with no area); stiffness 0 pushes nothing.
// Invariant: no overlap now and no push before: every push stays exactly zero.
//
// When the overlap ends, the push fades at the same rate (3 N in 30 ms at the default rate).
//
// Units: SI, world frame. resize() allocates; update() and push() are real-time safe.
#pragma once

#include "god_finger/physics/world_params.h"
#include "proxy.h"

#include <Eigen/Core>
#include <vector>

namespace god_finger::internal
{
class OverlapPush
{
 public:
  // One push per interface, all zero (a new interface, a reset).
  void resize(int interfaces);
  // From the proxies' contact areas of the step that just ended (their targets are the hands).
  void update(const WorldParams& params, std::vector<Proxy>* proxies);
  // The force (N, world) on interface `interface`'s proxy in the next step.
  const Eigen::Vector3d& push(int interface) const
  {
    return pushes_[interface];
  }

 private:
  std::vector<Eigen::Vector3d> targets_;
  std::vector<Eigen::Vector3d> pushes_;
};
}  // namespace god_finger::internal
