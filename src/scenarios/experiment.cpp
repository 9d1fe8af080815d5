#include "god_finger/scenarios/experiment.h"

#include "god_finger/scenarios/joint_metrics.h"
#include "god_finger/scenarios/overlap_metrics.h"
#include "god_finger/scenarios/pinch_metrics.h"
#include "god_finger/scenarios/scenario_metrics.h"
#include "god_finger/scenarios/soft_contact_metrics.h"
#include "roll_metrics.h"

#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/parameter_json.h"
#include "god_finger/support/text_numbers.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>

namespace god_finger
{
namespace
{
// What a scenario needs: its scene, the object watched, the hand's script per finger, and
// the time the lift ends (metrics "after the lift" start there).
struct Script
{
  std::string scene_file;
  std::string object;
  std::vector<WaypointPath> fingers;
  std::vector<OrientationPath> orientations;               // per finger; empty: 3-DOF fingers
  double duration = 0.0;                                   // s, default length
  double lift_start = 0.0;                                 // s
  double lift_end = 0.0;                                   // s
  double lift_height = 0.0;                                // m, commanded
  double carry_end = 0.0;                                  // s, pick and place only
  double release = 0.0;                                    // s, pick and place only
  Eigen::Vector3d place_target = Eigen::Vector3d::Zero();  // m, world, pick and place only
};

ScenarioTimes timesOf(const Script& script)
{
  ScenarioTimes times;
  times.duration = script.duration;
  times.lift_end = script.lift_end;
  times.lift_height = script.lift_height;
  times.lift_start = script.lift_start;
  times.carry_end = script.carry_end;
  times.release = script.release;
  times.place_target = script.place_target;
  return times;
}

Eigen::Vector3d xyz(double x, double y, double z)
{
  return Eigen::Vector3d(x, y, z);
}

// The seed's share of the asymmetry: a uniform offset in [-0.5, 0.5] mm.
double seededJitter(std::uint64_t seed)
{
  std::mt19937_64 generator(seed);
  // Drawn by hand from the raw bits so that every standard library gives the same value.
  const double unit = static_cast<double>(generator() >> 11) / 9007199254740992.0;  // [0, 1)
  return (unit - 0.5) * 1e-3;
}

// Fig. 5. Ball r = 4 cm centred at z = 0.04. The hand, `push_height` above the ball's
// centre, comes from x = -0.07 to x = -0.03 in 0.5 s (the proxy stops on the ball's back at
// x ~ -0.041: about 4 N of coupling), waits 0.3 s, then pushes 10 cm along +x in 2 s and
// waits 0.5 s. Asymmetry: the hand drifts 2 mm (+ jitter) sideways (+y) while pushing.
Script slideScript(double push_height, std::uint64_t seed)
{
  const double drift = 0.002 + seededJitter(seed);
  const double z = 0.04 + push_height;
  Script script;
  script.scene_file = "table_sphere.urdf";
  script.object = "ball";
  script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(-0.07, 0, z)},
                                                    {0.5, xyz(-0.03, 0, z)},
                                                    {0.8, xyz(-0.03, 0, z)},
                                                    {2.8, xyz(0.07, drift, z)},
                                                    {3.3, xyz(0.07, drift, z)}});
  script.duration = 3.3;
  script.lift_start = script.lift_end = 0.8;
  return script;
}

// Fig. 6 and 7. The plate (bottom at z = 0.1, 25 g) rests on two rails; fingers come from
// under it between the rails and lift it 10 cm, in 2 s (fast: 0.2 s), then hold until 4 s.
// Asymmetry: the fingers are 2 mm (+ jitter) off the plate's centre along x.
Script liftScript(bool two_fingers, bool fast, std::uint64_t seed)
{
  const double offset = 0.002 + seededJitter(seed);
  const double lift_time = fast ? 0.2 : 2.0;
  Script script;
  script.scene_file = "rails_plate.urdf";
  script.object = "plate";
  script.lift_start = 0.5;
  script.lift_end = script.lift_start + lift_time;
  script.lift_height = 0.1;
  script.duration = 4.0;
  const std::vector<double> ys = two_fingers ? std::vector<double>{-0.012, 0.012} : std::vector<double>{0.0};
  for (double y : ys)
  {
    // Below the plate by 2 mm of the proxy surface at lift start; the lift raises the hand
    // by 10.5 cm so that the plate, carried 0.5 mm under the coupling's rest, rises 10 cm.
    script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(offset, y, 0.08)},
                                                      {script.lift_start, xyz(offset, y, 0.095)},
                                                      {script.lift_end, xyz(offset, y, 0.2)},
                                                      {script.duration, xyz(offset, y, 0.2)}});
  }
  return script;
}

