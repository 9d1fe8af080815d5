// The tests' block object (urdf/objects/block.urdf: 6 x 4 x 3 cm, 80 g) placed as a spawn places
// it: named `name`, centred at `at` (m, world). Header only.
#pragma once

#include "god_finger/scene/scene_file.h"

#include <Eigen/Geometry>

#include <string>

namespace god_finger::test
{
inline SceneDescription placedBlock(const std::string& name, const Eigen::Vector3d& at)
{
  ObjectPlacement placement;
  placement.name = name;
  placement.pose.translation() = at;
  return loadPlacedObject(std::string(GOD_FINGER_SOURCE_DIR) + "/urdf/objects/block.urdf", placement);
}
}  // namespace god_finger::test
