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

// A driver's message: `Message` names its type, md5sum and definition (kType, kMd5,
// kDefinition) and visits its fields in the .msg's order (fields()); this gives roscpp its traits
// and its serialiser, as gencpp's generated code does. At global scope.
#define GOD_FINGER_DRIVER_MESSAGE(Message)                                                         \
  namespace ros                                                                                    \
  {                                                                                                \
  namespace message_traits                                                                         \
  {                                                                                                \
  template <>                                                                                      \
  struct MD5Sum<god_finger::driver_msgs::Message>                                                  \
  {                                                                                                \
    static const char* value()                                                                     \
    {                                                                                              \
      return god_finger::driver_msgs::Message::kMd5;                                               \
    }                                                                                              \
    static const char* value(const god_finger::driver_msgs::Message&)                              \
    {                                                                                              \
      return value();                                                                              \
    }                                                                                              \
  };                                                                                               \
  template <>                                                                                      \
  struct DataType<god_finger::driver_msgs::Message>                                                \
  {                                                                                                \
    static const char* value()                                                                     \
    {                                                                                              \
      return god_finger::driver_msgs::Message::kType;                                              \
    }                                                                                              \
    static const char* value(const god_finger::driver_msgs::Message&)                              \
    {                                                                                              \
      return value();                                                                              \
    }                                                                                              \
  };                                                                                               \
  template <>                                                                                      \
  struct Definition<god_finger::driver_msgs::Message>                                              \
  {                                                                                                \
    static const char* value()                                                                     \
    {                                                                                              \
      return god_finger::driver_msgs::Message::kDefinition;                                        \
    }                                                                                              \
    static const char* value(const god_finger::driver_msgs::Message&)                              \
    {                                                                                              \
      return value();                                                                              \
    }                                                                                              \
  };                                                                                               \
  }                                                                                                \
  namespace serialization                                                                          \
  {                                                                                                \
  template <>                                                                                      \
  struct Serializer<god_finger::driver_msgs::Message>                                              \
  {                                                                                                \
    template <typename Stream, typename T>                                                         \
    inline static void allInOne(Stream& stream, T m)                                               \
    {                                                                                              \
      god_finger::driver_msgs::Message::fields(m, [&stream](auto& field) { stream.next(field); }); \
    }                                                                                              \
    ROS_DECLARE_ALLINONE_SERIALIZER                                                                \
  };                                                                                               \
  }                                                                                                \
  }

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

  static constexpr const char* kType = "omni_msgs/OmniState";
  static constexpr const char* kMd5 = "89c2a741de66e9e904f59a02b171dd6e";
  static constexpr const char* kDefinition = R"DEF(std_msgs/Header         header

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
  template <class Self, class Visit>
  static void fields(Self& m, Visit visit)
  {
    visit(m.header);
    visit(m.locked);
    visit(m.close_gripper);
    visit(m.pose);
    visit(m.current);
    visit(m.velocity);
  }
};
using OmniStateConstPtr = boost::shared_ptr<const OmniState>;

struct OmniFeedback
{
  geometry_msgs::Vector3 force;
  geometry_msgs::Vector3 position;

  static constexpr const char* kType = "omni_msgs/OmniFeedback";
  static constexpr const char* kMd5 = "e9083ac4fd95494e94fbb0c0f90b6c00";
  static constexpr const char* kDefinition =
      R"DEF(# This is the force as estimated from the applied torques as well as the
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
  template <class Self, class Visit>
  static void fields(Self& m, Visit visit)
  {
    visit(m.force);
    visit(m.position);
  }
};
using OmniFeedbackConstPtr = boost::shared_ptr<const OmniFeedback>;

struct OmniButtonEvent
{
  std::int32_t grey_button = 0;
  std::int32_t white_button = 0;

  static constexpr const char* kType = "omni_msgs/OmniButtonEvent";
  static constexpr const char* kMd5 = "fb77877e6b639935c3360838062f05f0";
  static constexpr const char* kDefinition = R"DEF(int32 grey_button
int32 white_button
)DEF";
  template <class Self, class Visit>
  static void fields(Self& m, Visit visit)
  {
    visit(m.grey_button);
    visit(m.white_button);
  }
};
using OmniButtonEventConstPtr = boost::shared_ptr<const OmniButtonEvent>;

