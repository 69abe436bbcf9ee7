#pragma once

/// @file
/// Conversions between Python objects and the C++ values that abstract ports, abstract state and abstract
/// parameters carry (systems::AbstractValue).
///
/// Every C++ value type that crosses between Python and C++ systems is registered once, by the submodule that
/// binds it (perception registers images and grids, planning registers terrains and plans, ...), with a name that
/// Python code may use in AbstractValue.Make(value, type=...). Values of unregistered Python types are held as
/// PythonObject. Conversions follow the declared type of the port or state they go into, so a numpy array fixed on
/// a cv::Mat input becomes a cv::Mat, and the same array given to a Python-object port stays an array.

#include <functional>
#include <memory>
#include <string>
#include <typeindex>
#include <vector>

#include <pybind11/pybind11.h>

#include "cairn/systems/framework/abstract_value.h"
#include "cairn/systems/framework/system.h"
#include "cairn/systems/framework/value.h"
#include "python_object.h"

namespace cairn::python {

namespace py = pybind11;

/// How a registered C++ type converts to and from Python.
struct AbstractValueType {
  /// Name used by AbstractValue.Make(value, type=name) and in messages, e.g. "Image" or "OccupancyGrid".
  std::string name;
  /// The C++ type T of Value<T>.
  std::type_index type{typeid(void)};
  /// The bound Python class of T, if T is bound as a class (used to recognise its instances); else empty.
  py::handle python_type;
  /// The value as a Python object: a copy when `copy`, else a view or reference kept valid by `owner`.
  std::function<py::object(const systems::AbstractValue& value, bool copy, py::handle owner)> to_python;
  /// A new Value<T> converted from `object`; throws py::cast_error (or ValueError) when it cannot be converted.
  std::function<std::unique_ptr<systems::AbstractValue>(py::handle object)> from_python;
  /// A ConstantValueSource<T> outputting `value` (a Value<T>).
  std::function<std::unique_ptr<systems::System>(const systems::AbstractValue& value)> make_constant_source;
};

/// Registers `type` (once per C++ type and name; a second registration of either throws std::logic_error).
void RegisterAbstractValueType(AbstractValueType type);

/// The registered types, in registration order.
const std::vector<AbstractValueType>& RegisteredAbstractValueTypes();

/// The registration of C++ type `type`, or nullptr.
const AbstractValueType* FindAbstractValueType(const std::type_info& type);

/// Registers a C++ type that is bound as a pybind11 class: converted with py::cast, recognised by isinstance.
template <typename T>
void RegisterBoundAbstractValueType(const std::string& name);

/// Registers a C++ type that pybind11 converts by value (a type caster: Eigen vectors, strings, numbers, poses as
/// 4x4 arrays); its Python values are not recognised by type, only converted when a port asks for T.
template <typename T>
void RegisterConvertedAbstractValueType(const std::string& name);

/// `value` as a Python object. A PythonObject gives back its object itself; registered types give a copy when
/// `copy`, else a view or reference whose lifetime is tied to `owner`. Throws py::type_error for an unregistered
/// C++ type, naming it.
py::object AbstractValueToPython(const systems::AbstractValue& value, bool copy = true, py::handle owner = {});

/// A new abstract value of the same C++ type as `model` holding `object` converted to that type. `object` may be
/// an AbstractValue of that type, which is copied. `what` names the destination in error messages (e.g.
/// "input port 'u' of system '::plant'"). Throws py::type_error naming both types when no conversion exists.
std::unique_ptr<systems::AbstractValue> AbstractValueFromPython(py::handle object, const systems::AbstractValue& model,
                                                                const std::string& what);

/// Stores `object`, converted to the C++ type of `destination`, in `destination`; throws as AbstractValueFromPython.
void AssignAbstractValueFromPython(py::handle object, systems::AbstractValue* destination, const std::string& what);

/// A new abstract value for `object`: an AbstractValue is copied; with `type_name`, the registered type of that
/// name; otherwise the registered bound class `object` is an instance of, else a PythonObject holding it.
std::unique_ptr<systems::AbstractValue> MakeAbstractValue(py::handle object, const std::string& type_name = "");

/// Converts a Python model value (an AbstractValue, or any object, made into one by MakeAbstractValue).
std::unique_ptr<systems::AbstractValue> ModelValueFromPython(py::handle object);

// -------------------------------------------------------------------------------------------------------------------
// Implementation of the templates.

namespace internal {
template <typename T>
std::unique_ptr<systems::System> MakeConstantValueSource(const systems::AbstractValue& value);
}  // namespace internal

template <typename T>
void RegisterBoundAbstractValueType(const std::string& name) {
  AbstractValueType type;
  type.name = name;
  type.type = std::type_index(typeid(T));
  type.python_type = py::type::of<T>();
  type.to_python = [](const systems::AbstractValue& value, bool copy, py::handle owner) -> py::object {
    const T& held = value.get_value<T>();
    if (copy) return py::cast(held, py::return_value_policy::copy);
    return py::cast(&held, py::return_value_policy::reference_internal, owner);
  };
  type.from_python = [](py::handle object) -> std::unique_ptr<systems::AbstractValue> {
    return std::make_unique<systems::Value<T>>(object.cast<T>());
  };
  type.make_constant_source = &internal::MakeConstantValueSource<T>;
  RegisterAbstractValueType(std::move(type));
}

template <typename T>
void RegisterConvertedAbstractValueType(const std::string& name) {
  AbstractValueType type;
  type.name = name;
  type.type = std::type_index(typeid(T));
  type.to_python = [](const systems::AbstractValue& value, bool, py::handle) -> py::object {
    return py::cast(value.get_value<T>(), py::return_value_policy::copy);
  };
  type.from_python = [](py::handle object) -> std::unique_ptr<systems::AbstractValue> {
    return std::make_unique<systems::Value<T>>(object.cast<T>());
  };
  type.make_constant_source = &internal::MakeConstantValueSource<T>;
  RegisterAbstractValueType(std::move(type));
}

}  // namespace cairn::python

#include "cairn/systems/primitives/constant_value_source.h"

namespace cairn::python::internal {
template <typename T>
std::unique_ptr<systems::System> MakeConstantValueSource(const systems::AbstractValue& value) {
  return std::make_unique<systems::ConstantValueSource<T>>(value.get_value<T>());
}
}  // namespace cairn::python::internal
