// rostest: record:=true writes a bag of the session. Lets the loop run, stops the recorder,
// then reads the bag: every device state the driver published while recording is in it (the
// driver numbers them without gaps), and the poses, feedback, contact areas and TF are there.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <god_finger/DeviceState.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>

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
      "/finger/device/state", 2000, [](const god_finger::DeviceState::ConstPtr&) { ++g_states; });
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
  // Feedback and poses at the loop's rate too, over the time each was recorded (the recorder
  // finds topics by its regular expression one by one, so each starts at its own time; no gap
  // check: they carry no sequence number).
  for (const char* topic : {"/finger/feedback", "/finger/pose"})
  {
    const double span = spans[topic].second - spans[topic].first;
    EXPECT_GT(span, 2.0) << topic;
    EXPECT_GT(counts[topic], 0.95 * 1000.0 * span) << topic << " over " << span << " s";
  }
}
}  // namespace

int main(int argc, char** argv)
{
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "record_test");
  return RUN_ALL_TESTS();
}