// Fig. 8. Cylinder r = 3 cm, l = 12 cm, axis along x at z = 0.03, ends at x = +-0.06.
// Fingers at z = 0.025 (5 mm under the axis) close from x = +-0.075 to +-0.053 in 1 s (the
// proxies stop at +-0.063: 1 cm of coupling stretch, 4 N each), wait 0.5 s, lift 10 cm in
// 2 s, then stop until 25 s. Asymmetry: the fingers are 1 mm apart along y (+-0.5 mm), and
// the right one is off in z by the jitter.
Script pinchScript(std::uint64_t seed)
{
  const double jitter = seededJitter(seed);
  Script script;
  script.scene_file = "table_cylinder.urdf";
  script.object = "cylinder";
  script.lift_start = 1.5;
  script.lift_end = 3.5;
  script.lift_height = 0.1;
  script.duration = 25.0;
  for (int side : {-1, 1})
  {
    const double y = -0.0005 * side;
    const double z = 0.025 + (side > 0 ? jitter : 0.0);
    script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(0.075 * side, y, z)},
                                                      {1.0, xyz(0.053 * side, y, z)},
                                                      {script.lift_start, xyz(0.053 * side, y, z)},
                                                      {script.lift_end, xyz(0.053 * side, y, z + 0.1)},
                                                      {script.duration, xyz(0.053 * side, y, z + 0.1)}});
  }
  return script;
}

// table_clutter.urdf (scripts/make_clutter_scene): pick_box, a 5 cm cube of 100 g, stands on
// the pile's base (top at z = 0.04), centred at (0, -0.03, 0.065); the pile's other bodies stand
// 2 cm or more behind it (+y), nothing else within 10 cm on either side along x. Fingers 5 mm
// under the box's centre close along x from +-0.055 to +-0.018 in 1 s (the proxies stop at
// +-0.028: 1 cm of coupling stretch, 4 N each), wait 0.5 s, lift 6 cm in 1.5 s, carry 13 cm
// along -y in 2 s (6.5 cm/s), lower 10.2 cm in 1.5 s (to 2 mm under where the box, carried
// at its start height plus the lift, touches the table: the box lands, the grip slips or
// stretches by those 2 mm), wait 0.5 s, open to +-0.055 in 0.5 s, rise 5 cm in 0.5 s and wait
// until 9 s. Target: the box's centre at (0, -0.16, 0.025). Asymmetry as the pinch's: the
// fingers 1 mm apart along y (+-0.5 mm), the right one off in z by the jitter.
Script clutterScript(std::uint64_t seed)
{
  const double jitter = seededJitter(seed);
  const double y0 = -0.03;
  const double y1 = -0.16;
  const double z0 = 0.065 - 0.005;  // 5 mm under the box's centre
  const double lift = 0.06;
  const double lower = 0.102;
  Script script;
  script.scene_file = "table_clutter.urdf";
  script.object = "pick_box";
  script.lift_start = 1.5;
  script.lift_end = 3.0;
  script.lift_height = lift;
  script.carry_end = 5.0;
  script.release = 7.0;
  script.duration = 9.0;
  script.place_target = xyz(0.0, y1, 0.025);
  for (int side : {-1, 1})
  {
    const double dy = -0.0005 * side;
    const double z = z0 + (side > 0 ? jitter : 0.0);
    const double open = 0.055 * side;
    const double closed = 0.018 * side;
    script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(open, y0 + dy, z)},
                                                      {1.0, xyz(closed, y0 + dy, z)},
                                                      {script.lift_start, xyz(closed, y0 + dy, z)},
                                                      {script.lift_end, xyz(closed, y0 + dy, z + lift)},
                                                      {script.carry_end, xyz(closed, y1 + dy, z + lift)},
                                                      {6.5, xyz(closed, y1 + dy, z + lift - lower)},
                                                      {script.release, xyz(closed, y1 + dy, z + lift - lower)},
                                                      {7.5, xyz(open, y1 + dy, z + lift - lower)},
                                                      {8.0, xyz(open, y1 + dy, z + lift - lower + 0.05)},
                                                      {script.duration, xyz(open, y1 + dy, z + lift - lower + 0.05)}});
  }
  return script;
}

// table_mug.urdf: the mug (urdf/meshes/mug.obj: outer radius 4 cm, 9 cm high, the handle on
// +x) stands at the origin. Three fingers at 60, 180 and 300 degrees about z, 5 cm up, close
// from 7 cm off the axis to 3.3 cm in 1 s (the proxies stop on the wall at 4.3 cm: 1 cm of
// coupling stretch, 4 N each), wait 0.5 s, lift 10 cm in 2 s, hold until 4.5 s, open back to
// 7 cm in 0.3 s, and stay until 5.5 s (the mug falls back onto the table in about 0.15 s).
// Asymmetry: the hand's centre is 2 mm (+ jitter) off the mug's axis along y.
Script handGraspScript(std::uint64_t seed)
{
  const double offset = 0.002 + seededJitter(seed);
  Script script;
  script.scene_file = "table_mug.urdf";
  script.object = "mug";
  script.lift_start = 1.5;
  script.lift_end = 3.5;
  script.lift_height = 0.1;
  script.release = 4.5;
  script.duration = 5.5;
  const double z = 0.05;
  for (const double degrees : {60.0, 180.0, 300.0})
  {
    const double angle = degrees * M_PI / 180.0;
    const Eigen::Vector3d out(std::cos(angle), std::sin(angle), 0.0);
    const Eigen::Vector3d centre(0.0, offset, z);
    const Eigen::Vector3d up(0.0, 0.0, script.lift_height);
    script.fingers.emplace_back(std::vector<Waypoint>{{0.0, centre + 0.07 * out},
                                                      {1.0, centre + 0.033 * out},
                                                      {script.lift_start, centre + 0.033 * out},
                                                      {script.lift_end, centre + 0.033 * out + up},
                                                      {script.release, centre + 0.033 * out + up},
                                                      {script.release + 0.3, centre + 0.07 * out + up},
                                                      {script.duration, centre + 0.07 * out + up}});
  }
  return script;
}

