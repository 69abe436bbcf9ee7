#pragma once

/// @file
/// Helpers shared by the translation units that bind systems (framework, primitives, perception, planning).

#include <string>

#include <Eigen/Core>
#include <pybind11/pybind11.h>

#include "cairn/systems/framework/context.h"
#include "ownership.h"
#include "cairn/systems/framework/input_port.h"
#include "cairn/systems/framework/output_port.h"
#include "cairn/systems/framework/state.h"
#include "cairn/systems/framework/system.h"

namespace pybind11::detail {
// State holds its abstract values in std::unique_ptr (move-only), although its implicit copy constructor is
// declared; without this pybind11 would instantiate it.
template <>
struct is_copy_constructible<cairn::systems::State> : std::false_type {};
}  // namespace pybind11::detail

namespace cairn::python {

namespace py = pybind11;

/// A Python reference (not owning) to `object`, whose instance dictionary names `owner` (`_cairn_owner`) unless it
/// already names one: how ports, contexts and subsystems returned to Python keep what they point into alive. A
/// dictionary entry, unlike pybind11's keep_alive, is visible to the garbage collector, so a Python system that
/// stores its own ports (self.u = self.DeclareVectorInputPort(...)) does not make an uncollectable cycle.
/// The class of T must be bound with py::dynamic_attr().
template <typename T>
py::object Tied(const T* object, py::handle owner) {
  py::object result = py::cast(object, py::return_value_policy::reference);
  TieToOwner(result, owner);
  return result;
}

/// A method returning `getter()`'s port of a bound system, tied to the system.
template <typename Class, typename Port>
auto PortGetter(const Port& (Class::*getter)() const) {
  return [getter](py::object self) { return Tied(&(self.cast<const Class&>().*getter)(), self); };
}

/// True if `system` is a LeafSystem subclass written in Python.
bool IsPythonSystem(const systems::System& system);

/// Evaluates `port` in `context` with the GIL released (upstream C++ systems may compute for long), then converts
/// the value: a vector port gives a new numpy array; an abstract port gives a copy of its value (or, with
/// copy=False, a read-only view or reference valid while `context_object` lives and until the value is recomputed).
py::object EvalInputPort(const systems::InputPort& port, const systems::Context& context, py::handle context_object,
                         bool copy);
py::object EvalOutputPort(const systems::OutputPort& port, const systems::Context& context, py::handle context_object,
                          bool copy);

/// The value for `port` converted from `object` (a vector for vector ports, the port's type for abstract ones).
std::unique_ptr<systems::AbstractValue> InputValueFromPython(const systems::InputPort& port, py::handle object);

/// Sets the attribute `name` of `object`'s instance dictionary.
void SetInstanceAttribute(py::handle object, const char* name, py::handle value);

/// Converts snake_case-free Python class names ("PdController") to the default system names ("pd_controller").
std::string SnakeCase(const std::string& name);

}  // namespace cairn::python
