// The ROS drivers' own messages (devices/driver_bridge.h), declared here so that god_finger builds
// and runs without their packages installed, and talks to the real drivers on the wire: each
// type carries the real type name, md5sum and full definition (as genmsg computes them from the
// drivers' .msg files: omni_msgs of the Touch driver omni_common, geomagic_control of WPI's
// ros_geomagic, crtk_msgs, ros_falcon), and serialises its fields in the .msg's order, as gencpp's
// generated code does. A driver built from another version of a .msg (another md5sum) is refused
// by roscpp, which names the topic and both md5sums. docs/decisions.md says why this form.
// The fakes of test/ros/ros_drivers/ build their messages with genpy from those .msg files: a
// rostest connecting them is the check that these match.
#pragma once

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Vector3.h>
#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <std_msgs/Header.h>

#include <cstdint>
#include <string>
#include <vector>

namespace god_finger
{
namespace driver_msgs
{
struct OmniState
{
  std_msgs::Header header;
  std::uint8_t locked = 0;
  std::uint8_t close_gripper = 0;
  geometry_msgs::Pose pose;
  geometry_msgs::Vector3 current;
  geometry_msgs::Vector3 velocity;
};
using OmniStateConstPtr = boost::shared_ptr<const OmniState>;
struct OmniFeedback
{
  geometry_msgs::Vector3 force;
  geometry_msgs::Vector3 position;
};
using OmniFeedbackConstPtr = boost::shared_ptr<const OmniFeedback>;
struct OmniButtonEvent
{
  std::int32_t grey_button = 0;
  std::int32_t white_button = 0;
};
using OmniButtonEventConstPtr = boost::shared_ptr<const OmniButtonEvent>;
struct DeviceFeedback
{
  geometry_msgs::Vector3 force;
  geometry_msgs::Vector3 position;
  std::vector<std::uint8_t> lock;
};
using DeviceFeedbackConstPtr = boost::shared_ptr<const DeviceFeedback>;
struct DeviceButtonEvent
{
  std::int32_t grey_button = 0;
  std::int32_t white_button = 0;
};
using DeviceButtonEventConstPtr = boost::shared_ptr<const DeviceButtonEvent>;
struct OperatingState
{
  std_msgs::Header header;
  std::string state;
  std::uint8_t is_homed = 0;
  std::uint8_t is_busy = 0;
};
using OperatingStateConstPtr = boost::shared_ptr<const OperatingState>;
struct FalconPos
{
  double X = 0.0;
  double Y = 0.0;
  double Z = 0.0;
};
using FalconPosConstPtr = boost::shared_ptr<const FalconPos>;
struct FalconForces
{
  double X = 0.0;
  double Y = 0.0;
  double Z = 0.0;
};
using FalconForcesConstPtr = boost::shared_ptr<const FalconForces>;
}  // namespace driver_msgs
}  // namespace god_finger