// table_box.urdf: the 6 cm cube (100 g) stands on the table, its top at z = 0.06. The finger,
// along +x with its pulp down, comes down from 7.5 cm to 5.3 cm in 0.5 s (the proxy stops on the
// top at 6.3 cm: 1 cm of coupling stretch, 4 N), waits 0.3 s, rolls 40 degrees about its own x
// in 1 s and holds until 2.5 s. Asymmetry: the finger is 2 mm (+ jitter) off the top's centre
// along x.
Script rollFingerScript(std::uint64_t seed)
{
  const double x = 0.002 + seededJitter(seed);
  const double roll = 40.0 * M_PI / 180.0;
  Script script;
  script.scene_file = "table_box.urdf";
  script.object = "cube";
  script.lift_start = 0.8;
  script.lift_end = 1.8;
  script.duration = 2.5;
  script.fingers.emplace_back(
      std::vector<Waypoint>{{0.0, xyz(x, 0, 0.075)}, {0.5, xyz(x, 0, 0.053)}, {script.duration, xyz(x, 0, 0.053)}});
  const Eigen::Quaterniond pulp_down(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));
  const Eigen::Quaterniond rolled = pulp_down * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
  script.orientations.emplace_back(std::vector<OrientationWaypoint>{
      {0.0, pulp_down}, {script.lift_start, pulp_down}, {script.lift_end, rolled}, {script.duration, rolled}});
  return script;
}

// holder_plate.urdf: a 2 mm plate clamped upright, its faces at x = -+0.001, 10 cm wide along y.
// Two fingers on the same face (-x), 3.5 cm up, come from x = -0.02 to x = 0 in 0.5 s (their
// proxies stop on the face at x = -0.004: 4 mm of coupling stretch, 1.6 N each, pads of r = 9.8 mm),
// 1.5 cm to either side of the middle along y (3 cm apart: the areas do not overlap yet). They
// wait 0.2 s, then slide towards each other along the face for 2 s until they meet (their areas
// would cover each other: the paper's bimanual overlap), and hold until 3.5 s. Asymmetry: the right
// finger ends 1 mm (+ jitter) past the left one along y, and 0.5 mm higher.
Script pinchThinScript(std::uint64_t seed)
{
  const double jitter = seededJitter(seed);
  const double z = 0.035;
  Script script;
  script.scene_file = "holder_plate.urdf";
  script.object = "plate";
  script.lift_start = script.lift_end = 0.7;
  script.duration = 3.5;
  for (int side : {-1, 1})
  {
    const double y0 = 0.015 * side;
    const double y1 = side > 0 ? 0.001 + jitter : 0.0;
    const double zs = z + (side > 0 ? 0.0005 : 0.0);
    script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(-0.02, y0, zs)},
                                                      {0.5, xyz(0.0, y0, zs)},
                                                      {0.7, xyz(0.0, y0, zs)},
                                                      {2.7, xyz(0.0, y1, zs)},
                                                      {script.duration, xyz(0.0, y1, zs)}});
  }
  return script;
}

