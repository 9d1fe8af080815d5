#include "parameters.h"

#include <XmlRpcValue.h>

namespace god_finger
{
namespace
{
ParameterValue fromXmlRpc(XmlRpc::XmlRpcValue& value)
{
  ParameterValue result;
  switch (value.getType())
  {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return ParameterValue::of(static_cast<bool>(value));
    case XmlRpc::XmlRpcValue::TypeInt:
      return ParameterValue::ofInteger(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble:
      return ParameterValue::of(static_cast<double>(value));
    case XmlRpc::XmlRpcValue::TypeString:
      return ParameterValue::of(static_cast<std::string>(value));
    case XmlRpc::XmlRpcValue::TypeArray:
      result.kind = ParameterValue::Kind::kList;
      for (int i = 0; i < value.size(); ++i)
      {
        result.items.push_back(fromXmlRpc(value[i]));
      }
      return result;
    default:
      // A struct, date or binary: an empty list, which every reader refuses with its message
      // (a reader of lists of names or rows requires a non-empty one).
      result.kind = ParameterValue::Kind::kList;
      return result;
  }
}
}  // namespace

bool RosParameterSource::get(const std::string& name, ParameterValue* value) const
{
  XmlRpc::XmlRpcValue raw;
  if (!nh_.getParam(name, raw))
  {
    return false;
  }
  *value = fromXmlRpc(raw);
  return true;
}

double readDouble(const ros::NodeHandle& nh, const std::string& name, double fallback, double low, double high,
                  const std::string& unit, bool low_open)
{
  return readDouble(RosParameterSource(nh), name, fallback, low, high, unit, low_open);
}

int readInt(const ros::NodeHandle& nh, const std::string& name, int fallback, int low, int high)
{
  return readInt(RosParameterSource(nh), name, fallback, low, high);
}

bool readBool(const ros::NodeHandle& nh, const std::string& name, bool fallback)
{
  return readBool(RosParameterSource(nh), name, fallback);
}

std::string readString(const ros::NodeHandle& nh, const std::string& name, const std::string& fallback)
{
  return readString(RosParameterSource(nh), name, fallback);
}

Eigen::VectorXd readVector(const ros::NodeHandle& nh, const std::string& name, const Eigen::VectorXd& fallback)
{
  return readVector(RosParameterSource(nh), name, fallback);
}

std::vector<std::string> readStringList(const ros::NodeHandle& nh, const std::string& name,
                                        const std::vector<std::string>& fallback)
{
  return readStringList(RosParameterSource(nh), name, fallback);
}
}  // namespace god_finger
