#include "god_finger/runtime/servo_command.h"

namespace god_finger
{
bool isWorldCommand(ServoCommand::Kind kind)
{
  return kind == ServoCommand::Kind::kSetContactModel || kind == ServoCommand::Kind::kSetContactParams ||
         kind == ServoCommand::Kind::kReset || kind == ServoCommand::Kind::kSetPadSolver;
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
    default:  // not a world command (isWorldCommand above names the same four)
      return false;
  }
}
}  // namespace god_finger
