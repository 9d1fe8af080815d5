#include "driver_link_ros.h"

#include "diagnostics.h"
#include "driver_messages.h"
#include "god_finger/runtime/servo_clock.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"
#include "zero_on_stop.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/Joy.h>

#include <atomic>
#include <mutex>
#include <thread>

namespace god_finger
{
const std::vector<DriverWire>& driverWires()
{
  static const std::vector<DriverWire> wires = {
      {"omni_msgs", "the Geomagic Touch / Phantom Omni driver omni_common (fsuarez6/phantom_omni)", "state",
       "omni_msgs/OmniState", "button (omni_msgs/OmniButtonEvent): grey = button 0, white = button 1", "force_feedback",
       "omni_msgs/OmniFeedback"},
      {"ros_geomagic", "WPI's ros_geomagic, geomagic_control (WPI-AIM/ros_geomagic)", "pose",
       "geometry_msgs/PoseStamped", "button (geomagic_control/DeviceButtonEvent): grey = button 0, white = button 1",
       "force_feedback", "geomagic_control/DeviceFeedback"},
      {"crtk", "CRTK drivers: sawSensablePhantom, sawForceDimensionSDK, the dVRK and AMBF bridges", "measured_cp",
       "geometry_msgs/PoseStamped",
       "front or button1 = button 0, back or button2 = button 1 (sensor_msgs/Joy, buttons[0] = 1 pressed); "
       "operating_state (crtk_msgs/OperatingState) shown on /diagnostics",
       "servo_cf", "geometry_msgs/WrenchStamped"},
      {"ros_falcon", "WPI's ros_falcon (WPI-AIM/ros_falcon)", "falconPos", "ros_falcon/falconPos", "none",
       "/falconForce", "ros_falcon/falconForces"},
  };
  return wires;
}

const DriverWire& driverWire(const std::string& backend)
{
  for (const DriverWire& wire : driverWires())
  {
    if (backend == wire.backend)
    {
      return wire;
    }
  }
  throw InputError("backend '" + backend + "' is not a ROS driver bridge");
}

namespace
{
// `name` in `ns` unless absolute.
std::string driverTopic(const std::string& ns, const std::string& name)
{
  if (!name.empty() && name[0] == '/')
  {
    return name;
  }
  std::string topic = ns.empty() || ns.back() != '/' ? ns + "/" + name : ns + name;
  return topic[0] == '/' ? topic : "/" + topic;
}

template <class M>
ros::Subscriber subscribeTo(ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue,
                            boost::function<void(const boost::shared_ptr<const M>&)> callback,
                            const ros::TransportHints& hints = ros::TransportHints())
{
  return nh.subscribe<M>(topic, queue, callback, ros::VoidConstPtr(), hints);
}

geometry_msgs::Vector3 vector3(const Eigen::Vector3d& v)
{
  geometry_msgs::Vector3 out;
  out.x = v.x();
  out.y = v.y();
  out.z = v.z();
  return out;
}

class DriverConnection
{
 public:
  DriverConnection(ros::NodeHandle nh, const std::string& node_name, const DriverBridgeParams& params,
                   std::shared_ptr<DriverLink> link)
      : nh_(nh), params_(params), wire_(driverWire(params.backend)), link_(link.get())
  {
    state_topic_ = driverTopic(params.driver_ns, wire_.state_topic);
    force_topic_ = driverTopic(params.driver_ns, wire_.force_topic);
    status_name_ = node_name + ": " + params.backend + " driver " + state_topic_;
    // The driver's states on a queue and thread of their own: never behind the node's other
    // callbacks (markers, services), one hop from roscpp's poll thread to the link.
    states_nh_ = nh_;
    states_nh_.setCallbackQueue(&states_queue_);
    subscribe();
    states_spinner_.start();
    diagnostics_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
    timer_ = nh_.createWallTimer(ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) { report(); });
    zero_hook_ = registerZeroOnStop([this]() { stop(); });
    sender_ = std::thread([this]() { send(); });
    ROS_INFO("%s: state from %s (%s), force to %s (%s)", params_.backend.c_str(), state_topic_.c_str(),
             wire_.state_type, force_topic_.c_str(), wire_.force_type);
  }

  ~DriverConnection()
  {
    for (ros::Subscriber& subscriber : subscribers_)
    {
      subscriber.shutdown();  // waits for a callback under way: none runs on what goes below
    }
    states_spinner_.stop();
    unregisterZeroOnStop(zero_hook_);
    running_ = false;
    sender_.join();
    timer_.stop();
    stop();
    waitForPublishes(0.15);  // the zero written before the publisher goes
  }

