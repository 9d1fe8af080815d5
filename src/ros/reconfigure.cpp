#include "god_finger/ros/reconfigure.h"

#include "god_finger/support/input_error.h"

#include <dynamic_reconfigure/Config.h>
#include <ros/console.h>

namespace god_finger
{
namespace
{
const ParameterRow<WorldParams>* rowNamed(const std::string& name)
{
  for (const ParameterRow<WorldParams>& row : worldParameterTable())
  {
    if (name == row.name)
    {
      return &row;
    }
  }
  return nullptr;
}
}  // namespace

god_finger::GodFingerConfig configOf(const WorldParams& params)
{
  // Every entry of the cfg is a row of the world's table (parameter_tables_test checks it):
  // each takes the row's value in `params`.
  dynamic_reconfigure::Config message;
  god_finger::GodFingerConfig::__getDefault__().__toMessage__(message);
  for (dynamic_reconfigure::DoubleParameter& entry : message.doubles)
  {
    if (const ParameterRow<WorldParams>* row = rowNamed(entry.name))
    {
      entry.value = row->number(params);
    }
  }
  for (dynamic_reconfigure::IntParameter& entry : message.ints)
  {
    if (const ParameterRow<WorldParams>* row = rowNamed(entry.name))
    {
      entry.value = static_cast<int>(row->number(params));
    }
  }
  for (dynamic_reconfigure::StrParameter& entry : message.strs)
  {
    if (const ParameterRow<WorldParams>* row = rowNamed(entry.name))
    {
      entry.value = row->valueText(params);
    }
  }
  god_finger::GodFingerConfig config;
  config.__fromMessage__(message);
  return config;
}

std::vector<std::string> clampToLiveRanges(god_finger::GodFingerConfig* config)
{
  dynamic_reconfigure::Config message;
  config->__toMessage__(message);
  std::vector<std::string> notes;
  for (dynamic_reconfigure::DoubleParameter& entry : message.doubles)
  {
    if (const ParameterRow<WorldParams>* row = rowNamed(entry.name))
    {
      std::string note;
      entry.value = clampToLive(*row, entry.value, &note);
      if (!note.empty())
      {
        notes.push_back(note);
      }
    }
  }
  for (dynamic_reconfigure::IntParameter& entry : message.ints)
  {
    if (const ParameterRow<WorldParams>* row = rowNamed(entry.name))
    {
      std::string note;
      entry.value = static_cast<int>(clampToLive(*row, entry.value, &note));
      if (!note.empty())
      {
        notes.push_back(note);
      }
    }
  }
  if (!notes.empty())
  {
    config->__fromMessage__(message);
  }
  return notes;
}

bool worldFromConfig(const god_finger::GodFingerConfig& config, const WorldParams& base, WorldParams* params,
                     std::string* error)
{
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  MapParameterSource source("reconfigure: ");
  for (const dynamic_reconfigure::DoubleParameter& entry : message.doubles)
  {
    source.set(entry.name, ParameterValue::of(entry.value));
  }
  for (const dynamic_reconfigure::IntParameter& entry : message.ints)
  {
    source.set(entry.name, ParameterValue::ofInteger(entry.value));
  }
  for (const dynamic_reconfigure::StrParameter& entry : message.strs)
  {
    source.set(entry.name, ParameterValue::of(entry.value));
  }
  for (const dynamic_reconfigure::BoolParameter& entry : message.bools)
  {
    source.set(entry.name, ParameterValue::of(static_cast<bool>(entry.value)));
  }
  *params = base;
  try
  {
    readRows(source, worldParameterTable(), params);
  }
  catch (const InputError& bad)
  {
    *error = bad.what();
    return false;
  }
  *error = validate(*params);
  return error->empty();
}
LiveReconfigure::LiveReconfigure(const ros::NodeHandle& pnh, const WorldParams& initial, Apply apply, std::string node)
    : apply_(std::move(apply)), node_(std::move(node)), in_force_(configOf(initial))
{
  ros::NodeHandle handle(pnh);
  server_ = std::make_unique<dynamic_reconfigure::Server<god_finger::GodFingerConfig>>(mutex_, handle);
  server_->updateConfig(in_force_);
  // Calls back once at once, with in_force_: nothing changes.
  server_->setCallback([this](god_finger::GodFingerConfig& config, std::uint32_t) { onReconfigure(config); });
}

void LiveReconfigure::onReconfigure(god_finger::GodFingerConfig& config)
{
  boost::recursive_mutex::scoped_lock lock(mutex_);
  // A value in its row's range but outside the row's live range is clamped, and said so: the
  // clamped configuration is what gets applied and sent back.
  for (const std::string& note : clampToLiveRanges(&config))
  {
    ROS_WARN("%s: reconfiguration: %s", node_.c_str(), note.c_str());
  }
  std::string error;
  if (!apply_(config, config.model != in_force_.model, &error))
  {
    ROS_WARN("%s: reconfiguration refused (%s); the previous parameters stay", node_.c_str(), error.c_str());
    config = in_force_;
    return;
  }
  in_force_ = config;
}

void LiveReconfigure::showModel(ContactModel model)
{
  boost::recursive_mutex::scoped_lock lock(mutex_);
  const std::string name = contactModelName(model);
  if (in_force_.model == name)
  {
    return;
  }
  in_force_.model = name;
  server_->updateConfig(in_force_);
}

void LiveReconfigure::serveSetModel(const god_finger::SetContactModel::Request& request,
                                    god_finger::SetContactModel::Response& response, const ApplyModel& apply)
{
  ContactModel model;
  if (!parseContactModel(request.model, &model))
  {
    response.success = false;
    response.message = "unknown contact model '" + request.model + "' (" + contactModelNames() + ")";
    return;
  }
  boost::recursive_mutex::scoped_lock lock(mutex_);  // no reconfiguration in between
  std::string error;
  response.success = apply(model, &error);
  if (!response.success)
  {
    response.message = error;
    return;
  }
  showModel(model);
  response.message = std::string("contact model: ") + contactModelName(model);
}

god_finger::GodFingerConfig LiveReconfigure::config()
{
  boost::recursive_mutex::scoped_lock lock(mutex_);
  return in_force_;
}
}  // namespace god_finger
