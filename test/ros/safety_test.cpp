// rostest: safety of the loop with every node in its own process (safety.test).
//  - NaN poses, forces and device states are rejected and counted by the node that receives
//    them, and nothing downstream sees them;
//  - the physics node killed (feedback forwarded): the driver ramps its force to zero
//    (command_timeout 20 ms after the last command arrived, then linearly within ramp_time
//    10 ms), judged exactly on the driver's clock from its states' command_age, so that a
//    loaded machine cannot fail it; and the loop resumes when the physics respawns.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Vector3Stamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <god_finger/DeviceState.h>
#include <god_finger/InterfacePose.h>

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
ros::WallTime g_first_zero_force;  // when the test first read a zero force while watching
bool g_watch_zero = false;
double g_killed_at = 0.0;  // s, wall: states stamped before it are not the kill's
// s, the driver's stamps: its first state with a force (its soft start's beginning) and its latest.
double g_first_force_stamp = 0.0;
double g_latest_stamp = 0.0;
// A device state while watching: its stamp (s, wall), command_age (s, the driver's clock) and
// |applied force| (N).
struct DriverRecord
{
  double stamp = 0.0;
  double command_age = 0.0;
  double force = 0.0;
};
std::vector<DriverRecord> g_force_after_kill;

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
          ++g_feedback;
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
    subscribers_.push_back(nh_.subscribe<god_finger::InterfacePose>(
        "finger/interface_pose", 100,
        [](const god_finger::InterfacePose::ConstPtr& m)
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
          g_latest_stamp = m->header.stamp.toSec();
          if (force > 0.0 && g_first_force_stamp == 0.0)
          {
            g_first_force_stamp = g_latest_stamp;
          }
          if (g_watch_zero)
          {
            g_force_after_kill.push_back({m->header.stamp.toSec(), m->command_age, force});
            if (force == 0.0 && g_first_zero_force.isZero() && m->header.stamp.toSec() >= g_killed_at)
            {
              g_first_zero_force = ros::WallTime::now();
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
  // The physics' input across processes (the haptic node's NAME/pose is for tools).
  ros::Publisher poses = nh_.advertise<god_finger::InterfacePose>("finger/interface_pose", 10);
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
      god_finger::InterfacePose pose;
      pose.header.stamp = kInjectedPose;
      pose.header.frame_id = "world";
      pose.pose.position.x = NAN;
      pose.pose.orientation.w = 1.0;
      pose.has_orientation = (i % 2) != 0;  // a 3-DOF finger's and an oriented one's
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
  // The soft start over (0.5 s from the first force, config/devices/fake.yaml; 0.1 s more), so
  // that the hold holds one force: on the driver's clock.
  constexpr double kSoftStart = 0.5;
  waitFor(
      []
      {
        std::lock_guard<std::mutex> lock(g_mutex);
        return g_first_force_stamp > 0.0 && g_latest_stamp > g_first_force_stamp + kSoftStart + 0.1;
      },
      10.0, "the driver's soft start to end");
  // And the press under way, so that the hold holds a force worth judging (on a loaded machine
  // the script can still be on its way down when the soft start ends: 0.45 N was seen).
  waitFor(
      []
      {
        std::lock_guard<std::mutex> lock(g_mutex);
        return g_applied_force > 1.0;
      },
      20.0, "the driver to render more than 1 N");
  const double killed_at = ros::Time::now().toSec();  // the driver's stamps' clock (wall)
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    g_killed_at = killed_at;
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
  // Judged on the driver's own clock, so that a loaded machine cannot move it: each state says
  // how old the command it renders was at its read (command_age), exactly the age the force
  // guard's watchdog judged. The watchdog holds a command for command_timeout (20 ms) and then
  // ramps it linearly to zero within ramp_time (10 ms): a state of age a renders
  // F (1 - (a - 20 ms) / 10 ms) clamped to [0, 1], F the held force. Late ticks (a stalled
  // driver thread) change which ages are sampled, never what each one shows.
  constexpr double kCommandTimeout = 0.02;  // s: the fake profile's (config/devices/fake.yaml)
  constexpr double kRampTime = 0.01;        // s: idem
  std::vector<DriverRecord> states;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    states = g_force_after_kill;
    g_watch_zero = false;
  }
  // The first zero after the kill (a zero before it would be the watchdog on a late command of
  // the living physics, which the force's return then ends).
  std::size_t zero = 0;
  while (zero < states.size() && (states[zero].force != 0.0 || states[zero].stamp < killed_at))
  {
    ++zero;
  }
  ASSERT_LT(zero, states.size()) << "no zero after the kill among " << states.size() << " states";
  ASSERT_GT(zero, 0u);
  const double zero_age = states[zero].command_age;
  EXPECT_GE(zero_age, kCommandTimeout + kRampTime) << "the force went to zero before the watchdog's time";
  // Back from the zero, the same command's states: from one to the next its age grows by the
  // time between their reads (a newer command's age starts again from its own arrival: on a
  // loaded machine commands come unevenly, and a newer one read 0.7 ms after it came can follow
  // an older one read 0.3 ms after it came, so a growing age alone does not tell them apart).
  constexpr double kSameCommand = 2.5e-4;  // s: the reads' stamps are taken just after the reads
  std::size_t first = zero;
  while (first > 0 && states[first - 1].command_age >= 0.0 &&
         std::abs((states[first].command_age - states[first - 1].command_age) -
                  (states[first].stamp - states[first - 1].stamp)) < kSameCommand)
  {
    --first;
  }
  ASSERT_LT(first, zero) << "the tick before the zero rendered another command";
  EXPECT_LT(states[zero - 1].command_age, kCommandTimeout + kRampTime) << "the force stayed past the ramp";
  // The held force: the states within the hold (none if the driver's thread stalled through
  // it; then only the ramp's bounds are judged).
  double held = 0.0;
  int holding = 0;
  int ramping = 0;
  for (std::size_t i = first; i < zero; ++i)
  {
    const double age = states[i].command_age;
    if (age <= kCommandTimeout)
    {
      if (holding == 0)
      {
        held = states[i].force;
      }
      EXPECT_EQ(states[i].force, held) << "the hold changed the force at age " << age;
      ++holding;
      continue;
    }
    const double scale = std::max(0.0, 1.0 - (age - kCommandTimeout) / kRampTime);
    if (holding > 0)
    {
      EXPECT_NEAR(states[i].force, held * scale, 1e-9 * held) << "the ramp at age " << age;
    }
    EXPECT_GT(states[i].force, 0.0);
    ++ramping;
  }
  if (holding > 0)
  {
    EXPECT_GT(held, 0.5) << "the driver held no force before the ramp";
  }
  const double last_age = states[zero - 1].command_age;
  const long feedback = g_feedback;
  const ros::WallTime waiting = ros::WallTime::now();
  waitFor([feedback] { return g_feedback > feedback + 100; }, 20.0, "the physics to come back");
  waitFor(
      []
      {
        std::lock_guard<std::mutex> lock(g_mutex);
        return g_applied_force > 0.5;
      },
      10.0, "the force to come back");
  char line[320];
  std::snprintf(line, sizeof(line),
                "physics killed: the driver held %.3f N over %d ticks, ramped over %d, zero when the last command was "
                "%.1f ms old (the tick before: %.1f ms); loop back after %.1f s",
                held, holding, ramping, 1e3 * zero_age, 1e3 * last_age, (ros::WallTime::now() - waiting).toSec());
  std::printf("[ measured ] %s\n", line);
  RecordProperty("measured", line);
}
}  // namespace

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "safety_test");
  return RUN_ALL_TESTS();
}
