// Stage "soft_bodies" of the world's step, the fingers' coupling to the soft bodies (soft_body.h),
// as Drake's DeformableDriver is a piece of its own: after the solve, each finger's contact force
// loads the soft bodies it touches, and they step. Internal to physics.
//
// The force the solver put on proxy i is m dv/dt minus what was applied to it (captured by
// beforeSolve); a finger touching one body gives it all (reversed, under-relaxed: soft_body.h
// kSoftLoadRelaxation), one touching several gives each soft body the part along that contact's
// normal that presses into it. A moved soft body carries the fingers' friction anchors with its
// material and drops the manifolds on it (found again by the next detection).
// Units: SI, world frame. Real-time safe once sized (resize allocates).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace god_finger::internal
{
struct WorldCore;

struct SoftCoupling
{
  // Per proxy: its velocity (m/s) and the force applied to it (N) before this step's solve.
  std::vector<Eigen::Vector3d> proxy_velocity_before;
  std::vector<Eigen::Vector3d> proxy_force_before;

  // One entry per proxy, zero (allocates).
  void resize(std::size_t proxies);
  // Before Bullet's step (nothing without soft bodies).
  void beforeSolve(WorldCore* core);
  // After it: loads and steps the soft bodies (nothing without soft bodies).
  void loadAndStep(WorldCore* core);
};
}  // namespace god_finger::internal
