// The fake hand (backend fake_hand): a simulated hand tracker, a thumb and two to four fingers
// scripted through a grasp of the mug of urdf/scenes/table_mug.urdf (close, lift, hold, open),
// for tests and the demo. Input only: it renders no force (devices/hand_device.h); each
// fingertip goes exactly where the script says, its proxy stops on the mug.
//
// The grasp, in the device frame (m), around the vertical axis through `grasp_center`: the
// thumb on +y (90 deg), the fingers on -y spread 35 deg apart around 270 deg (clear of the
// mug's handle on +x). Script time (s): 0 open at open_radius from the axis; 1.0 closed (the
// fingers at grasp_radius, the thumb deeper by what balances the fingers' push along y, so the
// mug is not shoved); 1.5 to 3.5 lift by `lift`; hold until 4.5; open back to open_radius by
// 4.8; back down to the start by 5.8; stays there, or with `cycle` > 0 grasps again every
// `cycle` seconds. Deterministic: a pure function of the script time.
// Wrist turn (`wrist_turn`, rad, 0: none): held up, the whole hand turns about the grasp's axis
// (vertical, through grasp_center lifted) by wrist_turn from 3.5 to 4.2 s (positive: counter-
// clockwise seen from above), fingertips on the arc and each finger's orientation turned with
// them; it holds turned until 4.5, opens turned, and turns back while it goes down (4.8 to 5.8).
//
// Orientations (`orientation` pulp_in, the default): every fingertip is an oriented (6-DOF)
// finger (physics/oriented_finger.h) held the way a hand holds a mug: its pulp (z) towards the
// axis, its tip (x) down, its body leaning out from the wall by `finger_pitch` (so the pulp
// meets the wall tilted by that angle, and the body stays clear of it). `none`: positions only,
// 3-DOF fingers.
#pragma once

#include "god_finger/devices/hand_device.h"
#include "god_finger/haptics/orientation_path.h"
#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/support/parameter_source.h"
#include "god_finger/support/parameter_table.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

namespace god_finger
{
struct FakeHandParams
{
  int fingers = 2;                                                 // besides the thumb, [2, 4]
  Eigen::Vector3d grasp_center = Eigen::Vector3d(0.0, 0.0, 0.05);  // m, device frame: the mug's axis, 5 cm up
  double grasp_radius = 0.033;  // m from the axis: where the fingers close (the mug's wall at 0.04)
  double open_radius = 0.07;    // m from the axis: open
  double object_radius = 0.04;  // m: the grasped object's radius (the mug's), to balance the thumb
  double lift = 0.1;            // m
  double cycle = 0.0;           // s: 0 grasps once; else again every cycle s (>= 5.8, the grasp's length)
  bool oriented = true;         // `orientation`: pulp_in (true) or none
  double finger_pitch = 0.5;    // rad: the finger's body's lean out from the wall (0: along it)
  double wrist_turn = 0.0;      // rad: the held hand's turn about the grasp's axis (0: none)
};

// The numeric parameters' one table (names, units, ranges, meanings; defaults: the struct's
// initialisers above); grasp_center, a vector, is read beside it.
const ParameterTable<FakeHandParams>& fakeHandParameterTable();

// The table's rows, grasp_center, and open_radius > grasp_radius, cycle 0 or >= 5.8 s;
// InputError naming a bad one.
FakeHandParams readFakeHandParams(const ParameterSource& source);

// Each finger's path (thumb first), in script time; names thumb, index, middle, ring, little.
std::vector<std::string> fakeHandFingerNames(int fingers);
std::vector<WaypointPath> fakeHandPaths(const FakeHandParams& params);
// Each finger's orientation at the script's start (thumb first; the finger frame in the device
// frame); empty when `oriented` is false.
std::vector<Eigen::Quaterniond> fakeHandOrientations(const FakeHandParams& params);
// Each finger's orientation through the script (the start's, turned with the wrist); empty when
// `oriented` is false.
std::vector<OrientationPath> fakeHandOrientationPaths(const FakeHandParams& params);

std::shared_ptr<HandSource> makeFakeHand(const FakeHandParams& params);
}  // namespace god_finger
