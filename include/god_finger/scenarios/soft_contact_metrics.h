// The soft scenarios' metrics (press_soft, stroke_soft: docs/experiments.md), step by step from
// the soft body (BodyDescription::soft, static: its surface is the world's walk mesh of it,
// deformed) and the finger (interface 0):
//  - press_soft, over the hold's last 0.5 s (ScenarioTimes: lift_start is the hold's start,
//    lift_end the run's end): sink_m, the surface's deepest sink from where it rests untouched
//    (the dimple); hand_force_N, the force on the hand (mean); area_radius_m, the contact area's
//    radius r (mean); w0_m, Boussinesq's sink of that force spread as a uniform pressure over a
//    disk of that radius on a half-space of the body's E and nu (soft/surface_load.h), and
//    sink_over_w0;
//  - stroke_soft, over the stroke [lift_start, lift_end]: trace_m, the proxy's path length;
//    stick_slip_events, how often the proxy went from stuck (under 1 mm/s) to slipping (over
//    5 mm/s); friction_ratio_max, the largest |tangential| / |normal| force on the hand (z is
//    the surface's normal); hand_force_N, the mean normal force; sink_m, the deepest sink;
//  - pinch_soft: squash, the largest relative shortening of the body along x (across the two
//    fingers: 1 - its width now over its width untouched, its width in the frame that follows
//    its mean displacement); lift_height_m, its frame's rise at the end; over the hold after
//    the lift (from ScenarioTimes::lift_end on), hand_force_N, the fingers' mean force, and
//    sink_m, the deepest deformation (its best-fit rigid motion since untouched taken out:
//    Eigen's umeyama); turn_rad, its largest best-fit rotation from the lift's start on (its
//    Bullet body only translates: pinch_metrics.h cannot see it turn). Before stop 43 sink_m
//    counted the turn too: 8.1 mm of a 3 cm ball turned 0.25 rad from its untouched shape;
//  - all, over every step with a finger on the body: penetration_max_m and
//    penetration_p99_m, how far a proxy's sphere reached into the deformed surface (its
//    radius less its centre's distance to the surface, 0 when outside).
// Units: SI, world frame. Not real-time (vectors grow, a map of results).
#pragma once

#include "god_finger/geometry/surface_locator.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scenarios/experiment.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace god_finger
{
class SoftContactMetrics
{
 public:
  // `object`: the soft body's index in `world`, before the first step. InputError when it is
  // not a soft body.
  SoftContactMetrics(Scenario scenario, int object, const ScenarioTimes& times, const GodFingerWorld& world);
  // After each step that ended at `time` (s).
  void add(double time, const GodFingerWorld& world);
  std::map<std::string, double> metrics() const;

 private:
  double deepestSink(const GodFingerWorld& world) const;
  // pinch_soft's free ball: its deepest deformation with its best-fit rigid motion since it was
  // untouched taken out (a turn in the grip moves its surface too, and is no sink).
  double deepestDeformation(const GodFingerWorld& world) const;
  static double widthAlongX(const std::vector<Eigen::Vector3d>& vertices);

  Scenario scenario_;
  int object_ = -1;
  ScenarioTimes times_;
  double young_modulus_ = 0.0;  // Pa
  double poisson_ratio_ = 0.0;
  std::vector<Eigen::Vector3d> untouched_;   // the surface's vertices before the first step (body frame)
  std::unique_ptr<SurfaceLocator> locator_;  // on the world's walk mesh of the body, refitted each step
  std::vector<double> penetrations_;         // m, per step in contact
  // press_soft's hold and stroke_soft's stroke.
  int samples_ = 0;
  double force_sum_ = 0.0;
  double radius_sum_ = 0.0;
  double sink_ = 0.0;
  double trace_ = 0.0;
  Eigen::Vector3d last_proxy_ = Eigen::Vector3d::Zero();
  bool tracing_ = false;
  bool stuck_ = true;
  int stick_slips_ = 0;
  double friction_ratio_ = 0.0;
  // pinch_soft's.
  double untouched_width_ = 0.0;  // m
  double start_height_ = 0.0;     // m
  double squash_ = 0.0;
  double lift_ = 0.0;                           // m
  std::vector<Eigen::Vector3d> grip_vertices_;  // the surface at the lift's start (body frame)
  double turn_ = 0.0;                           // rad
};
}  // namespace god_finger
