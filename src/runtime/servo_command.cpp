#include "god_finger/runtime/servo_command.h"

#include "god_finger/support/input_error.h"

namespace god_finger
{
bool isWorldCommand(ServoCommand::Kind kind)
{
  return kind == ServoCommand::Kind::kSetContactModel || kind == ServoCommand::Kind::kSetContactParams ||
         kind == ServoCommand::Kind::kReset || kind == ServoCommand::Kind::kSetPadSolver ||
         kind == ServoCommand::Kind::kAddObject || kind == ServoCommand::Kind::kRemoveObject;
}

namespace
{
void applyObjectEdit(const ServoCommand& command, GodFingerWorld* world)
{
  ObjectEdit::Outcome outcome;
  if (!command.edit)
  {
    return;  // nobody to answer (ServoLoop::post refuses it)
  }
  if (command.kind == ServoCommand::Kind::kAddObject && !command.edit->object)
  {
    outcome.message = "an object edit without its object";
    command.edit->done.set_value(outcome);
    return;
  }
  try
  {
    if (command.kind == ServoCommand::Kind::kAddObject)
    {
      const std::vector<std::string> warnings = world->addObject(command.edit->object.get());
      outcome.message = "added " + std::to_string(command.edit->object->object().bodies.size()) + " body(ies)";
      for (const std::string& line : warnings)
      {
        outcome.message += "; warning: " + line;
      }
    }
    else
    {
      outcome.message = "deleted " + std::to_string(world->removeObject(command.edit->name)) + " body(ies)";
    }
    outcome.success = true;
  }
  catch (const InputError& error)
  {
    outcome.message = error.what();
  }
  catch (const std::exception& error)  // out of memory: the caller hears of it, the world's thread stops
  {
    outcome.message = std::string("failed: ") + error.what();
    command.edit->done.set_value(outcome);
    throw;
  }
  command.edit->done.set_value(outcome);
}
}  // namespace

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
    case ServoCommand::Kind::kAddObject:
    case ServoCommand::Kind::kRemoveObject:
      applyObjectEdit(command, world);
      return true;
    default:  // not a world command (isWorldCommand above names the same)
      return false;
  }
}
}  // namespace god_finger
