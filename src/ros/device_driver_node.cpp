#include "god_finger/ros/device_driver_node.h"
#include "node_parameters.h"

#include "bag_track.h"
#include "diagnostics.h"
#include "driver_link_ros.h"
#include "god_finger/DeviceState.h"
#include "god_finger/devices/device_registry.h"
#include "god_finger/haptics/force_guard.h"
#include "god_finger/haptics/passivity_controller.h"
#include "god_finger/ros/conversions.h"
#include "god_finger/runtime/fixed_rate_schedule.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/support/denormals.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/spsc_queue.h"
#include "god_finger/support/text_numbers.h"
#include "hand_marker.h"
#include "interface_parameters.h"
#include "parameters.h"
#include "queues.h"
#include "realtime.h"

#include <XmlRpcValue.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>

#include <semaphore.h>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <mutex>
#include <thread>

namespace god_finger
{
namespace
{
// One tick of the device loop, handed to the publisher thread.
struct DriverSample
{
  ros::Time stamp;  // when the device was read (wall clock)
  DeviceReading reading;
  Eigen::Vector3d applied_force = Eigen::Vector3d::Zero();   // N, device frame
  Eigen::Vector3d applied_torque = Eigen::Vector3d::Zero();  // N m, device frame
  // s: how long before the read the force command being rendered arrived (the guard's clock);
  // negative before any command.
  double command_age = -1.0;
};
// Ticks of samples the publisher thread may lag behind (a second at 1 kHz); beyond it a sample
// is dropped (counted) rather than the loop waiting.
constexpr std::size_t kSampleQueueTicks = 1000;
}  // namespace

// Threads: the device loop (real-time priority when permitted) reads the device, takes the
// guard's output and leaves a sample in a preallocated queue: it allocates nothing, logs
// nothing and takes one lock, `mutex`, which the other threads hold only around a call of the
// guard. The publisher thread (normal priority) turns samples into device/state messages and
// publishes the diagnostics; ROS callbacks (force commands, stop_force) command the guard.
struct DeviceDriverNode::Impl
{
  // The node's own name (a nodelet's, not its manager's): the diagnostics' statuses start with it.
  std::string node_name;
  // The backend's name in the device registry (devices/device_registry.h): the status is named
  // for it ("interactive device"), not for the class that simulates it.
  std::string backend_name;
  std::unique_ptr<HapticDevice> device;
  std::unique_ptr<ForceGuard> guard;
  // Under `mutex`: the passivity observer and controller after the guard (its force and the
  // device's last velocity in, the force rendered out).
  std::unique_ptr<PassivityController> passivity;
  double period = 1e-3;
  int realtime_priority = 0;
  std::string frame;
  ros::Publisher state_publisher;
  ros::Publisher diagnostics_publisher;
  ros::Subscriber force_subscriber;
  ros::Subscriber torque_subscriber;
  DeviceProfile profile;  // torque_axes, max_torque (renderableTorque)
  // Under `mutex`: the last device/torque (N m, device frame, renderable) and when it came
  // (now()); one older than the guard's command_timeout is not rendered.
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  double torque_time = -1e9;
  double command_time = -1.0;       // under `mutex`: when the last accepted force command arrived (now())
  ros::ServiceServer stop_service;  // stop_force, in the interface's namespace
  std::unique_ptr<interactive_markers::InteractiveMarkerServer> marker_server;
  std::mutex mutex;  // guards the guard, the passivity controller and command_time
  std::thread thread;
  std::thread publisher_thread;
  std::atomic<bool> running{true};
  std::chrono::steady_clock::time_point epoch = std::chrono::steady_clock::now();
  SpscQueue<DriverSample> samples{kSampleQueueTicks};  // device loop -> publisher thread
  sem_t samples_ready;                                 // posted by the loop per sample (lock-free)
  std::atomic<long> ticks{0};
  std::atomic<long> overruns{0};
  std::atomic<long> dropped{0};  // samples the publisher thread had no room for
  long reported_ticks = 0;       // publisher thread: ticks and overruns at the last diagnostics
  long reported_overruns = 0;
  DiagnosticThresholds thresholds;  // the status's level (runtime/diagnostic_levels.h)
  bool lost_device = false;  // written by the device loop under `mutex`: its last reading untracked (a stale driver)
  bool stopped_by_loss = false;             // under `mutex`: the loss stopped the force (not the user)
  std::atomic<long> lost_device_events{0};  // losses and regains, each counted
  std::mutex trips_mutex;                   // guards round_trips_us (callback and publisher threads)
  std::vector<double> round_trips_us;       // since the last diagnostics
  std::uint32_t published = 0;              // publisher thread only
  std::FILE* timing = nullptr;              // ~timing_csv: every round trip (us), for the bench (callback thread)