namespace ros
{
namespace message_traits
{
template <>
struct MD5Sum<god_finger::driver_msgs::OmniState>
{
  static const char* value()
  {
    return "89c2a741de66e9e904f59a02b171dd6e";
  }
  static const char* value(const god_finger::driver_msgs::OmniState&)
  {
    return value();
  }
  static const std::uint64_t static_value1 = 0x89c2a741de66e9e9ULL;
  static const std::uint64_t static_value2 = 0x04f59a02b171dd6eULL;
};
template <>
struct DataType<god_finger::driver_msgs::OmniState>
{
  static const char* value()
  {
    return "omni_msgs/OmniState";
  }
  static const char* value(const god_finger::driver_msgs::OmniState&)
  {
    return value();
  }
};
template <>
struct Definition<god_finger::driver_msgs::OmniState>
{
  static const char* value()
  {
    return R"DEF(std_msgs/Header         header

bool                    locked

bool                    close_gripper

geometry_msgs/Pose      pose        # meters

geometry_msgs/Vector3   current     # Amperes

geometry_msgs/Vector3   velocity    # meters/s

================================================================================
MSG: std_msgs/Header
# Standard metadata for higher-level stamped data types.
# This is generally used to communicate timestamped data 
# in a particular coordinate frame.
# 
# sequence ID: consecutively increasing ID 
uint32 seq
#Two-integer timestamp that is expressed as:
# * stamp.sec: seconds (stamp_secs) since epoch (in Python the variable is called 'secs')
# * stamp.nsec: nanoseconds since stamp_secs (in Python the variable is called 'nsecs')
# time-handling sugar is provided by the client library
time stamp
#Frame this data is associated with
string frame_id

================================================================================
MSG: geometry_msgs/Pose
# A representation of pose in free space, composed of position and orientation. 
Point position
Quaternion orientation

================================================================================
MSG: geometry_msgs/Point
# This contains the position of a point in free space
float64 x
float64 y
float64 z

================================================================================
MSG: geometry_msgs/Quaternion
# This represents an orientation in free space in quaternion form.

float64 x
float64 y
float64 z
float64 w

================================================================================
MSG: geometry_msgs/Vector3
# This represents a vector in free space. 
# It is only meant to represent a direction. Therefore, it does not
# make sense to apply a translation to it (e.g., when applying a 
# generic rigid transformation to a Vector3, tf2 will only apply the
# rotation). If you want your data to be translatable too, use the
# geometry_msgs/Point message instead.

float64 x
float64 y
float64 z)DEF";
  }
  static const char* value(const god_finger::driver_msgs::OmniState&)
  {
    return value();
  }
};
template <>
struct HasHeader<god_finger::driver_msgs::OmniState> : TrueType
{
};
template <>
struct MD5Sum<god_finger::driver_msgs::OmniFeedback>
{
  static const char* value()
  {
    return "e9083ac4fd95494e94fbb0c0f90b6c00";
  }
  static const char* value(const god_finger::driver_msgs::OmniFeedback&)
  {
    return value();
  }
  static const std::uint64_t static_value1 = 0xe9083ac4fd95494eULL;
  static const std::uint64_t static_value2 = 0x94fbb0c0f90b6c00ULL;
};
template <>
struct DataType<god_finger::driver_msgs::OmniFeedback>
{
  static const char* value()
  {
    return "omni_msgs/OmniFeedback";
  }
  static const char* value(const god_finger::driver_msgs::OmniFeedback&)
  {
    return value();
  }
};
template <>
struct Definition<god_finger::driver_msgs::OmniFeedback>
{
  static const char* value()
  {
    return R"DEF(# This is the force as estimated from the applied torques as well as the
# current end effector position of the robot arm
geometry_msgs/Vector3  force
geometry_msgs/Vector3  position

================================================================================
MSG: geometry_msgs/Vector3
# This represents a vector in free space. 
# It is only meant to represent a direction. Therefore, it does not
# make sense to apply a translation to it (e.g., when applying a 
# generic rigid transformation to a Vector3, tf2 will only apply the
# rotation). If you want your data to be translatable too, use the
# geometry_msgs/Point message instead.

float64 x
float64 y
float64 z)DEF";
  }
  static const char* value(const god_finger::driver_msgs::OmniFeedback&)
  {
    return value();
  }
};
template <>
struct MD5Sum<god_finger::driver_msgs::OmniButtonEvent>
{
  static const char* value()
  {
    return "fb77877e6b639935c3360838062f05f0";
  }
  static const char* value(const god_finger::driver_msgs::OmniButtonEvent&)
  {
    return value();
  }
  static const std::uint64_t static_value1 = 0xfb77877e6b639935ULL;
  static const std::uint64_t static_value2 = 0xc3360838062f05f0ULL;
};
template <>
struct DataType<god_finger::driver_msgs::OmniButtonEvent>
{
  static const char* value()
  {
    return "omni_msgs/OmniButtonEvent";
  }
  static const char* value(const god_finger::driver_msgs::OmniButtonEvent&)
  {
    return value();
  }
};
template <>
struct Definition<god_finger::driver_msgs::OmniButtonEvent>
{
  static const char* value()
  {
    return R"DEF(int32 grey_button
int32 white_button
)DEF";
  }
  static const char* value(const god_finger::driver_msgs::OmniButtonEvent&)
  {
    return value();
  }
};
template <>
struct MD5Sum<god_finger::driver_msgs::DeviceFeedback>
{
  static const char* value()
  {
    return "94755b031db27fe99c2c235c0da9b072";
  }
  static const char* value(const god_finger::driver_msgs::DeviceFeedback&)
  {
    return value();
  }
  static const std::uint64_t static_value1 = 0x94755b031db27fe9ULL;
  static const std::uint64_t static_value2 = 0x9c2c235c0da9b072ULL;
};
template <>
struct DataType<god_finger::driver_msgs::DeviceFeedback>
{
  static const char* value()
  {
    return "geomagic_control/DeviceFeedback";
  }
  static const char* value(const god_finger::driver_msgs::DeviceFeedback&)
  {
    return value();
  }
};
template <>
struct Definition<god_finger::driver_msgs::DeviceFeedback>
{
  static const char* value()
  {
    return R"DEF(# This is the force as estimated from the applied torques as well as the current
# end effector position of the robot arm                           
geometry_msgs/Vector3  force                                                                  
geometry_msgs/Vector3  position 
bool[] lock 
================================================================================
MSG: geometry_msgs/Vector3
# This represents a vector in free space. 
# It is only meant to represent a direction. Therefore, it does not
# make sense to apply a translation to it (e.g., when applying a 
# generic rigid transformation to a Vector3, tf2 will only apply the
# rotation). If you want your data to be translatable too, use the
# geometry_msgs/Point message instead.

float64 x
float64 y
float64 z)DEF";
  }
  static const char* value(const god_finger::driver_msgs::DeviceFeedback&)
  {
    return value();
  }
};
template <>
struct MD5Sum<god_finger::driver_msgs::DeviceButtonEvent>
{
  static const char* value()
  {
    return "fb77877e6b639935c3360838062f05f0";
  }
  static const char* value(const god_finger::driver_msgs::DeviceButtonEvent&)
  {
    return value();
  }
  static const std::uint64_t static_value1 = 0xfb77877e6b639935ULL;
  static const std::uint64_t static_value2 = 0xc3360838062f05f0ULL;
};
template <>
struct DataType<god_finger::driver_msgs::DeviceButtonEvent>
{
  static const char* value()
  {
    return "geomagic_control/DeviceButtonEvent";
  }
  static const char* value(const god_finger::driver_msgs::DeviceButtonEvent&)
  {
    return value();
  }
};
template <>
struct Definition<god_finger::driver_msgs::DeviceButtonEvent>
{
  static const char* value()
  {
    return R"DEF(int32 grey_button
int32 white_button
)DEF";
  }
  static const char* value(const god_finger::driver_msgs::DeviceButtonEvent&)
  {
    return value();
  }
};
template <>
struct MD5Sum<god_finger::driver_msgs::OperatingState>
{
  static const char* value()
  {
    return "b1bd4021639d9d9c5fbfff78d6ff3158";
  }
  static const char* value(const god_finger::driver_msgs::OperatingState&)
  {
    return value();
  }
  static const std::uint64_t static_value1 = 0xb1bd4021639d9d9cULL;
  static const std::uint64_t static_value2 = 0x5fbfff78d6ff3158ULL;
};
template <>
struct DataType<god_finger::driver_msgs::OperatingState>
{
  static const char* value()
  {
    return "crtk_msgs/OperatingState";
  }
  static const char* value(const god_finger::driver_msgs::OperatingState&)
  {
    return value();
  }
};
template <>
struct Definition<god_finger::driver_msgs::OperatingState>
{
  static const char* value()
  {
    return R"DEF(#
# See https://github.com/collaborative-robotics/documentation/wiki/Robot-API-status
#
# Standard states include DISABLED, ENABLED, PAUSED and FAULT
#
std_msgs/Header header
string          state
bool            is_homed
bool            is_busy

================================================================================
MSG: std_msgs/Header
# Standard metadata for higher-level stamped data types.
# This is generally used to communicate timestamped data 
# in a particular coordinate frame.
# 
# sequence ID: consecutively increasing ID 
uint32 seq
#Two-integer timestamp that is expressed as:
# * stamp.sec: seconds (stamp_secs) since epoch (in Python the variable is called 'secs')
# * stamp.nsec: nanoseconds since stamp_secs (in Python the variable is called 'nsecs')
# time-handling sugar is provided by the client library
time stamp
#Frame this data is associated with
string frame_id
)DEF";
  }
  static const char* value(const god_finger::driver_msgs::OperatingState&)
  {
    return value();
  }
};
template <>
struct HasHeader<god_finger::driver_msgs::OperatingState> : TrueType
{
};
template <>
struct MD5Sum<god_finger::driver_msgs::FalconPos>
{
  static const char* value()
  {
    return "8219583d7802cc50be3e9ab911877ba5";
  }
  static const char* value(const god_finger::driver_msgs::FalconPos&)
  {
    return value();
  }
  static const std::uint64_t static_value1 = 0x8219583d7802cc50ULL;
  static const std::uint64_t static_value2 = 0xbe3e9ab911877ba5ULL;
};
template <>
struct DataType<god_finger::driver_msgs::FalconPos>
{
  static const char* value()
  {
    return "ros_falcon/falconPos";
  }
  static const char* value(const god_finger::driver_msgs::FalconPos&)
  {
    return value();
  }
};
template <>
struct Definition<god_finger::driver_msgs::FalconPos>
{
  static const char* value()
  {
    return R"DEF(float64 X
float64 Y
float64 Z
)DEF";
  }
  static const char* value(const god_finger::driver_msgs::FalconPos&)
  {
    return value();
  }
};
template <>
struct MD5Sum<god_finger::driver_msgs::FalconForces>
{
  static const char* value()
  {
    return "8219583d7802cc50be3e9ab911877ba5";
  }
  static const char* value(const god_finger::driver_msgs::FalconForces&)
  {
    return value();
  }
  static const std::uint64_t static_value1 = 0x8219583d7802cc50ULL;
  static const std::uint64_t static_value2 = 0xbe3e9ab911877ba5ULL;
};
template <>
struct DataType<god_finger::driver_msgs::FalconForces>
{
  static const char* value()
  {
    return "ros_falcon/falconForces";
  }
  static const char* value(const god_finger::driver_msgs::FalconForces&)
  {
    return value();
  }
};
template <>
struct Definition<god_finger::driver_msgs::FalconForces>
{
  static const char* value()
  {
    return R"DEF(float64 X
float64 Y
float64 Z
)DEF";
  }
  static const char* value(const god_finger::driver_msgs::FalconForces&)
  {
    return value();
  }
};
}  // namespace message_traits

