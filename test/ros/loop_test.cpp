// rostest: the whole haptic loop (fake device -> coupling -> physics -> force) runs, in any
// topology: the servo loop, or driver -> haptic -> physics -> haptic -> driver through topics.
// Counts device states and feedback for ~duration seconds, reads the measured device-to-force
// time (the servo's latency_us_*, or the driver's round_trip_us_*) from /diagnostics, prints
// them. Only a sanity floor on the rates (timing targets live in scripts/bench).
// Parameters: ~interface ("finger"), ~duration (5 s), ~min_rate (900 Hz: within 10 % of the
// 1 kHz loop), ~label (printed).
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/WrenchStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <god_finger/DeviceState.h>

#include <atomic>
#include <cstdio>
#include <mutex>

namespace
{
std::atomic<long> g_states{0};
std::atomic<long> g_feedback{0};
std::mutex g_mutex;
std::vector<double> g_p50;
std::vector<double> g_p99;

void onDiagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& array)
{
  for (const auto& status : array->status)
  {
    double p50 = -1.0;
    double p99 = -1.0;
    for (const auto& pair : status.values)
    {
      if ((pair.key == "round_trip_us_p50" || pair.key == "latency_us_p50") && pair.value != "null")
      {
        p50 = std::stod(pair.value);
      }
      if ((pair.key == "round_trip_us_p99" || pair.key == "latency_us_p99") && pair.value != "null")
      {
        p99 = std::stod(pair.value);
      }
    }
    if (p50 > 0.0)
    {
      std::lock_guard<std::mutex> lock(g_mutex);
      g_p50.push_back(p50);
      g_p99.push_back(p99);
    }
  }
}

TEST(HapticLoop, RunsAtOneKilohertz)
{
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  const std::string interface = pnh.param<std::string>("interface", "finger");
  const double duration = pnh.param("duration", 5.0);
  const double min_rate = pnh.param("min_rate", 900.0);
  const std::string label = pnh.param<std::string>("label", "loop");
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  ros::Subscriber states = nh.subscribe<god_finger::DeviceState>(
      interface + "/device/state", 2000, [](const god_finger::DeviceState::ConstPtr&) { ++g_states; },
      ros::VoidConstPtr(), hints);
  ros::Subscriber feedback = nh.subscribe<geometry_msgs::WrenchStamped>(
      interface + "/feedback", 2000, [](const geometry_msgs::WrenchStamped::ConstPtr&) { ++g_feedback; },
      ros::VoidConstPtr(), hints);
  ros::Subscriber diagnostics = nh.subscribe("/diagnostics", 100, onDiagnostics);
  ros::AsyncSpinner spinner(2);
  spinner.start();

  // Wait until the loop is closed (the physics answers), then let it settle for a second.
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(30.0);
  while (g_feedback == 0 && ros::WallTime::now() < give_up)
  {
    ros::WallDuration(0.01).sleep();
  }
  ASSERT_GT(g_feedback.load(), 0) << "no feedback on " << interface << "/feedback within 30 s";
  ros::WallDuration(1.0).sleep();
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    g_p50.clear();
    g_p99.clear();
  }
  const long states0 = g_states;
  const long feedback0 = g_feedback;
  const ros::WallTime start = ros::WallTime::now();
  ros::WallDuration(duration).sleep();
  const double elapsed = (ros::WallTime::now() - start).toSec();
  const double state_rate = (g_states - states0) / elapsed;
  const double feedback_rate = (g_feedback - feedback0) / elapsed;
  double p50 = -1.0;
  double p99 = -1.0;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    if (!g_p50.empty())
    {
      std::sort(g_p50.begin(), g_p50.end());
      std::sort(g_p99.begin(), g_p99.end());
      p50 = g_p50[g_p50.size() / 2];
      p99 = g_p99[g_p99.size() / 2];
    }
  }
  std::printf(
      "%s: device state %.1f Hz, feedback %.1f Hz, device to force p50 %.0f us, p99 %.0f us (medians of %zu 1-s "
      "windows)\n",
      label.c_str(), state_rate, feedback_rate, p50, p99, g_p50.size());
  std::fflush(stdout);
  // In the test's XML result, so that scripts/test can print them.
  RecordProperty("measured", label + ": device state " + std::to_string(state_rate) + " Hz, feedback " +
                                 std::to_string(feedback_rate) + " Hz, device to force p50 " + std::to_string(p50) +
                                 " us, p99 " + std::to_string(p99) + " us");
  EXPECT_GE(state_rate, min_rate);
  EXPECT_GE(feedback_rate, min_rate);
  EXPECT_GT(p50, 0.0) << "no device-to-force time on /diagnostics";
}
}  // namespace

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "loop_test");
  return RUN_ALL_TESTS();
}
