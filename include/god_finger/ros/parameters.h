// Reading node parameters with a unit, a default and a range, checked at start-up: a bad
// value is an InputError whose one line names the parameter, its value and the allowed range
// (the node then stops with that line).
#pragma once

#include <ros/node_handle.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace god_finger
{
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