// table_card.urdf: a 14 x 7 x 0.8 cm phone (150 g) on the table, 5.5 cm of it over the edge
// (x = 0). Two fingers pinch the overhang 2 cm past the edge across the phone's thickness: the top
// one comes down from 2 cm above it onto its top face in 0.4 s, the bottom one up from under the
// edge (z = -0.02) onto its bottom face in 0.2-0.6 s, each touching with 1 mm of coupling stretch
// (0.4 N: less than the phone's weight holds about the edge), then both squeeze together to 1 cm
// inside their proxies' rest (proxy radius 3 mm; 3.9 N each) in 0.6-0.9 s, so that neither tips the
// phone over the edge. They lift it 10 cm in 1.0-2.5 s and hold until 3.5 s: its far end comes off
// the table and only the pinch holds it, against the 0.05 N m of its weight 3.5 cm from the pinch.
// Asymmetry: the fingers are 2 mm (+ jitter) off the phone's middle along y.
Script pinchCardScript(std::uint64_t seed)
{
  const double x = 0.02;
  const double y = 0.002 + seededJitter(seed);
  const double thickness = 0.008;
  const double proxy = 0.003;
  const double touch = 0.001;
  const double squeeze = 0.01;
  const double lift = 0.1;
  Script script;
  script.scene_file = "table_card.urdf";
  script.object = "card";
  script.lift_start = 1.0;
  script.lift_end = 2.5;
  script.lift_height = lift;
  script.duration = 3.5;
  const double top_face = thickness + proxy;  // the top proxy's centre at rest on the face
  const double bottom_face = -proxy;
  script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(x, y, top_face + 0.02)},
                                                    {0.4, xyz(x, y, top_face - touch)},
                                                    {0.6, xyz(x, y, top_face - touch)},
                                                    {0.9, xyz(x, y, top_face - squeeze)},
                                                    {script.lift_start, xyz(x, y, top_face - squeeze)},
                                                    {script.lift_end, xyz(x, y, top_face - squeeze + lift)},
                                                    {script.duration, xyz(x, y, top_face - squeeze + lift)}});
  script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(x, y, -0.02)},
                                                    {0.2, xyz(x, y, -0.02)},
                                                    {0.6, xyz(x, y, bottom_face + touch)},
                                                    {0.9, xyz(x, y, bottom_face + squeeze)},
                                                    {script.lift_start, xyz(x, y, bottom_face + squeeze)},
                                                    {script.lift_end, xyz(x, y, bottom_face + squeeze + lift)},
                                                    {script.duration, xyz(x, y, bottom_face + squeeze + lift)}});
  return script;
}

// door.urdf: a 30 x 40 cm door on a vertical hinge at the origin, closed along +x, its -y face at
// y = -0.0075. A finger at the door's mid-height, `lever` = 27 cm from the hinge, comes to that
// face from 4 cm away in 0.5 s, its target 4 mm inside where its proxy rests on the face (1.6 N
// of coupling to start the door), then follows the face's arc open to 65 degrees in 3 s (0.5 to
// 3.5 s; about 0.38 rad/s, the hinge's damping then asks 0.03 N m, 0.1 N at the finger) and holds
// until 4.5 s. Asymmetry: the lever is off by the seed's jitter, the finger 3 mm above mid-height.
Script doorScript(std::uint64_t seed)
{
  const double lever = 0.27 + seededJitter(seed);
  const double z = 0.005 + 0.2 + 0.003;
  const double inside = 0.0075 + 0.003 - 0.004;  // the target's distance from the hinge plane
  const double open = 65.0 * M_PI / 180.0;
  Script script;
  script.scene_file = "door.urdf";
  script.object = "door";
  script.lift_start = 0.5;
  script.lift_end = 3.5;
  script.duration = 4.5;
  const auto on_arc = [&](double angle, double off_face)
  {
    return xyz(lever * std::cos(angle) + off_face * std::sin(angle),
               lever * std::sin(angle) - off_face * std::cos(angle), z);
  };
  std::vector<Waypoint> path = {{0.0, on_arc(0.0, 0.04)}, {script.lift_start, on_arc(0.0, inside)}};
  const int pieces = 26;  // 2.5 degrees each: the chord strays 0.07 mm from the arc
  for (int k = 1; k <= pieces; ++k)
  {
    const double share = static_cast<double>(k) / pieces;
    path.push_back({script.lift_start + share * (script.lift_end - script.lift_start), on_arc(share * open, inside)});
  }
  path.push_back({script.duration, on_arc(open, inside)});
  script.fingers.emplace_back(path);
  return script;
}

// drawer.urdf: a handle-less drawer drawn 8 cm out of its cabinet, its top at z = 0.10 showing
// from x = 0 to 0.08. A finger comes down onto that top at x = 5 cm in 0.5 s, its target 7.5 mm
// inside where its proxy rests (3 N of coupling: a pad of friction 0.8 x 0.8 can pull 1.9 N),
// waits 0.2 s, pulls 12 cm along +x in 2 s (0.06 m/s: the runners ask 0.5 N of friction and
// 0.12 N of damping) and waits 0.3 s, then rises 4 cm by 3.5 s. Asymmetry: 3 mm (+ jitter) off
// the drawer's middle along y.
Script drawerScript(std::uint64_t seed)
{
  const double x = 0.05;
  const double y = 0.003 + seededJitter(seed);
  const double press = 0.10 + 0.003 - 0.0075;
  const double pull = 0.12;
  Script script;
  script.scene_file = "drawer.urdf";
  script.object = "drawer";
  script.lift_start = 0.7;
  script.lift_end = 2.7;
  script.duration = 3.5;
  script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(x, y, 0.14)},
                                                    {0.5, xyz(x, y, press)},
                                                    {script.lift_start, xyz(x, y, press)},
                                                    {script.lift_end, xyz(x + pull, y, press)},
                                                    {3.0, xyz(x + pull, y, press)},
                                                    {script.duration, xyz(x + pull, y, 0.14)}});
  return script;
}

