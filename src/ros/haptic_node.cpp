#include "god_finger/ros/haptic_node.h"
#include "node_parameters.h"

#include "channel_port.h"
#include "device_frame.h"
#include "diagnostics.h"
#include "god_finger/DeviceState.h"
#include "god_finger/SetContactModel.h"
#include "god_finger/haptics/interface_input.h"
#include "god_finger/haptics/virtual_coupling.h"
#include "god_finger/haptics/workspace_mapping.h"
#include "god_finger/physics/contact_model.h"
#include "god_finger/ros/conversions.h"
#include "god_finger/runtime/multirate_render.h"
#include "god_finger/runtime/servo_loop.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"
#include "interface_parameters.h"
#include "parameters.h"
#include "queues.h"
#include "world_messages.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cmath>
#include <mutex>

namespace god_finger
{
namespace
{
}  // namespace

struct HapticNode::Impl
{
  // The node's own name (a nodelet's, not its manager's): the diagnostics' statuses start with it.
  std::string node_name;
  ros::NodeHandle nh;
  WorkspaceMapping mapping;
  bool local_coupling = false;
  DeviceProfile profile;  // torque_axes here; interface_input holds a copy for the workspace bound
  Eigen::Vector3d wall_force = Eigen::Vector3d::Zero();  // N, device frame, under mutex: the last state's wall
  CouplingProfile coupling;  // the device's profile: the physics pulls the proxy with the same
  std::string frame;
  ros::Subscriber state_subscriber;
  ros::Subscriber feedback_subscriber;
  ros::Subscriber proxy_subscriber;
  ros::Publisher pose_publisher;            // NAME/pose: for tools (identity for a 3-DOF finger)
  ros::Publisher interface_pose_publisher;  // NAME/interface_pose: the physics' input, with has_orientation
  ros::Publisher force_publisher;
  ros::Publisher torque_publisher;  // device/torque: a profile with torque_axes only
  ros::Publisher diagnostics_publisher;
  ros::ServiceClient model_client;
  ros::ServiceClient reset_client;
  ros::Timer timer;
  tf2_ros::TransformBroadcaster broadcaster;
  tf2_ros::StaticTransformBroadcaster static_broadcaster;
  std::string device_frame;
  std::mutex mutex;
  // The local coupling (under mutex): the last step's god-object (NAME/proxy_state), rendered
  // against between steps as the servo loop's haptic side does (runtime/multirate_render.h:
  // the step's proxy while the hand presses into its contact planes, the hand itself otherwise, so free motion is free
  // through any delay), and the renderer's state and the device's previous target and velocity (m, m/s, world).
  MultirateStep step;
  MultirateState render;
  Eigen::Vector3d previous_target = Eigen::Vector3d::Zero();
  Eigen::Vector3d previous_velocity = Eigen::Vector3d::Zero();
  bool have_previous = false;
  long rejected_proxy_states = 0;
  ros::Time proxy_stamp;           // the last proxy state's (the pose it answered)
  ros::SteadyTime proxy_received;  // when the last proxy state came
  // s: older than this, the proxy is stale (the physics is gone); long enough that a loaded
  // machine delaying the proxy topic (tens of ms) does not cut the spring.
  double proxy_timeout = NodeParams().proxy_timeout;
  bool have_proxy = false;
  int pending_model_switch = 0;
  bool pending_reset = false;
  ContactModel model = ContactModel::kGodFinger;  // the physics' initial one (~model)
  long rejected_states = 0;
  long rejected_orientations = 0;  // unusable orientations of device states (the position taken)
  InterfaceInput interface_input;  // under mutex: bound, map, presses, the last usable orientation
  long rejected_feedback = 0;
  long states = 0;
  long timer_ticks = 0;
  ros::SteadyTime state_received;  // under mutex: when the last device state came (accepted or not)
  bool have_state = false;
  DiagnosticThresholds thresholds;  // the status's level (runtime/diagnostic_levels.h)
  // The channel's device port (channel_port.h): the hand's work through the rendered force,
  // sent on device_energy; the physics port's packets from physics_energy.
  std::unique_ptr<ChannelPort> channel;
  ros::Time previous_state_stamp;  // under mutex: the last accepted state's
  // s: a longer gap between two states (the driver paused) is not integrated over.
  static constexpr double kLongestStateGap = 0.1;

