#include "world_messages.h"

#include "god_finger/physics/joint_measure.h"

#include <algorithm>
#include <boost/make_shared.hpp>
#include <cmath>
#include <limits>

#include "god_finger/ros/conversions.h"
#include "markers.h"

namespace god_finger
{
god_finger::ContactAreaArrayPtr contactAreaMessage(const SceneDescription& scene, const WorldSnapshot& world,
                                                   const std::vector<std::string>& interface_names,
                                                   const ros::Time& stamp)
{
  god_finger::ContactAreaArrayPtr areas(new god_finger::ContactAreaArray);
  areas->header.stamp = stamp;
  areas->header.frame_id = "world";
  for (std::size_t i = 0; i < world.interfaces.size() && i < interface_names.size(); ++i)
  {
    const InterfaceState& state = world.interfaces[i];
    for (int c = 0; c < state.contact_count; ++c)
    {
      const WorldContactArea& area = state.contacts[c];
      god_finger::ContactArea message;
      message.header = areas->header;
      message.interface = interface_names[i];
      message.object = scene.bodies[area.body].name;
      message.point = toPoint(area.point);
      message.normal = toVector(area.normal);
      message.depth = area.depth;
      message.feature = static_cast<std::uint8_t>(area.feature);
      message.radius = area.radius;
      message.overlap_area = area.overlap_area;
      for (int k = 0; k < area.sub_god_object_count; ++k)
      {
        message.sub_god_objects.push_back(toPoint(area.positions[k]));
      }
      areas->areas.push_back(message);
    }
  }
  return areas;
}

visualization_msgs::MarkerArrayPtr markerMessage(const SceneDescription& scene, const WorldSnapshot& world,
                                                 double proxy_radius, const ros::Time& stamp)
{
  visualization_msgs::MarkerArrayPtr markers(new visualization_msgs::MarkerArray);
  appendBodyMarkers(scene, world, stamp, markers.get());
  appendInteractionMarkers(world, proxy_radius, stamp, markers.get());
  return markers;
}

geometry_msgs::WrenchStampedPtr feedbackMessage(const ros::Time& stamp, const Eigen::Vector3d& user_force,
                                                const Eigen::Vector3d& user_torque)
{
  geometry_msgs::WrenchStampedPtr feedback(new geometry_msgs::WrenchStamped);
  feedback->header.stamp = stamp;
  feedback->header.frame_id = "world";
  feedback->wrench.force = toVector(user_force);
  feedback->wrench.torque = toVector(user_torque);
  return feedback;
}

geometry_msgs::PoseStampedPtr poseMessage(const ros::Time& stamp, const Eigen::Vector3d& position,
                                          const Eigen::Quaterniond* orientation)
{
  geometry_msgs::PoseStampedPtr pose(new geometry_msgs::PoseStamped);
  pose->header.stamp = stamp;
  pose->header.frame_id = "world";
  pose->pose.position = toPoint(position);
  pose->pose.orientation = toQuaternion(orientation ? *orientation : Eigen::Quaterniond::Identity());
  return pose;
}

god_finger::InterfacePosePtr interfacePoseMessage(const ros::Time& stamp, const Eigen::Vector3d& position,
                                                  const Eigen::Quaterniond* orientation)
{
  god_finger::InterfacePosePtr pose(new god_finger::InterfacePose);
  pose->header.stamp = stamp;
  pose->header.frame_id = "world";
  pose->pose.position = toPoint(position);
  pose->pose.orientation = toQuaternion(orientation ? *orientation : Eigen::Quaterniond::Identity());
  pose->has_orientation = orientation != nullptr;
  return pose;
}

geometry_msgs::TransformStamped interfaceTransform(const geometry_msgs::PoseStamped& pose, const std::string& frame)
{
  geometry_msgs::TransformStamped transform;
  transform.header = pose.header;
  transform.child_frame_id = frame;
  transform.transform.translation.x = pose.pose.position.x;
  transform.transform.translation.y = pose.pose.position.y;
  transform.transform.translation.z = pose.pose.position.z;
  transform.transform.rotation = pose.pose.orientation;
  return transform;
}

bool poseOrientation(const god_finger::InterfacePose& pose, Eigen::Quaterniond* orientation)
{
  if (!pose.has_orientation)
  {
    return false;
  }
  const geometry_msgs::Quaternion& q = pose.pose.orientation;
  *orientation = Eigen::Quaterniond(q.w, q.x, q.y, q.z);
  return true;
}

bool recordedThreeDofPose(const geometry_msgs::Pose& pose)
{
  const geometry_msgs::Quaternion& q = pose.orientation;
  return q.w == 0.0 && q.x == 0.0 && q.y == 0.0 && q.z == 0.0;
}

geometry_msgs::PointStampedPtr proxyMessage(const ros::Time& stamp, const Eigen::Vector3d& proxy_position)
{
  geometry_msgs::PointStampedPtr proxy(new geometry_msgs::PointStamped);
  proxy->header.stamp = stamp;
  proxy->header.frame_id = "world";
  proxy->point = toPoint(proxy_position);
  return proxy;
}

god_finger::ProxyStatePtr proxyStateMessage(const ros::Time& stamp, const InterfaceState& state)
{
  god_finger::ProxyStatePtr message(new god_finger::ProxyState);
  message->header.stamp = stamp;
  message->header.frame_id = "world";
  message->proxy = toPoint(state.proxy_position);
  message->target = toPoint(state.interface_position);
  message->force = toVector(state.user_force);
  for (int c = 0; c < std::min(state.contact_count, MultirateStep::kMaxPlanes); ++c)
  {
    message->planes.push_back(toVector(state.contacts[c].normal));
  }
  const bool soft = state.contact_stiffness < std::numeric_limits<double>::infinity();
  message->contact_stiffness = soft ? state.contact_stiffness : 0.0;
  message->contact_normal = toVector(state.contact_normal);
  return message;
}

bool multirateStep(const god_finger::ProxyState& message, long lag, MultirateStep* step)
{
  MultirateStep read;
  read.proxy_position = fromPoint(message.proxy);
  read.step_target = fromPoint(message.target);
  read.user_force = fromVector(message.force);
  read.contact_normal = fromVector(message.contact_normal);
  read.lag = lag;
  if (!read.proxy_position.allFinite() || !read.step_target.allFinite() || !read.user_force.allFinite() ||
      !read.contact_normal.allFinite() || !std::isfinite(message.contact_stiffness) ||
      message.contact_stiffness < 0.0 || message.planes.size() > static_cast<std::size_t>(MultirateStep::kMaxPlanes))
  {
    return false;
  }
  read.contact_stiffness =
      message.contact_stiffness > 0.0 ? message.contact_stiffness : std::numeric_limits<double>::infinity();
  for (const geometry_msgs::Vector3& plane : message.planes)
  {
    const Eigen::Vector3d normal = fromVector(plane);
    if (!normal.allFinite() || std::abs(normal.norm() - 1.0) > 1e-6)
    {
      return false;
    }
    read.plane_normals[read.plane_count++] = normal;
  }
  if (read.contact_stiffness < std::numeric_limits<double>::infinity() &&
      std::abs(read.contact_normal.norm() - 1.0) > 1e-6)
  {
    return false;
  }
  *step = read;
  return true;
}

std::vector<geometry_msgs::TransformStamped> bodyTransforms(const SceneDescription& scene, const WorldSnapshot& world,
                                                            const ros::Time& stamp)
{
  std::vector<geometry_msgs::TransformStamped> transforms;
  for (std::size_t i = 0; i < world.bodies.size() && i < scene.bodies.size(); ++i)
  {
    const BodyState& body = world.bodies[i];
    geometry_msgs::TransformStamped transform;
    transform.header.stamp = stamp;
    transform.header.frame_id = "world";
    transform.child_frame_id = scene.bodies[i].name;
    transform.transform.translation = toVector(body.pose.translation());
    const Eigen::Quaterniond q(body.pose.linear());
    transform.transform.rotation.x = q.x();
    transform.transform.rotation.y = q.y();
    transform.transform.rotation.z = q.z();
    transform.transform.rotation.w = q.w();
    transforms.push_back(transform);
  }
  return transforms;
}

sensor_msgs::JointStatePtr jointStateMessage(const SceneDescription& scene, const WorldSnapshot& world,
                                             const ros::Time& stamp)
{
  auto message = boost::make_shared<sensor_msgs::JointState>();
  message->header.stamp = stamp;
  for (const JointDescription& joint : scene.joints)
  {
    if (joint.child >= static_cast<int>(world.bodies.size()) || joint.parent >= static_cast<int>(world.bodies.size()))
    {
      continue;
    }
    const JointState state =
        measureJoint(joint, joint.parent < 0 ? nullptr : &world.bodies[joint.parent], world.bodies[joint.child]);
    message->name.push_back(joint.name);
    message->position.push_back(state.position);
    message->velocity.push_back(state.velocity);
  }
  return message;
}
}  // namespace god_finger
