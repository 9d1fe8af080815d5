#include "god_finger/support/parameter_source.h"

#include "god_finger/support/input_error.h"

#include <cmath>
#include <sstream>

namespace god_finger
{
namespace
{
[[noreturn]] void notA(const ParameterSource& source, const std::string& name, const std::string& what)
{
  throw InputError("parameter '" + source.fullName(name) + "' must be " + what);
}

bool isNumber(const ParameterValue& value)
{
  return value.kind == ParameterValue::Kind::kNumber || value.kind == ParameterValue::Kind::kInteger;
}
}  // namespace

ParameterValue ParameterValue::of(double value)
{
  ParameterValue result;
  result.number = value;
  return result;
}

ParameterValue ParameterValue::ofInteger(int value)
{
  ParameterValue result;
  result.kind = Kind::kInteger;
  result.number = value;
  return result;
}

ParameterValue ParameterValue::of(bool value)
{
  ParameterValue result;
  result.kind = Kind::kBool;
  result.boolean = value;
  return result;
}

ParameterValue ParameterValue::of(const std::string& value)
{
  ParameterValue result;
  result.kind = Kind::kString;
  result.text = value;
  return result;
}

ParameterValue ParameterValue::of(const std::vector<double>& values)
{
  ParameterValue result;
  result.kind = Kind::kList;
  for (double value : values)
  {
    result.items.push_back(of(value));
  }
  return result;
}

ParameterValue ParameterValue::of(const std::vector<std::string>& values)
{
  ParameterValue result;
  result.kind = Kind::kList;
  for (const std::string& value : values)
  {
    result.items.push_back(of(value));
  }
  return result;
}

bool MapParameterSource::get(const std::string& name, ParameterValue* value) const
{
  const auto found = values_.find(name);
  if (found == values_.end())
  {
    return false;
  }
  *value = found->second;
  return true;
}

double readDouble(const ParameterSource& source, const std::string& name, double fallback, double low, double high,
                  const std::string& unit, bool low_open)
{
  ParameterValue value;
  double number = fallback;
  if (source.get(name, &value))
  {
    if (!isNumber(value))
    {
      notA(source, name, "a number (" + unit + ")");
    }
    number = value.number;
  }
  const bool low_ok = low_open ? number > low : number >= low;
  if (!(low_ok && number <= high))
  {
    std::ostringstream message;
    message << "parameter '" << source.fullName(name) << "' = " << number << " is out of range "
            << (low_open ? "(" : "[") << low << ", " << high << "] (" << unit << ")";
    throw InputError(message.str());
  }
  return number;
}

int readInt(const ParameterSource& source, const std::string& name, int fallback, int low, int high)
{
  ParameterValue value;
  int number = fallback;
  if (source.get(name, &value))
  {
    if (value.kind != ParameterValue::Kind::kInteger)
    {
      notA(source, name, "an integer");
    }
    number = static_cast<int>(value.number);
  }
  if (number < low || number > high)
  {
    std::ostringstream message;
    message << "parameter '" << source.fullName(name) << "' = " << number << " is out of range [" << low << ", " << high
            << "] (count)";
    throw InputError(message.str());
  }
  return number;
}

bool readBool(const ParameterSource& source, const std::string& name, bool fallback)
{
  ParameterValue value;
  if (!source.get(name, &value))
  {
    return fallback;
  }
  if (value.kind != ParameterValue::Kind::kBool)
  {
    notA(source, name, "true or false");
  }
  return value.boolean;
}

std::string readString(const ParameterSource& source, const std::string& name, const std::string& fallback)
{
  ParameterValue value;
  if (!source.get(name, &value))
  {
    return fallback;
  }
  if (value.kind != ParameterValue::Kind::kString)
  {
    notA(source, name, "a string");
  }
  return value.text;
}

Eigen::VectorXd readVector(const ParameterSource& source, const std::string& name, const Eigen::VectorXd& fallback)
{
  ParameterValue value;
  if (!source.get(name, &value))
  {
    return fallback;
  }
  const std::string what = "a list of " + std::to_string(fallback.size()) + " numbers";
  if (value.kind != ParameterValue::Kind::kList || static_cast<Eigen::Index>(value.items.size()) != fallback.size())
  {
    notA(source, name, what);
  }
  Eigen::VectorXd result(fallback.size());
  for (std::size_t i = 0; i < value.items.size(); ++i)
  {
    if (!isNumber(value.items[i]) || !std::isfinite(value.items[i].number))
    {
      notA(source, name, what + " (finite)");
    }
    result[static_cast<Eigen::Index>(i)] = value.items[i].number;
  }
  return result;
}

std::vector<std::string> readStringList(const ParameterSource& source, const std::string& name,
                                        const std::vector<std::string>& fallback)
{
  ParameterValue value;
  if (!source.get(name, &value))
  {
    return fallback;
  }
  if (value.kind != ParameterValue::Kind::kList || value.items.empty())
  {
    notA(source, name, "a non-empty list of names");
  }
  std::vector<std::string> result;
  for (const ParameterValue& item : value.items)
  {
    if (item.kind != ParameterValue::Kind::kString || item.text.empty())
    {
      notA(source, name, "a non-empty list of names");
    }
    result.push_back(item.text);
  }
  return result;
}

bool readTable(const ParameterSource& source, const std::string& name, int columns, const std::string& what,
               std::vector<std::vector<double>>* rows)
{
  ParameterValue value;
  if (!source.get(name, &value))
  {
    return false;
  }
  if (value.kind != ParameterValue::Kind::kList || value.items.empty())
  {
    notA(source, name, what);
  }
  rows->clear();
  for (std::size_t i = 0; i < value.items.size(); ++i)
  {
    const ParameterValue& row = value.items[i];
    if (row.kind != ParameterValue::Kind::kList || static_cast<int>(row.items.size()) != columns)
    {
      notA(source, name, what + " (row " + std::to_string(i) + ")");
    }
    std::vector<double> numbers;
    for (const ParameterValue& item : row.items)
    {
      if (!isNumber(item))
      {
        notA(source, name, what + " (row " + std::to_string(i) + ")");
      }
      numbers.push_back(item.number);
    }
    rows->push_back(numbers);
  }
  return true;
}
}  // namespace god_finger