  // `wall`: the workspace wall (device frame, haptics/workspace_bound.h), added to the command.
  void publishForce(const ros::Time& stamp, const Eigen::Vector3d& world_force, const Eigen::Vector3d& wall)
  {
    geometry_msgs::Vector3StampedPtr force(new geometry_msgs::Vector3Stamped);
    force->header.stamp = stamp;
    force->header.frame_id = frame + "_device";
    const Eigen::Vector3d device = mapping.forceToDevice(world_force) + wall;
    force->vector.x = device.x();
    force->vector.y = device.y();
    force->vector.z = device.z();
    force_publisher.publish(force);
  }

  void onState(const god_finger::DeviceState::ConstPtr& state)
  {
    {
      std::lock_guard<std::mutex> lock(mutex);
      state_received = ros::SteadyTime::now();
      have_state = true;
    }
    InterfaceReading reading;
    reading.position = fromVector(state->position);
    reading.velocity = fromVector(state->velocity);
    reading.buttons = state->buttons;
    reading.has_orientation = state->has_orientation;
    reading.orientation =
        Eigen::Quaterniond(state->orientation.w, state->orientation.x, state->orientation.y, state->orientation.z);
    // The pipeline both topologies share (haptics/interface_input.h): a non-finite state is
    // rejected whole, the reading bounded to the workspace and mapped, presses detected, an
    // unusable orientation counted and the last usable one kept.
    InterfaceInputResult input;
    Eigen::Quaterniond world_orientation = Eigen::Quaterniond::Identity();
    bool oriented = false;
    {
      std::lock_guard<std::mutex> lock(mutex);
      input = interface_input.read(reading);
      if (!input.accepted)
      {
        ++rejected_states;
        ROS_WARN_THROTTLE(1.0, "haptic: rejected a non-finite device state (%ld so far)", rejected_states);
        return;
      }
      rejected_orientations += input.orientation == OrientationInput::kRejected ? 1 : 0;
      oriented = state->has_orientation && interface_input.oriented();
      world_orientation = interface_input.worldOrientation();
    }
    const Eigen::Vector3d& world = input.target;
    const Eigen::Quaterniond* orientation = oriented ? &world_orientation : nullptr;
    interface_pose_publisher.publish(interfacePoseMessage(state->header.stamp, world, orientation));
    const geometry_msgs::PoseStampedPtr pose = poseMessage(state->header.stamp, world, orientation);
    pose_publisher.publish(pose);
    broadcaster.sendTransform(interfaceTransform(*pose, frame));
    if (!state->header.frame_id.empty() && state->header.frame_id != device_frame)
    {
      publishDeviceFrame(state->header.frame_id);
    }

    std::lock_guard<std::mutex> lock(mutex);
    ++states;
    // The hand's work through the channel since the last state: the force applied, less the
    // workspace wall this node added to the command it applies (not the channel's).
    const double gap = previous_state_stamp.isZero() ? 0.0 : (state->header.stamp - previous_state_stamp).toSec();
    if (gap > 0.0 && gap <= kLongestStateGap)
    {
      const Eigen::Vector3d channel_force = fromVector(state->applied_force) - wall_force;
      channel->observeWork(mapping.powerToWorld(-channel_force.dot(reading.velocity)) * gap, state->header.stamp);
    }
    previous_state_stamp = state->header.stamp;
    wall_force = input.wall_force;
    if (input.pressed & kButtonCycleModel)
    {
      ++pending_model_switch;
    }
    if (input.pressed & kButtonReset)
    {
      pending_reset = true;
    }
    // A stale proxy (the physics died or stalled) renders nothing: the driver's watchdog then
    // ramps the force to zero instead of the hand pressing on a frozen proxy.
    const Eigen::Vector3d velocity = mapping.velocityToWorld(reading.velocity);
    if (local_coupling && have_proxy && (ros::SteadyTime::now() - proxy_received).toSec() < proxy_timeout)
    {
      // The hand feels the reaction of the force that pulls the proxy; a step is always older
      // than this state (lag 1), so never passed through as it is.
      const MultirateDevice device{world, have_previous ? previous_target : world, velocity,
                                   have_previous ? previous_velocity : velocity};
      renderMultirate(coupling, ServoLoopParams().recovery_periods, device, step, &render);
      publishForce(state->header.stamp, render.force, input.wall_force);
    }
    previous_target = world;
    previous_velocity = velocity;
    have_previous = true;
  }

  // world -> the device's frame (ros/device_frame.h).
  void publishDeviceFrame(const std::string& name)
  {
    device_frame = name;
    static_broadcaster.sendTransform(deviceFrameTransform(mapping.params(), name, ros::Time::now()));
  }