 private:
  void subscribe()
  {
    const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
    const std::string& backend = params_.backend;
    if (backend == "omni_msgs")
    {
      subscribers_.push_back(subscribeTo<driver_msgs::OmniState>(
          states_nh_, state_topic_, 1, [this](const driver_msgs::OmniStateConstPtr& m) { onState(m->pose.position); },
          hints));
      subscribers_.push_back(
          subscribeTo<driver_msgs::OmniButtonEvent>(states_nh_, driverTopic(params_.driver_ns, "button"), 100,
                                                    [this](const driver_msgs::OmniButtonEventConstPtr& m)
                                                    {
                                                      link_->setButton(0, m->grey_button != 0);
                                                      link_->setButton(1, m->white_button != 0);
                                                    }));
      publisher_ = nh_.advertise<driver_msgs::OmniFeedback>(force_topic_, 1);
      publish_ = [this](const Eigen::Vector3d& force)
      {
        driver_msgs::OmniFeedback message;
        message.force = vector3(force);
        message.position = vector3(lastPosition());  // read by the driver, used by none
        publisher_.publish(message);
      };
    }
    else if (backend == "ros_geomagic")
    {
      subscribers_.push_back(subscribeTo<geometry_msgs::PoseStamped>(
          states_nh_, state_topic_, 1,
          [this](const geometry_msgs::PoseStampedConstPtr& m) { onState(m->pose.position); }, hints));
      subscribers_.push_back(
          subscribeTo<driver_msgs::DeviceButtonEvent>(states_nh_, driverTopic(params_.driver_ns, "button"), 100,
                                                      [this](const driver_msgs::DeviceButtonEventConstPtr& m)
                                                      {
                                                        link_->setButton(0, m->grey_button != 0);
                                                        link_->setButton(1, m->white_button != 0);
                                                      }));
      publisher_ = nh_.advertise<driver_msgs::DeviceFeedback>(force_topic_, 1);
      publish_ = [this](const Eigen::Vector3d& force)
      {
        driver_msgs::DeviceFeedback message;
        message.force = vector3(force);
        message.position = vector3(lastPosition());
        message.lock.assign(3, 0);  // the driver reads lock[0..2] unchecked; false: no axis locked
        publisher_.publish(message);
      };
    }
    else if (backend == "crtk")
    {
      subscribers_.push_back(subscribeTo<geometry_msgs::PoseStamped>(
          states_nh_, state_topic_, 1,
          [this](const geometry_msgs::PoseStampedConstPtr& m) { onState(m->pose.position); }, hints));
      const std::pair<const char*, int> buttons[] = {{"front", 0}, {"button1", 0}, {"back", 1}, {"button2", 1}};
      for (const auto& [topic, bit] : buttons)
      {
        const int index = bit;
        subscribers_.push_back(
            subscribeTo<sensor_msgs::Joy>(states_nh_, driverTopic(params_.driver_ns, topic), 10,
                                          [this, index](const sensor_msgs::JoyConstPtr& m)
                                          { link_->setButton(index, !m->buttons.empty() && m->buttons[0] == 1); }));
      }
      subscribers_.push_back(
          subscribeTo<driver_msgs::OperatingState>(states_nh_, driverTopic(params_.driver_ns, "operating_state"), 10,
                                                   [this](const driver_msgs::OperatingStateConstPtr& m)
                                                   {
                                                     std::lock_guard<std::mutex> lock(mutex_);
                                                     operating_state_ = m->state;
                                                   }));
      publisher_ = nh_.advertise<geometry_msgs::WrenchStamped>(force_topic_, 1);
      publish_ = [this](const Eigen::Vector3d& force)
      {
        geometry_msgs::WrenchStamped message;
        message.header.stamp = ros::Time::now();
        message.wrench.force = vector3(force);  // torque zero: the driver renders force only
        publisher_.publish(message);
      };
    }
    else
    {
      subscribers_.push_back(subscribeTo<driver_msgs::FalconPos>(
          states_nh_, state_topic_, 1,
          [this](const driver_msgs::FalconPosConstPtr& m)
          {
            geometry_msgs::Point position;
            position.x = m->X;
            position.y = m->Y;
            position.z = m->Z;
            onState(position);
          },
          hints));
      publisher_ = nh_.advertise<driver_msgs::FalconForces>(force_topic_, 1);
      publish_ = [this](const Eigen::Vector3d& force)
      {
        driver_msgs::FalconForces message;
        message.X = force.x();
        message.Y = force.y();
        message.Z = force.z();
        publisher_.publish(message);
      };
    }
  }

  void onState(const geometry_msgs::Point& p)
  {
    const Eigen::Vector3d position(p.x, p.y, p.z);
    const double now = steadySeconds();
    link_->writeState(position, now);
    last_arrival_ = now;
    std::lock_guard<std::mutex> lock(mutex_);
    last_position_ = position;
  }

  Eigen::Vector3d lastPosition()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_position_;
  }

