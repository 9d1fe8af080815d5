// A command to the servo loop or the physics node (the world services, runtime/servo_loop.h
// post(), ros/world_services.h), and its one application to a world, which both topologies
// call: the in-process servo loop on its physics side, the physics node under its lock.
// Hand targets and the force stop act on the haptic side and are not world commands.
// Units: hand_target m, device frame; orientations unit quaternions (finger frame in the
// device frame). applyWorldCommand is real-time safe only as far as the world's own call is.
#pragma once

#include "god_finger/contact/contact_params.h"
#include "god_finger/physics/contact_model.h"
#include "god_finger/physics/god_finger_world.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace god_finger
{
struct ServoCommand
{
  enum class Kind
  {
    kSetContactModel,
    kSetContactParams,
    kReset,
    kHandTarget,
    kStopForce,    // every guard's output to zero at once (ForceGuard::stop), haptic side
    kResumeForce,  // force back with the soft start (ForceGuard::resume)
    kSetPadSolver,
  };
  Kind kind = Kind::kReset;
  ContactModel model = ContactModel::kGodFinger;
  ContactParams contact;                            // validated by post()
  PadSolver pad_solver = WorldParams().pad_solver;  // kSetPadSolver, validated by post()
  int interface = 0;
  Eigen::Vector3d hand_target = Eigen::Vector3d::Zero();  // m, device frame
  // kHandTarget: with an orientation too (HapticDevice::setHandPose; the finger frame in the
  // device frame, unit), else the position alone (setHandTarget).
  bool hand_oriented = false;
  Eigen::Quaterniond hand_orientation = Eigen::Quaterniond::Identity();
};

// kReset, kSetContactModel, kSetPadSolver and kSetContactParams act on the world.
bool isWorldCommand(ServoCommand::Kind kind);

// Applies a world command to `world`; false for one that is not (the world is untouched).
// kSetContactParams throws InputError on bad parameters (the servo loop validates them in
// post(), the physics node passes the error to its service's caller).
bool applyWorldCommand(const ServoCommand& command, GodFingerWorld* world);
}  // namespace god_finger
