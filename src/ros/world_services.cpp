#include "world_services.h"

#include "god_finger/scene/scene_file.h"
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/support/input_error.h"

#include <ros/console.h>
#include <ros/package.h>

#include <cctype>
#include <chrono>
#include <future>

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
  ros::NodeHandle edit_nh(nh);
  edit_nh.setCallbackQueue(&edit_queue_);
  spawn_service_ = edit_nh.advertiseService("spawn_object", &WorldServices::onSpawn, this);
  delete_service_ = edit_nh.advertiseService("delete_object", &WorldServices::onDelete, this);
  edit_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &edit_queue_);
  edit_spinner_->start();
}

WorldServices::~WorldServices()
{
  edit_spinner_->stop();
}

namespace
{
// How long a service waits for the world to take an edit (s): the world takes it between two
// steps, so only a stopped loop makes it wait this long.
constexpr double kEditDeadline = 10.0;

bool startsWith(const std::string& text, const std::string& prefix)
{
  return text.compare(0, prefix.size(), prefix) == 0;
}

// The request's pose: an all-zero quaternion (what a request that leaves it out carries) is no
// rotation; others must be finite with a norm in [0.5, 2] and are normalised.
Eigen::Isometry3d requestPose(const geometry_msgs::Pose& pose)
{
  const geometry_msgs::Quaternion& q = pose.orientation;
  Eigen::Quaterniond rotation(q.w, q.x, q.y, q.z);
  if (q.w == 0.0 && q.x == 0.0 && q.y == 0.0 && q.z == 0.0)
  {
    rotation = Eigen::Quaterniond::Identity();
  }
  if (!rotation.coeffs().allFinite() || rotation.norm() < 0.5 || rotation.norm() > 2.0)
  {
    throw InputError("the pose's orientation is not a usable quaternion (finite, of norm near 1)");
  }
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.linear() = rotation.normalized().toRotationMatrix();
  result.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  if (!result.translation().allFinite())
  {
    throw InputError("the pose's position must be finite");
  }
  return result;
}
}  // namespace

ObjectEdit::Outcome WorldServices::edit(ServoCommand::Kind kind, const std::shared_ptr<ObjectEdit>& edit)
{
  std::future<ObjectEdit::Outcome> done = edit->done.get_future();
  ServoCommand command;
  command.kind = kind;
  command.edit = edit;
  ObjectEdit::Outcome outcome;
  if (!post_(command, &outcome.message))
  {
    return outcome;
  }
  if (done.wait_for(std::chrono::duration<double>(kEditDeadline)) != std::future_status::ready)
  {
    outcome.message = "the world did not take the edit within " + std::to_string(int(kEditDeadline)) +
                      " s (is its loop running?); it may still take it";
    return outcome;
  }
  return done.get();
}

bool WorldServices::onSpawn(god_finger::SpawnObject::Request& request, god_finger::SpawnObject::Response& response)
{
  auto edit = std::make_shared<ObjectEdit>();
  try
  {
    if (!startsWith(request.file, "/") && !startsWith(request.file, "file:///") &&
        !startsWith(request.file, "package://"))
    {
      throw InputError("file '" + request.file +
                       "': give an absolute path, file:///..., or package://PACKAGE/... (the node's folder is not "
                       "yours)");
    }
    for (const char c : request.name)
    {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
      {
        throw InputError("name '" + request.name +
                         "': letters, digits, '_', '-' and '.' only (it names TF frames; an object of several "
                         "links names them NAME/LINK)");
      }
    }
    if (request.fixed > god_finger::SpawnObject::Request::FREE)
    {
      throw InputError("fixed must be AS_IN_FILE (0), FIXED (1) or FREE (2), not " + std::to_string(request.fixed));
    }
    const PackageResolver packages = [](const std::string& name) { return ros::package::getPath(name); };
    std::string package;
    const std::string path = resolveFileName(request.file, "", packages, &package);
    if (path.empty())
    {
      throw InputError("file '" + request.file + "': ROS package '" + package + "' not found");
    }
    ObjectPlacement placement;
    placement.name = request.name;
    placement.pose = requestPose(request.pose);
    if (request.fixed != god_finger::SpawnObject::Request::AS_IN_FILE)
    {
      placement.fixed = request.fixed == god_finger::SpawnObject::Request::FIXED;
    }
    WorldParams params;
    {
      std::lock_guard<std::mutex> lock(params_mutex_);
      params = params_;
    }
    // The costly part (reading, decomposing) here, in this service's thread.
    edit->object = GodFingerWorld::prepareObject(loadPlacedObject(path, placement, packages), params);
  }
  catch (const InputError& error)
  {
    response.success = false;
    response.message = error.what();
    ROS_WARN("%s: spawn_object refused: %s", node_.c_str(), error.what());
    return true;
  }
  for (const std::string& warning : edit->object->object().warnings)
  {
    ROS_WARN("%s: spawn_object: %s", node_.c_str(), warning.c_str());
  }
  const ObjectEdit::Outcome outcome = this->edit(ServoCommand::Kind::kAddObject, edit);
  response.success = outcome.success;
  response.message = outcome.message;
  if (outcome.success)
  {
    ROS_INFO("%s: spawn_object '%s' from '%s': %s", node_.c_str(), request.name.c_str(), request.file.c_str(),
             outcome.message.c_str());
  }
  else
  {
    ROS_WARN("%s: spawn_object '%s' from '%s' refused: %s", node_.c_str(), request.name.c_str(), request.file.c_str(),
             outcome.message.c_str());
  }
  return true;
}

bool WorldServices::onDelete(god_finger::DeleteObject::Request& request, god_finger::DeleteObject::Response& response)
{
  auto edit = std::make_shared<ObjectEdit>();
  edit->name = request.name;
  const ObjectEdit::Outcome outcome = this->edit(ServoCommand::Kind::kRemoveObject, edit);
  response.success = outcome.success;
  response.message = outcome.message;
  if (outcome.success)
  {
    ROS_INFO("%s: delete_object '%s': %s", node_.c_str(), request.name.c_str(), outcome.message.c_str());
  }
  else
  {
    ROS_WARN("%s: delete_object '%s' refused: %s", node_.c_str(), request.name.c_str(), outcome.message.c_str());
  }
  return true;
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
  WorldParams base;
  {
    std::lock_guard<std::mutex> lock(params_mutex_);
    base = params_;
  }
  if (!worldFromConfig(config, base, &applied, error))
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
  {
    std::lock_guard<std::mutex> lock(params_mutex_);
    params_.contact = applied.contact;
  }
  if (applied.pad_solver != base.pad_solver)
  {
    ServoCommand solver;
    solver.kind = ServoCommand::Kind::kSetPadSolver;
    solver.pad_solver = applied.pad_solver;
    if (!post_(solver, error))
    {
      return false;
    }
    std::lock_guard<std::mutex> lock(params_mutex_);
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
