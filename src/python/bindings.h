// The Python module god_finger._core (pybind11), the compiled half of the package god_finger
// (python/god_finger/__init__.py): the world, the contact area on a mesh, the evaluation. One
// file per part; this header holds what they share: the conversions of Python values (any
// sequence or numpy array) to Eigen and of keyword arguments to a parameter source, so that a
// parameter read from Python is read by the same table rows, ranges and messages as from ROS
// or the command line (support/parameter_table.h).
//
// Errors: every InputError (a bad file, parameter, argument) reaches Python as god_finger.Error,
// a subclass of ValueError, with the C++ message. Units SI, frames as the C++ headers say;
// quaternions are (x, y, z, w), PyBullet's order. None of this is real-time safe.
#pragma once

#include "god_finger/support/input_error.h"
#include "god_finger/support/parameter_table.h"

#include <pybind11/pybind11.h>
#include <Eigen/Geometry>
#include <set>
#include <string>

namespace god_finger::python
{
namespace py = pybind11;

void bindErrors(py::module_& module);
void bindContact(py::module_& module);
void bindWorld(py::module_& module);
void bindExperiment(py::module_& module);

// `value` as three numbers (a sequence or array of shape (3,)); InputError naming `what` and
// the shape otherwise, or when a number is not finite.
Eigen::Vector3d vector3(const py::handle& value, const std::string& what);
// A unit quaternion from (x, y, z, w): InputError on a shape other than (4,), a non-finite
// number or a norm outside [0.5, 2] (the world's own bounds); the world normalises it.
Eigen::Quaterniond quaternion(const py::handle& value, const std::string& what);
// numpy's C API for array3 (the module's init calls it once).
void initNumpy();
// A copy of `v` as a numpy array of shape (3,).
py::object array3(const Eigen::Vector3d& v);
// (x, y, z, w) as a numpy array.
py::object quaternionArray(const Eigen::Quaterniond& q);

// `value` as a T (`kind` names it: "a number", "an integer", "text"); InputError naming `what` when
// it is not one or does not fit (an integer beyond int's range).
template <typename T>
T argument(const py::handle& value, const std::string& what, const char* kind)
{
  try
  {
    return value.cast<T>();
  }
  catch (const py::cast_error&)
  {
    throw InputError(what + " must be " + kind + ", not " + std::string(py::repr(value)));
  }
}

// InputError listing `known` (whose they are: `owner`) when a key of `kwargs` is not among them.
void checkNames(const py::dict& kwargs, const std::set<std::string>& known, const std::string& owner);
// Keyword arguments as a parameter source (a bool, int, float, str or list each); every name
// must be in `known` (InputError listing them otherwise, with `owner` saying whose they are).
MapParameterSource parameterSource(const py::dict& kwargs, const std::set<std::string>& known,
                                   const std::string& owner);
// The names of a table's rows.
template <typename Table>
std::set<std::string> rowNames(const Table& table)
{
  std::set<std::string> names;
  for (const auto& row : table)
  {
    names.insert(row.name);
  }
  return names;
}
// A table's values as a dict: numbers as float, integers as int, choices as str.
template <typename Table, typename Params>
py::dict rowValues(const Table& table, const Params& params)
{
  py::dict values;
  for (const auto& row : table)
  {
    const ParameterValue value = valueOf(row, params);
    if (value.kind == ParameterValue::Kind::kString)
    {
      values[row.name] = value.text;
    }
    else if (value.kind == ParameterValue::Kind::kInteger)
    {
      values[row.name] = static_cast<long>(value.number);
    }
    else
    {
      values[row.name] = value.number;
    }
  }
  return values;
}
}  // namespace god_finger::python
