#include "pose_feed_ros.h"

#include "god_finger/runtime/servo_clock.h"

#include <geometry_msgs/PoseArray.h>
#include <ros/ros.h>

namespace god_finger
{
std::shared_ptr<void> connectPoseFeed(ros::NodeHandle nh, const std::string& topic, std::shared_ptr<PoseFeed> feed)
{
  std::weak_ptr<PoseFeed> weak = feed;
  auto poses = std::make_shared<std::vector<FingerPose>>();
  boost::function<void(const geometry_msgs::PoseArray::ConstPtr&)> callback =
      [weak, poses](const geometry_msgs::PoseArray::ConstPtr& message)
  {
    const std::shared_ptr<PoseFeed> target = weak.lock();
    if (!target)
    {
      return;
    }
    const double age = message->header.stamp.isZero() ? 0.0 : (ros::Time::now() - message->header.stamp).toSec();
    const double stamp = steadySeconds() - age;
    poses->resize(message->poses.size());
    for (std::size_t i = 0; i < message->poses.size(); ++i)
    {
      const geometry_msgs::Point& p = message->poses[i].position;
      (*poses)[i].position = Eigen::Vector3d(p.x, p.y, p.z);
      (*poses)[i].stamp = stamp;
    }
    target->write(*poses);
  };
  return std::make_shared<ros::Subscriber>(nh.subscribe<geometry_msgs::PoseArray>(topic, 10, callback));
}
}  // namespace god_finger
