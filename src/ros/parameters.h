// Node parameters through the ROS-free readers of support/parameter_source.h: a ParameterSource
// over a node handle, and the same typed readers taking the node handle directly. A bad value
// is an InputError whose one line names the parameter, its value and the allowed range (the
// node then stops with that line).
#pragma once

#include "god_finger/support/parameter_source.h"

#include <ros/node_handle.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace god_finger
{
// The parameters under a node handle's namespace (names relative to it, as NodeHandle takes).
class RosParameterSource : public ParameterSource
{
 public:
  explicit RosParameterSource(ros::NodeHandle nh) : nh_(std::move(nh)) {}
  bool get(const std::string& name, ParameterValue* value) const override;
  std::string fullName(const std::string& name) const override
  {
    return nh_.resolveName(name);
  }

 private:
  ros::NodeHandle nh_;
};

// A number in [low, high] (or (low, high] when low_open).
double readDouble(const ros::NodeHandle& nh, const std::string& name, double fallback, double low, double high,
                  const std::string& unit, bool low_open = false);
int readInt(const ros::NodeHandle& nh, const std::string& name, int fallback, int low, int high);
bool readBool(const ros::NodeHandle& nh, const std::string& name, bool fallback);
std::string readString(const ros::NodeHandle& nh, const std::string& name, const std::string& fallback);
// A list of `size` numbers.
Eigen::VectorXd readVector(const ros::NodeHandle& nh, const std::string& name, const Eigen::VectorXd& fallback);
std::vector<std::string> readStringList(const ros::NodeHandle& nh, const std::string& name,
                                        const std::vector<std::string>& fallback);
}  // namespace god_finger