  double now() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch).count();
  }

  void onForce(const geometry_msgs::Vector3Stamped::ConstPtr& message)
  {
    const Eigen::Vector3d force(message->vector.x, message->vector.y, message->vector.z);
    // The command is stamped with the device state it answers: the loop's round trip.
    const double round_trip = (ros::Time::now() - message->header.stamp).toSec();
    bool accepted = true;
    long rejected = 0;
    {
      std::lock_guard<std::mutex> lock(mutex);
      const double arrival = now();
      accepted = guard->command(arrival, force);
      rejected = guard->rejected();
      if (accepted)
      {
        command_time = arrival;
      }
    }
    if (!accepted)
    {
      ROS_WARN_THROTTLE(1.0, "device_driver: rejected a non-finite force command (%ld so far)", rejected);
    }
    if (!message->header.stamp.isZero() && round_trip >= 0.0 && round_trip < 10.0)
    {
      {
        std::lock_guard<std::mutex> lock(trips_mutex);
        round_trips_us.push_back(1e6 * round_trip);
      }
      if (timing)  // the bench's file, written here in the callback thread, under no lock the loop takes
      {
        std::fprintf(timing, "%.3f\n", 1e6 * round_trip);
      }
    }
  }

  // device/torque (an oriented finger's torque on the hand, device frame): kept for the loop,
  // on the profile's torque axes and saturated at its max_torque; a non-finite one is dropped.
  void onTorque(const geometry_msgs::Vector3Stamped::ConstPtr& message)
  {
    const Eigen::Vector3d value(message->vector.x, message->vector.y, message->vector.z);
    if (!value.allFinite())
    {
      return;
    }
    const Eigen::Vector3d renderable = renderableTorque(profile, value);
    std::lock_guard<std::mutex> lock(mutex);
    torque = renderable;
    torque_time = now();
  }

  // stop_force: true stops this device's force at once, false resumes it with the soft start.
  bool onStopForce(std_srvs::SetBool::Request& request, std_srvs::SetBool::Response& response)
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (request.data)
    {
      guard->stop();
      stopped_by_loss = false;  // the user's stop: a regained device does not resume it
    }
    else
    {
      guard->resume(now());
    }
    response.success = true;
    response.message = request.data ? "force stopped" : "force resuming (soft start)";
    return true;
  }

  void publishDiagnostics(double rate)
  {
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = ros::Time::now();
    diagnostic_msgs::DiagnosticStatus status;
    status.name = node_name + ": " + backend_name + " device";
    status.hardware_id = backend_name;
    bool timed_out = false;
    bool lost = false;
    long rejected = 0;
    long saturated = 0;
    bool stopped = false;
    long budget_limited = 0;
    double passivity_energy = 0.0;
    double passivity_lowest = 0.0;
    double passivity_dissipated = 0.0;
    long passivity_ticks = 0;
    std::vector<double> trips;
    {
      std::lock_guard<std::mutex> lock(mutex);
      timed_out = guard->timedOut(now());
      lost = lost_device;
      rejected = guard->rejected();
      saturated = guard->saturated();
      stopped = guard->stopped();
      budget_limited = guard->budgetLimited();
      passivity_energy = passivity->energy();
      passivity_lowest = passivity->lowestEnergy();
      passivity_dissipated = passivity->dissipated();
      passivity_ticks = passivity->activeTicks();
    }
    {
      std::lock_guard<std::mutex> lock(trips_mutex);
      trips.swap(round_trips_us);
    }
    status.level = diagnostic_msgs::DiagnosticStatus::OK;
    status.message = timed_out ? "no force commands: output ramped to zero" : "running";
    raiseLevel(&status, rate < 0.95 / period ? DiagnosticLevel::kWarn : DiagnosticLevel::kOk, "below its rate");
    const long now_ticks = ticks.load();
    const long now_overruns = overruns.load();
    const long late = now_overruns - reported_overruns;
    const long ticked = now_ticks - reported_ticks;
    reported_ticks = now_ticks;
    reported_overruns = now_overruns;
    raiseLevel(&status, overrunLevel(late, ticked, thresholds), overrunText(late, ticked, thresholds));
    // A device that lost its source (a ROS driver older than its stale_timeout) reads untracked:
    // its force is stopped until it is back (the loop above).
    raiseLevel(&status, lost ? DiagnosticLevel::kError : DiagnosticLevel::kOk,
               "device lost (its driver is stale): force stopped until it is back");
    auto add = [&status](const std::string& key, const std::string& value) { addValue(&status, key, value); };
    add("rate_hz", std::to_string(rate));
    add("overruns", std::to_string(overruns.load()));
    add("dropped_states", std::to_string(dropped.load()));
    add("rejected_commands", std::to_string(rejected));
    add("saturated_commands", std::to_string(saturated));
    add("force_stopped", stopped ? "true" : "false");
    add("budget_limited_outputs", std::to_string(budget_limited));
    add("watchdog_timed_out", timed_out ? "true" : "false");
    add("device_lost_events", std::to_string(lost_device_events.load()));  // a stale ROS driver, lost and back
    add("commands", std::to_string(trips.size()));
    add("round_trip_us_p50", jsonNumber(percentile(trips, 0.5)));
    add("round_trip_us_p99", jsonNumber(percentile(trips, 0.99)));
    add("round_trip_us_max", jsonNumber(trips.empty() ? NAN : *std::max_element(trips.begin(), trips.end())));
    // The passivity observer at this port (haptics/passivity_controller.h): the energy the hand
    // put into the loop behind it since the start (J), its lowest, what the controller's damping
    // took out (J) and at how many ticks.
    add("passivity_energy_J", jsonNumber(passivity_energy));
    add("passivity_lowest_energy_J", jsonNumber(passivity_lowest));
    add("passivity_dissipated_J", jsonNumber(passivity_dissipated));
    add("passivity_damped_ticks", std::to_string(passivity_ticks));
    add("passivity_damping_limit", jsonNumber(profile.passivity.passivity_damping_limit));

    array.status.push_back(status);
    diagnostics_publisher.publish(array);
  }

  void loop()
  {
    flushDenormalsInThisThread();  // support/denormals.h
    requestRealTimePriority(realtime_priority, node_name + " (device loop)");
    FixedRateSchedule schedule(period, steadySeconds());
    Eigen::Vector3d last_velocity = Eigen::Vector3d::Zero();  // m/s, device frame: the last reading's
    while (running && ros::ok())
    {
      const double t = now();
      Eigen::Vector3d force;
      Eigen::Vector3d applied_torque = Eigen::Vector3d::Zero();
      double command_age = -1.0;
      {
        std::lock_guard<std::mutex> lock(mutex);
        force = guard->output(t);
        if (guard->scale(t) > 0.0)
        {
          force = passivity->apply(force, last_velocity, profile.coupling.max_force);
        }
        else
        {
          passivity->reset();  // stopped, timed out or not started: the next session starts clean
        }
        if (command_time >= 0.0)
        {
          command_age = std::max(0.0, t - command_time);  // a command that came after `t` was read: 0
        }
        // The torque through the force's guard (soft start, watchdog ramp, stop), while fresh.
        if (t - torque_time <= guard->params().command_timeout)
        {
          applied_torque = guard->scale(t) * torque;
        }
      }
      DeviceReading reading;
      try
      {
        reading = device->updateWrench(t, force, applied_torque);
      }
      catch (const DeviceError& error)
      {
        ROS_FATAL("device_driver: %s", error.what());
        ros::shutdown();
        return;
      }
      last_velocity = reading.velocity;
      if (reading.tracked == lost_device)
      {
        // A device that lost its source (a stale ROS driver: devices/driver_bridge.h) is a fault:
        // its force stops at once, and comes back through the soft start when it is tracked again.
        // A force the user stopped (stop_force) stays stopped.
        std::lock_guard<std::mutex> lock(mutex);
        lost_device = !reading.tracked;
        if (lost_device && !guard->stopped())
        {
          guard->stop();
          stopped_by_loss = true;
        }
        else if (!lost_device && stopped_by_loss)
        {
          guard->resume(now());
          stopped_by_loss = false;
        }
        ++lost_device_events;
      }
      DriverSample* sample = samples.reserve();
      if (sample)
      {
        sample->stamp = ros::Time::now();
        sample->reading = reading;
        sample->applied_force = force;
        sample->applied_torque = applied_torque;
        sample->command_age = command_age;
        samples.commit();
        sem_post(&samples_ready);
      }
      else
      {
        ++dropped;
      }
      ++ticks;
      const double after = steadySeconds();
      const double next = schedule.tickEnded(after);
      overruns.store(schedule.overruns());
      if (next > after)
      {
        sleepUntil(next);
      }
    }
  }

  void publishSample(const DriverSample& sample)
  {
    god_finger::DeviceStatePtr state(new god_finger::DeviceState);
    state->header.stamp = sample.stamp;
    state->header.seq = ++published;  // gap-free: a recording can be checked
    state->header.frame_id = frame;
    state->position.x = sample.reading.position.x();
    state->position.y = sample.reading.position.y();
    state->position.z = sample.reading.position.z();
    state->velocity.x = sample.reading.velocity.x();
    state->velocity.y = sample.reading.velocity.y();
    state->velocity.z = sample.reading.velocity.z();
    state->buttons = sample.reading.buttons;
    state->applied_force.x = sample.applied_force.x();
    state->applied_force.y = sample.applied_force.y();
    state->applied_force.z = sample.applied_force.z();
    state->applied_torque = toVector(sample.applied_torque);
    state->command_age = sample.command_age;
    state->has_orientation = sample.reading.has_orientation;
    if (sample.reading.has_orientation)
    {
      state->orientation = toQuaternion(sample.reading.orientation);
    }
    state_publisher.publish(state);
  }

  // The publisher thread: every sample the loop leaves as device/state, the diagnostics at 1 Hz.
  void publish()
  {
    double diagnostics_start = steadySeconds();
    long diagnostics_ticks = ticks.load();
    DriverSample sample;
    while (running && ros::ok())
    {
      timespec wake;
      clock_gettime(CLOCK_REALTIME, &wake);
      wake.tv_nsec += 20000000;  // 20 ms: looks at `running` at least that often
      if (wake.tv_nsec >= 1000000000)
      {
        wake.tv_nsec -= 1000000000;
        ++wake.tv_sec;
      }
      sem_timedwait(&samples_ready, &wake);
      while (samples.tryPop(&sample))
      {
        publishSample(sample);
      }
      const double now_s = steadySeconds();
      if (now_s - diagnostics_start >= 1.0)
      {
        const long now_ticks = ticks.load();
        publishDiagnostics((now_ticks - diagnostics_ticks) / (now_s - diagnostics_start));
        diagnostics_start = now_s;
        diagnostics_ticks = now_ticks;
      }
    }
  }
};

