#include "god_finger/ros/servo_node.h"
#include "node_parameters.h"

#include "bag_track.h"
#include "device_frame.h"
#include "diagnostics.h"
#include "god_finger/DeviceState.h"
#include "god_finger/devices/device_registry.h"
#include "god_finger/ros/conversions.h"
#include "god_finger/runtime/left_world_report.h"
#include "god_finger/runtime/loop_statistics.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/runtime/servo_loop.h"
#include "god_finger/scene/urdf_scene.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"
#include "hand_marker.h"
#include "interface_parameters.h"
#include "parameters.h"
#include "queues.h"
#include "servo_setup.h"
#include "world_messages.h"
#include "world_services.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <std_srvs/SetBool.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <thread>

namespace god_finger
{
struct ServoNode::Impl
{
  // The node's own name (a nodelet's, not its manager's): the diagnostics' statuses start with it.
  std::string node_name;
  struct Interface
  {
    std::string name;
    std::string interface_frame;  // world -> NAME_interface
    std::string device_frame;     // NAME_device
    ros::Publisher state;
    ros::Publisher force;
    ros::Publisher pose;
    ros::Publisher feedback;
    ros::Publisher proxy;
    std::unique_ptr<interactive_markers::InteractiveMarkerServer> hand_marker;
    std::uint32_t published = 0;
    bool tracked = true;    // the last sample's: false, its source lost the finger (let go)
    bool missing = false;   // the last sample's: untracked because the source's message lacked it
    long lost_samples = 0;  // samples untracked since the last diagnostics
  };

  ros::NodeHandle nh;  // the node's namespace (topics advertised late: joint_states)
  std::unique_ptr<ServoLoop> loop;
  std::vector<Interface> interfaces;
  std::vector<std::string> names;
  bool sim_time = false;
  ros::Publisher clock_publisher;
  ros::Publisher contact_publisher;
  ros::Publisher marker_publisher;
  ros::Publisher joint_publisher;  // joint_states, when the scene has joints
  ros::Publisher diagnostics_publisher;
  ros::ServiceServer stop_service;  // /stop_force
  tf2_ros::TransformBroadcaster broadcaster;
  // world -> NAME_device of every interface (ros/device_frame.h): the interactive handle's frame.
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_broadcaster;
  std::unique_ptr<WorldServices> services;  // reset_scene, set_contact_model, dynamic_reconfigure
  int shown_model = -1;                     // the loop's model the publisher thread last saw (counters().model)
  std::thread publisher_thread;
  std::atomic<bool> publishing{true};
  LoopStatistics statistics;
  LeftWorldReport left_world;  // the publisher thread's
  long last_ticks = 0;
  double last_ticks_at = -1.0;
  long last_overruns = 0;
  DiagnosticThresholds thresholds;  // the statuses' levels (runtime/diagnostic_levels.h)
  long last_dropped = 0;

  double steady_to_ros = 0.0;   // s: ROS wall time minus steadySeconds()
  std::FILE* timing = nullptr;  // ~timing_csv: one line per tick

  // Simulated time: the loop's time after the step (never 0). Wall clock: when the device
  // was read (as a driver stamps its states), so that stamps show the loop's own period.
  ros::Time stampOf(double loop_time) const
  {
    return sim_time ? ros::Time(loop_time + loop->period()) : ros::Time::now();
  }
  ros::Time stampOf(const ServoSample& sample) const
  {
    return sim_time ? stampOf(sample.time) : ros::Time(sample.read_at + steady_to_ros);
  }

  // /stop_force: true stops every device's force at once (the guards output zero), false
  // resumes it with the guards' soft start.
  bool onStopForce(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response)
  {
    ServoCommand command;
    command.kind = request.data ? ServoCommand::Kind::kStopForce : ServoCommand::Kind::kResumeForce;
    std::string error;
    response.success = loop->post(command, &error);
    response.message = response.success ? (request.data ? "force stopped" : "force resuming (soft start)") : error;
    return true;
  }

