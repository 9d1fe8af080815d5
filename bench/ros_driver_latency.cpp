// End-to-end latency through a ROS driver bridge (devices/driver_bridge.h), measured from the
// driver's side: this program is the driver (its topics, message types, units and axes, at
// 1 kHz), god_finger runs apart (`roslaunch god_finger demo.launch device:=DRIVER`).
//
// usage: ros_driver_latency DRIVER SECONDS   (omni_msgs | ros_geomagic | crtk | ros_falcon)
//        ros_driver_latency --echo            (instead of god_finger: the floor, below)
//
// The floor: `--echo` answers each ros_falcon state at once in its subscriber callback (a
// spring, no loop, no physics) with roscpp's default threads, as god_finger's side does; run
// against `ros_driver_latency ros_falcon SECONDS` it measures what roscpp's round trip between
// two processes costs on this machine, with the same messages.
//
// The stylus comes down onto the demo ball's top (2 s), rests 1 mm deep (2 s), then steps 1 mm
// deeper or back every 50 ms (0.4 N to 0.8 N: under the Touch profile's continuous 0.88 N, which
// the force guard's budget would otherwise hold it to). A step's latency: from the publication of the first state at
// the new depth to the arrival of the first force that differs from the force before the step by more than 0.1 N (the
// 400 N/m spring's 1 mm is 0.4 N; the coupling's damper adds to it at the step). Prints one JSON line: the driver, the
// steps, their latency's p50, p99 and max (us), the state rate it published at, and the forces it got.
#include "driver_messages.h"
#include "god_finger/devices/vendor_frames.h"

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/ros.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace
{
using god_finger::findVendorFrame;
using god_finger::VendorFrame;

double seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Driver
{
  std::string name;
  std::string ns;
  const VendorFrame* frame;
  double unit;             // m per unit
  Eigen::Vector3d center;  // driver units
};

struct Forces
{
  std::mutex mutex;
  std::vector<std::pair<double, double>> arrivals;  // (s, force up, N)
};

double percentile(std::vector<double> values, double q)
{
  if (values.empty())
  {
    return NAN;
  }
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()))];
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ros_driver_latency", ros::init_options::AnonymousName);
  const std::string name = argc > 1 ? argv[1] : "";
  if (name == "--echo")
  {
    ros::NodeHandle nh;
    ros::Publisher answer = nh.advertise<god_finger::driver_msgs::FalconForces>("/falconForce", 1);
    ros::Subscriber states = nh.subscribe<god_finger::driver_msgs::FalconPos>(
        "/falconPos", 1,
        [&answer](const god_finger::driver_msgs::FalconPosConstPtr& m)
        {
          god_finger::driver_msgs::FalconForces force;  // 800 N/m below the demo ball's top, HD y up
          force.Y = std::max(0.0, 800.0 * (-0.017 - m->Y));
          answer.publish(force);
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
    ros::spin();
    return 0;
  }
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: ros_driver_latency DRIVER SECONDS | ros_driver_latency --echo\n");
    return 2;
  }
  const double run = std::stod(argv[2]);
  Driver driver{name, "", &findVendorFrame("hd", "frame"), 1.0, Eigen::Vector3d::Zero()};
  if (name == "omni_msgs")
  {
    driver = {name, "/phantom/phantom", &findVendorFrame("omni_common", "frame"), 0.001, Eigen::Vector3d::Zero()};
  }
  else if (name == "ros_geomagic")
  {
    driver = {name, "/Geomagic", &findVendorFrame("hd", "frame"), 0.001, Eigen::Vector3d::Zero()};
  }
  else if (name == "crtk")
  {
    driver = {name, "/arm", &findVendorFrame("hd", "frame"), 1.0, Eigen::Vector3d::Zero()};
  }
  else if (name == "ros_falcon")
  {
    driver = {name, "", &findVendorFrame("hd", "frame"), 1.0, Eigen::Vector3d(0.0, 0.0, 0.11)};
  }
  else
  {
    std::fprintf(stderr, "ros_driver_latency: unknown driver '%s'\n", name.c_str());
    return 2;
  }
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);
  Forces forces;
  const Eigen::Vector3d up_driver = driver.frame->toVendor(Eigen::Vector3d::UnitZ());
  auto record = [&forces, &up_driver](const Eigen::Vector3d& force)
  {
    const double now = seconds();
    std::lock_guard<std::mutex> lock(forces.mutex);
    forces.arrivals.emplace_back(now, force.dot(up_driver));
  };
  ros::Publisher state;
  ros::Subscriber force;
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  if (name == "omni_msgs")
  {
    state = nh.advertise<god_finger::driver_msgs::OmniState>(driver.ns + "/state", 1);
    force = nh.subscribe<god_finger::driver_msgs::OmniFeedback>(
        driver.ns + "/force_feedback", 100,
        [&record](const god_finger::driver_msgs::OmniFeedbackConstPtr& m)
        { record(Eigen::Vector3d(m->force.x, m->force.y, m->force.z)); },
        ros::VoidConstPtr(), hints);
  }
  else if (name == "ros_geomagic")
  {
    state = nh.advertise<geometry_msgs::PoseStamped>(driver.ns + "/pose", 1);
    force = nh.subscribe<god_finger::driver_msgs::DeviceFeedback>(
        driver.ns + "/force_feedback", 100,
        [&record](const god_finger::driver_msgs::DeviceFeedbackConstPtr& m)
        { record(Eigen::Vector3d(m->force.x, m->force.y, m->force.z)); },
        ros::VoidConstPtr(), hints);
  }
  else if (name == "crtk")
  {
    state = nh.advertise<geometry_msgs::PoseStamped>(driver.ns + "/measured_cp", 1);
    force = nh.subscribe<geometry_msgs::WrenchStamped>(
        driver.ns + "/servo_cf", 100,
        [&record](const geometry_msgs::WrenchStampedConstPtr& m)
        { record(Eigen::Vector3d(m->wrench.force.x, m->wrench.force.y, m->wrench.force.z)); },
        ros::VoidConstPtr(), hints);
  }
  else
  {
    state = nh.advertise<god_finger::driver_msgs::FalconPos>("/falconPos", 1);
    force = nh.subscribe<god_finger::driver_msgs::FalconForces>(
        "/falconForce", 100,
        [&record](const god_finger::driver_msgs::FalconForcesConstPtr& m)
        { record(Eigen::Vector3d(m->X, m->Y, m->Z)); },
        ros::VoidConstPtr(), hints);
  }
  spinner.start();
  // The surface the proxy (3 mm) meets on the demo ball (4 cm, its centre 4 cm up): world z
  // 0.083 m; the profiles' workspace centre 0.1 m up.
  const double top = 0.083 - 0.1;
  auto depth_at = [&](double t) -> double
  {
    if (t < 2.0)
    {
      return -0.03 + 0.031 * t / 2.0;  // from 3 cm above to 1 mm deep
    }
    if (t < 4.0)
    {
      return 0.001;
    }
    return 0.001 + (static_cast<long>((t - 4.0) / 0.05) % 2 == 1 ? 0.001 : 0.0);
  };
  auto publish = [&](double depth, std::uint32_t seq)
  {
    const Eigen::Vector3d p =
        driver.frame->toVendor(Eigen::Vector3d(0.0, 0.0, top - depth)) / driver.unit + driver.center;
    if (name == "omni_msgs")
    {
      god_finger::driver_msgs::OmniState m;
      m.header.seq = seq;
      m.header.stamp = ros::Time::now();
      m.pose.position.x = p.x();
      m.pose.position.y = p.y();
      m.pose.position.z = p.z();
      m.pose.orientation.w = 1.0;
      state.publish(m);
    }
    else if (name == "ros_falcon")
    {
      god_finger::driver_msgs::FalconPos m;
      m.X = p.x();
      m.Y = p.y();
      m.Z = p.z();
      state.publish(m);
    }
    else
    {
      geometry_msgs::PoseStamped m;
      m.header.stamp = ros::Time::now();
      m.pose.position.x = p.x();
      m.pose.position.y = p.y();
      m.pose.position.z = p.z();
      m.pose.orientation.w = 1.0;
      state.publish(m);
    }
  };
  // Wait for god_finger to take the force, then run.
  const double wait_until = seconds() + 60.0;
  while (ros::ok() && force.getNumPublishers() == 0 && seconds() < wait_until)
  {
    publish(-0.03, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));  // the driver's period
  }
  const double start = seconds();
  std::vector<double> steps;  // s: publication of each step's first state
  double last_depth = depth_at(0.0);
  std::uint32_t published = 0;
  for (long tick = 0; ros::ok(); ++tick)
  {
    const double t = start + tick * 1e-3;
    std::this_thread::sleep_until(std::chrono::steady_clock::time_point(
        std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(t))));
    if (t - start > 4.0 + run)
    {
      break;
    }
    const double depth = depth_at(t - start);
    const double now = seconds();
    publish(depth, ++published);
    if (t - start >= 4.0 && depth != last_depth)
    {
      steps.push_back(now);
    }
    last_depth = depth;
  }
  // Leave the driver as a real one is left: the bridge's zero comes when god_finger stops.
  std::vector<std::pair<double, double>> arrivals;
  {
    std::lock_guard<std::mutex> lock(forces.mutex);
    arrivals = forces.arrivals;
  }
  std::vector<double> latencies;
  std::size_t next = 0;
  for (double step : steps)
  {
    while (next < arrivals.size() && arrivals[next].first < step)
    {
      ++next;
    }
    if (next == 0 || next >= arrivals.size())
    {
      continue;
    }
    const double before = arrivals[next - 1].second;
    for (std::size_t k = next; k < arrivals.size() && arrivals[k].first < step + 0.04; ++k)
    {
      if (std::abs(arrivals[k].second - before) > 0.1)
      {
        latencies.push_back(1e6 * (arrivals[k].first - step));
        break;
      }
    }
  }
  if (std::getenv("ROS_DRIVER_LATENCY_TRACE"))
  {
    for (std::size_t k = 0; k < arrivals.size(); k += 50)
    {
      std::fprintf(stderr, "%.3f %.4f\n", arrivals[k].first - start, arrivals[k].second);
    }
  }
  const double span = run + 4.0;
  std::printf(
      "{\"driver\": \"%s\", \"steps\": %zu, \"answered\": %zu, \"latency_us_p50\": %.1f, \"latency_us_p99\": %.1f, "
      "\"latency_us_max\": %.1f, \"state_rate_hz\": %.1f, \"forces\": %zu}\n",
      name.c_str(), steps.size(), latencies.size(), percentile(latencies, 0.5), percentile(latencies, 0.99),
      latencies.empty() ? NAN : *std::max_element(latencies.begin(), latencies.end()), published / span,
      arrivals.size());
  return latencies.size() * 2 > steps.size() ? 0 : 1;
}
