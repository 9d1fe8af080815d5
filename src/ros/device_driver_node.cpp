#include "god_finger/ros/device_driver_node.h"

#include "god_finger/DeviceState.h"
#include "god_finger/core/force_guard.h"
#include "god_finger/core/input_error.h"
#include "god_finger/core/text_numbers.h"
#include "god_finger/devices/fake_device.h"
#include "god_finger/devices/falcon_device.h"
#include "god_finger/devices/omni_device.h"
#include "god_finger/devices/replay_device.h"
#include "god_finger/devices/vendor_io.h"
#include "god_finger/ros/bag_track.h"
#include "god_finger/ros/parameters.h"
#include "god_finger/ros/queues.h"
#include "god_finger/ros/realtime.h"

#include <XmlRpcValue.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <interactive_markers/interactive_marker_server.h>
#include <ros/ros.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

namespace god_finger
{
namespace
{
WaypointPath readScript(const ros::NodeHandle& pnh)
{
  XmlRpc::XmlRpcValue value;
  const std::string name = pnh.resolveName("script");
  if (!pnh.getParam("script", value))
  {
    // No script: the hand holds the handle at the workspace centre.
    return WaypointPath({{0.0, Eigen::Vector3d::Zero()}});
  }
  const std::string what = "parameter '" + name + "' must be a list of [t, x, y, z] waypoints (s, m)";
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray || value.size() == 0)
  {
    throw InputError(what);
  }
  std::vector<Waypoint> waypoints;
  for (int i = 0; i < value.size(); ++i)
  {
    XmlRpc::XmlRpcValue& row = value[i];
    if (row.getType() != XmlRpc::XmlRpcValue::TypeArray || row.size() != 4)
    {
      throw InputError(what + " (waypoint " + std::to_string(i) + ")");
    }
    double numbers[4];
    for (int k = 0; k < 4; ++k)
    {
      if (row[k].getType() == XmlRpc::XmlRpcValue::TypeDouble)
      {
        numbers[k] = static_cast<double>(row[k]);
      }
      else if (row[k].getType() == XmlRpc::XmlRpcValue::TypeInt)
      {
        numbers[k] = static_cast<int>(row[k]);
      }
      else
      {
        throw InputError(what + " (waypoint " + std::to_string(i) + ")");
      }
    }
    waypoints.push_back({numbers[0], Eigen::Vector3d(numbers[1], numbers[2], numbers[3])});
  }
  try
  {
    return WaypointPath(waypoints);
  }
  catch (const InputError& error)
  {
    throw InputError("parameter '" + name + "': " + error.what());
  }
}

FakeDeviceParams readFakeDeviceParams(const ros::NodeHandle& pnh)
{
  FakeDeviceParams params;
  params.handle_mass = readDouble(pnh, "handle_mass", params.handle_mass, 0.0, 100.0, "kg", true);
  params.handle_damping = readDouble(pnh, "handle_damping", params.handle_damping, 0.0, 1e4, "N s/m");
  params.grip_stiffness = readDouble(pnh, "grip_stiffness", params.grip_stiffness, 0.0, 1e6, "N/m", true);
  params.grip_damping = readDouble(pnh, "grip_damping", params.grip_damping, 0.0, 1e4, "N s/m");
  return params;
}

// Script time 0 of the launch's fake and replay devices, on the driver's clock (s): the
// launch's /god_finger_script_epoch (wall clock) plus ~script_delay; NaN without an epoch.
double sharedScriptStart(const ros::NodeHandle& pnh, double seconds_since_start)
{
  const double delay = readDouble(pnh, "script_delay", 2.0, 0.0, 60.0, "s");
  std::string epoch_text;
  double epoch = 0.0;
  if (ros::param::get("/god_finger_script_epoch", epoch_text) &&
      parseDouble(epoch_text.substr(0, epoch_text.find_last_not_of(" \n\r\t") + 1), &epoch))
  {
    return seconds_since_start + epoch + delay - ros::WallTime::now().toSec();
  }
  if (ros::param::get("/god_finger_script_epoch", epoch))
  {
    return seconds_since_start + epoch + delay - ros::WallTime::now().toSec();
  }
  return NAN;
}

#if defined(GOD_FINGER_HAVE_NIFALCON) || defined(GOD_FINGER_HAVE_OPENHAPTICS)
// Clock and wait for the hardware backends' start-up (homing, calibration), which waits for the user.
double steadySeconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void waitForUser()
{
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
}
#endif

// `max_force` (N) is the profile's limit; hardware backends clamp to it as well as the guard.
std::unique_ptr<HapticDevice> makeDevice(const std::string& backend, const ros::NodeHandle& nh,
                                         const ros::NodeHandle& pnh, double seconds_since_start, double max_force)
{
  if (backend == "fake")
  {
    const FakeDeviceParams params = readFakeDeviceParams(pnh);
    auto device = std::make_unique<FakeDevice>(params, readScript(pnh));
    // Fake devices of one launch follow their scripts in step.
    const double start = sharedScriptStart(pnh, seconds_since_start);
    if (std::isfinite(start))
    {
      device->setScriptStart(start);
    }
    return device;
  }
  if (backend == "falcon")
  {
    FalconParams params;
    params.index = readInt(pnh, "index", params.index, 0, 15);
    params.firmware_attempts = readInt(pnh, "firmware_attempts", params.firmware_attempts, 1, 100);
    params.homing_timeout = readDouble(pnh, "homing_timeout", params.homing_timeout, 0.0, 600.0, "s", true);
    params.max_force = std::min(max_force, params.max_force);
    params.center_z = readDouble(pnh, "center_z", params.center_z, 0.0, 0.3, "m");
#ifdef GOD_FINGER_HAVE_NIFALCON
    return std::make_unique<FalconDevice>(makeNifalconIo(), params, steadySeconds, waitForUser);
#else
    throw DeviceError(
        "backend 'falcon' needs libnifalcon, which this build did not find: build and install libnifalcon "
        "(https://github.com/libnifalcon/libnifalcon), then rebuild god_finger (README, Devices)");
#endif
  }
  if (backend == "omni")
  {
    OmniParams params;
    params.device_name = readString(pnh, "device_name", params.device_name);
    params.calibration_timeout =
        readDouble(pnh, "calibration_timeout", params.calibration_timeout, 0.0, 600.0, "s", true);
    params.max_force = max_force;
    const Eigen::VectorXd center = readVector(pnh, "center_mm", Eigen::Vector3d::Zero());
    if (center.size() != 3)
    {
      throw InputError("parameter '" + pnh.resolveName("center_mm") + "' must be [x, y, z] (mm, Omni frame)");
    }
    params.center_mm = {center[0], center[1], center[2]};
#ifdef GOD_FINGER_HAVE_OPENHAPTICS
    return std::make_unique<OmniDevice>(makeOpenHapticsIo(), params, steadySeconds, waitForUser);
#else
    throw DeviceError(
        "backend 'omni' needs the OpenHaptics HD API, which this build did not find: install 3D Systems' "
        "OpenHaptics (and the Touch / Phantom device driver), then rebuild god_finger (README, Devices)");
#endif
  }
  if (backend == "replay")
  {
    const std::string bag = readString(pnh, "bag", "");
    if (bag.empty())
    {
      throw InputError("parameter '" + pnh.resolveName("bag") + "' is required by backend 'replay' (a recorded bag)");
    }
    const std::string topic = readString(pnh, "topic", nh.resolveName("device/state"));
    auto device = std::make_unique<ReplayDevice>(readBagTrack(bag, topic));
    const double start = sharedScriptStart(pnh, seconds_since_start);
    if (std::isfinite(start))
    {
      device->setStart(start);
    }
    return device;
  }
  if (backend == "interactive")
  {
    // A simulated handle whose hand is an rviz marker (DeviceDriverNode adds the marker).
    const FakeDeviceParams params = readFakeDeviceParams(pnh);
    const Eigen::Vector3d start = readVector(pnh, "start", Eigen::Vector3d(0.0, 0.0, 0.12));
    return std::make_unique<FakeDevice>(params, WaypointPath({{0.0, start}}));
  }
  throw InputError("parameter '" + pnh.resolveName("backend") + "' = '" + backend +
                   "' is not one of fake, interactive, replay, falcon, omni");
}
}  // namespace