  // The loop's model changed (a command, or a device button, which only the loop sees): the
  // reconfiguration server shows it.
  void showLoopModel()
  {
    const int model = loop->counters().model.load();
    if (model != shown_model)
    {
      shown_model = model;
      services->showModel(static_cast<ContactModel>(model));
    }
  }

  void publishSample(const ServoSample& sample)
  {
    Interface& interface = interfaces[sample.interface];
    const ros::Time stamp = stampOf(sample);
    interface.tracked = sample.tracked;
    interface.missing = sample.missing;
    interface.lost_samples += sample.tracked ? 0 : 1;
    if (timing && sample.interface == 0)
    {
      std::fprintf(timing, "%.3f,%.3f,%.3f\n", sample.period_us, sample.latency_us, sample.step_us);
    }
    god_finger::DeviceStatePtr state(new god_finger::DeviceState);
    state->header.stamp = stamp;
    state->header.seq = ++interface.published;  // gap-free: a recording can be checked
    state->header.frame_id = interface.device_frame;
    state->position = toVector(sample.reading.position);
    state->velocity = toVector(sample.reading.velocity);
    state->buttons = sample.reading.buttons;
    state->applied_force = toVector(sample.applied_force);
    state->applied_torque = toVector(sample.applied_torque);
    state->command_age = -1.0;  // the force comes in process, not as a command
    state->has_orientation = sample.reading.has_orientation;
    if (sample.reading.has_orientation)
    {
      state->orientation = toQuaternion(sample.reading.orientation);
    }
    interface.state.publish(state);

    geometry_msgs::Vector3StampedPtr force(new geometry_msgs::Vector3Stamped);
    force->header.stamp = stamp;
    force->header.frame_id = interface.device_frame;
    // The force the device is given (after the force guard: 0 while /stop_force holds it,
    // ramped by the soft start and the watchdog), as device/state's applied_force: what one
    // echoes is what the hand feels. The coupling's ask is on `feedback` (world frame).
    force->vector = toVector(sample.applied_force);
    interface.force.publish(force);

    const geometry_msgs::PoseStampedPtr pose = poseMessage(
        stamp, sample.interface_position, sample.reading.has_orientation ? &sample.interface_orientation : nullptr);
    interface.pose.publish(pose);

    interface.feedback.publish(feedbackMessage(stamp, sample.user_force, sample.user_torque));
    interface.proxy.publish(proxyMessage(stamp, sample.proxy_position));

    broadcaster.sendTransform(interfaceTransform(*pose, interface.interface_frame));
  }

