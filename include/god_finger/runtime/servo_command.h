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
#include <future>
#include <memory>
#include <string>

namespace god_finger
{
// An object added or removed while the world runs (kAddObject, kRemoveObject: the spawn_object
// and delete_object services), and its outcome, which the world's thread sets when it applies
// the edit (the caller waits on `done`, with a deadline).
struct ObjectEdit
{
  // kAddObject: scene_file.h loadPlacedObject's, its bodies made beforehand in the caller's thread
  // (GodFingerWorld::prepareObject): the world's thread only adds its bodies to Bullet's world.
  std::unique_ptr<PreparedObject> object;
  std::string name;  // kRemoveObject: a body's name, or an object's (its NAME/... bodies)
  struct Outcome
  {
    bool success = false;
    std::string message;  // what was done, with the warnings (a body starting inside another); or why not
  };
  std::promise<Outcome> done;
};

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
    kAddObject,     // `edit`: GodFingerWorld::addObject
    kRemoveObject,  // `edit`: GodFingerWorld::removeObject
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
  std::shared_ptr<ObjectEdit> edit;  // kAddObject, kRemoveObject (non-null, validated by post())
};

// kReset, kSetContactModel, kSetPadSolver, kSetContactParams, kAddObject and kRemoveObject act on
// the world.
bool isWorldCommand(ServoCommand::Kind kind);

// Applies a world command to `world`; false for one that is not (the world is untouched).
// kSetContactParams throws InputError on bad parameters (the servo loop validates them in
// post(), the physics node passes the error to its service's caller). An object edit never
// throws: its outcome goes to its `done`.
bool applyWorldCommand(const ServoCommand& command, GodFingerWorld* world);
}  // namespace god_finger
