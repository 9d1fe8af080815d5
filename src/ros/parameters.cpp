#include "god_finger/ros/parameters.h"

#include "god_finger/core/input_error.h"

#include <XmlRpcValue.h>

#include <cmath>
#include <sstream>

namespace god_finger
{
namespace
{
std::string fullName(const ros::NodeHandle& nh, const std::string& name)
{
  return nh.resolveName(name);
}

bool toNumber(const XmlRpc::XmlRpcValue& value, double* number)
{
  if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble)
  {
    *number = static_cast<double>(const_cast<XmlRpc::XmlRpcValue&>(value));
    return true;
  }
  if (value.getType() == XmlRpc::XmlRpcValue::TypeInt)
  {
    *number = static_cast<int>(const_cast<XmlRpc::XmlRpcValue&>(value));
    return true;
  }
  return false;
}

[[noreturn]] void notA(const ros::NodeHandle& nh, const std::string& name, const std::string& what)
{
  throw InputError("parameter '" + fullName(nh, name) + "' must be " + what);
}
}  // namespace

double readDouble(const ros::NodeHandle& nh, const std::string& name, double fallback, double low, double high,
                  const std::string& unit, bool low_open)
{
  XmlRpc::XmlRpcValue value;
  double number = fallback;
  if (nh.getParam(name, value) && !toNumber(value, &number))
  {
    notA(nh, name, "a number (" + unit + ")");
  }
  const bool low_ok = low_open ? number > low : number >= low;
  if (!(low_ok && number <= high))
  {
    std::ostringstream message;
    message << "parameter '" << fullName(nh, name) << "' = " << number << " is out of range " << (low_open ? "(" : "[")
            << low << ", " << high << "] (" << unit << ")";
    throw InputError(message.str());
  }
  return number;
}

int readInt(const ros::NodeHandle& nh, const std::string& name, int fallback, int low, int high)
{
  XmlRpc::XmlRpcValue value;
  int number = fallback;
  if (nh.getParam(name, value))
  {
    if (value.getType() != XmlRpc::XmlRpcValue::TypeInt)
    {
      notA(nh, name, "an integer");
    }
    number = static_cast<int>(value);
  }
  if (number < low || number > high)
  {
    std::ostringstream message;
    message << "parameter '" << fullName(nh, name) << "' = " << number << " is out of range [" << low << ", " << high
            << "] (count)";
    throw InputError(message.str());
  }
  return number;
}

bool readBool(const ros::NodeHandle& nh, const std::string& name, bool fallback)
{
  XmlRpc::XmlRpcValue value;
  if (!nh.getParam(name, value))
  {
    return fallback;
  }
  if (value.getType() != XmlRpc::XmlRpcValue::TypeBoolean)
  {
    notA(nh, name, "true or false");
  }
  return static_cast<bool>(value);
}

std::string readString(const ros::NodeHandle& nh, const std::string& name, const std::string& fallback)
{
  XmlRpc::XmlRpcValue value;
  if (!nh.getParam(name, value))
  {
    return fallback;
  }
  if (value.getType() != XmlRpc::XmlRpcValue::TypeString)
  {
    notA(nh, name, "a string");
  }
  return static_cast<std::string>(value);
}

Eigen::VectorXd readVector(const ros::NodeHandle& nh, const std::string& name, const Eigen::VectorXd& fallback)
{
  XmlRpc::XmlRpcValue value;
  if (!nh.getParam(name, value))
  {
    return fallback;
  }
  const std::string what = "a list of " + std::to_string(fallback.size()) + " numbers";
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray || value.size() != fallback.size())
  {
    notA(nh, name, what);
  }
  Eigen::VectorXd result(fallback.size());
  for (int i = 0; i < value.size(); ++i)
  {
    if (!toNumber(value[i], &result[i]) || !std::isfinite(result[i]))
    {
      notA(nh, name, what + " (finite)");
    }
  }
  return result;
}

std::vector<std::string> readStringList(const ros::NodeHandle& nh, const std::string& name,
                                        const std::vector<std::string>& fallback)
{
  XmlRpc::XmlRpcValue value;
  if (!nh.getParam(name, value))
  {
    return fallback;
  }
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray || value.size() == 0)
  {
    notA(nh, name, "a non-empty list of names");
  }
  std::vector<std::string> result;
  for (int i = 0; i < value.size(); ++i)
  {
    if (value[i].getType() != XmlRpc::XmlRpcValue::TypeString || static_cast<std::string>(value[i]).empty())
    {
      notA(nh, name, "a non-empty list of names");
    }
    result.push_back(static_cast<std::string>(value[i]));
  }
  return result;
}
}  // namespace god_finger