  void publishDiagnostics()
  {
    const ServoCounters& counters = loop->counters();
    LoopSummary summary = statistics.summarize();
    // The loop's own rate (its tick counter), not the publisher's, which may drop samples.
    const long ticks = counters.ticks.load();
    const long overruns = counters.overruns.load();
    const double now = steadySeconds();
    if (last_ticks_at > 0.0 && now > last_ticks_at)
    {
      summary.rate_hz = (ticks - last_ticks) / (now - last_ticks_at);
    }
    const long ticked = ticks - last_ticks;
    const long late = overruns - last_overruns;
    last_ticks = ticks;
    last_ticks_at = now;
    last_overruns = overruns;
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = ros::Time::now();
    diagnostic_msgs::DiagnosticStatus status;
    status.name = node_name + ": servo loop";
    status.hardware_id = "god_finger";
    const bool slow = !sim_time && summary.rate_hz < 0.95 * loop->params().rate;
    status.level = diagnostic_msgs::DiagnosticStatus::OK;
    status.message = "running";
    raiseLevel(&status, counters.failed ? DiagnosticLevel::kError : DiagnosticLevel::kOk, "stopped: a device failed");
    raiseLevel(&status, slow ? DiagnosticLevel::kWarn : DiagnosticLevel::kOk, "below its rate");
    // On simulated time a late tick is the wall clock's, not the hand's: not judged (as the rate).
    if (!sim_time)
    {
      raiseLevel(&status, overrunLevel(late, ticked, thresholds), overrunText(late, ticked, thresholds));
    }
    auto add = [&status](const std::string& key, const std::string& value) { addValue(&status, key, value); };
    add("clock", sim_time ? "simulated" : "real time");
    add("realtime_priority", counters.realtime ? "SCHED_FIFO" : "none");
    add("rate_hz", jsonNumber(summary.rate_hz));
    add("period_us_p50", jsonNumber(summary.period_us.p50));
    add("period_us_p99", jsonNumber(summary.period_us.p99));
    add("period_us_max", jsonNumber(summary.period_us.max));
    add("latency_us_p50", jsonNumber(summary.latency_us.p50));
    add("latency_us_p99", jsonNumber(summary.latency_us.p99));
    add("latency_us_max", jsonNumber(summary.latency_us.max));
    add("step_us_p50", jsonNumber(summary.step_us.p50));
    add("step_us_p99", jsonNumber(summary.step_us.p99));
    add("ticks", std::to_string(counters.ticks.load()));
    add("overruns", std::to_string(counters.overruns.load()));
    add("dropped_samples", std::to_string(counters.dropped_samples.load()));
    add("dropped_snapshots", std::to_string(counters.dropped_snapshots.load()));
    add("rejected_readings", std::to_string(counters.rejected_readings.load()));
    add("rejected_orientations", std::to_string(counters.rejected_orientations.load()));  // ignored, position taken
    add("rejected_forces", std::to_string(counters.rejected_forces.load()));
    add("force_stopped", counters.force_stopped ? "true" : "false");  // /stop_force
    // The multi-rate scheme: interface-ticks whose force the haptic side rendered because the
    // physics was late, steps taken, and targets the late physics skipped.
    add("stale_ticks", std::to_string(counters.stale_ticks.load()));
    add("physics_steps", std::to_string(counters.physics_steps.load()));
    add("skipped_targets", std::to_string(counters.skipped_targets.load()));
    // Resets, spawns and deletes: each rebuilds the world on the physics thread (allocates).
    add("world_rebuilds", std::to_string(counters.world_rebuilds.load()));
    // The hold's passivity observer and controller (runtime/multirate_render.h).
    add("hold_damped_ticks", std::to_string(counters.hold_damped_ticks.load()));
    add("hold_dissipated_J", jsonNumber(counters.hold_dissipated.load()));
    add("hold_lowest_energy_J", jsonNumber(counters.hold_lowest_energy.load()));
    add("contact_model", contactModelName(static_cast<ContactModel>(counters.model.load())));
    add("pad_solver", padSolverName(static_cast<PadSolver>(counters.pad_solver.load())));
    add("left_world", left_world.diagnosticValue());  // bodies put back at their start (world_margin)
    add("untracked_readings", std::to_string(counters.untracked_readings.load()));  // fingers let go
    array.status.push_back(status);
    array.status.push_back(stepProfileStatus(node_name + ": step profile", summary.stage_us));
    // A finger its pose source lost (no pose newer than its timeout): let go, named; the others go on.
    for (Interface& interface : interfaces)
    {
      if (!interface.tracked || interface.lost_samples > 0)
      {
        diagnostic_msgs::DiagnosticStatus lost;
        lost.name = node_name + ": finger " + interface.name;
        lost.hardware_id = "god_finger";
        lost.level =
            interface.tracked ? diagnostic_msgs::DiagnosticStatus::OK : diagnostic_msgs::DiagnosticStatus::WARN;
        lost.message = interface.tracked   ? "tracked again"
                       : interface.missing ? "missing from the pose array (it has fewer poses than fingers): let go"
                                           : "pose stream lost or late (no pose newer than its pose_timeout): let go";
        addValue(&lost, "tracked", interface.tracked ? "true" : "false");
        addValue(&lost, "untracked_samples", std::to_string(interface.lost_samples));
        array.status.push_back(lost);
        interface.lost_samples = 0;
      }
    }
    diagnostics_publisher.publish(array);
    statistics.clear();
  }

  // The normal-priority side: everything the loop leaves behind goes out as messages. An
  // exception here stops the node with its message instead of terminating the process.
  void publish()
  {
    try
    {
      publishUntilStopped();
    }
    catch (const std::exception& error)
    {
      ROS_FATAL("servo: publishing failed (%s); shutting down", error.what());
      loop->stop();
      ros::requestShutdown();
    }
  }