// soft_block.urdf: a 10 cm soft cube on the table, its top at z = 0.10 (a little lower, settled
// under its weight). A finger comes down from 3 cm above the top's centre to 3 mm above it in
// 0.5 s, then its target goes 1.5 cm past the top by 1.5 s (press_soft: about 4 N through the
// 400 N/m coupling, a dimple of millimetres) and holds until 3 s. Asymmetry: 2 mm (+ jitter)
// off the centre along x, 1 mm along y.
Script pressSoftScript(std::uint64_t seed)
{
  const double x = 0.002 + seededJitter(seed);
  const double y = 0.001;
  const double top = 0.10;
  Script script;
  script.scene_file = "soft_block.urdf";
  script.object = "soft_block";
  script.lift_start = 1.5;  // the hold
  script.lift_end = 3.0;
  script.duration = 3.0;
  script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(x, y, top + 0.03)},
                                                    {0.5, xyz(x, y, top + 0.003)},
                                                    {script.lift_start, xyz(x, y, top - 0.015)},
                                                    {script.duration, xyz(x, y, top - 0.015)}});
  return script;
}

// stroke_soft: the same approach, the target 1.2 cm past the top by 1.5 s, a hold until 2 s, a
// stroke of 3 cm along +x in 2 s (15 mm/s), a hold of 0.5 s and a rise to 3 cm above the top by
// 5 s. Asymmetry: 1.5 cm before the centre along x (the stroke crosses it), 1 mm (+ jitter)
// along y.
Script strokeSoftScript(std::uint64_t seed)
{
  const double x = -0.015;
  const double y = 0.001 + seededJitter(seed);
  const double top = 0.10;
  const double press = top - 0.012;
  Script script;
  script.scene_file = "soft_block.urdf";
  script.object = "soft_block";
  script.lift_start = 2.0;  // the stroke
  script.lift_end = 4.0;
  script.duration = 5.0;
  script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(x, y, top + 0.03)},
                                                    {0.5, xyz(x, y, top + 0.003)},
                                                    {1.5, xyz(x, y, press)},
                                                    {script.lift_start, xyz(x, y, press)},
                                                    {script.lift_end, xyz(x + 0.03, y, press)},
                                                    {4.5, xyz(x + 0.03, y, press)},
                                                    {script.duration, xyz(x + 0.03, y, top + 0.03)}});
  return script;
}

// soft_ball.urdf: a soft ball of radius 3 cm (E 100 kPa, nu 0.45, 0.1 kg) resting free on the
// table, its centre at (0, 0, 0.03). Two fingers at its equator close along x from +-7 cm to
// touching (their proxies, radius 3 mm, at +-3.3 cm) in 0.8 s, squeeze their targets 1 cm past
// that in 0.8-1.2 s (about 4 N each through the coupling, less the dimple's sink: the pads need
// 0.6 N each at friction 0.8 to carry its 0.98 N), wait until 1.5 s, lift 5 cm in 1.5 s and hold
// until 4 s. Asymmetry: the fingers 1 mm apart along y (+-0.5 mm), the right one off in z by the
// jitter.
Script pinchSoftScript(std::uint64_t seed)
{
  const double jitter = seededJitter(seed);
  const double radius = 0.03;
  const double proxy = 0.003;
  const double squeeze = 0.01;
  const double lift = 0.05;
  Script script;
  script.scene_file = "soft_ball.urdf";
  script.object = "soft_ball";
  script.lift_start = 1.5;
  script.lift_end = 3.0;
  script.lift_height = lift;
  script.duration = 4.0;
  for (int side : {-1, 1})
  {
    const double y = -0.0005 * side;
    const double z = radius + (side > 0 ? jitter : 0.0);
    const double touch = side * (radius + proxy);
    const double pressed = side * (radius + proxy - squeeze);
    script.fingers.emplace_back(std::vector<Waypoint>{{0.0, xyz(0.07 * side, y, z)},
                                                      {0.8, xyz(touch, y, z)},
                                                      {1.2, xyz(pressed, y, z)},
                                                      {script.lift_start, xyz(pressed, y, z)},
                                                      {script.lift_end, xyz(pressed, y, z + lift)},
                                                      {script.duration, xyz(pressed, y, z + lift)}});
  }
  return script;
}

