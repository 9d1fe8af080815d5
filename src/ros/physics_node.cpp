#include "god_finger/ros/physics_node.h"
#include "node_parameters.h"

#include "channel_port.h"
#include "diagnostics.h"
#include "god_finger/ContactAreaArray.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/ros/conversions.h"
#include "god_finger/runtime/fixed_rate_schedule.h"
#include "god_finger/runtime/left_world_report.h"
#include "god_finger/runtime/multirate_render.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/runtime/servo_command.h"
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/support/denormals.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"
#include "interface_parameters.h"
#include "parameters.h"
#include "queues.h"
#include "scene_parameter.h"
#include "world_messages.h"
#include "world_services.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace god_finger
{

struct PhysicsNode::Impl
{
  // The node's own name (a nodelet's, not its manager's): the diagnostics' statuses start with it.
  std::string node_name;
  struct Interface
  {
    std::string name;
    int index = -1;            // in the world, once the first pose came
    CouplingProfile coupling;  // the device's (NAME/coupling_*), as its haptic node renders it
    // Read again at the interface's first pose: on several machines the device's launch may
    // load its profile after the physics started (callback thread only).
    bool profile_current = false;
    ros::Subscriber pose_subscriber;  // NAME/interface_pose (god_finger/InterfacePose)
    // NAME/pose (PoseStamped) from a recording made before NAME/interface_pose (a bag played
    // into this node): its all-zero quaternion is a 3-DOF finger's. Shut down at the first
    // interface pose: the nodes now send NAME/pose for tools only (the identity for 3-DOF).
    ros::Subscriber recorded_pose_subscriber;
    bool interface_pose_seen = false;  // under mutex
    ros::Publisher feedback_publisher;
    ros::Publisher proxy_publisher;
    ros::Publisher proxy_state_publisher;  // NAME/proxy_state: the haptic node's local coupling
    // Written by the pose callback, read by the loop.
    Eigen::Vector3d target = Eigen::Vector3d::Zero();
    // The pose's orientation (world_messages.h poseOrientation): an oriented finger's, else none.
    bool oriented = false;
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    ros::Time target_stamp;  // of the pose the target came from: feedback carries it on
    bool have_target = false;
    bool fresh = false;  // a pose came since the last step
    // What the last step left for this interface's publishers: copied under the lock by step(),
    // published after it by publishStep() (loop thread only).
    bool stepped = false;  // in the world, so feedback and proxy are published
    ros::Time feedback_stamp;
    Eigen::Vector3d user_force = Eigen::Vector3d::Zero();      // N, world
    Eigen::Vector3d user_torque = Eigen::Vector3d::Zero();     // N m, world (an oriented finger's)
    Eigen::Vector3d proxy_position = Eigen::Vector3d::Zero();  // m, world
    InterfaceState state;                                      // the whole, for proxy_state
    // The channel's physics port and its controller (channel_port.h): it gives the world the
    // target it may use (pulled back out of a contact the device has not paid for), counting the
    // force the last step holds for it (heldForce), and sends its count after each step.
    std::unique_ptr<ChannelPort> channel;
    double contact_credit = 0.0;  // J: the profile's passivity_contact_credit (the channel's status level)
    MultirateStep held;           // the last step's, for heldForce (none yet: no planes, no force)
    bool port_answered = false;   // the port has answered once
  };

  ros::NodeHandle nh;
  ros::NodeHandle pnh;
  std::unique_ptr<GodFingerWorld> world;
  std::vector<Interface> interfaces;
  std::mutex mutex;  // guards world and the targets
  std::condition_variable pose_arrived;
  ros::Publisher contact_publisher;
  ros::Publisher marker_publisher;
  ros::Publisher joint_publisher;  // joint_states, when the scene has joints
  ros::Publisher diagnostics_publisher;
  tf2_ros::TransformBroadcaster broadcaster;
  double publish_period = 1.0 / 60.0;
  std::thread thread;
  std::atomic<bool> running{true};
  long rejected_poses = 0;
  // Loop thread: steps whose poses were all in before the deadline and that ended after it (the
  // physics late), and steps taken at the deadline without a new pose from every interface that
  // has sent one (its poses late, or its device stalled: the step starts at the deadline, so it
  // ends after it; before any pose came, none is counted).
  long overruns = 0;
  long late_pose_steps = 0;
  long reported_late_pose_steps = 0;        // at the last diagnostics
  long reported_overruns = 0;               // at the last diagnostics (loop thread)
  DiagnosticThresholds thresholds;          // the statuses' levels (runtime/diagnostic_levels.h)
  std::unique_ptr<WorldServices> services;  // reset_scene, set_contact_model, dynamic_reconfigure
  std::vector<double> step_us;              // since the last diagnostics (under `mutex`)
  std::vector<double> step_us_read;         // publishDiagnostics' swap partner: both keep their capacity
  long reported_dropped_contacts = 0;       // WorldCounters::dropped_contacts_total at the last diagnostics
  std::vector<StepProfile> profiles;        // each step's stages, as step_us
  std::vector<StepProfile> profiles_read;
  WorldSnapshot snapshot;      // read by publishScene
  LeftWorldReport left_world;  // guarded by mutex

  // NAME/interface_pose: the haptic node's, with every device state.
  void onInterfacePose(int i, const god_finger::InterfacePose::ConstPtr& message)
  {
    bool first = false;
    {
      std::lock_guard<std::mutex> lock(mutex);
      first = !interfaces[i].interface_pose_seen;
      interfaces[i].interface_pose_seen = true;
    }
    if (first)
    {
      interfaces[i].recorded_pose_subscriber.shutdown();
    }
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    const bool oriented = poseOrientation(*message, &orientation);
    onPose(i, message->header, message->pose.position, oriented, orientation);
  }

  // NAME/pose before any interface pose came: a recording's 3-DOF finger (the all-zero
  // quaternion) is taken; any other is a tool's copy of an interface pose, not taken.
  void onRecordedPose(int i, const geometry_msgs::PoseStamped::ConstPtr& message)
  {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (interfaces[i].interface_pose_seen)
      {
        return;
      }
    }
    if (recordedThreeDofPose(message->pose))
    {
      onPose(i, message->header, message->pose.position, false, Eigen::Quaterniond::Identity());
    }
  }

  void onPose(int i, const std_msgs::Header& header, const geometry_msgs::Point& position, bool oriented,
              const Eigen::Quaterniond& orientation)
  {
    const Eigen::Vector3d p(position.x, position.y, position.z);
    if (!interfaces[i].profile_current)
    {
      try
      {
        const DeviceProfile profile =
            readInterfaceConfig(RosParameterSource(ros::NodeHandle(nh, interfaces[i].name)), interfaces[i].name)
                .profile;
        std::lock_guard<std::mutex> lock(mutex);
        interfaces[i].coupling = profile.coupling;
        interfaces[i].contact_credit = profile.passivity.passivity_contact_credit;
        if (!interfaces[i].port_answered)  // the port has not answered yet
        {
          interfaces[i].channel->reconfigure(profile.passivity, world->params().time_step);
        }
        interfaces[i].profile_current = true;
      }
      catch (const std::exception& error)
      {
        ROS_ERROR_THROTTLE(1.0, "physics: interface '%s' refused: %s", interfaces[i].name.c_str(), error.what());
        return;
      }
    }
    std::lock_guard<std::mutex> lock(mutex);
    if (!p.allFinite() || (!header.frame_id.empty() && header.frame_id != "world"))
    {
      ++rejected_poses;
      ROS_WARN_THROTTLE(1.0, "physics: rejected a pose of '%s' (frame '%s', finite %d)", interfaces[i].name.c_str(),
                        header.frame_id.c_str(), int(p.allFinite()));
      return;
    }
    interfaces[i].target = p;
    interfaces[i].oriented = oriented;
    interfaces[i].orientation = orientation;
    interfaces[i].target_stamp = header.stamp;
    interfaces[i].have_target = true;
    interfaces[i].fresh = true;
    pose_arrived.notify_one();
  }

  // True when an interface has sent a pose (a device drives the world).
  bool anyTarget() const
  {
    for (const Interface& interface : interfaces)
    {
      if (interface.have_target)
      {
        return true;
      }
    }
    return false;
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

  // A world command of the services (world_services.h), applied at once under the lock.
  bool apply(const ServoCommand& command, std::string* error)
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (!isWorldCommand(command.kind))
    {
      *error = "the physics node has no device: it takes no force or hand commands";
      return false;
    }
    try
    {
      return applyWorldCommand(command, world.get());
    }
    catch (const InputError& bad)
    {
      *error = bad.what();
      return false;
    }
  }

  // One step; leaves the per-step messages' contents in the interfaces (publishStep()).
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
        try
        {
          try
          {
            interface.index = world->addInterface(interface.target, interface.coupling);
          }
          catch (const ProxyInsideBodyError& inside)
          {
            // The hand is inside a body: this node started (or respawned) under a hand that
            // presses an object. Refusing would leave the hand without force until it withdraws;
            // the proxy starts at the hand, the solver pushes it out, and the device's guard ramps
            // the force in (its watchdog tripped while this node was away).
            ROS_WARN("physics: interface '%s': %s; started there anyway (a running session)", interface.name.c_str(),
                     inside.what());
            interface.index = world->addInterface(interface.target, interface.coupling, true);
          }
        }
        catch (const std::exception& error)
        {
          // A profile unstable at this rate and proxy mass (read after start-up): refused, and
          // tried again at the next pose.
          ROS_ERROR_THROTTLE(1.0, "physics: interface '%s' refused: %s", interface.name.c_str(), error.what());
          interface.have_target = false;
          continue;
        }
      }
      // The channel's physics port: the target the world may take, against the device's energy.
      // It counts the held spring, what the world can give back: the coupling's damper only
      // dissipates, and its share, estimated from poses that come in bursts through a link, was
      // counted well over what the hand paid for it at the device (measured in the interactive
      // demo through 30 ms: the margin pinned at the credit and the target held 5 mm out of the
      // table after a minute's press, its contact flickering).
      interface.port_answered = true;
      Eigen::Vector3d used = interface.target;
      Eigen::Vector3d used_velocity;
      interface.channel->answer(
          interface.target, Eigen::Vector3d::Zero(),
          [&interface](const Eigen::Vector3d& x, const Eigen::Vector3d& /*v*/) -> Eigen::Vector3d
          { return heldForce(interface.coupling, interface.held, x, Eigen::Vector3d::Zero()); },
          &used, &used_velocity);
      if (interface.oriented)
      {
        world->setInterfaceTarget(interface.index, used, interface.orientation);
      }
      else
      {
        world->setInterfaceTarget(interface.index, used);
      }
    }
    const auto start = std::chrono::steady_clock::now();
    world->step();
    step_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
    if (profiles.empty() || profiles.back().step != world->stepProfile().step)  // one step in profile_every is timed
    {
      profiles.push_back(world->stepProfile());
    }
    for (Interface& interface : interfaces)
    {
      interface.stepped = interface.index >= 0;
      if (!interface.stepped)
      {
        continue;
      }
      const InterfaceState& state = world->interfaceState(interface.index);
      interface.feedback_stamp = interface.target_stamp;
      interface.user_force = state.user_force;
      interface.user_torque = state.user_torque;
      interface.proxy_position = state.proxy_position;
      interface.state = state;
      interface.held = multirateStepOf(state, 1);
    }
  }

  // The per-step messages of what step() left, published without the lock (loop thread).
  void publishStep()
  {
    const ros::Time stamp = ros::Time::now();
    for (const Interface& interface : interfaces)
    {
      if (!interface.stepped)
      {
        continue;
      }
      // Stamped with the pose it answers (the device state's time, through the haptic node),
      // so that the driver can measure the whole round trip.
      interface.feedback_publisher.publish(
          feedbackMessage(interface.feedback_stamp.isZero() ? stamp : interface.feedback_stamp, interface.user_force,
                          interface.user_torque));
      interface.proxy_publisher.publish(proxyMessage(stamp, interface.proxy_position));
      // Stamped as the feedback: the pose it answered.
      interface.proxy_state_publisher.publish(
          proxyStateMessage(interface.feedback_stamp.isZero() ? stamp : interface.feedback_stamp, interface.state));
      interface.channel->sendPacket(stamp);
    }
  }

  void publishScene()
  {
    std::vector<std::string> names(interfaces.size());
    double proxy_radius = 0.0;
    {
      std::lock_guard<std::mutex> lock(mutex);
      world->snapshot(&snapshot);
      proxy_radius = world->params().coupling.proxy_radius;
      // The snapshot lists the world's interfaces, which are added in the order poses came.
      for (const Interface& interface : interfaces)
      {
        if (interface.index >= 0)
        {
          names[interface.index] = interface.name;
        }
      }
    }
    const ros::Time stamp = ros::Time::now();
    const SceneDescription& scene = *snapshot.scene;  // the world's may change meanwhile (spawn_object)
    contact_publisher.publish(contactAreaMessage(scene, snapshot, names, stamp));
    marker_publisher.publish(markerMessage(scene, snapshot, proxy_radius, stamp));
    broadcaster.sendTransform(bodyTransforms(scene, snapshot, stamp));
    if (!scene.joints.empty())
    {
      if (!joint_publisher)  // the first joint came with a spawned object
      {
        joint_publisher = nh.advertise<sensor_msgs::JointState>("joint_states", 10);
      }
      joint_publisher.publish(jointStateMessage(scene, snapshot, stamp));
    }
    std::lock_guard<std::mutex> lock(mutex);
    left_world.update(scene, snapshot, stamp.toSec(),
                      [](const std::string& line) { ROS_WARN("physics: %s", line.c_str()); });
  }

  // Reads the counters and the world under the lock, publishes after it.
  void publishDiagnostics(double seconds, long steps)
  {
    double wanted = 0.0;
    ContactModel model;
    long rejected = 0;
    PadSolver solver = PadSolver::kConstraint;
    std::string left;
    long dropped_contacts = 0;
    {
      std::lock_guard<std::mutex> lock(mutex);
      step_us_read.clear();
      step_us_read.swap(step_us);
      profiles_read.clear();
      profiles_read.swap(profiles);
      dropped_contacts = world->counters().dropped_contacts_total;
      wanted = 1.0 / world->params().time_step;
      model = world->contactModel();
      rejected = rejected_poses;
      solver = world->params().pad_solver;
      left = left_world.diagnosticValue();
    }
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = ros::Time::now();
    diagnostic_msgs::DiagnosticStatus status;
    status.name = node_name + ": physics loop";
    status.hardware_id = "god_finger";
    const double rate = steps / seconds;
    status.level = diagnostic_msgs::DiagnosticStatus::OK;
    status.message = "running";
    raiseLevel(&status, rate < 0.95 * wanted ? DiagnosticLevel::kWarn : DiagnosticLevel::kOk, "below its rate");
    // Overruns since the last report, of the steps taken since (the loop's own counts); a step
    // that waited for a pose until its deadline is the pose's lateness, not the physics'.
    const long late = overruns - reported_overruns;
    reported_overruns = overruns;
    raiseLevel(&status, overrunLevel(late, steps, thresholds), overrunText(late, steps, thresholds));
    // Steps that waited for a late pose: the link's or the device side's lateness (WARN at most:
    // runtime/diagnostic_levels.h), named as such.
    const long waited = late_pose_steps - reported_late_pose_steps;
    reported_late_pose_steps = late_pose_steps;
    raiseLevel(&status, latePoseLevel(waited, steps, thresholds), latePoseText(waited, steps, thresholds));
    auto add = [&status](const std::string& key, const std::string& value) { addValue(&status, key, value); };
    add("rate_hz", jsonNumber(rate));
    add("overruns", std::to_string(overruns));
    add("late_pose_steps", std::to_string(late_pose_steps));
    add("rejected_poses", std::to_string(rejected));
    add("step_us_median", jsonNumber(percentile(step_us_read, 0.5)));
    add("step_us_p99", jsonNumber(percentile(step_us_read, 0.99)));
    add("contact_model", contactModelName(model));
    add("pad_solver", padSolverName(solver));
    add("left_world", left);  // bodies put back at their start (world_margin)
    // Contacts beyond InterfaceState::kMaxContacts bodies per finger, since the start: WARN in a
    // window that dropped any.
    add("dropped_contacts", std::to_string(dropped_contacts));
    raiseLevel(&status, dropped_contacts > reported_dropped_contacts ? DiagnosticLevel::kWarn : DiagnosticLevel::kOk,
               "a finger touched more than " + std::to_string(InterfaceState::kMaxContacts) +
                   " bodies at once: the others' contacts dropped");
    reported_dropped_contacts = dropped_contacts;
    array.status.push_back(status);
    StepProfileStatistics stages;
    for (const StepProfile& profile : profiles_read)
    {
      stages.add(profile);
    }
    array.status.push_back(stepProfileStatus(node_name + ": step profile", stages.summarize()));
    for (const Interface& interface : interfaces)
    {
      // The channel's physics port, per interface (channel_port.h).
      diagnostic_msgs::DiagnosticStatus channel;
      channel.name = node_name + ": channel " + interface.name;
      channel.hardware_id = interface.name;
      channel.level = diagnostic_msgs::DiagnosticStatus::OK;
      channel.message = "physics port";
      interface.channel->addValues(&channel);
      double credit = 0.0;
      {
        std::lock_guard<std::mutex> lock(mutex);
        credit = interface.contact_credit;
      }
      const double margin = interface.channel->port().margin();
      raiseLevel(&channel, marginLevel(margin, credit, thresholds), marginText(margin, credit, thresholds));
      array.status.push_back(channel);
    }
    diagnostics_publisher.publish(array);
  }

  // Fixed-step at 1/time_step on average, but each step is taken as soon as every interface's
  // new pose is in (so the feedback answers the freshest pose without waiting for a timer
  // tick), never earlier than half a period before its slot and never later than half a period
  // after it. A step (and its publishing) that ends after that latest moment, the schedule's
  // deadline (runtime/fixed_rate_schedule.h), is an overrun of the physics when every pose was in
  // before it; one that waited for a pose until the deadline is a late pose step.
  void loop()
  {
    flushDenormalsInThisThread();             // support/denormals.h
    using Clock = std::chrono::steady_clock;  // CLOCK_MONOTONIC, as steadySeconds()
    const double period_s = world->params().time_step;
    const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period_s));
    const auto publish_every =
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(publish_period));
    // The first slot one period from now; its deadline half a period after it.
    FixedRateSchedule schedule(period_s, steadySeconds() + period_s / 2);
    auto next_publish = Clock::now() + period;
    auto diagnostics_start = next_publish;
    long diagnostics_steps = 0;
    // ros::ok() turns false only once roscpp's shutdown has closed every topic, which takes it
    // 0.1-0.4 s (unregistering each with the master); the subscriptions go first, and a loop that
    // went on would publish feedback answering a pose that no longer comes, which the driver
    // renders. A node that is shutting down (rosnode kill, Ctrl-C) stops answering at once: the
    // driver's watchdog then acts 30 ms after its last fresh command (safety.test).
    while (running && ros::ok() && !ros::isShuttingDown())
    {
      const double deadline = schedule.deadline();
      sleepUntil(deadline - period_s);
      bool poses_in = false;  // every interface's new pose came before the deadline
      bool driven = false;    // some interface has sent a pose
      {
        std::unique_lock<std::mutex> lock(mutex);
        poses_in = pose_arrived.wait_until(
            lock,
            Clock::time_point(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(deadline))),
            [this] { return allPosesFresh() || !running; });
        driven = anyTarget();
        step();
      }
      publishStep();
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
      const long before = schedule.overruns();
      schedule.tickEnded(steadySeconds());  // the next step's window opens at the deadline or now
      late_pose_steps += driven && !poses_in ? 1 : 0;
      overruns += (poses_in || !driven) && schedule.overruns() > before ? 1 : 0;
    }
  }
};

