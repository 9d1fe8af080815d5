#include "bindings.h"

#include "god_finger/support/input_error.h"

#include <cmath>
#include <pybind11/numpy.h>

namespace god_finger::python
{
namespace
{
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string shapeText(const Array& array)
{
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i)
  {
    text += (i > 0 ? ", " : "") + std::to_string(array.shape(i));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

Array numbers(const py::handle& value, const std::string& what, py::ssize_t count)
{
  Array array;
  try
  {
    array = Array::ensure(value);
  }
  catch (const py::error_already_set&)
  {
  }
  if (!array)
  {
    PyErr_Clear();
    throw InputError(what + " must be " + std::to_string(count) + " numbers, not " +
                     std::string(py::str(py::type::of(value).attr("__name__"))));
  }
  if (array.ndim() != 1 || array.shape(0) != count)
  {
    throw InputError(what + " must be " + std::to_string(count) + " numbers, shape (" + std::to_string(count) +
                     ",), not shape " + shapeText(array));
  }
  for (py::ssize_t i = 0; i < count; ++i)
  {
    if (!std::isfinite(array.at(i)))
    {
      throw InputError(what + " must be finite, not " + std::string(py::str(value)));
    }
  }
  return array;
}
}  // namespace

Eigen::Vector3d vector3(const py::handle& value, const std::string& what)
{
  const Array array = numbers(value, what, 3);
  return Eigen::Vector3d(array.at(0), array.at(1), array.at(2));
}

Eigen::Quaterniond quaternion(const py::handle& value, const std::string& what)
{
  const Array array = numbers(value, what + " (x, y, z, w)", 4);
  Eigen::Quaterniond q(array.at(3), array.at(0), array.at(1), array.at(2));
  const double norm = q.norm();
  if (norm < 0.5 || norm > 2.0)
  {
    throw InputError(what + " (x, y, z, w) must be a unit quaternion, its norm is " + std::to_string(norm));
  }
  return q;  // the world normalises it, as it does the C++ caller's
}

py::object quaternionArray(const Eigen::Quaterniond& q)
{
  Array array(4);
  array.mutable_at(0) = q.x();
  array.mutable_at(1) = q.y();
  array.mutable_at(2) = q.z();
  array.mutable_at(3) = q.w();
  return std::move(array);
}

namespace
{
ParameterValue parameterValue(const py::handle& value, const std::string& name)
{
  if (py::isinstance<py::bool_>(value))
  {
    return ParameterValue::of(value.cast<bool>());
  }
  if (py::isinstance<py::int_>(value))
  {
    return ParameterValue::ofInteger(value.cast<int>());
  }
  if (py::isinstance<py::float_>(value))
  {
    return ParameterValue::of(value.cast<double>());
  }
  if (py::isinstance<py::str>(value))
  {
    return ParameterValue::of(value.cast<std::string>());
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value))
  {
    ParameterValue list;
    list.kind = ParameterValue::Kind::kList;
    for (const py::handle item : value)
    {
      list.items.push_back(parameterValue(item, name));
    }
    return list;
  }
  // numpy scalars and anything else that is a number.
  try
  {
    return ParameterValue::of(value.cast<double>());
  }
  catch (const py::cast_error&)
  {
    throw InputError("parameter '" + name + "' = " + std::string(py::repr(value)) + " is not a number or text");
  }
}
}  // namespace

MapParameterSource parameterSource(const py::dict& kwargs, const std::set<std::string>& known,
                                   const std::string& owner)
{
  MapParameterSource source;
  for (const auto& item : kwargs)
  {
    const std::string name = py::str(item.first);
    if (known.count(name) == 0)
    {
      std::string names;
      for (const std::string& candidate : known)
      {
        names += (names.empty() ? "" : ", ") + candidate;
      }
      throw InputError("unknown parameter '" + name + "' (" + owner + ": " + names + ")");
    }
    source.set(name, parameterValue(item.second, name));
  }
  return source;
}
}  // namespace god_finger::python