Script scriptFor(const ExperimentOptions& options)
{
  switch (options.scenario)
  {
    case Scenario::kSlide:
      return slideScript(options.push_height, options.seed);
    case Scenario::kLiftOne:
      return liftScript(false, options.fast, options.seed);
    case Scenario::kLiftTwo:
      return liftScript(true, options.fast, options.seed);
    case Scenario::kPinchCylinder:
      return pinchScript(options.seed);
    case Scenario::kClutter:
      return clutterScript(options.seed);
    case Scenario::kHandGrasp:
      return handGraspScript(options.seed);
    case Scenario::kRollFinger:
      return rollFingerScript(options.seed);
    case Scenario::kPinchThin:
      return pinchThinScript(options.seed);
    case Scenario::kPinchCard:
      return pinchCardScript(options.seed);
    case Scenario::kDoor:
      return doorScript(options.seed);
    case Scenario::kDrawer:
      return drawerScript(options.seed);
    case Scenario::kPressSoft:
      return pressSoftScript(options.seed);
    case Scenario::kStrokeSoft:
      return strokeSoftScript(options.seed);
    case Scenario::kPinchSoft:
      return pinchSoftScript(options.seed);
  }
  return slideScript(options.push_height, options.seed);
}

bool finite(const BodyState& state)
{
  return state.pose.matrix().allFinite() && state.linear_velocity.allFinite() && state.angular_velocity.allFinite();
}

// The time series of a run: one row per step (the watched object's pose, velocities and net
// force, then each finger's target, proxy, force, contacts and sub-god-objects), written to the
// CSV file (ExperimentOptions::csv) and kept in the result (ExperimentOptions::series).
class SeriesRecorder
{
 public:
  SeriesRecorder(const std::string& path, bool keep, int fingers, ExperimentResult* result)
      : keep_(keep), result_(result)
  {
    if (path.empty() && !keep)
    {
      return;
    }
    names_ = {"t", "x", "y", "z", "qx", "qy", "qz", "qw", "vx", "vy", "vz", "wx", "wy", "wz", "fx", "fy", "fz"};
    for (int i = 0; i < fingers; ++i)
    {
      const std::string f = "f" + std::to_string(i) + "_";
      for (const char* column : {"ix", "iy", "iz", "px", "py", "pz", "ux", "uy", "uz", "contacts", "sgo"})
      {
        names_.push_back(f + column);
      }
    }
    if (keep_)
    {
      result_->series_names = names_;
    }
    if (path.empty())
    {
      return;
    }
    file_.open(path);
    if (!file_)
    {
      throw InputError("csv file '" + path + "': cannot be written");
    }
    std::string header;
    for (const std::string& name : names_)
    {
      header += (header.empty() ? "" : ",") + name;
    }
    file_ << header << "\n";
  }

  void add(double time, const BodyState& body, const GodFingerWorld& world)
  {
    if (names_.empty())
    {
      return;
    }
    const Eigen::Quaterniond q(body.pose.linear());
    row_.clear();
    row_.push_back(time);
    appendAll(body.pose.translation());
    row_.insert(row_.end(), {q.x(), q.y(), q.z(), q.w()});
    appendAll(body.linear_velocity);
    appendAll(body.angular_velocity);
    appendAll(body.net_force);
    for (int i = 0; i < world.interfaceCount(); ++i)
    {
      const InterfaceState& state = world.interfaceState(i);
      appendAll(state.interface_position);
      appendAll(state.proxy_position);
      appendAll(state.user_force);
      int sgo = 0;
      for (int c = 0; c < state.contact_count; ++c)
      {
        sgo += state.contacts[c].sub_god_object_count;
      }
      row_.push_back(state.contact_count);
      row_.push_back(sgo);
    }
    if (keep_)
    {
      result_->series.insert(result_->series.end(), row_.begin(), row_.end());
    }
    if (file_.is_open())
    {
      line_.clear();
      for (double value : row_)
      {
        char buffer[32];
        std::snprintf(buffer, sizeof(buffer), "%.17g,", value);
        line_ += buffer;
      }
      line_.back() = '\n';
      file_ << line_;
    }
  }

  void close()
  {
    if (file_.is_open())
    {
      file_.close();
      if (!file_)
      {
        throw InputError("csv file: write failed");
      }
    }
  }

 private:
  void appendAll(const Eigen::Vector3d& v)
  {
    row_.insert(row_.end(), {v.x(), v.y(), v.z()});
  }
  bool keep_ = false;
  ExperimentResult* result_ = nullptr;
  std::vector<std::string> names_;
  std::ofstream file_;
  std::vector<double> row_;
  std::string line_;
};

}  // namespace

const char* scenarioName(Scenario scenario)
{
  switch (scenario)
  {
    case Scenario::kSlide:
      return "slide";
    case Scenario::kLiftOne:
      return "lift_one";
    case Scenario::kLiftTwo:
      return "lift_two";
    case Scenario::kPinchCylinder:
      return "pinch_cylinder";
    case Scenario::kClutter:
      return "clutter";
    case Scenario::kHandGrasp:
      return "hand_grasp";
    case Scenario::kRollFinger:
      return "roll_finger";
    case Scenario::kPinchThin:
      return "pinch_thin";
    case Scenario::kPinchCard:
      return "pinch_card";
    case Scenario::kDoor:
      return "door";
    case Scenario::kDrawer:
      return "drawer";
    case Scenario::kPressSoft:
      return "press_soft";
    case Scenario::kStrokeSoft:
      return "stroke_soft";
    case Scenario::kPinchSoft:
      return "pinch_soft";
  }
  return "?";
}

