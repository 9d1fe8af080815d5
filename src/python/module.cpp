// god_finger._core: see bindings.h. Python imports it through the package god_finger.
#include "bindings.h"

#include "god_finger/physics/god_finger_world.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/memory_budget.h"

namespace god_finger::python
{
void bindErrors(py::module_& module)
{
  // Translators run newest first: the subclasses after InputError.
  static py::exception<InputError> error(module, "Error", PyExc_ValueError);
  error.doc() =
      "A bad file, parameter or argument (a subclass of ValueError), with the C++ message: one line naming the\n"
      "file, body or parameter and the problem. The world it came from is unchanged.";
  static py::exception<ProxyInsideBodyError> inside(module, "ProxyInsideBodyError", error.ptr());
  inside.doc() =
      "A finger added inside a body (its message names the body and the position); "
      "add_finger(..., allow_inside=True) allows it.";
  static py::exception<ResourceLimitError> limit(module, "ResourceLimitError", error.ptr());
  limit.doc() = "A file too large for the memory left (its message names the file, the count and the limit).";
  py::register_exception_translator(
      [](std::exception_ptr pointer)
      {
        try
        {
          if (pointer)
          {
            std::rethrow_exception(pointer);
          }
        }
        catch (const ProxyInsideBodyError& e)
        {
          PyErr_SetString(inside.ptr(), e.what());
        }
        catch (const ResourceLimitError& e)
        {
          PyErr_SetString(limit.ptr(), e.what());
        }
        catch (const InputError& e)
        {
          PyErr_SetString(error.ptr(), e.what());
        }
      });
}
}  // namespace god_finger::python

PYBIND11_MODULE(_core, module)
{
  module.doc() =
      "god_finger's compiled core: the god-finger method (Bullet world, god-object proxies, god-finger\n"
      "contact areas) without ROS. Import the package god_finger, not this module.";
  god_finger::python::initNumpy();
  god_finger::python::bindErrors(module);
  god_finger::python::bindContact(module);
  god_finger::python::bindWorld(module);
  god_finger::python::bindExperiment(module);
}