  void onFeedback(const geometry_msgs::WrenchStamped::ConstPtr& feedback)
  {
    // An oriented finger's torque on the hand, to the device frame, for a profile that renders
    // torque (the driver keeps it on the torque axes, saturated, through its guard). Rendered
    // from the physics' feedback whatever the coupling: the proxy's orientation is there only.
    const Eigen::Vector3d torque = fromVector(feedback->wrench.torque);
    if (profile.torque_axes != 0 && torque.allFinite())
    {
      geometry_msgs::Vector3StampedPtr message(new geometry_msgs::Vector3Stamped);
      message->header.stamp = feedback->header.stamp;
      message->header.frame_id = frame + "_device";
      message->vector = toVector(mapping.torqueToDevice(torque));
      torque_publisher.publish(message);
    }
    if (local_coupling)
    {
      return;
    }
    const Eigen::Vector3d force = fromVector(feedback->wrench.force);
    if (!force.allFinite())
    {
      std::lock_guard<std::mutex> lock(mutex);
      ++rejected_feedback;  // the driver would reject it too; never forward it
      return;
    }
    Eigen::Vector3d wall;
    {
      std::lock_guard<std::mutex> lock(mutex);
      wall = wall_force;
    }
    publishForce(feedback->header.stamp, force, wall);
  }

  void onProxyState(const god_finger::ProxyState::ConstPtr& message)
  {
    MultirateStep read;
    if (!multirateStep(*message, 1, &read))
    {
      std::lock_guard<std::mutex> lock(mutex);
      ++rejected_proxy_states;  // a non-finite value or a bad plane: the last good step stays
      ROS_WARN_THROTTLE(1.0, "haptic: rejected a malformed proxy state (%ld so far)", rejected_proxy_states);
      return;
    }
    std::lock_guard<std::mutex> lock(mutex);
    if (have_proxy && message->header.stamp < proxy_stamp)
    {
      return;  // older than the step rendered against (a reordering link): the newer one stays
    }
    const bool stale = have_proxy && (ros::SteadyTime::now() - proxy_received).toSec() >= proxy_timeout;
    if (!have_proxy || stale)
    {
      // The first step, or the first after the physics was gone: its force as it is, the anchor
      // on the proxy it predicts for the hand.
      render.anchor = have_previous ? predictedProxy(read, previous_target) : read.proxy_position;
      render.force = read.user_force;
      render.exact = true;
    }
    step = read;
    proxy_stamp = message->header.stamp;
    proxy_received = ros::SteadyTime::now();
    have_proxy = true;
  }

  void publishDiagnostics()
  {
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = ros::Time::now();
    diagnostic_msgs::DiagnosticStatus status;
    status.name = node_name + ": haptic";
    status.hardware_id = frame;
    status.level = diagnostic_msgs::DiagnosticStatus::OK;
    status.message = local_coupling ? "local coupling" : "forwarding feedback";
    std::lock_guard<std::mutex> lock(mutex);
    const ros::SteadyTime now = ros::SteadyTime::now();
    // The device's states (a driver gone or stalled) and, with the local coupling, the physics'
    // proxy states (older than proxy_timeout nothing is rendered).
    const double state_age = have_state ? (now - state_received).toSec() : INFINITY;
    const DiagnosticLevel device = streamLevel(have_state, state_age, thresholds.device_state_timeout);
    raiseLevel(&status, device,
               !have_state ? "waiting for the device's states"
                           : "device stale: no device state for " + roundedNumber(state_age) +
                                 " s (device_state_timeout " + roundedNumber(thresholds.device_state_timeout) + " s)");
    if (local_coupling)
    {
      const double proxy_age = have_proxy ? (now - proxy_received).toSec() : INFINITY;
      const DiagnosticLevel physics = streamLevel(have_proxy, proxy_age, proxy_timeout);
      raiseLevel(&status, physics,
                 !have_proxy ? "waiting for the physics' proxy states"
                             : "physics stale: no proxy state for " + roundedNumber(proxy_age) + " s (proxy_timeout " +
                                   roundedNumber(proxy_timeout) + " s): rendering no force");
    }
    const double margin = channel->port().margin();
    const double credit = profile.passivity.passivity_contact_credit;
    raiseLevel(&status, marginLevel(margin, credit, thresholds), marginText(margin, credit, thresholds));
    addValue(&status, "device_state_age_s", jsonNumber(have_state ? state_age : -1.0));
    addValue(&status, "device_states", std::to_string(states));
    addValue(&status, "rejected_states", std::to_string(rejected_states));
    addValue(&status, "rejected_orientations", std::to_string(rejected_orientations));
    addValue(&status, "rejected_feedback", std::to_string(rejected_feedback));
    addValue(&status, "rejected_proxy_states", std::to_string(rejected_proxy_states));
    channel->addValues(&status);
    array.status.push_back(status);
    diagnostics_publisher.publish(array);
  }