  // The sender thread: each force the device leaves, while running and not stopped.
  void send()
  {
    Eigen::Vector3d force;
    while (running_ && ros::ok())
    {
      if (link_->takeForce(0.05, &force))
      {
        std::lock_guard<std::mutex> lock(publish_mutex_);
        if (!stopped_)
        {
          publish_(force);
        }
      }
    }
  }

  // The last force: zero, and nothing else from now on.
  void stop()
  {
    std::lock_guard<std::mutex> lock(publish_mutex_);
    stopped_ = true;
    publish_(Eigen::Vector3d::Zero());
  }

  void report()
  {
    const double now = steadySeconds();
    const long states = link_->states();
    const double rate = report_time_ > 0.0 ? (states - report_states_) / (now - report_time_) : 0.0;
    report_time_ = now;
    report_states_ = states;
    const double arrival = last_arrival_.load();
    const double age = arrival > 0.0 ? now - arrival : INFINITY;
    const bool stale = age > params_.stale_timeout;
    const std::uint32_t takers = publisher_.getNumSubscribers();
    diagnostic_msgs::DiagnosticStatus status;
    status.name = status_name_;
    status.hardware_id = params_.backend;
    std::string operating_state;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      operating_state = operating_state_;
    }
    if (stale)
    {
      status.level = diagnostic_msgs::DiagnosticStatus::ERROR;
      status.message = arrival > 0.0
                           ? "driver stale: no state on " + state_topic_ + " for " + jsonNumber(age) +
                                 " s (the finger lets go, the force is zero)"
                           : "waiting for the driver: no state on " + state_topic_ + " (" + wire_.state_type +
                                 ") yet; is it running in namespace " + params_.driver_ns + "? (rostopic list)";
      ROS_WARN_THROTTLE(5.0, "%s: %s", params_.backend.c_str(), status.message.c_str());
    }
    else if (takers == 0)
    {
      status.level = diagnostic_msgs::DiagnosticStatus::WARN;
      status.message = "nothing subscribes to " + force_topic_ + " (" + wire_.force_type + "): no force is felt";
    }
    else if (params_.backend == "crtk" && !operating_state.empty() && operating_state != "ENABLED")
    {
      status.level = diagnostic_msgs::DiagnosticStatus::WARN;
      status.message = "the arm is " + operating_state + ": it takes servo_cf only when ENABLED";
    }
    else
    {
      status.level = diagnostic_msgs::DiagnosticStatus::OK;
      status.message = "running";
    }
    addValue(&status, "state_topic", state_topic_);
    addValue(&status, "force_topic", force_topic_);
    addValue(&status, "driver_rate_hz", jsonNumber(rate));
    addValue(&status, "state_age_ms", jsonNumber(std::isfinite(age) ? 1e3 * age : -1.0));
    addValue(&status, "states", std::to_string(states));
    addValue(&status, "rejected_states", std::to_string(link_->rejectedStates()));
    addValue(&status, "force_subscribers", std::to_string(takers));
    if (params_.backend == "crtk")
    {
      addValue(&status, "operating_state", operating_state.empty() ? "unknown" : operating_state);
    }
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = ros::Time::now();
    array.status.push_back(status);
    diagnostics_.publish(array);
  }

  ros::NodeHandle nh_;
  ros::CallbackQueue states_queue_;
  ros::NodeHandle states_nh_;                            // nh_ on states_queue_
  ros::AsyncSpinner states_spinner_{1, &states_queue_};  // declared after the queue it spins
  DriverBridgeParams params_;
  const DriverWire& wire_;
  DriverLink* link_;  // owns this connection (DriverLink::connection): outlives it
  std::string state_topic_;
  std::string force_topic_;
  std::string status_name_;
  std::vector<ros::Subscriber> subscribers_;
  ros::Publisher publisher_;
  std::function<void(const Eigen::Vector3d&)> publish_;
  ros::Publisher diagnostics_;
  ros::WallTimer timer_;
  std::thread sender_;
  std::atomic<bool> running_{true};
  std::mutex publish_mutex_;  // one publish at a time; stopped_
  bool stopped_ = false;
  std::mutex mutex_;  // last_position_, operating_state_ (callbacks, sender, timer)
  Eigen::Vector3d last_position_ = Eigen::Vector3d::Zero();
  std::string operating_state_;
  std::atomic<double> last_arrival_{-1.0};
  double report_time_ = -1.0;
  long report_states_ = 0;
  int zero_hook_ = -1;
};
}  // namespace

std::shared_ptr<void> connectDriverLink(ros::NodeHandle nh, const std::string& node_name,
                                        const DriverBridgeParams& params, std::shared_ptr<DriverLink> link)
{
  return std::make_shared<DriverConnection>(nh, node_name, params, std::move(link));
}
}  // namespace god_finger
