// One interface's input pipeline, shared by both topologies (the in-process servo loop's
// readDevices and the haptic node's device/state callback), so that a reading means the same in
// each: reject a non-finite reading as a whole, bound it to the device's workspace (the wall the
// hand feels), map it into the world, detect newly pressed buttons, and keep the last usable
// orientation.
//
// Frames and units: the reading is in the device frame (HapticDevice convention: origin at the
// workspace centre), m, m/s; the target is in the world frame (m) through the interface's
// WorkspaceMapping; the wall force is on the hand, device frame (N, haptics/workspace_bound.h).
// Invariants: a rejected reading changes no state (buttons and orientation stay as they were);
// `orientation_world` is the mapping of the last usable orientation and is meaningful only once
// `oriented()`. Buttons: bit 0 cycles the model, bit 1 resets the scene, bit 2 stops or resumes
// the force (kButton* below; the docs' devices page). Real-time safe: no allocation, no locks.
#pragma once

#include "god_finger/haptics/device_profile.h"
#include "god_finger/haptics/workspace_mapping.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>

namespace god_finger
{
constexpr std::uint32_t kButtonCycleModel = 1u;  // the next contact model
constexpr std::uint32_t kButtonReset = 2u;       // the scene back to its start
constexpr std::uint32_t kButtonStopForce = 4u;   // stop every device's force, or resume it

// One reading as the device gives it (device frame).
struct InterfaceReading
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s
  std::uint32_t buttons = 0;                           // bit i: button i held
  bool has_orientation = false;
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // any norm; checked here
};

enum class OrientationInput
{
  kNone,      // the reading has none
  kUsable,    // taken: orientation_world is the new one
  kRejected,  // unusable (haptics/orientation_path.h usableOrientation): ignored, the last kept
};

struct InterfaceInputResult
{
  bool accepted = false;                             // finite position and velocity; false: nothing below is meaningful
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  // m, world: the bounded reading, mapped
  Eigen::Vector3d wall_force = Eigen::Vector3d::Zero();  // N, device frame: on the hand
  std::uint32_t pressed = 0;                             // buttons down now and not before
  OrientationInput orientation = OrientationInput::kNone;
};

class InterfaceInput
{
 public:
  InterfaceInput() = default;
  InterfaceInput(const DeviceProfile& profile, const WorkspaceMapping& mapping);

  InterfaceInputResult read(const InterfaceReading& reading);

  // A usable orientation has been read.
  bool oriented() const
  {
    return oriented_;
  }
  // The last usable orientation, normalised: device frame and world frame.
  const Eigen::Quaterniond& deviceOrientation() const
  {
    return device_orientation_;
  }
  const Eigen::Quaterniond& worldOrientation() const
  {
    return world_orientation_;
  }

 private:
  DeviceProfile profile_;
  WorkspaceMapping mapping_;
  std::uint32_t buttons_ = 0;
  bool oriented_ = false;
  Eigen::Quaterniond device_orientation_ = Eigen::Quaterniond::Identity();
  Eigen::Quaterniond world_orientation_ = Eigen::Quaterniond::Identity();
};
}  // namespace god_finger
