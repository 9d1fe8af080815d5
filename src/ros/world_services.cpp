#include "world_services.h"

#include <ros/console.h>

namespace god_finger
{
WorldServices::WorldServices(ros::NodeHandle nh, const ros::NodeHandle& pnh, const WorldParams& initial, Post post,
                             const std::string& node)
    : post_(std::move(post)), node_(node), params_(initial)
{
  // Starts from `initial` (the same private names the node read), so it changes nothing until
  // someone reconfigures.
  reconfigure_ = std::make_unique<LiveReconfigure>(
      pnh, initial,
      [this](const god_finger::GodFingerConfig& config, bool model_changed, std::string* error)
      { return applyConfig(config, model_changed, error); },
      node);
  reset_service_ = nh.advertiseService("reset_scene", &WorldServices::onReset, this);
  model_service_ = nh.advertiseService("set_contact_model", &WorldServices::onSetModel, this);
}

void WorldServices::showModel(ContactModel model)
{
  reconfigure_->showModel(model);
}

bool WorldServices::onReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response)
{
  ServoCommand command;
  command.kind = ServoCommand::Kind::kReset;
  std::string error;
  response.success = post_(command, &error);
  response.message = response.success ? "scene reset" : error;
  return true;
}

// The haptic node's button comes through here too.
bool WorldServices::onSetModel(god_finger::SetContactModel::Request& request,
                               god_finger::SetContactModel::Response& response)
{
  reconfigure_->serveSetModel(request, response,
                              [this](ContactModel model, std::string* error)
                              {
                                ServoCommand command;
                                command.kind = ServoCommand::Kind::kSetContactModel;
                                command.model = model;
                                return post_(command, error);
                              });
  return true;
}

// The model is sent only when the reconfiguration changes it: the world's may have changed
// since (the service, a button) and is not the configuration's to undo.
bool WorldServices::applyConfig(const god_finger::GodFingerConfig& config, bool model_changed, std::string* error)
{
  WorldParams applied;
  if (!worldFromConfig(config, params_, &applied, error))
  {
    return false;
  }
  ServoCommand contact;
  contact.kind = ServoCommand::Kind::kSetContactParams;
  contact.contact = applied.contact;
  if (!post_(contact, error))
  {
    return false;
  }
  params_.contact = applied.contact;
  if (applied.pad_solver != params_.pad_solver)
  {
    ServoCommand solver;
    solver.kind = ServoCommand::Kind::kSetPadSolver;
    solver.pad_solver = applied.pad_solver;
    if (!post_(solver, error))
    {
      return false;
    }
    params_.pad_solver = applied.pad_solver;
  }
  if (model_changed)
  {
    ServoCommand model;
    model.kind = ServoCommand::Kind::kSetContactModel;
    model.model = applied.model;
    std::string model_error;
    if (!post_(model, &model_error))
    {
      ROS_WARN("%s: contact model refused (%s)", node_.c_str(), model_error.c_str());
    }
  }
  return true;
}
}  // namespace god_finger