struct DeviceDriverNode::Impl
{
  std::unique_ptr<HapticDevice> device;
  std::unique_ptr<ForceGuard> guard;
  double period = 1e-3;
  int realtime_priority = 0;
  std::string frame;
  ros::Publisher state_publisher;
  ros::Publisher diagnostics_publisher;
  ros::Subscriber force_subscriber;
  std::unique_ptr<interactive_markers::InteractiveMarkerServer> marker_server;
  std::mutex mutex;  // guards the guard
  std::thread thread;
  std::atomic<bool> running{true};
  std::chrono::steady_clock::time_point epoch = std::chrono::steady_clock::now();
  long overruns = 0;
  std::vector<double> round_trips_us;  // since the last diagnostics
  long published = 0;

  double now() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch).count();
  }

  // The interactive backend's hand: a marker in the device frame, dragged in rviz (a sphere
  // moved freely in the view plane, and arrows along each axis).
  void addMarker(ros::NodeHandle& nh, const Eigen::Vector3d& start)
  {
    FakeDevice* hand = static_cast<FakeDevice*>(device.get());
    marker_server = std::make_unique<interactive_markers::InteractiveMarkerServer>(nh.resolveName("device_marker"));
    visualization_msgs::InteractiveMarker marker;
    marker.header.frame_id = frame;
    marker.name = "hand";
    marker.description = "drag to move the finger";
    marker.scale = 0.05;
    marker.pose.position.x = start.x();
    marker.pose.position.y = start.y();
    marker.pose.position.z = start.z();
    marker.pose.orientation.w = 1.0;
    visualization_msgs::InteractiveMarkerControl free;
    free.interaction_mode = visualization_msgs::InteractiveMarkerControl::MOVE_3D;
    free.always_visible = true;
    visualization_msgs::Marker ball;
    ball.type = visualization_msgs::Marker::SPHERE;
    ball.scale.x = ball.scale.y = ball.scale.z = 0.012;
    ball.color.r = 0.2f;
    ball.color.g = 0.9f;
    ball.color.b = 0.2f;
    ball.color.a = 0.6f;
    free.markers.push_back(ball);
    marker.controls.push_back(free);
    const double axes[3][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};  // quaternions x, y, z of each arrow pair
    const char* names[3] = {"move_x", "move_z", "move_y"};
    for (int i = 0; i < 3; ++i)
    {
      visualization_msgs::InteractiveMarkerControl axis;
      axis.name = names[i];
      axis.orientation.w = axes[i][3] / std::sqrt(2.0);
      axis.orientation.x = axes[i][0] / std::sqrt(2.0);
      axis.orientation.y = axes[i][1] / std::sqrt(2.0);
      axis.orientation.z = axes[i][2] / std::sqrt(2.0);
      axis.interaction_mode = visualization_msgs::InteractiveMarkerControl::MOVE_AXIS;
      marker.controls.push_back(axis);
    }
    marker_server->insert(marker,
                          [hand](const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback)
                          {
                            if (feedback->event_type == visualization_msgs::InteractiveMarkerFeedback::POSE_UPDATE)
                            {
                              hand->setHandTarget(Eigen::Vector3d(feedback->pose.position.x, feedback->pose.position.y,
                                                                  feedback->pose.position.z));
                            }
                          });
    marker_server->applyChanges();
  }

  void onForce(const geometry_msgs::Vector3Stamped::ConstPtr& message)
  {
    const Eigen::Vector3d force(message->vector.x, message->vector.y, message->vector.z);
    // The command is stamped with the device state it answers: the loop's round trip.
    const double round_trip = (ros::Time::now() - message->header.stamp).toSec();
    std::lock_guard<std::mutex> lock(mutex);
    if (!message->header.stamp.isZero() && round_trip >= 0.0 && round_trip < 10.0)
    {
      round_trips_us.push_back(1e6 * round_trip);
    }
    if (!guard->command(now(), force))
    {
      ROS_WARN_THROTTLE(1.0, "device_driver: rejected a non-finite force command (%ld so far)", guard->rejected());
    }
  }

  void publishDiagnostics(double rate)
  {
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = ros::Time::now();
    diagnostic_msgs::DiagnosticStatus status;
    status.name = ros::this_node::getName() + ": " + device->name() + " device";
    status.hardware_id = device->name();
    status.level =
        rate < 0.95 / period ? diagnostic_msgs::DiagnosticStatus::WARN : diagnostic_msgs::DiagnosticStatus::OK;
    bool timed_out = false;
    long rejected = 0;
    long saturated = 0;
    std::vector<double> trips;
    {
      std::lock_guard<std::mutex> lock(mutex);
      timed_out = guard->timedOut(now());
      rejected = guard->rejected();
      saturated = guard->saturated();
      trips.swap(round_trips_us);
    }
    status.message = timed_out ? "no force commands: output ramped to zero" : "running";
    auto add = [&status](const std::string& key, const std::string& value)
    {
      diagnostic_msgs::KeyValue pair;
      pair.key = key;
      pair.value = value;
      status.values.push_back(pair);
    };
    add("rate_hz", std::to_string(rate));
    add("overruns", std::to_string(overruns));
    add("rejected_commands", std::to_string(rejected));
    add("saturated_commands", std::to_string(saturated));
    add("watchdog_timed_out", timed_out ? "true" : "false");
    add("commands", std::to_string(trips.size()));
    add("round_trip_us_p50", jsonNumber(percentile(trips, 0.5)));
    add("round_trip_us_p99", jsonNumber(percentile(trips, 0.99)));
    array.status.push_back(status);
    diagnostics_publisher.publish(array);
  }

  void loop()
  {
    requestRealTimePriority(realtime_priority, ros::this_node::getName() + " (device loop)");
    using Clock = std::chrono::steady_clock;
    const auto step = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period));
    auto next = Clock::now();
    auto diagnostics_start = next;
    long ticks = 0;
    while (running && ros::ok())
    {
      next += step;
      const double t = now();
      Eigen::Vector3d force;
      {
        std::lock_guard<std::mutex> lock(mutex);
        force = guard->output(t);
      }
      DeviceReading reading;
      try
      {
        reading = device->update(t, force);
      }
      catch (const DeviceError& error)
      {
        ROS_FATAL("device_driver: %s", error.what());
        ros::shutdown();
        return;
      }
      god_finger::DeviceStatePtr state(new god_finger::DeviceState);
      state->header.stamp = ros::Time::now();
      state->header.seq = static_cast<std::uint32_t>(++published);  // gap-free: a recording can be checked
      state->header.frame_id = frame;
      state->position.x = reading.position.x();
      state->position.y = reading.position.y();
      state->position.z = reading.position.z();
      state->velocity.x = reading.velocity.x();
      state->velocity.y = reading.velocity.y();
      state->velocity.z = reading.velocity.z();
      state->buttons = reading.buttons;
      state->applied_force.x = force.x();
      state->applied_force.y = force.y();
      state->applied_force.z = force.z();
      state_publisher.publish(state);
      ++ticks;
      const auto after = Clock::now();
      if (after - diagnostics_start >= std::chrono::seconds(1))
      {
        publishDiagnostics(ticks / std::chrono::duration<double>(after - diagnostics_start).count());
        diagnostics_start = after;
        ticks = 0;
      }
      if (after > next)
      {
        ++overruns;
        if (after - next > 10 * step)
        {
          next = after;
        }
      }
      else
      {
        std::this_thread::sleep_until(next);
      }
    }
  }
};

