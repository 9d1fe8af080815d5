#include "god_finger/ros/physics_node.h"

#include "god_finger/ContactAreaArray.h"
#include "god_finger/GodFingerConfig.h"
#include "god_finger/SetContactModel.h"
#include "god_finger/core/input_error.h"
#include "god_finger/core/text_numbers.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/physics/urdf_scene.h"
#include "god_finger/ros/conversions.h"
#include "god_finger/ros/markers.h"
#include "god_finger/ros/parameters.h"
#include "god_finger/ros/queues.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/transform_broadcaster.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace god_finger
{
namespace
{
WorldParams readWorldParams(const ros::NodeHandle& pnh)
{
  WorldParams params;
  const double rate = readDouble(pnh, "rate", 1000.0, 10.0, 10000.0, "Hz");
  params.time_step = 1.0 / rate;
  params.solver_iterations = readInt(pnh, "solver_iterations", params.solver_iterations, 1, 1000);
  const std::string model = readString(pnh, "model", contactModelName(params.model));
  if (!parseContactModel(model, &params.model))
  {
    throw InputError("parameter '" + pnh.resolveName("model") + "' = '" + model +
                     "' is not one of god_object, god_finger, soft_finger");
  }
  ContactParams& contact = params.contact;
  // Ranges are the core's (validate() below names the parameter); here only the types.
  contact.max_radius = readDouble(pnh, "r_max", contact.max_radius, -INFINITY, INFINITY, "m");
  contact.distance_constant = readDouble(pnh, "d0", 0.001, -INFINITY, INFINITY, "m");
  contact.alpha = readDouble(pnh, "alpha", contact.alpha, -INFINITY, INFINITY, "dimensionless");
  contact.sub_god_objects = readInt(pnh, "n_sgo", contact.sub_god_objects, -1000000, 1000000);
  contact.max_angle = readDouble(pnh, "tau_a", contact.max_angle, -INFINITY, INFINITY, "rad");
  contact.friction = readDouble(pnh, "friction", contact.friction, -INFINITY, INFINITY, "dimensionless");
  const std::string walk = readString(pnh, "walk", walkVariantName(contact.walk));
  if (!parseWalkVariant(walk, &contact.walk))
  {
    throw InputError("parameter '" + pnh.resolveName("walk") + "' = '" + walk + "' is not one of project, unfold");
  }
  CouplingParams& coupling = params.coupling;
  coupling.stiffness = readDouble(pnh, "coupling_stiffness", coupling.stiffness, -INFINITY, INFINITY, "N/m");
  coupling.damping = readDouble(pnh, "coupling_damping", coupling.damping, -INFINITY, INFINITY, "N s/m");
  coupling.max_force = readDouble(pnh, "max_force", coupling.max_force, -INFINITY, INFINITY, "N");
  coupling.proxy_radius = readDouble(pnh, "proxy_radius", coupling.proxy_radius, -INFINITY, INFINITY, "m");
  coupling.proxy_mass = readDouble(pnh, "proxy_mass", coupling.proxy_mass, -INFINITY, INFINITY, "kg");
  validateOrThrow(params);
  return params;
}

}  // namespace

struct PhysicsNode::Impl
{
  struct Interface
  {
    std::string name;
    int index = -1;  // in the world, once the first pose came
    ros::Subscriber pose_subscriber;
    ros::Publisher feedback_publisher;
    ros::Publisher proxy_publisher;
    // Written by the pose callback, read by the loop.
    Eigen::Vector3d target = Eigen::Vector3d::Zero();
    ros::Time target_stamp;  // of the pose the target came from: feedback carries it on
    bool have_target = false;
    bool fresh = false;  // a pose came since the last step
  };

  ros::NodeHandle nh;
  ros::NodeHandle pnh;
  std::unique_ptr<GodFingerWorld> world;
  std::vector<Interface> interfaces;
  std::mutex mutex;  // guards world and the targets
  std::condition_variable pose_arrived;
  ros::Publisher contact_publisher;
  ros::Publisher marker_publisher;
  ros::Publisher diagnostics_publisher;
  ros::ServiceServer reset_service;
  ros::ServiceServer model_service;
  tf2_ros::TransformBroadcaster broadcaster;
  double publish_period = 1.0 / 60.0;
  std::thread thread;
  std::atomic<bool> running{true};
  long rejected_poses = 0;
  long overruns = 0;
  boost::recursive_mutex reconfigure_mutex;
  std::unique_ptr<dynamic_reconfigure::Server<god_finger::GodFingerConfig>> reconfigure;
  god_finger::GodFingerConfig last_good_config;
  bool have_good_config = false;
  std::vector<double> step_us;

  void onPose(int i, const geometry_msgs::PoseStamped::ConstPtr& message)
  {
    const Eigen::Vector3d p(message->pose.position.x, message->pose.position.y, message->pose.position.z);
    std::lock_guard<std::mutex> lock(mutex);
    if (!p.allFinite() || (!message->header.frame_id.empty() && message->header.frame_id != "world"))
    {
      ++rejected_poses;
      ROS_WARN_THROTTLE(1.0, "physics: rejected a pose of '%s' (frame '%s', finite %d)", interfaces[i].name.c_str(),
                        message->header.frame_id.c_str(), int(p.allFinite()));
      return;
    }
    interfaces[i].target = p;
    interfaces[i].target_stamp = message->header.stamp;
    interfaces[i].have_target = true;
    interfaces[i].fresh = true;
    pose_arrived.notify_one();
  }

  // True when every interface that has sent a pose has sent a new one since the last step.
  bool allPosesFresh() const
  {
    bool any = false;
    for (const Interface& interface : interfaces)
    {
      if (interface.have_target)
      {
        any = true;
        if (!interface.fresh)
        {
          return false;
        }
      }
    }
    return any;
  }

  bool onReset(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response)
  {
    std::lock_guard<std::mutex> lock(mutex);
    world->reset();
    response.success = true;
    response.message = "scene reset";
    return true;
  }

  // dynamic_reconfigure: the method's parameters and the model, applied together if valid;
  // otherwise the previous ones stay (and the tool shows them again).
  void onReconfigure(god_finger::GodFingerConfig& config, std::uint32_t)
  {
    ContactModel model;
    std::lock_guard<std::mutex> lock(mutex);
    ContactParams contact = world->params().contact;
    contact.max_radius = config.r_max;
    contact.distance_constant = config.d0;
    contact.alpha = config.alpha;
    contact.sub_god_objects = config.n_sgo;
    contact.max_angle = config.tau_a;
    contact.friction = config.friction;
    const bool walk_ok = parseWalkVariant(config.walk, &contact.walk);
    const bool model_ok = parseContactModel(config.model, &model);
    const std::string error = validate(contact);
    if (!walk_ok || !model_ok || !error.empty())
    {
      ROS_WARN("physics: reconfiguration refused (%s); the previous parameters stay",
               !error.empty() ? error.c_str() : "unknown model or walk");
      if (have_good_config)
      {
        config = last_good_config;
      }
      return;
    }
    world->setContactParams(contact);
    world->setContactModel(model);
    last_good_config = config;
    have_good_config = true;
  }

  bool onSetModel(god_finger::SetContactModel::Request& request, god_finger::SetContactModel::Response& response)
  {
    ContactModel model;
    if (!parseContactModel(request.model, &model))
    {
      response.success = false;
      response.message = "unknown contact model '" + request.model + "' (god_object, god_finger, soft_finger)";
      return true;
    }
    std::lock_guard<std::mutex> lock(mutex);
    world->setContactModel(model);
    response.success = true;
    response.message = std::string("contact model: ") + contactModelName(model);
    return true;
  }

  // One step under the lock; publishes the per-step messages.
  // Called with `mutex` held.
  void step()
  {
    for (Interface& interface : interfaces)
    {
      interface.fresh = false;
      if (!interface.have_target)
      {
        continue;
      }
      if (interface.index < 0)
      {
        interface.index = world->addInterface(interface.target);
      }
      world->setInterfaceTarget(interface.index, interface.target);
    }
    const auto start = std::chrono::steady_clock::now();
    world->step();
    step_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
    const ros::Time stamp = ros::Time::now();
    for (const Interface& interface : interfaces)
    {
      if (interface.index < 0)
      {
        continue;
      }
      const InterfaceState& state = world->interfaceState(interface.index);
      geometry_msgs::WrenchStampedPtr feedback(new geometry_msgs::WrenchStamped);
      // Stamped with the pose it answers (the device state's time, through the haptic node),
      // so that the driver can measure the whole round trip.
      feedback->header.stamp = interface.target_stamp.isZero() ? stamp : interface.target_stamp;
      feedback->header.frame_id = "world";
      feedback->wrench.force = toVector(state.user_force);
      interface.feedback_publisher.publish(feedback);
      geometry_msgs::PointStampedPtr proxy(new geometry_msgs::PointStamped);
      proxy->header.stamp = stamp;
      proxy->header.frame_id = "world";
      proxy->point = toPoint(state.proxy_position);
      interface.proxy_publisher.publish(proxy);
    }
  }

  void publishScene()
  {
    std::lock_guard<std::mutex> lock(mutex);
    const ros::Time stamp = ros::Time::now();
    god_finger::ContactAreaArrayPtr areas(new god_finger::ContactAreaArray);
    areas->header.stamp = stamp;
    areas->header.frame_id = "world";
    for (const Interface& interface : interfaces)
    {
      if (interface.index < 0)
      {
        continue;
      }
      const InterfaceState& state = world->interfaceState(interface.index);
      for (int c = 0; c < state.contact_count; ++c)
      {
        const WorldContactArea& area = state.contacts[c];
        god_finger::ContactArea message;
        message.header = areas->header;
        message.interface = interface.name;
        message.object = world->scene().bodies[area.body].name;
        message.point = toPoint(area.point);
        message.normal = toVector(area.normal);
        message.depth = area.depth;
        message.feature = static_cast<std::uint8_t>(area.feature);
        message.radius = area.radius;
        for (int k = 0; k < area.sub_god_object_count; ++k)
        {
          message.sub_god_objects.push_back(toPoint(area.positions[k]));
        }
        areas->areas.push_back(message);
      }
    }
    contact_publisher.publish(areas);

    visualization_msgs::MarkerArrayPtr markers(new visualization_msgs::MarkerArray);
    appendBodyMarkers(*world, stamp, markers.get());
    appendInteractionMarkers(*world, stamp, markers.get());
    marker_publisher.publish(markers);

    std::vector<geometry_msgs::TransformStamped> transforms;
    for (int i = 0; i < world->bodyCount(); ++i)
    {
      const BodyState body = world->bodyState(i);
      geometry_msgs::TransformStamped transform;
      transform.header.stamp = stamp;
      transform.header.frame_id = "world";
      transform.child_frame_id = world->scene().bodies[i].name;
      transform.transform.translation = toVector(body.pose.translation());
      const Eigen::Quaterniond q(body.pose.linear());
      transform.transform.rotation.x = q.x();
      transform.transform.rotation.y = q.y();
      transform.transform.rotation.z = q.z();
      transform.transform.rotation.w = q.w();
      transforms.push_back(transform);
    }
    broadcaster.sendTransform(transforms);
  }

  void publishDiagnostics(double seconds, long steps)
  {
    std::lock_guard<std::mutex> lock(mutex);
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = ros::Time::now();
    diagnostic_msgs::DiagnosticStatus status;
    status.name = ros::this_node::getName() + ": physics loop";
    status.hardware_id = "god_finger";
    const double rate = steps / seconds;
    const double wanted = 1.0 / world->params().time_step;
    status.level =
        rate < 0.95 * wanted ? diagnostic_msgs::DiagnosticStatus::WARN : diagnostic_msgs::DiagnosticStatus::OK;
    status.message = status.level == diagnostic_msgs::DiagnosticStatus::OK ? "running" : "below its rate";
    auto add = [&status](const std::string& key, const std::string& value)
    {
      diagnostic_msgs::KeyValue pair;
      pair.key = key;
      pair.value = value;
      status.values.push_back(pair);
    };
    add("rate_hz", jsonNumber(rate));
    add("overruns", std::to_string(overruns));
    add("rejected_poses", std::to_string(rejected_poses));
    add("step_us_median", jsonNumber(percentile(step_us, 0.5)));
    add("step_us_p99", jsonNumber(percentile(step_us, 0.99)));
    add("contact_model", contactModelName(world->contactModel()));
    step_us.clear();
    array.status.push_back(status);
    diagnostics_publisher.publish(array);
  }

  // Fixed-step at 1/time_step on average, but each step is taken as soon as every interface's
  // new pose is in (so the feedback answers the freshest pose without waiting for a timer
  // tick), never earlier than half a period before its slot and never later than half a period
  // after it. A step that ends after that latest moment is an overrun.
  void loop()
  {
    using Clock = std::chrono::steady_clock;
    const auto period =
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(world->params().time_step));
    const auto publish_every =
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(publish_period));
    auto slot = Clock::now() + period;
    auto next_publish = slot;
    auto diagnostics_start = slot;
    long diagnostics_steps = 0;
    while (running && ros::ok())
    {
      std::this_thread::sleep_until(slot - period / 2);
      {
        std::unique_lock<std::mutex> lock(mutex);
        pose_arrived.wait_until(lock, slot + period / 2, [this] { return allPosesFresh() || !running; });
        step();
      }
      ++diagnostics_steps;
      const auto now = Clock::now();
      if (now >= next_publish)
      {
        publishScene();
        next_publish = now + publish_every;
      }
      if (now - diagnostics_start >= std::chrono::seconds(1))
      {
        publishDiagnostics(std::chrono::duration<double>(now - diagnostics_start).count(), diagnostics_steps);
        diagnostics_start = now;
        diagnostics_steps = 0;
      }
      const auto after = Clock::now();
      if (after > slot + period / 2)
      {
        ++overruns;
      }
      slot += period;
      if (after - slot > 10 * period)
      {
        slot = after + period;  // far behind (a debugger, a suspended process): do not race to catch up
      }
    }
  }
};

