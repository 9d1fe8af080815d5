// The world's services, one implementation for the physics node and the servo node (private to
// the ROS library): reset_scene (std_srvs/Trigger), set_contact_model (god_finger/SetContactModel)
// and dynamic_reconfigure of the method's parameters and the model (ros/reconfigure.h), all in
// the node's namespace. Each node only says how a world command reaches its world (Post): the
// physics node applies it under its world's lock, the servo node posts it to its loop, which
// applies it between two steps.
//
// spawn_object (god_finger/SpawnObject) and delete_object (god_finger/DeleteObject) edit the
// running world as Gazebo's spawn_urdf_model and delete_model do: the file is read and its shapes
// checked in the service's thread, the world takes the edit between two steps
// (GodFingerWorld::addObject / removeObject), and the service answers once it did (or after
// kEditDeadline, saying so).
//
// reset_scene means the same in every topology: the scene back to its initial state and time
// 0, each proxy restarting at its interface's current target (GodFingerWorld::
// resetAtInterfaces), so that a hand holding a device feels no jump.
//
// Not real-time: called from ROS callbacks.
#pragma once

#include "god_finger/DeleteObject.h"
#include "god_finger/SetContactModel.h"
#include "god_finger/SpawnObject.h"
#include "god_finger/physics/world_params.h"
#include "god_finger/ros/reconfigure.h"
#include "god_finger/runtime/servo_command.h"

#include <ros/callback_queue.h>
#include <ros/node_handle.h>
#include <ros/service_server.h>
#include <ros/spinner.h>
#include <std_srvs/Trigger.h>

#include <functional>
#include <memory>
#include <mutex>
#include <string>

namespace god_finger
{
class WorldServices
{
 public:
  // Applies a world command (kReset, kSetContactModel or kSetContactParams); false, with
  // `error` set, refuses it.
  using Post = std::function<bool(const ServoCommand& command, std::string* error)>;

  // `initial`: what the world was built with. `node`: the name in log lines. Advertises the
  // services on `nh` and the reconfiguration server on `pnh`.
  WorldServices(ros::NodeHandle nh, const ros::NodeHandle& pnh, const WorldParams& initial, Post post,
                const std::string& node);
  ~WorldServices();
  WorldServices(const WorldServices&) = delete;
  WorldServices& operator=(const WorldServices&) = delete;

  // The model in force changed by other means (a device button): the server shows it.
  void showModel(ContactModel model);

 private:
  bool onReset(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  bool onSetModel(god_finger::SetContactModel::Request& request, god_finger::SetContactModel::Response& response);
  bool onSpawn(god_finger::SpawnObject::Request& request, god_finger::SpawnObject::Response& response);
  bool onDelete(god_finger::DeleteObject::Request& request, god_finger::DeleteObject::Response& response);
  // Posts an object edit and waits for the world's outcome (at most kEditDeadline).
  ObjectEdit::Outcome edit(ServoCommand::Kind kind, const std::shared_ptr<ObjectEdit>& edit);
  [[nodiscard]] bool applyConfig(const god_finger::GodFingerConfig& config, bool model_changed, std::string* error);

  Post post_;
  std::string node_;
  // The base of a reconfiguration: the initial parameters with the contact parameters in
  // force. Written by reconfiguration callbacks (LiveReconfigure serialises them), read by
  // spawn_object's thread too: under params_mutex_.
  WorldParams params_;
  std::mutex params_mutex_;
  std::unique_ptr<LiveReconfigure> reconfigure_;
  ros::ServiceServer reset_service_;
  ros::ServiceServer model_service_;
  // spawn_object and delete_object wait for the world (a first load decomposes a mesh; the loop
  // takes the edit between two steps): on a queue and thread of their own, so that they never
  // hold up the node's other callbacks (poses, /stop_force). Destroyed in reverse: the thread
  // stops, then the services go, then the queue.
  ros::CallbackQueue edit_queue_;
  ros::ServiceServer spawn_service_;
  ros::ServiceServer delete_service_;
  std::unique_ptr<ros::AsyncSpinner> edit_spinner_;
};
}  // namespace god_finger
