// The scale section's scene (issue 17): a static table with `objects` boxes (4 cm, 50 g, friction
// 1 so that Bullet's product and MuJoCo's maximum agree) in a grid 8 cm apart, resting on it, and
// `fingers` fingers, finger i on box i (row-major from the grid's corner): from 2 cm above its top
// it presses 4 mm in (0.3 s), drags the box 2 cm along x (1.5 s), holds (0.7 s): 2.5 s in all.
// Header-only, for the benchmarks that build it (god_finger's worlds and MuJoCo's).
//
// Units SI, world z up (REP-103); the table top is z = 0.
#pragma once

#include "god_finger/haptics/waypoint_path.h"
#include "god_finger/scene/scene_description.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace god_finger
{
namespace scale
{
constexpr double kBox = 0.04;      // m, edge
constexpr double kBoxMass = 0.05;  // kg
constexpr double kSpacing = 0.08;  // m, grid pitch
constexpr double kFriction = 1.0;  // every body's
constexpr double kDuration = 2.5;  // s, one run
constexpr double kPress = 0.004;   // m, into the box's top
constexpr double kDrag = 0.02;     // m along x

inline int gridColumns(int objects)
{
  return std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(objects)))));
}

inline Eigen::Vector3d boxCentre(int index, int objects)
{
  const int columns = gridColumns(objects);
  return Eigen::Vector3d(kSpacing * (index % columns), kSpacing * (index / columns), kBox / 2.0);
}

inline SceneDescription scene(int objects)
{
  SceneDescription scene;
  scene.name = "scale_" + std::to_string(objects);
  const int columns = gridColumns(objects);
  const double extent = kSpacing * columns;
  BodyDescription table;
  table.name = "table";
  table.is_static = true;
  table.geometry.kind = GeometryKind::kBox;
  table.geometry.size = Eigen::Vector3d(extent + 0.4, extent + 0.4, 0.05);
  table.pose.translation() = Eigen::Vector3d(0.5 * extent - 0.5 * kSpacing, 0.5 * extent - 0.5 * kSpacing, -0.025);
  table.material.friction = kFriction;
  scene.bodies.push_back(table);
  for (int i = 0; i < objects; ++i)
  {
    BodyDescription box;
    box.name = "box" + std::to_string(i);
    box.geometry.kind = GeometryKind::kBox;
    box.geometry.size = Eigen::Vector3d::Constant(kBox);
    box.mass = kBoxMass;
    box.inertia = Eigen::Matrix3d::Identity() * kBoxMass * 2.0 * kBox * kBox / 12.0;
    box.pose.translation() = boxCentre(i, objects);
    box.material.friction = kFriction;
    scene.bodies.push_back(box);
  }
  return scene;
}

inline std::vector<WaypointPath> fingers(int count, int objects)
{
  std::vector<WaypointPath> paths;
  for (int i = 0; i < count; ++i)
  {
    // A little off the box's centre, as a hand would be.
    const Eigen::Vector3d top = boxCentre(i, objects) + Eigen::Vector3d(-0.003, 0.002, kBox / 2.0);
    const Eigen::Vector3d pressed = top - Eigen::Vector3d(0.0, 0.0, kPress);
    const Eigen::Vector3d dragged = pressed + Eigen::Vector3d(kDrag, 0.0, 0.0);
    paths.emplace_back(std::vector<Waypoint>{
        {0.0, top + Eigen::Vector3d(0.0, 0.0, 0.02)}, {0.3, pressed}, {1.8, dragged}, {kDuration, dragged}});
  }
  return paths;
}

// Median and 99th percentile (us) of per-step times, in place.
struct StepTimes
{
  std::vector<double> us;
  double percentile(double p)
  {
    if (us.empty())
    {
      return 0.0;
    }
    const std::size_t k = std::min(us.size() - 1, static_cast<std::size_t>(p * (us.size() - 1) + 0.5));
    std::nth_element(us.begin(), us.begin() + static_cast<long>(k), us.end());
    return us[k];
  }
};

using Clock = std::chrono::steady_clock;
inline double microseconds(Clock::time_point begin, Clock::time_point end)
{
  return std::chrono::duration<double, std::micro>(end - begin).count();
}
}  // namespace scale
}  // namespace god_finger
