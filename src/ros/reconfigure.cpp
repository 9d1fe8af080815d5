#include "god_finger/ros/reconfigure.h"

#include "god_finger/core/input_error.h"

#include <dynamic_reconfigure/Config.h>

namespace god_finger
{
namespace
{
const ParameterRow<WorldParams>* rowNamed(const std::string& name)
{
  for (const ParameterRow<WorldParams>& row : worldParameterTable())
  {
    if (name == row.name)
    {
      return &row;
    }
  }
  return nullptr;
}
}  // namespace

god_finger::GodFingerConfig configOf(const WorldParams& params)
{
  // Every entry of the cfg is a row of the world's table (parameter_tables_test checks it):
  // each takes the row's value in `params`.
  dynamic_reconfigure::Config message;
  god_finger::GodFingerConfig::__getDefault__().__toMessage__(message);
  for (dynamic_reconfigure::DoubleParameter& entry : message.doubles)
  {
    if (const ParameterRow<WorldParams>* row = rowNamed(entry.name))
    {
      entry.value = row->number(params);
    }
  }
  for (dynamic_reconfigure::IntParameter& entry : message.ints)
  {
    if (const ParameterRow<WorldParams>* row = rowNamed(entry.name))
    {
      entry.value = static_cast<int>(row->number(params));
    }
  }
  for (dynamic_reconfigure::StrParameter& entry : message.strs)
  {
    if (const ParameterRow<WorldParams>* row = rowNamed(entry.name))
    {
      entry.value = row->valueText(params);
    }
  }
  god_finger::GodFingerConfig config;
  config.__fromMessage__(message);
  return config;
}

bool worldFromConfig(const god_finger::GodFingerConfig& config, const WorldParams& base, WorldParams* params,
                     std::string* error)
{
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  MapParameterSource source("reconfigure: ");
  for (const dynamic_reconfigure::DoubleParameter& entry : message.doubles)
  {
    source.set(entry.name, ParameterValue::of(entry.value));
  }
  for (const dynamic_reconfigure::IntParameter& entry : message.ints)
  {
    source.set(entry.name, ParameterValue::ofInteger(entry.value));
  }
  for (const dynamic_reconfigure::StrParameter& entry : message.strs)
  {
    source.set(entry.name, ParameterValue::of(entry.value));
  }
  for (const dynamic_reconfigure::BoolParameter& entry : message.bools)
  {
    source.set(entry.name, ParameterValue::of(static_cast<bool>(entry.value)));
  }
  *params = base;
  try
  {
    readRows(source, worldParameterTable(), params);
  }
  catch (const InputError& bad)
  {
    *error = bad.what();
    return false;
  }
  *error = validate(*params);
  return error->empty();
}
}  // namespace god_finger
