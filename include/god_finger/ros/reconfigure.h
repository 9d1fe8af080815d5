// dynamic_reconfigure of the method's parameters and the contact model (cfg/GodFinger.cfg),
// shared by the physics node and the servo node. Not real-time (called from ROS callbacks).
#pragma once

#include "god_finger/GodFingerConfig.h"
#include "god_finger/SetContactModel.h"
#include "god_finger/physics/world_params.h"

#include <dynamic_reconfigure/server.h>
#include <boost/thread/recursive_mutex.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace god_finger
{
// The configuration that shows `params` (to start the server from what the node runs with).
// The cfg's entries are rows of worldParameterTable(), matched by name.
god_finger::GodFingerConfig configOf(const WorldParams& params);
// Clamps every entry of `config` that lies in its row's range but outside the row's live range
// (support/parameter_table.h) to that live range; one line per clamped entry, naming it, its value,
// the live range and the clamped value (empty: nothing clamped). The cfg's ends are the rows'
// ranges, so dynamic_reconfigure's server itself never clamps a value the table accepts.
std::vector<std::string> clampToLiveRanges(god_finger::GodFingerConfig* config);
// `config` applied over `base` through worldParameterTable(): false (and `error` says why,
// naming the parameter) when any value or the whole set is invalid; nothing is to be applied then.
bool worldFromConfig(const god_finger::GodFingerConfig& config, const WorldParams& base, WorldParams* params,
                     std::string* error);

// A node's dynamic_reconfigure server and the one configuration in force. The contact model
// has several writers (a reconfiguration, the set_contact_model service, a device button):
// each goes through here, so that the server always shows the model that runs, and a
// reconfiguration of one entry (dynparam set r_max) never sends a stale model back: the model
// is applied only when the reconfiguration changes it.
class LiveReconfigure
{
 public:
  // Applies a whole configuration (`model_changed`: its model differs from the one in force).
  // False, with `error` set, refuses it: the previous configuration stays in force and shown.
  using Apply = std::function<bool(const god_finger::GodFingerConfig& config, bool model_changed, std::string* error)>;
  // Applies the model (the service's request); false, with `error` set, refuses it.
  using ApplyModel = std::function<bool(ContactModel model, std::string* error)>;

  // `node`: the name in log lines. Starts from `initial` (what the node already runs with).
  LiveReconfigure(const ros::NodeHandle& pnh, const WorldParams& initial, Apply apply, std::string node);
  LiveReconfigure(const LiveReconfigure&) = delete;
  LiveReconfigure& operator=(const LiveReconfigure&) = delete;

  // The model in force changed by other means (a button): shown from now on. Any thread.
  void showModel(ContactModel model);
  // The set_contact_model service: parses the request, applies it and shows it in force.
  void serveSetModel(const god_finger::SetContactModel::Request& request,
                     god_finger::SetContactModel::Response& response, const ApplyModel& apply);
  god_finger::GodFingerConfig config();

 private:
  void onReconfigure(god_finger::GodFingerConfig& config);

  Apply apply_;
  std::string node_;
  // The server calls back with it held; every change to in_force_ takes it too. Taken before
  // any lock of the node's (the order a reconfiguration takes them in).
  boost::recursive_mutex mutex_;
  god_finger::GodFingerConfig in_force_;
  std::unique_ptr<dynamic_reconfigure::Server<god_finger::GodFingerConfig>> server_;
};
}  // namespace god_finger
