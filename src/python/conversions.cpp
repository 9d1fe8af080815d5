#include "bindings.h"

#include "god_finger/support/input_error.h"

#include <pybind11/numpy.h>
#include <cmath>
#include <cstring>

// numpy's C API, in this file only (its table is static here; initNumpy fills it): a vector of
// three as an array costs a tenth of a microsecond this way, a third through pybind11's.
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>

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
  const Array array = Array::ensure(value);  // null (and a Python error set) when not numbers
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

void initNumpy()
{
  if (_import_array() < 0)
  {
    throw py::error_already_set();
  }
}

py::object array3(const Eigen::Vector3d& v)
{
  npy_intp size = 3;
  PyObject* array = PyArray_SimpleNew(1, &size, NPY_DOUBLE);
  if (array == nullptr)
  {
    throw py::error_already_set();
  }
  std::memcpy(PyArray_DATA(reinterpret_cast<PyArrayObject*>(array)), v.data(), sizeof(double) * 3);
  return py::reinterpret_steal<py::object>(array);
}

Eigen::Vector3d vector3(const py::handle& value, const std::string& what)
{
  // An array of three float64 (what numpy code passes): read in place.
  if (PyArray_Check(value.ptr()))
  {
    PyArrayObject* array = reinterpret_cast<PyArrayObject*>(value.ptr());
    if (PyArray_NDIM(array) == 1 && PyArray_DIM(array, 0) == 3 && PyArray_TYPE(array) == NPY_DOUBLE &&
        PyArray_IS_C_CONTIGUOUS(array))
    {
      Eigen::Vector3d vector;
      std::memcpy(vector.data(), PyArray_DATA(array), sizeof(double) * 3);
      if (vector.allFinite())
      {
        return vector;
      }
    }
  }
  // A list or tuple of three Python numbers (what a loop that sets targets passes): read
  // directly, without making an array (a third of a microsecond).
  if (PyList_CheckExact(value.ptr()) || PyTuple_CheckExact(value.ptr()))
  {
    PyObject* const* items = PySequence_Fast_ITEMS(value.ptr());
    if (PySequence_Fast_GET_SIZE(value.ptr()) == 3 && PyFloat_CheckExact(items[0]) && PyFloat_CheckExact(items[1]) &&
        PyFloat_CheckExact(items[2]))
    {
      const Eigen::Vector3d vector(PyFloat_AS_DOUBLE(items[0]), PyFloat_AS_DOUBLE(items[1]),
                                   PyFloat_AS_DOUBLE(items[2]));
      if (vector.allFinite())
      {
        return vector;
      }
    }
  }
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
    return ParameterValue::of(argument<bool>(value, "parameter '" + name + "'", "true or false"));
  }
  if (py::isinstance<py::int_>(value))
  {
    return ParameterValue::ofInteger(argument<int>(value, "parameter '" + name + "'", "an integer within int's range"));
  }
  if (py::isinstance<py::float_>(value))
  {
    return ParameterValue::of(argument<double>(value, "parameter '" + name + "'", "a number"));
  }
  if (py::isinstance<py::str>(value))
  {
    return ParameterValue::of(argument<std::string>(value, "parameter '" + name + "'", "text"));
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

void checkNames(const py::dict& kwargs, const std::set<std::string>& known, const std::string& owner)
{
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
  }
}

MapParameterSource parameterSource(const py::dict& kwargs, const std::set<std::string>& known, const std::string& owner)
{
  checkNames(kwargs, known, owner);
  MapParameterSource source;
  for (const auto& item : kwargs)
  {
    const std::string name = py::str(item.first);
    source.set(name, parameterValue(item.second, name));
  }
  return source;
}
}  // namespace god_finger::python
