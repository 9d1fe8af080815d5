// rostest: safety of the loop with every node in its own process (safety.test).
//  - NaN poses, forces and device states are rejected and counted by the node that receives
//    them, and nothing downstream sees them;
//  - the physics node killed (feedback forwarded): the driver ramps its force to zero
//    (command_timeout 20 ms after the last command, then within ramp_time 10 ms), and the loop
//    resumes when the physics respawns.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <god_finger/DeviceState.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>

namespace
{
const ros::Time kInjectedPose(1, 1);
const ros::Time kInjectedState(2, 2);

std::mutex g_mutex;
std::map<std::string, std::string> g_diagnostics;  // "status name/key" -> value
std::atomic<long> g_feedback{0};
std::atomic<long> g_non_finite_downstream{0};
ros::WallTime g_last_feedback;
double g_applied_force = 0.0;
ros::WallTime g_first_zero_force;
ros::WallTime g_last_feedback_before_zero;  // g_last_feedback when the force first read zero
// The header stamp of the last feedback (the stamp of the device state it answers, on the
// driver's clock), and the largest round trip seen (arrival at the test - that stamp, s).
double g_last_feedback_stamp = 0.0;
double g_max_round_trip = 0.0;
bool g_watch_zero = false;
std::vector<std::pair<double, double>> g_force_after_kill;  // (driver stamp s, |applied force| N)
// The stamps of the force commands the driver is sent (finger/device/force, from the haptic node,
// which forwards the physics' feedback with the stamp of the device state it answers): the last
// one before the driver's first zero is when its hold began. The haptic node outlives the
// physics, so none of its commands is lost with the dying process.
std::vector<double> g_command_stamps;

bool finite(const geometry_msgs::Vector3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool finite(const geometry_msgs::Point& p)
{
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

void onDiagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& array)
{
  std::lock_guard<std::mutex> lock(g_mutex);
  for (const auto& status : array->status)
  {
    for (const auto& pair : status.values)
    {
      g_diagnostics[status.name + "/" + pair.key] = pair.value;
    }
  }
}

long diagnostic(const std::string& name, const std::string& key)
{
  std::lock_guard<std::mutex> lock(g_mutex);
  const auto found = g_diagnostics.find(name + "/" + key);
  return found == g_diagnostics.end() ? -1 : std::stol(found->second);
}

// How many nodes the master lists as subscribers of `topic` (this one included), -1 when the
// master does not answer.
int subscribersOnMaster(const std::string& topic)
{
  XmlRpc::XmlRpcValue request;
  XmlRpc::XmlRpcValue response;
  XmlRpc::XmlRpcValue payload;
  request[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", request, response, payload, false))
  {
    return -1;
  }
  XmlRpc::XmlRpcValue& subscriptions = payload[1];
  for (int i = 0; i < subscriptions.size(); ++i)
  {
    if (static_cast<std::string>(subscriptions[i][0]) == topic)
    {
      return subscriptions[i][1].size();
    }
  }
  return 0;
}

// Every subscriber the master knows of `publisher`'s topic is connected to it (a message
// published now reaches them all).
bool connectedToEverySubscriber(const ros::Publisher& publisher)
{
  const int expected = subscribersOnMaster(publisher.getTopic());
  return expected > 0 && publisher.getNumSubscribers() >= static_cast<std::uint32_t>(expected);
}

class Safety : public testing::Test
{
 protected:
  void SetUp() override
  {
    const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
    subscribers_.push_back(nh_.subscribe<geometry_msgs::WrenchStamped>(
        "finger/feedback", 100,
        [](const geometry_msgs::WrenchStamped::ConstPtr& m)
        {
          g_non_finite_downstream += finite(m->wrench.force) ? 0 : 1;
          std::lock_guard<std::mutex> lock(g_mutex);
          g_last_feedback = ros::WallTime::now();
          if (!m->header.stamp.isZero())
          {
            g_last_feedback_stamp = m->header.stamp.toSec();
            g_max_round_trip = std::max(g_max_round_trip, ros::Time::now().toSec() - g_last_feedback_stamp);
          }
          ++g_feedback;
        },
        ros::VoidConstPtr(), hints));
    subscribers_.push_back(nh_.subscribe<geometry_msgs::Vector3Stamped>(
        "finger/device/force", 10000,
        [](const geometry_msgs::Vector3Stamped::ConstPtr& m)
        {
          if (m->header.stamp.isZero() || !finite(m->vector))
          {
            return;  // the first test's injected commands
          }
          std::lock_guard<std::mutex> lock(g_mutex);
          g_command_stamps.push_back(m->header.stamp.toSec());
        },
        ros::VoidConstPtr(), hints));
    subscribers_.push_back(nh_.subscribe<geometry_msgs::PointStamped>(
        "finger/proxy", 100,
        [](const geometry_msgs::PointStamped::ConstPtr& m) { g_non_finite_downstream += finite(m->point) ? 0 : 1; },
        ros::VoidConstPtr(), hints));
    subscribers_.push_back(nh_.subscribe<geometry_msgs::PoseStamped>(
        "finger/pose", 100,
        [](const geometry_msgs::PoseStamped::ConstPtr& m)
        {
          if (m->header.stamp != kInjectedPose)
          {
            g_non_finite_downstream += finite(m->pose.position) ? 0 : 1;
          }
        },
        ros::VoidConstPtr(), hints));
    // 10 s of device states: a test thread stalled by a loaded machine must not lose the
    // states that show the hold and the ramp (a 100-message queue once dropped the hold).
    subscribers_.push_back(nh_.subscribe<god_finger::DeviceState>(
        "finger/device/state", 10000,
        [](const god_finger::DeviceState::ConstPtr& m)
        {
          if (m->header.stamp == kInjectedState)
          {
            return;
          }
          g_non_finite_downstream += finite(m->applied_force) && finite(m->position) ? 0 : 1;
          const double force =
              std::sqrt(m->applied_force.x * m->applied_force.x + m->applied_force.y * m->applied_force.y +
                        m->applied_force.z * m->applied_force.z);
          std::lock_guard<std::mutex> lock(g_mutex);
          g_applied_force = force;
          if (g_watch_zero)
          {
            g_force_after_kill.emplace_back(m->header.stamp.toSec(), force);
            if (force == 0.0 && g_first_zero_force.isZero())
            {
              g_first_zero_force = ros::WallTime::now();
              // The respawned physics may send feedback again before the test reads this.
              g_last_feedback_before_zero = g_last_feedback;
            }
          }
        },
        ros::VoidConstPtr(), hints));
    subscribers_.push_back(nh_.subscribe("/diagnostics", 100, onDiagnostics));
    spinner_.start();
    waitFor([] { return g_feedback > 0; }, 30.0, "feedback");
    waitFor(
        []
        {
          std::lock_guard<std::mutex> lock(g_mutex);
          return g_applied_force > 0.5;
        },
        10.0, "the finger pressing on the ball");
  }

  void waitFor(const std::function<bool()>& condition, double seconds, const std::string& what)
  {
    const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(seconds);
    while (!condition())
    {
      ASSERT_LT(ros::WallTime::now(), give_up) << "waited " << seconds << " s for " << what;
      ros::WallDuration(0.005).sleep();
    }
  }

  ros::NodeHandle nh_;
  std::vector<ros::Subscriber> subscribers_;
  ros::AsyncSpinner spinner_{2};
};

TEST_F(Safety, NonFiniteInputIsRejectedCountedAndNeverPassedOn)
{
  ros::Publisher poses = nh_.advertise<geometry_msgs::PoseStamped>("finger/pose", 10);
  ros::Publisher forces = nh_.advertise<geometry_msgs::Vector3Stamped>("finger/device/force", 10);
  ros::Publisher states = nh_.advertise<god_finger::DeviceState>("finger/device/state", 10);
  // Every node that takes these topics (SetUp saw the loop running, so all have subscribed)
  // is connected, so that none of the injected messages is published before it can arrive.
  for (const ros::Publisher* publisher : {&poses, &forces, &states})
  {
    waitFor([publisher] { return connectedToEverySubscriber(*publisher); }, 10.0,
            "every subscriber of " + publisher->getTopic() + " to connect");
  }
  // The counts so far (each node reports once a second): the injection must add exactly ten.
  long poses_before = -1;
  long forces_before = -1;
  long states_before = -1;
  waitFor(
      [&]
      {
        poses_before = diagnostic("/physics: physics loop", "rejected_poses");
        forces_before = diagnostic("/finger/device_driver: fake device", "rejected_commands");
        states_before = diagnostic("/finger/haptic: haptic", "rejected_states");
        return poses_before >= 0 && forces_before >= 0 && states_before >= 0;
      },
      10.0, "the three rejection counts on /diagnostics");
  const long downstream_before = g_non_finite_downstream;
  // One bad message of each kind a round, and the next round once /diagnostics counted all three
  // (each receiving queue also takes the loop's own 1 kHz stream, and a queue that is full drops
  // a message: counted exactly, a dropped one would fail the test for ROS's reason). A kind not
  // counted within 3 s (three diagnostics periods) was dropped and is sent again.
  const auto send = [&](int kind, int i)
  {
    if (kind == 0)
    {
      geometry_msgs::PoseStamped pose;
      pose.header.stamp = kInjectedPose;
      pose.header.frame_id = "world";
      pose.pose.position.x = NAN;
      pose.pose.orientation.w = 1.0;
      poses.publish(pose);
    }
    else if (kind == 1)
    {
      geometry_msgs::Vector3Stamped force;
      force.vector.z = (i % 2) ? INFINITY : NAN;
      forces.publish(force);
    }
    else
    {
      god_finger::DeviceState state;
      state.header.stamp = kInjectedState;
      state.position.y = NAN;
      states.publish(state);
    }
  };
  const auto counts = [&]
  {
    return std::array<long, 3>{diagnostic("/physics: physics loop", "rejected_poses") - poses_before,
                               diagnostic("/finger/device_driver: fake device", "rejected_commands") - forces_before,
                               diagnostic("/finger/haptic: haptic", "rejected_states") - states_before};
  };
  for (int i = 0; i < 10; ++i)
  {
    for (int kind = 0; kind < 3; ++kind)
    {
      send(kind, i);
    }
    for (int attempt = 0; attempt < 5; ++attempt)
    {
      const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(3.0);
      std::array<long, 3> seen = counts();
      while ((seen[0] <= i || seen[1] <= i || seen[2] <= i) && ros::WallTime::now() < give_up)
      {
        ros::WallDuration(0.005).sleep();  // polls /diagnostics within the deadline
        seen = counts();
      }
      if (seen[0] > i && seen[1] > i && seen[2] > i)
      {
        break;
      }
      for (int kind = 0; kind < 3; ++kind)
      {
        if (seen[kind] <= i)
        {
          send(kind, i);
        }
      }
    }
  }
  long rejected_poses = -1;
  long rejected_forces = -1;
  long rejected_states = -1;
  const auto read_counts = [&]
  {
    rejected_poses = diagnostic("/physics: physics loop", "rejected_poses") - poses_before;
    rejected_forces = diagnostic("/finger/device_driver: fake device", "rejected_commands") - forces_before;
    rejected_states = diagnostic("/finger/haptic: haptic", "rejected_states") - states_before;
    return rejected_poses >= 10 && rejected_forces >= 10 && rejected_states >= 10;
  };
  waitFor(read_counts, 10.0, "10 rejections of each kind on /diagnostics");
  read_counts();
  char line[300];
  std::snprintf(line, sizeof(line),
                "non-finite input: rejected poses %ld, forces %ld, device states %ld; seen downstream %ld",
                rejected_poses, rejected_forces, rejected_states, g_non_finite_downstream.load() - downstream_before);
  RecordProperty("measured", line);
  EXPECT_EQ(rejected_poses, 10);
  EXPECT_EQ(rejected_forces, 10);
  EXPECT_EQ(rejected_states, 10);
  EXPECT_EQ(g_non_finite_downstream.load(), 0);
  // The loop goes on (behaviour, not its rate: 100 more feedback messages within 5 s).
  const long feedback = g_feedback;
  waitFor([feedback] { return g_feedback > feedback + 100; }, 5.0, "the loop to go on");
}

TEST_F(Safety, DriverRampsToZeroWhenThePhysicsDiesAndResumesAfterItsRespawn)
{
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    g_watch_zero = true;
  }
  ASSERT_EQ(std::system("rosnode kill /physics > /dev/null"), 0);
  waitFor(
      []
      {
        std::lock_guard<std::mutex> lock(g_mutex);
        return !g_first_zero_force.isZero();
      },
      5.0, "the driver's force to reach zero");
  double to_zero = 0.0;
  double zero_stamp = 0.0;  // s, the driver's clock
  double ramp = 0.0;
  double round_trip = 0.0;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    to_zero = (g_first_zero_force - g_last_feedback_before_zero).toSec();
    // On the driver's own clock (state stamps): the ramp is the run of falling forces before the
    // first zero. Where the hold began cannot be read from the forces: at rest the physics
    // commands the same force tick after tick (the pad constraint reaches an exact
    // equilibrium), so the hold is counted from the last command: the stamp of the device
    // state the last feedback answered.
    const auto& states = g_force_after_kill;
    std::size_t zero = 0;
    while (zero < states.size() && states[zero].second != 0.0)
    {
      ++zero;
    }
    std::size_t i = zero;
    while (i > 0 && states[i - 1].second > states[i].second)
    {
      --i;  // back through the ramp
    }
    if (zero < states.size())
    {
      ramp = states[zero].first - states[i].first;
      zero_stamp = states[zero].first;
    }
    round_trip = g_max_round_trip;
    g_watch_zero = false;
  }
  EXPECT_GE(ramp, 0.008);
  EXPECT_LE(ramp, 0.015);
  const ros::WallTime killed = ros::WallTime::now();
  const long feedback = g_feedback;
  waitFor([feedback] { return g_feedback > feedback + 100; }, 20.0, "the physics to come back");
  // Every command sent before the zero has reached the test once one sent after it has (one
  // publisher, one ordered connection): the respawned physics' feedback, forwarded.
  waitFor(
      [zero_stamp]
      {
        std::lock_guard<std::mutex> lock(g_mutex);
        return !g_command_stamps.empty() && g_command_stamps.back() > zero_stamp;
      },
      20.0, "a command after the zero");
  double last_command = 0.0;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    for (const double stamp : g_command_stamps)
    {
      if (stamp < zero_stamp)
      {
        last_command = std::max(last_command, stamp);
      }
    }
  }
  // The driver holds the last command for command_timeout (20 ms), then ramps to zero within
  // ramp_time (10 ms): 30 ms from the last command to zero. ForceGuard's unit test checks the
  // exact times; here the zero is sampled by the driver's 1 kHz ticks (a loaded 2-core machine
  // delays ticks by a few ms, hence +-5 ms), and the last command reached the driver a round
  // trip after the state it answers was stamped: up to the largest round trip this test saw
  // (device -> physics -> test). Both ends are the driver's stamps: the test's own clock and
  // its feedback from the dying physics are not used.
  // The hold's lower bound says the driver held the last command it got; it is judged only when
  // every command arrived within the watchdog's 20 ms. On a machine loaded enough that round
  // trips exceed it, commands arrive older than command_timeout and the watchdog rightly lets
  // go of them before the kill (measured: 6 ms from the last command's state to the zero, with
  // a 46 ms round trip): the zero is then not the kill's, and only the upper bound holds.
  ASSERT_GT(last_command, 0.0) << "no command before the zero";
  const double hold_and_ramp = zero_stamp - last_command;
  constexpr double kCommandTimeout = 0.02;  // s: the fake profile's (config/devices/fake.yaml)
  if (round_trip <= kCommandTimeout)
  {
    EXPECT_GE(hold_and_ramp, 0.025);
  }
  else
  {
    std::printf(
        "[ measured ] round trips up to %.1f ms, over the watchdog's 20 ms: the hold's lower bound is "
        "not judged (%.1f ms from the last command's state to the zero)\n",
        1e3 * round_trip, 1e3 * hold_and_ramp);
  }
  EXPECT_LE(hold_and_ramp, 0.035 + round_trip);
  waitFor(
      []
      {
        std::lock_guard<std::mutex> lock(g_mutex);
        return g_applied_force > 0.5;
      },
      10.0, "the force to come back");
  char line[320];
  std::snprintf(line, sizeof(line),
                "physics killed: driver at zero %.1f ms after the last command's state (largest round trip %.1f ms), "
                "ramped in %.1f ms (%.1f ms after the test's last feedback); loop back after %.1f s",
                1e3 * hold_and_ramp, 1e3 * round_trip, 1e3 * ramp, 1e3 * to_zero,
                (ros::WallTime::now() - killed).toSec());
  RecordProperty("measured", line);
}
}  // namespace

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "safety_test");
  return RUN_ALL_TESTS();
}