struct DeviceFeedback
{
  geometry_msgs::Vector3 force;
  geometry_msgs::Vector3 position;
  std::vector<std::uint8_t> lock;

  static constexpr const char* kType = "geomagic_control/DeviceFeedback";
  static constexpr const char* kMd5 = "94755b031db27fe99c2c235c0da9b072";
  static constexpr const char* kDefinition =
      R"DEF(# This is the force as estimated from the applied torques as well as the current
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
  template <class Self, class Visit>
  static void fields(Self& m, Visit visit)
  {
    visit(m.force);
    visit(m.position);
    visit(m.lock);
  }
};
using DeviceFeedbackConstPtr = boost::shared_ptr<const DeviceFeedback>;

struct DeviceButtonEvent
{
  std::int32_t grey_button = 0;
  std::int32_t white_button = 0;

  static constexpr const char* kType = "geomagic_control/DeviceButtonEvent";
  static constexpr const char* kMd5 = "fb77877e6b639935c3360838062f05f0";
  static constexpr const char* kDefinition = R"DEF(int32 grey_button
int32 white_button
)DEF";
  template <class Self, class Visit>
  static void fields(Self& m, Visit visit)
  {
    visit(m.grey_button);
    visit(m.white_button);
  }
};
using DeviceButtonEventConstPtr = boost::shared_ptr<const DeviceButtonEvent>;

struct OperatingState
{
  std_msgs::Header header;
  std::string state;
  std::uint8_t is_homed = 0;
  std::uint8_t is_busy = 0;

  static constexpr const char* kType = "crtk_msgs/OperatingState";
  static constexpr const char* kMd5 = "b1bd4021639d9d9c5fbfff78d6ff3158";
  static constexpr const char* kDefinition = R"DEF(#
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
  template <class Self, class Visit>
  static void fields(Self& m, Visit visit)
  {
    visit(m.header);
    visit(m.state);
    visit(m.is_homed);
    visit(m.is_busy);
  }
};
using OperatingStateConstPtr = boost::shared_ptr<const OperatingState>;

struct FalconPos
{
  double X = 0.0;
  double Y = 0.0;
  double Z = 0.0;

  static constexpr const char* kType = "ros_falcon/falconPos";
  static constexpr const char* kMd5 = "8219583d7802cc50be3e9ab911877ba5";
  static constexpr const char* kDefinition = R"DEF(float64 X
float64 Y
float64 Z
)DEF";
  template <class Self, class Visit>
  static void fields(Self& m, Visit visit)
  {
    visit(m.X);
    visit(m.Y);
    visit(m.Z);
  }
};
using FalconPosConstPtr = boost::shared_ptr<const FalconPos>;

struct FalconForces
{
  double X = 0.0;
  double Y = 0.0;
  double Z = 0.0;

  static constexpr const char* kType = "ros_falcon/falconForces";
  static constexpr const char* kMd5 = "8219583d7802cc50be3e9ab911877ba5";
  static constexpr const char* kDefinition = R"DEF(float64 X
float64 Y
float64 Z
)DEF";
  template <class Self, class Visit>
  static void fields(Self& m, Visit visit)
  {
    visit(m.X);
    visit(m.Y);
    visit(m.Z);
  }
};
using FalconForcesConstPtr = boost::shared_ptr<const FalconForces>;

}  // namespace driver_msgs
}  // namespace god_finger

GOD_FINGER_DRIVER_MESSAGE(OmniState)
GOD_FINGER_DRIVER_MESSAGE(OmniFeedback)
GOD_FINGER_DRIVER_MESSAGE(OmniButtonEvent)
GOD_FINGER_DRIVER_MESSAGE(DeviceFeedback)
GOD_FINGER_DRIVER_MESSAGE(DeviceButtonEvent)
GOD_FINGER_DRIVER_MESSAGE(OperatingState)
GOD_FINGER_DRIVER_MESSAGE(FalconPos)
GOD_FINGER_DRIVER_MESSAGE(FalconForces)

namespace ros
{
namespace message_traits
{
template <>
struct HasHeader<god_finger::driver_msgs::OmniState> : TrueType
{
};
template <>
struct HasHeader<god_finger::driver_msgs::OperatingState> : TrueType
{
};
}  // namespace message_traits
}  // namespace ros