  void publishUntilStopped()
  {
    ServoSample sample;
    WorldSnapshot snapshot;
    const double diagnostics_period = 1.0;
    double next_diagnostics = steadySeconds() + diagnostics_period;
    while (publishing)
    {
      bool any = false;
      double clock_time = -1.0;
      while (loop->samples().tryPop(&sample))
      {
        any = true;
        publishSample(sample);
        statistics.add(sample);
        clock_time = sample.time;
      }
      if (sim_time && clock_time >= 0.0)
      {
        rosgraph_msgs::Clock clock;
        clock.clock = stampOf(clock_time);
        clock_publisher.publish(clock);
      }
      while (loop->snapshots().tryPop(&snapshot))
      {
        any = true;
        const ros::Time stamp =
            sim_time ? ros::Time(snapshot.time > 0.0 ? snapshot.time : loop->period()) : ros::Time::now();
        const SceneDescription& scene = *snapshot.scene;  // the world's changes with spawn_object
        contact_publisher.publish(contactAreaMessage(scene, snapshot, names, stamp));
        marker_publisher.publish(markerMessage(scene, snapshot, loop->world().params().coupling.proxy_radius, stamp));
        broadcaster.sendTransform(bodyTransforms(scene, snapshot, stamp));
        if (!scene.joints.empty())
        {
          if (!joint_publisher)  // the first joint came with a spawned object
          {
            joint_publisher = nh.advertise<sensor_msgs::JointState>("joint_states", kPublisherQueue);
          }
          joint_publisher.publish(jointStateMessage(scene, snapshot, stamp));
        }
        left_world.update(scene, snapshot, stamp.toSec(),
                          [](const std::string& line) { ROS_WARN("servo: %s", line.c_str()); });
      }
      showLoopModel();
      const double now = steadySeconds();
      if (now >= next_diagnostics)
      {
        publishDiagnostics();
        next_diagnostics = now + diagnostics_period;
      }
      if (loop->counters().failed && !loop->running())
      {
        ROS_FATAL("servo: the loop stopped (a device failed); shutting down");
        ros::requestShutdown();
        return;
      }
      if (!any)
      {
        sleepFor(5e-4);
      }
    }
  }
};

ServoNode::ServoNode(ros::NodeHandle nh, ros::NodeHandle pnh) : impl_(new Impl)
{
  Impl& impl = *impl_;
  impl.nh = nh;
  impl.node_name = pnh.getNamespace();  // "/servo", "/physics", "/finger/haptic"
  impl.thresholds = readDiagnosticThresholds(RosParameterSource(pnh));
  ServoSetup setup = makeServoSetup(nh, pnh, [](const std::string& message) { ROS_WARN("%s", message.c_str()); });
  impl.loop = std::move(setup.loop);
  impl.names = setup.names;
  impl.sim_time = impl.loop->params().simulated_time;
  const WorldParams& world_params = setup.world_params;
  const std::string& scene_path = setup.scene_path;
  const ServoLoopParams& loop_params = impl.loop->params();

  impl.interfaces.resize(impl.names.size());
  for (std::size_t i = 0; i < impl.names.size(); ++i)
  {
    Impl::Interface& interface = impl.interfaces[i];
    ros::NodeHandle interface_nh(nh, impl.names[i]);
    interface.name = impl.names[i];
    interface.interface_frame = impl.names[i] + "_interface";
    interface.device_frame = impl.names[i] + "_device";
    interface.state = interface_nh.advertise<god_finger::DeviceState>("device/state", kPublisherQueue);
    interface.force = interface_nh.advertise<geometry_msgs::Vector3Stamped>("device/force", kPublisherQueue);
    interface.pose = interface_nh.advertise<geometry_msgs::PoseStamped>("pose", kPublisherQueue);
    interface.feedback = interface_nh.advertise<geometry_msgs::WrenchStamped>("feedback", kPublisherQueue);
    interface.proxy = interface_nh.advertise<geometry_msgs::PointStamped>("proxy", kPublisherQueue);
    if (setup.hand_targets[i])
    {
      ServoLoop* loop = impl.loop.get();
      const int index = static_cast<int>(i);
      interface.hand_marker =
          makeHandMarker(interface_nh, interface.device_frame, setup.hand_starts[i],
                         impl.loop->interfaces()[i].profile.workspace_radius,
                         [loop, index](const HandMarkerPose& target)
                         {
                           ServoCommand command;
                           command.kind = ServoCommand::Kind::kHandTarget;
                           command.interface = index;
                           command.hand_target = target.position;
                           command.hand_oriented = target.rotated;
                           command.hand_orientation = target.orientation;
                           std::string refused;
                           if (!loop->post(command, &refused))  // the queue is full
                           {
                             ROS_WARN_THROTTLE(1.0, "hand marker: a target was dropped: %s", refused.c_str());
                           }
                         });
    }
  }
  impl.static_broadcaster = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
  std::vector<geometry_msgs::TransformStamped> device_frames;
  for (std::size_t i = 0; i < impl.interfaces.size(); ++i)
  {
    device_frames.push_back(deviceFrameTransform(impl.loop->interfaces()[i].mapping.params(),
                                                 impl.interfaces[i].device_frame, ros::Time::now()));
  }
  impl.static_broadcaster->sendTransform(device_frames);
  if (impl.sim_time)
  {
    impl.clock_publisher = nh.advertise<rosgraph_msgs::Clock>("/clock", kPublisherQueue);
  }
  impl.contact_publisher = nh.advertise<god_finger::ContactAreaArray>("contact_areas", kPublisherQueue);
  impl.marker_publisher = nh.advertise<visualization_msgs::MarkerArray>("markers", 2);
  if (!impl.loop->world().scene().joints.empty())
  {
    impl.joint_publisher = nh.advertise<sensor_msgs::JointState>("joint_states", kPublisherQueue);
  }
  impl.diagnostics_publisher = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  impl.services = std::make_unique<WorldServices>(
      nh, pnh, world_params,
      [this](const ServoCommand& command, std::string* error) { return impl_->loop->post(command, error); }, "servo");
  impl.shown_model = static_cast<int>(world_params.model);
  impl.stop_service = nh.advertiseService("/stop_force", &Impl::onStopForce, &impl);
  ROS_INFO("servo: scene '%s' (%d bodies), %zu interface(s), %.0f Hz on %s, model %s", scene_path.c_str(),
           impl.loop->world().bodyCount(), impl.names.size(), loop_params.rate,
           impl.sim_time ? "simulated time" : "the wall clock", contactModelName(world_params.model));
  // On simulated time a recorder (record:=true) gets the session from its first tick: the loop
  // waits (up to 10 s of wall clock) until every interface's device/state has this many
  // subscribers.
  // Meanwhile /clock says 1 ns: valid for those (rosbag record) that wait for a clock before
  // they subscribe.
  const int wait_for = readNodeParams(pnh).wait_for_subscribers;
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(10.0);
  while (impl.sim_time && wait_for > 0 && ros::ok() && ros::WallTime::now() < give_up &&
         std::any_of(impl.interfaces.begin(), impl.interfaces.end(),
                     [wait_for](const Impl::Interface& interface)
                     { return static_cast<int>(interface.state.getNumSubscribers()) < wait_for; }))
  {
    rosgraph_msgs::Clock clock;
    clock.clock = ros::Time(0, 1);
    impl.clock_publisher.publish(clock);
    ros::WallDuration(0.01).sleep();
  }
  impl.steady_to_ros = ros::WallTime::now().toSec() - steadySeconds();
  // ~timing_csv: period, device-to-force latency and step (us) of every tick, for the bench.
  impl.timing = openTimingCsv(pnh, "period_us,latency_us,step_us");
  impl.publisher_thread = std::thread([this]() { impl_->publish(); });
  impl.loop->start();
}

ServoNode::~ServoNode()
{
  impl_->loop->stop();
  impl_->publishing = false;
  if (impl_->publisher_thread.joinable())
  {
    impl_->publisher_thread.join();
  }
  if (impl_->timing)
  {
    std::fclose(impl_->timing);
  }
}
}  // namespace god_finger
