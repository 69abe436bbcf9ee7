#pragma once

/// @file
/// Python objects held by C++ code that may run without the GIL (solvers, simulations, planners).

#include <memory>
#include <utility>

#include <pybind11/pybind11.h>

namespace cairn::python {

namespace py = pybind11;

/// A reference to a Python object that C++ code may copy, share and destroy from any thread, with or without the
/// GIL: copies share one reference count (a std::shared_ptr), and the last owner takes the GIL to release the
/// object. Callables that C++ stores (evaluator functions, FunctionSystem functions) are held this way, because the
/// solvers and the simulator copy and drop their std::function objects inside calls that released the GIL.
class SharedPyObject {
 public:
  SharedPyObject() = default;
  /// Takes a new reference to `object`; the GIL must be held.
  explicit SharedPyObject(py::object object)
      : object_(new py::object(std::move(object)), [](py::object* held) {
          if (Py_IsInitialized() == 0) {
            // The interpreter is gone (process exit): the object's memory went with it.
            held->release();
            delete held;
            return;
          }
          py::gil_scoped_acquire gil;
          delete held;
        }) {}

  /// The object; the GIL must be held to use it.
  const py::object& get() const { return *object_; }
  explicit operator bool() const { return object_ != nullptr && static_cast<bool>(*object_); }

 private:
  std::shared_ptr<py::object> object_;
};

/// The C++ type of abstract values (ports, state, parameters) holding an arbitrary Python object.
///
/// Copies are deep (copy.deepcopy), as a context's values must be independent: an unrestricted update writes the
/// next state into a copy of the current one, and Context.Clone() must not share mutable state with the original.
/// Copying and destroying take the GIL, so the simulator may copy these values in calls that released it.
class PythonObject {
 public:
  PythonObject();
  explicit PythonObject(py::object object);
  PythonObject(const PythonObject& other);
  PythonObject(PythonObject&& other) noexcept;
  PythonObject& operator=(const PythonObject& other);
  PythonObject& operator=(PythonObject&& other) noexcept;
  ~PythonObject();

  /// The held object (a reference, not a copy); the GIL must be held.
  const py::object& get() const { return object_; }
  /// Replaces the held object; the GIL must be held.
  void set(py::object object) { object_ = std::move(object); }

 private:
  py::object object_;
};

}  // namespace cairn::python
