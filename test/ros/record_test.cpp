// rostest: record:=true writes a bag of the session. Lets the loop run, stops the recorder,
// then reads the bag: every device state the driver published while recording is in it (the
// driver numbers them without gaps), and the poses, feedback, contact areas and TF are there.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <god_finger/DeviceState.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <vector>

namespace
{
bool exists(const std::string& path)
{
  return std::ifstream(path).good();
}

// The topics of `topics` that the master does not yet list `node` as subscribed to (all of
// them when the master does not answer).
std::set<std::string> notSubscribed(const std::string& node, std::set<std::string> topics)
{
  XmlRpc::XmlRpcValue request;
  XmlRpc::XmlRpcValue response;
  XmlRpc::XmlRpcValue payload;
  request[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", request, response, payload, false))
  {
    return topics;
  }
  XmlRpc::XmlRpcValue& subscriptions = payload[1];
  for (int i = 0; i < subscriptions.size(); ++i)
  {
    for (int j = 0; j < subscriptions[i][1].size(); ++j)
    {
      if (static_cast<std::string>(subscriptions[i][1][j]) == node)
      {
        topics.erase(static_cast<std::string>(subscriptions[i][0]));
      }
    }
  }
  return topics;
}

std::string joined(const std::set<std::string>& names)
{
  std::string text;
  for (const std::string& name : names)
  {
    text += (text.empty() ? "" : ", ") + name;
  }
  return text;
}

std::atomic<long> g_states{0};

TEST(Record, BagHoldsEveryDeviceStateAndTheRestOfTheSession)
{
  ros::NodeHandle pnh("~");
  const std::string bag_path = pnh.param<std::string>("bag", "");
  ASSERT_FALSE(bag_path.empty());
  ros::NodeHandle nh;
  ros::Subscriber states_seen = nh.subscribe<god_finger::DeviceState>(
      "/finger/device/state", 2000, [](const god_finger::DeviceState::ConstPtr&) { ++g_states; }, ros::VoidConstPtr(),
      ros::TransportHints().tcpNoDelay());
  ros::AsyncSpinner spinner(1);
  spinner.start();
  // Let the session run, then stop the recorder (it closes the bag on shutdown): until the
  // recorder has subscribed to every topic the test looks for, then for 3000 more device states
  // (3 s of the 1 kHz loop; the bag must hold more than 2000 of them, and the feedback and poses
  // over more than 2 s).
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(30.0);
  while (!exists(bag_path + ".active"))
  {
    ASSERT_LT(ros::WallTime::now(), give_up) << "no " << bag_path << ".active";
    ros::WallDuration(0.05).sleep();
  }
  const std::set<std::string> topics = {
      "/finger/device/state", "/finger/device/force", "/finger/pose", "/finger/feedback",
      "/finger/proxy",        "/contact_areas",       "/tf"};
  while (!notSubscribed("/recorder", topics).empty())
  {
    ASSERT_LT(ros::WallTime::now(), give_up)
        << "the recorder has not subscribed to " << joined(notSubscribed("/recorder", topics));
    ros::WallDuration(0.05).sleep();
  }
  const long states_then = g_states;
  const ros::WallTime recorded_by = ros::WallTime::now() + ros::WallDuration(30.0);
  while (g_states - states_then < 3000)
  {
    ASSERT_LT(ros::WallTime::now(), recorded_by)
        << "only " << g_states - states_then << " of 3000 device states within 30 s of the recorder subscribing";
    ros::WallDuration(0.05).sleep();
  }
  ASSERT_EQ(std::system("rosnode kill /recorder > /dev/null"), 0);
  const ros::WallTime closed_by = ros::WallTime::now() + ros::WallDuration(20.0);
  while (!exists(bag_path) || exists(bag_path + ".active"))
  {
    ASSERT_LT(ros::WallTime::now(), closed_by) << "the recorder did not close " << bag_path;
    ros::WallDuration(0.05).sleep();
  }

  rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
  std::map<std::string, long> counts;
  std::map<std::string, std::pair<double, double>> spans;  // first, last recording time (s)
  // Header stamps (ns): the servo stamps a tick's device state, pose and feedback alike.
  std::map<std::string, std::vector<std::uint64_t>> stamps;
  long states = 0;
  std::uint32_t first_seq = 0;
  std::uint32_t last_seq = 0;
  for (const rosbag::MessageInstance& message : rosbag::View(bag))
  {
    ++counts[message.getTopic()];
    const double t = message.getTime().toSec();
    auto span = spans.emplace(message.getTopic(), std::make_pair(t, t)).first;
    span->second.second = t;
    if (message.getTopic() == "/finger/device/state")
    {
      const god_finger::DeviceState::ConstPtr state = message.instantiate<god_finger::DeviceState>();
      ASSERT_TRUE(state != nullptr);
      if (states == 0)
      {
        first_seq = state->header.seq;
      }
      last_seq = state->header.seq;
      ++states;
      stamps[message.getTopic()].push_back(state->header.stamp.toNSec());
    }
    else if (message.getTopic() == "/finger/feedback")
    {
      const geometry_msgs::WrenchStamped::ConstPtr feedback = message.instantiate<geometry_msgs::WrenchStamped>();
      ASSERT_TRUE(feedback != nullptr);
      stamps[message.getTopic()].push_back(feedback->header.stamp.toNSec());
    }
    else if (message.getTopic() == "/finger/pose")
    {
      const geometry_msgs::PoseStamped::ConstPtr pose = message.instantiate<geometry_msgs::PoseStamped>();
      ASSERT_TRUE(pose != nullptr);
      stamps[message.getTopic()].push_back(pose->header.stamp.toNSec());
    }
  }
  std::string summary;
  for (const auto& entry : counts)
  {
    summary += " " + entry.first + " " + std::to_string(entry.second);
  }
  RecordProperty("measured", "bag:" + summary);
  std::printf("bag:%s\n", summary.c_str());
  ASSERT_GT(states, 2000);  // a few seconds at 1 kHz
  EXPECT_EQ(states, static_cast<long>(last_seq - first_seq + 1)) << "device states missing from the bag";
  for (const char* topic :
       {"/finger/device/force", "/finger/pose", "/finger/feedback", "/finger/proxy", "/contact_areas", "/tf"})
  {
    EXPECT_GT(counts[topic], 0) << topic;
  }
  // Feedback and poses of every tick too, over the time each was recorded (the recorder finds
  // topics by its regular expression one by one, so each starts at its own time; they carry no
  // sequence number, but the stamp of the tick's device state, whose sequence has no gap).
  std::vector<std::uint64_t>& state_stamps = stamps["/finger/device/state"];
  std::sort(state_stamps.begin(), state_stamps.end());
  for (const char* topic : {"/finger/feedback", "/finger/pose"})
  {
    const double span = spans[topic].second - spans[topic].first;
    EXPECT_GT(span, 2.0) << topic;
    std::vector<std::uint64_t>& topic_stamps = stamps[topic];
    ASSERT_FALSE(topic_stamps.empty()) << topic;
    std::sort(topic_stamps.begin(), topic_stamps.end());
    // The ticks both were recorded over (the recorder was stopped in the middle of a tick's
    // messages, and started on each topic at its own time).
    const std::uint64_t first = std::max(state_stamps.front(), topic_stamps.front());
    const std::uint64_t last = std::min(state_stamps.back(), topic_stamps.back());
    const auto within = [first, last](const std::vector<std::uint64_t>& sorted)
    {
      return std::vector<std::uint64_t>(std::lower_bound(sorted.begin(), sorted.end(), first),
                                        std::upper_bound(sorted.begin(), sorted.end(), last));
    };
    const std::vector<std::uint64_t> ticks = within(state_stamps);
    const std::vector<std::uint64_t> recorded = within(topic_stamps);
    std::vector<std::uint64_t> missing;
    std::set_difference(ticks.begin(), ticks.end(), recorded.begin(), recorded.end(), std::back_inserter(missing));
    EXPECT_GT(ticks.size(), 2000u) << topic;
    EXPECT_EQ(missing.size(), 0u) << topic << ": " << missing.size() << " of the " << ticks.size()
                                  << " ticks recorded on both are not in the bag";
    EXPECT_EQ(recorded.size(), ticks.size()) << topic << ": stamps that are no device state's";
  }
}
}  // namespace

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "record_test");
  return RUN_ALL_TESTS();
}
