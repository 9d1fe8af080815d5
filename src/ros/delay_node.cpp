#include "god_finger/ros/delay_node.h"

#include "god_finger/runtime/delay_line.h"
#include "parameters.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <topic_tools/shape_shifter.h>

#include <mutex>
#include <queue>
#include <string>
#include <vector>

namespace god_finger
{
struct DelayNode::Impl
{
  struct InFlight
  {
    double leaves = 0.0;  // s, ROS clock
    double entered = 0.0;
    long order = 0;
    topic_tools::ShapeShifter::ConstPtr message;
    bool operator>(const InFlight& other) const
    {
      return leaves != other.leaves ? leaves > other.leaves : order > other.order;
    }
  };

  Impl(ros::NodeHandle nh, ros::NodeHandle pnh) : nh_(nh), schedule_(readParams(pnh))
  {
    in_ = nh_.resolveName("in");
    out_name_ = nh_.resolveName("out");
    subscriber_ =
        nh_.subscribe<topic_tools::ShapeShifter>("in", 1000, &Impl::enter, this, ros::TransportHints().tcpNoDelay());
    release_timer_ = nh_.createTimer(ros::Duration(0.001), &Impl::release, this);
    diagnostics_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
    diagnostics_timer_ = nh_.createTimer(ros::Duration(1.0), &Impl::report, this);
  }

  static DelayLineParams readParams(const ros::NodeHandle& pnh)
  {
    DelayLineParams params;
    readRows(RosParameterSource(pnh), delayLineParameterTable(), &params);
    return params;
  }

  void enter(const topic_tools::ShapeShifter::ConstPtr& message)
  {
    const double now = ros::Time::now().toSec();
    std::lock_guard<std::mutex> lock(mutex_);
    if (!advertised_)
    {
      publisher_ = message->advertise(nh_, "out", 1000);
      advertised_ = true;
    }
    const double leaves = schedule_.release(now);
    if (leaves >= 0.0)
    {
      queue_.push({leaves, now, order_++, message});
    }
  }

  void release(const ros::TimerEvent&)
  {
    const double now = ros::Time::now().toSec();
    std::vector<topic_tools::ShapeShifter::ConstPtr> due;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      while (!queue_.empty() && queue_.top().leaves <= now)
      {
        due.push_back(queue_.top().message);
        delay_sum_ += now - queue_.top().entered;
        ++released_;
        queue_.pop();
      }
    }
    for (const topic_tools::ShapeShifter::ConstPtr& message : due)
    {
      publisher_.publish(message);
    }
  }

  void report(const ros::TimerEvent&)
  {
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = ros::Time::now();
    diagnostic_msgs::DiagnosticStatus status;
    status.name = "delay: " + in_ + " -> " + out_name_;
    status.level = diagnostic_msgs::DiagnosticStatus::OK;
    const auto value = [&status](const std::string& key, const std::string& text)
    {
      diagnostic_msgs::KeyValue pair;
      pair.key = key;
      pair.value = text;
      status.values.push_back(pair);
    };
    {
      std::lock_guard<std::mutex> lock(mutex_);
      value("entered", std::to_string(schedule_.entered()));
      value("lost", std::to_string(schedule_.lost()));
      value("in flight", std::to_string(queue_.size()));
      value("mean delay (s), last second", released_ > 0 ? std::to_string(delay_sum_ / released_) : "none released");
      status.message = std::to_string(released_) + " released in the last second";
      released_ = 0;
      delay_sum_ = 0.0;
    }
    array.status.push_back(status);
    diagnostics_.publish(array);
  }

  ros::NodeHandle nh_;
  std::string in_;
  std::string out_name_;
  std::mutex mutex_;  // the queue and the schedule: the subscriber's and the timers' threads
  DelaySchedule schedule_;
  std::priority_queue<InFlight, std::vector<InFlight>, std::greater<InFlight>> queue_;
  long order_ = 0;
  long released_ = 0;
  double delay_sum_ = 0.0;
  bool advertised_ = false;
  ros::Subscriber subscriber_;
  ros::Publisher publisher_;
  ros::Publisher diagnostics_;
  ros::Timer release_timer_;
  ros::Timer diagnostics_timer_;
};

DelayNode::DelayNode(ros::NodeHandle nh, ros::NodeHandle pnh) : impl_(new Impl(nh, pnh)) {}

DelayNode::~DelayNode() = default;
}  // namespace god_finger
