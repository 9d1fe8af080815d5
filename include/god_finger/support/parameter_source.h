// Where parameters come from, without ROS: the ROS layer reads its parameter server through
// it, the servo loop, the device registry and the tools read a plain map. The typed readers
// below are the one place that checks a parameter's type, unit and range: a bad value is an
// InputError whose one line names the parameter (its full name), its value and the range.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

namespace god_finger
{
// A parameter's value as a tree (the XML-RPC types a parameter server holds).
struct ParameterValue
{
  enum class Kind
  {
    kBool,
    kInteger,
    kNumber,
    kString,
    kList,
  };
  Kind kind = Kind::kNumber;
  bool boolean = false;
  double number = 0.0;  // also set for kInteger
  std::string text;
  std::vector<ParameterValue> items;

  static ParameterValue of(double value);
  static ParameterValue ofInteger(int value);
  static ParameterValue of(bool value);
  static ParameterValue of(const std::string& value);
  static ParameterValue of(const std::vector<double>& values);
  static ParameterValue of(const std::vector<std::string>& values);
};

class ParameterSource
{
 public:
  virtual ~ParameterSource() = default;
  // False when the parameter is not set.
  virtual bool get(const std::string& name, ParameterValue* value) const = 0;
  // The name shown in messages (a ROS source resolves it: "/finger/device_driver/rate").
  virtual std::string fullName(const std::string& name) const = 0;
};

// Plain values by name (tools, tests, the offline servo loop); `prefix` is put before names in
// messages.
class MapParameterSource : public ParameterSource
{
 public:
  explicit MapParameterSource(std::string prefix = "") : prefix_(std::move(prefix)) {}
  void set(const std::string& name, const ParameterValue& value)
  {
    values_[name] = value;
  }
  bool get(const std::string& name, ParameterValue* value) const override;
  std::string fullName(const std::string& name) const override
  {
    return prefix_ + name;
  }

 private:
  std::string prefix_;
  std::map<std::string, ParameterValue> values_;
};

// `first`'s parameters, and `second`'s where `first` has none (a node's private parameters
// over its interface's). Both must outlive it.
class LayeredParameterSource : public ParameterSource
{
 public:
  LayeredParameterSource(const ParameterSource& first, const ParameterSource& second) : first_(first), second_(second)
  {
  }
  bool get(const std::string& name, ParameterValue* value) const override
  {
    return first_.get(name, value) || second_.get(name, value);
  }
  // The name where the value was found; the first's when it is set nowhere (where a value
  // given now would be read, whatever the second holds).
  std::string fullName(const std::string& name) const override
  {
    ParameterValue unused;
    return !first_.get(name, &unused) && second_.get(name, &unused) ? second_.fullName(name) : first_.fullName(name);
  }

 private:
  const ParameterSource& first_;
  const ParameterSource& second_;
};

// A number in [low, high] (or (low, high] when low_open); `fallback` when not set.
double readDouble(const ParameterSource& source, const std::string& name, double fallback, double low, double high,
                  const std::string& unit, bool low_open = false);
int readInt(const ParameterSource& source, const std::string& name, int fallback, int low, int high);
bool readBool(const ParameterSource& source, const std::string& name, bool fallback);
std::string readString(const ParameterSource& source, const std::string& name, const std::string& fallback);
// A list of fallback.size() finite numbers.
Eigen::VectorXd readVector(const ParameterSource& source, const std::string& name, const Eigen::VectorXd& fallback);
std::vector<std::string> readStringList(const ParameterSource& source, const std::string& name,
                                        const std::vector<std::string>& fallback);
// A non-empty list of rows of `columns` numbers each (e.g. [t, x, y, z] waypoints); false when
// not set.
bool readTable(const ParameterSource& source, const std::string& name, int columns, const std::string& what,
               std::vector<std::vector<double>>* rows);
}  // namespace god_finger