PhysicsNode::PhysicsNode(ros::NodeHandle nh, ros::NodeHandle pnh) : impl_(new Impl)
{
  Impl& impl = *impl_;
  impl.nh = nh;
  impl.pnh = pnh;
  const WorldParams params = readWorldParams(pnh);
  impl.publish_period = 1.0 / readDouble(pnh, "publish_rate", 60.0, 1.0, 1000.0, "Hz");
  const std::string scene_path = readString(pnh, "scene", "");
  if (scene_path.empty())
  {
    throw InputError("parameter '" + pnh.resolveName("scene") + "' is required (the scene's URDF file)");
  }
  impl.world = std::make_unique<GodFingerWorld>(loadUrdfScene(scene_path), params);
  const std::vector<std::string> names = readStringList(pnh, "interfaces", {"finger"});
  impl.interfaces.resize(names.size());
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    Impl::Interface& interface = impl.interfaces[i];
    interface.name = names[i];
    interface.pose_subscriber = nh.subscribe<geometry_msgs::PoseStamped>(
        names[i] + "/pose", kSubscriberQueue,
        [this, i](const geometry_msgs::PoseStamped::ConstPtr& m) { impl_->onPose(i, m); }, ros::VoidConstPtr(),
        ros::TransportHints().tcpNoDelay());
    interface.feedback_publisher = nh.advertise<geometry_msgs::WrenchStamped>(names[i] + "/feedback", kPublisherQueue);
    interface.proxy_publisher = nh.advertise<geometry_msgs::PointStamped>(names[i] + "/proxy", kPublisherQueue);
  }
  impl.contact_publisher = nh.advertise<god_finger::ContactAreaArray>("contact_areas", kPublisherQueue);
  impl.marker_publisher = nh.advertise<visualization_msgs::MarkerArray>("markers", 2);
  impl.diagnostics_publisher = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  impl.reset_service = nh.advertiseService("reset_scene", &Impl::onReset, &impl);
  impl.model_service = nh.advertiseService("set_contact_model", &Impl::onSetModel, &impl);
  // Starts from the parameters read above (the same private names), so it changes nothing
  // until someone reconfigures.
  impl.reconfigure =
      std::make_unique<dynamic_reconfigure::Server<god_finger::GodFingerConfig>>(impl.reconfigure_mutex, pnh);
  god_finger::GodFingerConfig initial;
  initial.model = contactModelName(params.model);
  initial.r_max = params.contact.max_radius;
  initial.d0 = params.contact.distance_constant;
  initial.alpha = params.contact.alpha;
  initial.n_sgo = params.contact.sub_god_objects;
  initial.tau_a = params.contact.max_angle;
  initial.friction = params.contact.friction;
  initial.walk = walkVariantName(params.contact.walk);
  impl.reconfigure->updateConfig(initial);
  impl.reconfigure->setCallback([this](god_finger::GodFingerConfig& config, std::uint32_t level)
                                { impl_->onReconfigure(config, level); });
  ROS_INFO("physics: scene '%s' (%d bodies), %zu interface(s), %.0f Hz, model %s", scene_path.c_str(),
           impl.world->bodyCount(), names.size(), 1.0 / params.time_step, contactModelName(params.model));
  impl.thread = std::thread([this]() { impl_->loop(); });
}

PhysicsNode::~PhysicsNode()
{
  impl_->running = false;
  impl_->pose_arrived.notify_all();
  if (impl_->thread.joinable())
  {
    impl_->thread.join();
  }
}
}  // namespace god_finger