PhysicsNode::PhysicsNode(ros::NodeHandle nh, ros::NodeHandle pnh) : impl_(new Impl)
{
  Impl& impl = *impl_;
  impl.node_name = pnh.getNamespace();  // "/servo", "/physics", "/finger/haptic"
  impl.nh = nh;
  impl.pnh = pnh;
  const WorldParams params = readWorldParams(pnh);
  impl.publish_period = 1.0 / readNodeParams(pnh).publish_rate;
  impl.thresholds = readDiagnosticThresholds(RosParameterSource(pnh));
  std::string scene_path;
  impl.world = loadSceneWorld(pnh, params, &scene_path);
  const std::vector<std::string> names = readStringList(pnh, "interfaces", {"finger"});
  impl.interfaces.resize(names.size());
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    Impl::Interface& interface = impl.interfaces[i];
    interface.name = names[i];
    const DeviceProfile profile =
        readInterfaceConfig(RosParameterSource(ros::NodeHandle(nh, names[i])), names[i]).profile;
    interface.coupling = profile.coupling;
    interface.contact_credit = profile.passivity.passivity_contact_credit;
    const std::string unstable =
        couplingStabilityError(interface.coupling, params.coupling.proxy_mass, params.time_step);
    if (!unstable.empty())
    {
      throw InputError("interface '" + names[i] + "': " + unstable);
    }
    interface.channel.reset(new ChannelPort(nh, names[i] + "/physics_energy", names[i] + "/device_energy",
                                            profile.passivity, params.time_step));
    interface.pose_subscriber = nh.subscribe<god_finger::InterfacePose>(
        names[i] + "/interface_pose", kSubscriberQueue,
        [this, i](const god_finger::InterfacePose::ConstPtr& m) { impl_->onInterfacePose(i, m); }, ros::VoidConstPtr(),
        ros::TransportHints().tcpNoDelay());
    interface.recorded_pose_subscriber = nh.subscribe<geometry_msgs::PoseStamped>(
        names[i] + "/pose", kSubscriberQueue,
        [this, i](const geometry_msgs::PoseStamped::ConstPtr& m) { impl_->onRecordedPose(i, m); }, ros::VoidConstPtr(),
        ros::TransportHints().tcpNoDelay());
    interface.feedback_publisher = nh.advertise<geometry_msgs::WrenchStamped>(names[i] + "/feedback", kPublisherQueue);
    interface.proxy_publisher = nh.advertise<geometry_msgs::PointStamped>(names[i] + "/proxy", kPublisherQueue);
    interface.proxy_state_publisher = nh.advertise<god_finger::ProxyState>(names[i] + "/proxy_state", kPublisherQueue);
  }
  impl.contact_publisher = nh.advertise<god_finger::ContactAreaArray>("contact_areas", kPublisherQueue);
  impl.marker_publisher = nh.advertise<visualization_msgs::MarkerArray>("markers", 2);
  if (!impl.world->scene().joints.empty())
  {
    impl.joint_publisher = nh.advertise<sensor_msgs::JointState>("joint_states", 10);
  }
  impl.diagnostics_publisher = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  impl.services = std::make_unique<WorldServices>(
      nh, pnh, params, [this](const ServoCommand& command, std::string* error) { return impl_->apply(command, error); },
      "physics");
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