std::string scenarioNames(const std::string& separator)
{
  std::string names;
  for (Scenario scenario : kAllScenarios)
  {
    names += (names.empty() ? "" : separator) + scenarioName(scenario);
  }
  return names;
}

bool parseScenario(const std::string& text, Scenario* scenario)
{
  for (Scenario candidate : kAllScenarios)
  {
    if (text == scenarioName(candidate))
    {
      *scenario = candidate;
      return true;
    }
  }
  return false;
}

WorldParams scenarioParams(const ExperimentOptions& options)
{
  WorldParams params;
  params.time_step = options.time_step;
  params.solver_iterations = options.solver_iterations;
  params.pad_solver = options.pad_solver;
  params.model = options.model;
  params.overlap.stiffness = options.overlap_stiffness;
  return params;
}

ScenarioSetup loadScenario(const ExperimentOptions& options)
{
  const Script script = scriptFor(options);
  ScenarioSetup setup;
  setup.scene = loadUrdfScene(options.scenes_dir + "/" + script.scene_file);
  setup.object = setup.scene.find(script.object);
  if (setup.object < 0)
  {
    throw InputError("scene '" + script.scene_file + "' has no link '" + script.object + "'");
  }
  setup.fingers = script.fingers;
  setup.orientations = script.orientations;
  setup.duration = script.duration;
  setup.times = timesOf(script);
  return setup;
}

const ParameterTable<ExperimentOptions>& experimentOptionTable()
{
  using P = ExperimentOptions;
  static const ParameterTable<P> table = {
      realRow<P>("dt", "s", timeStepRange(), "the world's fixed step", [](P& p) -> double& { return p.time_step; }),
      realRow<P>("duration", "s", closed(0.0, 3600.0), "how long to run (0: the scenario's own length)",
                 [](P& p) -> double& { return p.duration; }),
      realRow<P>("push_height", "m", closed(0.0, 0.04), "slide: the hand's height above the ball's centre",
                 [](P& p) -> double& { return p.push_height; }),
  };
  return table;
}

namespace
{
void checkOptions(const ExperimentOptions& options)
{
  const std::string error = validateRows(experimentOptionTable(), options);
  if (!error.empty())
  {
    throw InputError(error);
  }
}
}  // namespace