DeviceDriverNode::DeviceDriverNode(ros::NodeHandle nh, ros::NodeHandle pnh) : impl_(new Impl)
{
  Impl& impl = *impl_;
  impl.period = 1.0 / readDouble(pnh, "rate", 1000.0, 10.0, 10000.0, "Hz");
  // SCHED_FIFO priority of the servo loop (0: normal scheduling). It sleeps every tick, so it
  // never holds a core.
  impl.realtime_priority = readInt(pnh, "realtime_priority", 80, 0, 99);
  ForceGuardParams guard;
  guard.max_force = readDouble(pnh, "max_force", guard.max_force, 0.0, 1e3, "N", true);
  guard.command_timeout = readDouble(pnh, "command_timeout", guard.command_timeout, 0.0, 10.0, "s", true);
  guard.ramp_time = readDouble(pnh, "ramp_time", guard.ramp_time, 0.0, 1.0, "s", true);
  impl.guard = std::make_unique<ForceGuard>(guard);
  const std::string backend = readString(pnh, "backend", "fake");
  impl.frame = readString(pnh, "frame", "device");
  impl.device = makeDevice(backend, nh, pnh, impl.now(), guard.max_force);
  impl.device->start();
  if (backend == "interactive")
  {
    impl.addMarker(nh, readVector(pnh, "start", Eigen::Vector3d(0.0, 0.0, 0.12)));
  }
  impl.state_publisher = nh.advertise<god_finger::DeviceState>("device/state", kPublisherQueue);
  impl.diagnostics_publisher = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
  impl.force_subscriber =
      nh.subscribe("device/force", kSubscriberQueue, &Impl::onForce, &impl, ros::TransportHints().tcpNoDelay());
  ROS_INFO("device_driver: backend '%s' at %.0f Hz, max force %.1f N", backend.c_str(), 1.0 / impl.period,
           guard.max_force);
  impl.thread = std::thread([this]() { impl_->loop(); });
}

DeviceDriverNode::~DeviceDriverNode()
{
  impl_->running = false;
  if (impl_->thread.joinable())
  {
    impl_->thread.join();
  }
}
}  // namespace god_finger
