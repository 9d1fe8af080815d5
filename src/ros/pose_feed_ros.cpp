#include "pose_feed_ros.h"

#include "god_finger/runtime/servo_clock.h"

#include <geometry_msgs/PoseArray.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

namespace god_finger
{
namespace
{
// s on steadySeconds()' clock for a ROS stamp.
double steadyStamp(const ros::Time& stamp)
{
  const double age = stamp.isZero() ? 0.0 : (ros::Time::now() - stamp).toSec();
  return steadySeconds() - age;
}

struct TfFeed
{
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener{buffer};
  ros::WallTimer timer;
  std::vector<FingerPose> poses;
};

std::shared_ptr<void> connectTf(ros::NodeHandle nh, const PoseSourceParams& params, std::shared_ptr<PoseFeed> feed)
{
  auto tf = std::make_shared<TfFeed>();
  tf->poses.resize(params.frames.size());
  std::weak_ptr<PoseFeed> weak = feed;
  TfFeed* state = tf.get();  // the timer is part of it: it never outlives it
  tf->timer = nh.createWallTimer(ros::WallDuration(1.0 / params.poll_rate),
                                 [state, weak, params](const ros::WallTimerEvent&)
                                 {
                                   const std::shared_ptr<PoseFeed> target = weak.lock();
                                   if (!target)
                                   {
                                     return;
                                   }
                                   for (std::size_t i = 0; i < params.frames.size(); ++i)
                                   {
                                     FingerPose& pose = state->poses[i];
                                     pose.position = Eigen::Vector3d::Constant(NAN);  // not refreshed unless TF has it
                                     try
                                     {
                                       const geometry_msgs::TransformStamped transform = state->buffer.lookupTransform(
                                           params.reference_frame, params.frames[i], ros::Time(0));
                                       const geometry_msgs::Vector3& t = transform.transform.translation;
                                       pose.position = Eigen::Vector3d(t.x, t.y, t.z);
                                       const geometry_msgs::Quaternion& q = transform.transform.rotation;
                                       setPoseOrientation(q.x, q.y, q.z, q.w, &pose);
                                       pose.stamp = steadyStamp(transform.header.stamp);
                                     }
                                     catch (const tf2::TransformException&)
                                     {
                                     }
                                   }
                                   target->write(state->poses);
                                 });
  return tf;
}
}  // namespace

std::shared_ptr<void> connectPoseFeed(ros::NodeHandle nh, const PoseSourceParams& params,
                                      std::shared_ptr<PoseFeed> feed)
{
  if (!params.frames.empty())
  {
    return connectTf(nh, params, std::move(feed));
  }
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
    const double stamp = steadyStamp(message->header.stamp);
    poses->resize(message->poses.size());
    for (std::size_t i = 0; i < message->poses.size(); ++i)
    {
      const geometry_msgs::Point& p = message->poses[i].position;
      (*poses)[i].position = Eigen::Vector3d(p.x, p.y, p.z);
      const geometry_msgs::Quaternion& q = message->poses[i].orientation;
      setPoseOrientation(q.x, q.y, q.z, q.w, &(*poses)[i]);
      (*poses)[i].stamp = stamp;
    }
    target->write(*poses);
  };
  return std::make_shared<ros::Subscriber>(nh.subscribe<geometry_msgs::PoseArray>(params.topic, 10, callback));
}
}  // namespace god_finger