ExperimentResult measureScenario(const ExperimentOptions& options, const GodFingerWorld& world,
                                 const std::function<void(long step)>& step)
{
  checkOptions(options);
  const Script script = scriptFor(options);
  const SceneDescription& scene = world.scene();
  const int object = scene.find(script.object);
  if (object < 0)
  {
    throw InputError("scene '" + script.scene_file + "' has no link '" + script.object + "'");
  }
  const double duration = options.duration > 0.0 ? options.duration : script.duration;
  const long steps = std::lround(duration / options.time_step);

  ScenarioMetrics metrics(options.scenario, timesOf(script), world.bodyState(object), scene.bodies[object]);
  // The other dynamic bodies (clutter: the neighbours the pick may disturb).
  std::vector<int> neighbours;
  std::vector<Eigen::Vector3d> neighbours_before;
  if (options.scenario == Scenario::kClutter)
  {
    for (int body = 0; body < static_cast<int>(scene.bodies.size()); ++body)
    {
      if (body != object && !scene.bodies[body].is_static)
      {
        neighbours.push_back(body);
        neighbours_before.push_back(world.bodyState(body).center_of_mass);
      }
    }
  }
  // roll_finger: the rolling finger (interface 0) on the box.
  std::unique_ptr<RollMetrics> roll;
  if (options.scenario == Scenario::kRollFinger)
  {
    roll = std::make_unique<RollMetrics>(object, script.lift_start);
  }
  ExperimentResult result;
  SeriesRecorder csv(options.csv, options.series, world.interfaceCount(), &result);
  // pinch_thin's hand metrics (the other scenarios' results stay as they were).
  const bool overlap_metrics_wanted = options.scenario == Scenario::kPinchThin;
  OverlapMetrics overlap_metrics(world);
  // pinch_card: the grip's (pinch_metrics.h).
  std::unique_ptr<PinchMetrics> pinch;
  if (options.scenario == Scenario::kPinchCard || options.scenario == Scenario::kPinchSoft)
  {
    pinch = std::make_unique<PinchMetrics>(object, timesOf(script), world.bodyState(object),
                                           /*turn=*/options.scenario != Scenario::kPinchSoft);
  }
  // door, drawer: the joint's (joint_metrics.h).
  std::unique_ptr<JointMetrics> joint;
  if (options.scenario == Scenario::kDoor || options.scenario == Scenario::kDrawer)
  {
    joint = std::make_unique<JointMetrics>(scene, timesOf(script));
  }
  // press_soft, stroke_soft, pinch_soft: the soft body's (soft_contact_metrics.h).
  std::unique_ptr<SoftContactMetrics> soft;
  if (options.scenario == Scenario::kPressSoft || options.scenario == Scenario::kStrokeSoft ||
      options.scenario == Scenario::kPinchSoft)
  {
    soft = std::make_unique<SoftContactMetrics>(options.scenario, object, timesOf(script), world);
  }
  std::vector<double> step_us;
  step_us.reserve(static_cast<std::size_t>(steps));
  const long sample_every =
      options.sample_period > 0.0 ? std::max(1L, std::lround(options.sample_period / options.time_step)) : 0;
  for (long i = 0; i < steps; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    step(i);
    const auto stop = std::chrono::steady_clock::now();
    step_us.push_back(std::chrono::duration<double, std::micro>(stop - start).count());
    result.max_penetration_m = std::max(result.max_penetration_m, world.counters().deepest_penetration);
    const BodyState state = world.bodyState(object);
    if (!finite(state))
    {
      ++result.nan;
      continue;
    }
    metrics.add(world.time(), options.time_step, state);
    if (roll)
    {
      roll->add(world.time(), world.interfaceState(0));
    }
    overlap_metrics.add(world);
    if (pinch)
    {
      pinch->add(world.time(), world);
    }
    if (joint)
    {
      joint->add(world.time(), world);
    }
    if (soft)
    {
      soft->add(world.time(), world);
    }
    csv.add(world.time(), state, world);
    if (sample_every > 0 && (i + 1) % sample_every == 0)
    {
      result.trajectory.push_back({world.time(), state.center_of_mass, Eigen::Quaterniond(state.pose.linear())});
    }
  }
  csv.close();
  if (options.scenario == Scenario::kClutter)
  {
    std::vector<Eigen::Vector3d> neighbours_after;
    for (int body : neighbours)
    {
      neighbours_after.push_back(world.bodyState(body).center_of_mass);
    }
    metrics.setNeighbours(neighbours_before, neighbours_after);
  }
  result.scenario = scenarioName(options.scenario);
  result.model = contactModelName(options.model);
  result.duration_s = steps * options.time_step;
  result.steps = steps;
  result.step_us_median = percentile(step_us, 0.5);
  result.step_us_p99 = percentile(step_us, 0.99);
  for (double us : step_us)
  {
    result.step_us_total += us;
  }
  result.metrics = metrics.metrics();
  if (roll)
  {
    roll->addTo(&result.metrics);
  }
  if (pinch)
  {
    for (const auto& entry : pinch->metrics())
    {
      result.metrics.insert(entry);
    }
  }
  if (joint)
  {
    for (const auto& entry : joint->metrics())
    {
      result.metrics.insert(entry);
    }
  }
  if (soft)
  {
    for (const auto& entry : soft->metrics())
    {
      result.metrics.insert(entry);
    }
  }
  if (overlap_metrics_wanted)
  {
    for (const auto& entry : overlap_metrics.metrics())
    {
      result.metrics.insert(entry);
    }
  }
  return result;
}

ExperimentResult runExperiment(const ExperimentOptions& options)
{
  checkOptions(options);
  const ScenarioSetup setup = loadScenario(options);
  GodFingerWorld world(setup.scene, scenarioParams(options));
  for (std::size_t f = 0; f < setup.fingers.size(); ++f)
  {
    world.addInterface(setup.fingers[f].at(0.0));
    if (f < setup.orientations.size())
    {
      world.setInterfaceTarget(static_cast<int>(f), setup.fingers[f].at(0.0), setup.orientations[f].at(0.0));
    }
  }
  // The ideal hand: each interface is exactly where the script puts it at the step's end.
  return measureScenario(options, world,
                         [&world, &setup, &options](long i)
                         {
                           const double next_time = (i + 1) * options.time_step;
                           for (int f = 0; f < world.interfaceCount(); ++f)
                           {
                             if (static_cast<std::size_t>(f) < setup.orientations.size())
                             {
                               world.setInterfaceTarget(f, setup.fingers[f].at(next_time),
                                                        setup.orientations[f].at(next_time));
                             }
                             else
                             {
                               world.setInterfaceTarget(f, setup.fingers[f].at(next_time));
                             }
                           }
                           world.step();
                         });
}

std::string toJson(const ExperimentResult& result)
{
  Json json;
  json["scenario"] = result.scenario;
  json["model"] = result.model;
  json["duration_s"] = jsonMeasure(result.duration_s);
  json["steps"] = result.steps;
  json["step_us_median"] = jsonMeasure(result.step_us_median);
  json["step_us_p99"] = jsonMeasure(result.step_us_p99);
  json["max_penetration_m"] = jsonMeasure(result.max_penetration_m);
  json["nan"] = result.nan;
  json["metrics"] = Json::object();
  for (const auto& entry : result.metrics)
  {
    json["metrics"][entry.first] = jsonMeasure(entry.second);
  }
  return json.dump();
}
}  // namespace god_finger