namespace serialization
{
template <>
struct Serializer<god_finger::driver_msgs::OmniState>
{
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m)
  {
    stream.next(m.header);
    stream.next(m.locked);
    stream.next(m.close_gripper);
    stream.next(m.pose);
    stream.next(m.current);
    stream.next(m.velocity);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
template <>
struct Serializer<god_finger::driver_msgs::OmniFeedback>
{
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m)
  {
    stream.next(m.force);
    stream.next(m.position);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
template <>
struct Serializer<god_finger::driver_msgs::OmniButtonEvent>
{
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m)
  {
    stream.next(m.grey_button);
    stream.next(m.white_button);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
template <>
struct Serializer<god_finger::driver_msgs::DeviceFeedback>
{
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m)
  {
    stream.next(m.force);
    stream.next(m.position);
    stream.next(m.lock);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
template <>
struct Serializer<god_finger::driver_msgs::DeviceButtonEvent>
{
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m)
  {
    stream.next(m.grey_button);
    stream.next(m.white_button);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
template <>
struct Serializer<god_finger::driver_msgs::OperatingState>
{
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m)
  {
    stream.next(m.header);
    stream.next(m.state);
    stream.next(m.is_homed);
    stream.next(m.is_busy);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
template <>
struct Serializer<god_finger::driver_msgs::FalconPos>
{
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m)
  {
    stream.next(m.X);
    stream.next(m.Y);
    stream.next(m.Z);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
template <>
struct Serializer<god_finger::driver_msgs::FalconForces>
{
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m)
  {
    stream.next(m.X);
    stream.next(m.Y);
    stream.next(m.Z);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
}  // namespace serialization
}  // namespace ros
