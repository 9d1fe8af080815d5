#include "god_finger/runtime/servo_command.h"

namespace god_finger
{
bool isWorldCommand(ServoCommand::Kind kind)
{
  switch (kind)
  {
    case ServoCommand::Kind::kSetContactModel:
    case ServoCommand::Kind::kSetContactParams:
    case ServoCommand::Kind::kReset:
    case ServoCommand::Kind::kSetPadSolver:
      return true;
    case ServoCommand::Kind::kHandTarget:
    case ServoCommand::Kind::kStopForce:
    case ServoCommand::Kind::kResumeForce:
      return false;
  }
  return false;
}

bool applyWorldCommand(const ServoCommand& command, GodFingerWorld* world)
{
  switch (command.kind)
  {
    case ServoCommand::Kind::kSetContactModel:
      world->setContactModel(command.model);
      return true;
    case ServoCommand::Kind::kSetContactParams:
      world->setContactParams(command.contact);
      return true;
    case ServoCommand::Kind::kReset:
      world->resetAtInterfaces();
      return true;
    case ServoCommand::Kind::kSetPadSolver:
      world->setPadSolver(command.pad_solver);
      return true;
    case ServoCommand::Kind::kHandTarget:
    case ServoCommand::Kind::kStopForce:
    case ServoCommand::Kind::kResumeForce:
      return false;
  }
  return false;
}
}  // namespace god_finger