  void onTimer(const ros::TimerEvent&)
  {
    if (++timer_ticks % 20 == 0)
    {
      publishDiagnostics();
    }
    int switches = 0;
    bool reset = false;
    {
      std::lock_guard<std::mutex> lock(mutex);
      std::swap(switches, pending_model_switch);
      std::swap(reset, pending_reset);
    }
    for (int i = 0; i < switches; ++i)
    {
      model = nextContactModel(model);
      god_finger::SetContactModel call;
      call.request.model = contactModelName(model);
      if (!model_client.call(call) || !call.response.success)
      {
        ROS_WARN("haptic: could not switch the contact model to %s", contactModelName(model));
      }
      else
      {
        ROS_INFO("haptic: %s", call.response.message.c_str());
      }
    }
    if (reset)
    {
      std_srvs::Trigger call;
      if (!reset_client.call(call))
      {
        ROS_WARN("haptic: could not reset the scene");
      }
    }
  }
};

HapticNode::HapticNode(ros::NodeHandle nh, ros::NodeHandle pnh) : impl_(new Impl)
{
  Impl& impl = *impl_;
  impl.node_name = pnh.getNamespace();  // "/servo", "/physics", "/finger/haptic"
  impl.nh = nh;
  // The interface's namespace holds its profile and mapping (interface_parameters.h).
  const RosParameterSource private_params(pnh);
  const RosParameterSource interface_params(nh);
  const InterfaceConfig config =
      readInterfaceConfig(LayeredParameterSource(private_params, interface_params), nh.getNamespace());
  impl.mapping = WorkspaceMapping(config.mapping);
  impl.coupling = config.profile.coupling;
  impl.profile = config.profile;
  impl.interface_input = InterfaceInput(impl.profile, impl.mapping);
  // Across processes or machines the hand's spring is rendered here, from the freshest device
  // position, so that no topic latency sits between the hand and its spring.
  impl.local_coupling = readBool(pnh, "local_coupling", true);
  impl.proxy_timeout = readNodeParams(pnh).proxy_timeout;
  impl.thresholds = readDiagnosticThresholds(private_params);
  const std::string model_name = readString(pnh, "model", contactModelName(impl.model));
  if (!parseContactModel(model_name, &impl.model))
  {
    throw InputError("parameter '" + pnh.resolveName("model") + "' = '" + model_name + "' is not one of " +
                     contactModelNames());
  }
  std::string ns = nh.getNamespace();
  while (!ns.empty() && ns.front() == '/')
  {
    ns.erase(0, 1);
  }
  impl.frame = readString(pnh, "interface_frame", (ns.empty() ? std::string("finger") : ns) + "_interface");
  const std::string physics = readString(pnh, "physics_namespace", "/");
  ros::NodeHandle physics_nh(physics);
  impl.model_client = physics_nh.serviceClient<god_finger::SetContactModel>("set_contact_model");
  impl.reset_client = physics_nh.serviceClient<std_srvs::Trigger>("reset_scene");
  impl.pose_publisher = nh.advertise<geometry_msgs::PoseStamped>("pose", kPublisherQueue);
  impl.interface_pose_publisher = nh.advertise<god_finger::InterfacePose>("interface_pose", kPublisherQueue);
  impl.force_publisher = nh.advertise<geometry_msgs::Vector3Stamped>("device/force", kPublisherQueue);
  if (impl.profile.torque_axes != 0)
  {
    impl.torque_publisher = nh.advertise<geometry_msgs::Vector3Stamped>("device/torque", kPublisherQueue);
  }
  // Before the subscribers: a nodelet manager's threads call onState as soon as it is subscribed.
  impl.channel.reset(new ChannelPort(nh, "device_energy", "physics_energy"));
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  impl.state_subscriber = nh.subscribe("device/state", kSubscriberQueue, &Impl::onState, &impl, hints);
  impl.feedback_subscriber = nh.subscribe("feedback", kSubscriberQueue, &Impl::onFeedback, &impl, hints);
  impl.proxy_subscriber = nh.subscribe("proxy_state", 1, &Impl::onProxyState, &impl, hints);
  impl.diagnostics_publisher = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  impl.timer = nh.createTimer(ros::Duration(0.05), &Impl::onTimer, &impl);
  ROS_INFO("haptic: interface frame '%s', %s coupling", impl.frame.c_str(),
           impl.local_coupling ? "local" : "forwarded");
}

HapticNode::~HapticNode() = default;
}  // namespace god_finger