DeviceDriverNode::DeviceDriverNode(ros::NodeHandle nh, ros::NodeHandle pnh) : impl_(new Impl)
{
  Impl& impl = *impl_;
  impl.node_name = pnh.getNamespace();  // "/servo", "/physics", "/finger/haptic"
  // The loop's timing rows (servoLoopParameterTable()): SCHED_FIFO priority 0 is normal
  // scheduling; the loop sleeps every tick, so it never holds a core.
  const ServoLoopParams timing = readLoopParams(pnh);
  impl.period = 1.0 / timing.rate;
  impl.realtime_priority = timing.realtime_priority;
  // The interface's namespace holds its device, profile and mapping (interface_parameters.h).
  const RosParameterSource private_params(pnh);
  const RosParameterSource interface_params(nh);
  const LayeredParameterSource device_params(private_params, interface_params);
  const InterfaceConfig config = readInterfaceConfig(device_params, nh.getNamespace());
  impl.guard = std::make_unique<ForceGuard>(config.profile.coupling.max_force, config.profile.guard);
  impl.passivity = std::make_unique<PassivityController>(config.profile.passivity, impl.period);
  impl.profile = config.profile;
  impl.thresholds = readDiagnosticThresholds(private_params);
  const std::string backend_name = readString(device_params, "backend", "fake");
  const DeviceBackend& backend = findDeviceBackend(backend_name, device_params.fullName("backend"));
  impl.backend_name = backend.name;
  impl.frame = readString(pnh, "frame", "device");
  DeviceContext context(device_params, config.profile.coupling.max_force);
  context.script_start = sharedScriptStart(pnh, impl.now());
  context.read_track = readBagTrack;
  context.default_track_topic = nh.resolveName("device/state");
  const std::string node_name = impl.node_name;
  context.connect_driver = [nh, node_name](const DriverBridgeParams& params, std::shared_ptr<DriverLink> link)
  { return connectDriverLink(nh, node_name, params, std::move(link)); };
  context.now = steadySeconds;
  impl.device = makeDevice(backend, context);
  impl.device->start();
  if (backend.hand_target)
  {
    HapticDevice* hand = impl.device.get();
    impl.marker_server = makeHandMarker(nh, impl.frame, readVector(device_params, "start", Eigen::Vector3d(0, 0, 0.12)),
                                        config.profile.workspace_radius,
                                        [hand](const HandMarkerPose& target)
                                        {
                                          if (target.rotated)
                                          {
                                            hand->setHandPose(target.position, target.orientation);
                                          }
                                          else
                                          {
                                            hand->setHandTarget(target.position);
                                          }
                                        });
  }
  impl.state_publisher = nh.advertise<god_finger::DeviceState>("device/state", kPublisherQueue);
  impl.diagnostics_publisher = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  impl.force_subscriber =
      nh.subscribe("device/force", kSubscriberQueue, &Impl::onForce, &impl, ros::TransportHints().tcpNoDelay());
  impl.torque_subscriber =
      nh.subscribe("device/torque", kSubscriberQueue, &Impl::onTorque, &impl, ros::TransportHints().tcpNoDelay());
  impl.stop_service = nh.advertiseService("stop_force", &Impl::onStopForce, &impl);
  impl.timing = openTimingCsv(pnh, "latency_us");
  ROS_INFO("device_driver: backend '%s' at %.0f Hz, max force %.1f N", backend_name.c_str(), 1.0 / impl.period,
           config.profile.coupling.max_force);
  sem_init(&impl.samples_ready, 0, 0);
  impl.publisher_thread = std::thread([this]() { impl_->publish(); });
  impl.thread = std::thread([this]() { impl_->loop(); });
}

DeviceDriverNode::~DeviceDriverNode()
{
  impl_->running = false;
  if (impl_->thread.joinable())
  {
    impl_->thread.join();
  }
  if (impl_->publisher_thread.joinable())
  {
    impl_->publisher_thread.join();
  }
  sem_destroy(&impl_->samples_ready);
  if (impl_->timing)
  {
    std::fclose(impl_->timing);
  }
}
}  // namespace god_finger
