// cairn.systems: System, Context, ports, abstract values, Diagram and DiagramBuilder.

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "abstract_values.h"
#include "bindings.h"
#include "cairn/common/number_text.h"
#include "cairn/systems/framework/context.h"
#include "cairn/systems/framework/dependency_ticket.h"
#include "cairn/systems/framework/diagram.h"
#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/framework/discrete_values.h"
#include "cairn/systems/framework/input_port.h"
#include "cairn/systems/framework/output_port.h"
#include "cairn/systems/framework/state.h"
#include "cairn/systems/framework/system.h"
#include "numpy_support.h"
#include "ownership.h"
#include "system_support.h"

namespace cairn::python {

using namespace cairn::systems;

// ---------------------------------------------------------------------------------------------------------------
// Shared helpers (system_support.h)

namespace {

py::object PortValueToPython(const AbstractValue& value, bool is_vector, py::handle owner, bool copy) {
  if (is_vector) {
    const auto& vector = value.get_value<Eigen::VectorXd>();
    if (copy) return py::cast(vector);  // A new array (pybind11 copies a const lvalue Eigen object).
    return EigenView(vector, owner);
  }
  return AbstractValueToPython(value, copy, owner);
}

}  // namespace

py::object EvalInputPort(const InputPort& port, const Context& context, py::handle context_object, bool copy) {
  const AbstractValue* value = nullptr;
  {
    py::gil_scoped_release release;
    value = &port.EvalAbstract(context);
  }
  return PortValueToPython(*value, port.get_data_type() == PortDataType::kVector, context_object, copy);
}

py::object EvalOutputPort(const OutputPort& port, const Context& context, py::handle context_object, bool copy) {
  const AbstractValue* value = nullptr;
  {
    py::gil_scoped_release release;
    value = &port.EvalAbstract(context);
  }
  return PortValueToPython(*value, port.get_data_type() == PortDataType::kVector, context_object, copy);
}

std::unique_ptr<AbstractValue> InputValueFromPython(const InputPort& port, py::handle object) {
  if (port.get_data_type() == PortDataType::kVector && !py::isinstance<AbstractValue>(object)) {
    Eigen::VectorXd vector;
    try {
      vector = object.cast<Eigen::VectorXd>();
    } catch (const py::cast_error&) {
      throw py::type_error(port.GetFullDescription() + " takes a vector of size " + cairn::FormatShort(port.size()) +
                           "; a " + std::string(py::str(py::type::handle_of(object).attr("__name__"))) +
                           " cannot be converted to one");
    }
    return std::make_unique<Value<Eigen::VectorXd>>(std::move(vector));
  }
  return AbstractValueFromPython(object, port.model_value(), port.GetFullDescription());
}

void SetInstanceAttribute(py::handle object, const char* name, py::handle value) {
  PyObject** dict = _PyObject_GetDictPtr(object.ptr());
  if (dict == nullptr) throw std::logic_error("cairn: object without an instance dictionary");
  if (*dict == nullptr) *dict = PyDict_New();
  PyDict_SetItemString(*dict, name, value.ptr());
}

std::string SnakeCase(const std::string& name) {
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if (c >= 'A' && c <= 'Z') {
      const bool after_lower = i > 0 && ((name[i - 1] >= 'a' && name[i - 1] <= 'z') ||
                                         (name[i - 1] >= '0' && name[i - 1] <= '9'));
      const bool before_lower = i + 1 < name.size() && name[i + 1] >= 'a' && name[i + 1] <= 'z';
      if (!out.empty() && out.back() != '_' && (after_lower || (before_lower && i > 0))) out += '_';
      out += static_cast<char>(c - 'A' + 'a');
    } else {
      out += c;
    }
  }
  return out.empty() ? "system" : out;
}

namespace {

// A default name for a Python-written system, unique among the builder's systems: the snake_case class name, then
// _2, _3, ... (C++ systems get theirs from DiagramBuilder, which would name every Python one "py_leaf_system").
void NamePythonSystem(const DiagramBuilder& builder, py::handle object, System* system) {
  if (!system->get_name().empty() || !IsPythonSystem(*system)) return;
  const std::string base = SnakeCase(py::str(py::type::handle_of(object).attr("__name__")));
  std::set<std::string> taken;
  for (const System* existing : builder.GetSystems()) taken.insert(existing->get_name());
  std::string name = base;
  for (int k = 2; taken.count(name) != 0; ++k) name = base + "_" + cairn::FormatShort(k);
  system->set_name(name);
}

py::object AddSystemToBuilder(py::object builder_object, py::object system_object, const std::string& name) {
  auto& builder = builder_object.cast<DiagramBuilder&>();
  if (!GetInstanceAttribute(builder_object, "_cairn_built").is_none()) {
    throw std::logic_error("DiagramBuilder::AddSystem() after Build(): a builder makes one diagram; use a new "
                           "DiagramBuilder.");
  }
  auto* system = system_object.cast<System*>();
  if (!name.empty()) system->set_name(name);
  NamePythonSystem(builder, system_object, system);
  builder.AddSystem(ReleaseFromPython<System>(system_object, "DiagramBuilder.AddSystem"));
  Adopt(builder_object, system_object);
  return system_object;
}

py::object BuildDiagram(py::object builder_object) {
  auto& builder = builder_object.cast<DiagramBuilder&>();
  std::unique_ptr<Diagram> diagram = builder.Build();
  py::object diagram_object = py::cast(std::move(diagram));
  TransferAdopted(builder_object, diagram_object);
  SetInstanceAttribute(builder_object, "_cairn_built", diagram_object);
  return diagram_object;
}

py::list WrapSystems(const std::vector<const System*>& systems, py::handle owner) {
  py::list out;
  for (const System* system : systems) {
    out.append(Tied(system, owner));
  }
  return out;
}

template <typename Index>
void CheckIndex(Index index, Index count, const char* what) {
  if (index < 0 || index >= count) {
    throw py::index_error(std::string(what) + " " + cairn::FormatShort(index) + " is out of range [0, " +
                          cairn::FormatShort(count) + ")");
  }
}

}  // namespace

void DefineSystemsFramework(py::module_ m) {
  // Value types every submodule may carry on abstract ports.
  RegisterConvertedAbstractValueType<Eigen::VectorXd>("VectorXd");
  RegisterConvertedAbstractValueType<std::string>("str");
  RegisterConvertedAbstractValueType<double>("float");
  RegisterConvertedAbstractValueType<int>("int");
  RegisterConvertedAbstractValueType<bool>("bool");
  RegisterConvertedAbstractValueType<Eigen::Isometry3d>("Isometry3d");

  py::class_<DependencyTicket>(m, "DependencyTicket",
                               "Names one source of values a computation may depend on (time, a state group, an "
                               "input port, a cache entry, ...); output ports list theirs as prerequisites.")
      .def("index", &DependencyTicket::index, "The ticket's index within its system.")
      .def("is_valid", &DependencyTicket::is_valid, "False for a default-constructed ticket.")
      .def("__eq__", [](DependencyTicket a, DependencyTicket b) { return a == b; }, "Same ticket.")
      .def("__hash__", [](DependencyTicket t) { return t.index(); }, "Hash of the index.")
      .def("__repr__", [](DependencyTicket t) { return "DependencyTicket(" + cairn::FormatShort(t.index()) + ")"; },
           "DependencyTicket(<index>).");

  py::enum_<PortDataType>(m, "PortDataType",
                          "What a port carries: a vector of a declared size, or any C++ value behind AbstractValue.")
      .value("kVector", PortDataType::kVector, "A vector (numpy float64 array) of the port's size.")
      .value("kAbstract", PortDataType::kAbstract, "A value of the port's declared type.");

  py::class_<AbstractValue>(
      m, "AbstractValue",
      "A type-erased value: what abstract ports, abstract state and abstract parameters hold. Make one with "
      "AbstractValue.Make(value) (a registered C++ type when `value` is an instance of its class, else the Python "
      "object itself) or AbstractValue.Make(value, type=name) for a registered C++ type by name (\"Image\", "
      "\"OccupancyGrid\", ...; see registered_types()).")
      .def_static(
          "Make",
          [](py::handle value, const std::string& type) { return MakeAbstractValue(value, type); },
          py::arg("value"), py::arg("type") = "",
          "A new AbstractValue holding `value`: with `type`, converted to the registered C++ type of that name "
          "(\"object\" keeps the Python object); otherwise the registered type of `value`'s class, else the Python "
          "object. Raises ValueError for an unknown type name, TypeError when `value` does not convert.")
      .def_static(
          "registered_types",
          []() {
            std::vector<std::string> names{"object"};
            for (const AbstractValueType& type : RegisteredAbstractValueTypes()) names.push_back(type.name);
            return names;
          },
          "Names of the C++ value types Python values convert to, in registration order (\"object\" first).")
      .def(
          "get_value", [](const AbstractValue& self) { return AbstractValueToPython(self, true); },
          "A copy of the value (for a Python object, the object itself).")
      .def(
          "get_mutable_value",
          [](py::object self) {
            return AbstractValueToPython(self.cast<const AbstractValue&>(), false, self);
          },
          "The value itself for in-place changes (a reference to the C++ object, valid while this AbstractValue "
          "lives; in an output or event callback, only during the call).")
      .def(
          "set_value",
          [](AbstractValue& self, py::handle value) {
            AssignAbstractValueFromPython(value, &self, "AbstractValue.set_value: this value");
          },
          py::arg("value"),
          "Stores `value`, converted to this value's type (TypeError naming both types if it does not convert).")
      .def("type_name", &AbstractValue::GetNiceTypeName, "The demangled name of the C++ type held.")
      .def("Clone", &AbstractValue::Clone, "A copy of this value.")
      .def("__repr__", [](const AbstractValue& self) { return "AbstractValue[" + self.GetNiceTypeName() + "]"; },
           "AbstractValue[<C++ type>].");

  py::class_<DiscreteValues>(m, "DiscreteValues",
                             "The discrete state of one leaf system: a list of groups, each a vector of fixed "
                             "size. Discrete update events receive one initialised to the current values and write "
                             "the next values into it.")
      .def("num_groups", &DiscreteValues::num_groups, "Number of groups.")
      .def(
          "get_value",
          [](py::object self, int group) {
            auto& values = self.cast<DiscreteValues&>();
            return EigenView(values.get_mutable_value(group), self, true);
          },
          py::arg("group") = 0,
          "Group `group` as a writable numpy view (no copy; writing it sets the next state). In an event handler "
          "the view is valid during the call only. IndexError names the valid range.")
      .def(
          "set_value",
          [](DiscreteValues& self, int group, const Eigen::Ref<const Eigen::VectorXd>& value) {
            self.set_value(group, value);
          },
          py::arg("group"), py::arg("value"), "Sets group `group`; ValueError if the size differs.");

  py::class_<State>(m, "State",
                    "The complete state of one leaf system (continuous, discrete and abstract), as unrestricted "
                    "update events receive it: initialised to the current state; what the handler writes becomes "
                    "the next state.")
      .def(
          "get_continuous_state",
          [](py::object self) { return EigenView(self.cast<State&>().get_mutable_continuous_state(), self, true); },
          "The continuous state as a writable numpy view (valid during the handler).")
      .def("get_mutable_discrete_state", py::overload_cast<>(&State::get_mutable_discrete_state),
           py::return_value_policy::reference_internal, "The discrete state, for writing.")
      .def("num_abstract_states", &State::num_abstract_states, "Number of abstract states.")
      .def(
          "get_abstract_state",
          [](const State& self, int index) {
            CheckIndex(index, self.num_abstract_states(), "abstract state");
            return AbstractValueToPython(self.abstract_state_value(index), true);
          },
          py::arg("index"), "A copy of abstract state `index` (for a Python object, the object itself).")
      .def(
          "get_mutable_abstract_state",
          [](py::object self, int index) {
            auto& state = self.cast<State&>();
            CheckIndex(index, state.num_abstract_states(), "abstract state");
            return AbstractValueToPython(state.get_mutable_abstract_state_value(index), false, self);
          },
          py::arg("index"), "Abstract state `index` itself, for changing it in place (valid during the handler).")
      .def(
          "set_abstract_state",
          [](State& self, int index, py::handle value) {
            CheckIndex(index, self.num_abstract_states(), "abstract state");
            AssignAbstractValueFromPython(value, &self.get_mutable_abstract_state_value(index),
                                          "abstract state " + cairn::FormatShort(index));
          },
          py::arg("index"), py::arg("value"), "Sets abstract state `index` (converted to its type).");

  py::class_<Context>(
      m, "Context", py::dynamic_attr(),
      "Every runtime value of a system: time, continuous/discrete/abstract state, parameters, fixed input values and "
      "the cache. Created by System.CreateDefaultContext(); usable only with the system that created it, which it "
      "keeps alive. Setting a value invalidates the cached outputs that depend on it.")
      .def(
          "Clone",
          [](py::object self) {
            py::object clone = py::cast(self.cast<const Context&>().Clone());
            TieToOwner(clone, GetInstanceAttribute(self, "_cairn_owner"));
            return clone;
          },
           "An independent copy with the same values (state, parameters, fixed inputs); root contexts only.")
      .def("SetFrom", &Context::SetFrom, py::arg("source"),
           "Copies every value from `source`, a context of the same system.")
      .def("get_time", &Context::get_time, "The time.")
      .def("SetTime", &Context::SetTime, py::arg("time"), "Sets the time of this context and all its subcontexts.")
      .def("num_continuous_states", &Context::num_continuous_states,
           "Size of the continuous state (for a diagram: every subsystem's, concatenated).")
      .def(
          "get_continuous_state_vector",
          [](const Context& self) { return Eigen::VectorXd(self.get_continuous_state_vector()); },
          "A copy of the continuous state.")
      .def("SetContinuousState", &Context::SetContinuousState, py::arg("x"),
           "Sets the continuous state; ValueError if the size differs.")
      .def("num_discrete_state_groups", &Context::num_discrete_state_groups, "Number of discrete state groups.")
      .def(
          "get_discrete_state",
          [](const Context& self, int group) { return Eigen::VectorXd(self.get_discrete_state(group)); },
          py::arg("group") = 0, "A copy of discrete state group `group`.")
      .def("SetDiscreteState",
           py::overload_cast<int, const Eigen::Ref<const Eigen::VectorXd>&>(&Context::SetDiscreteState),
           py::arg("group"), py::arg("value"), "Sets discrete state group `group`; ValueError if the size differs.")
      .def("num_abstract_states", &Context::num_abstract_states, "Number of abstract states.")
      .def(
          "get_abstract_state",
          [](const Context& self, int index) {
            CheckIndex(index, self.num_abstract_states(), "abstract state");
            return AbstractValueToPython(self.get_abstract_state_value(index), true);
          },
          py::arg("index"), "A copy of abstract state `index` (for a Python object, the object itself).")
      .def(
          "get_mutable_abstract_state",
          [](py::object self, int index) {
            auto& context = self.cast<Context&>();
            CheckIndex(index, context.num_abstract_states(), "abstract state");
            return AbstractValueToPython(context.get_mutable_abstract_state_value(index), false, self);
          },
          py::arg("index"),
          "Abstract state `index` itself, for changing it in place; counts as a change of that state (now).")
      .def(
          "SetAbstractState",
          [](Context& self, int index, py::handle value) {
            CheckIndex(index, self.num_abstract_states(), "abstract state");
            AssignAbstractValueFromPython(value, &self.get_mutable_abstract_state_value(index),
                                          "abstract state " + cairn::FormatShort(index) + " of " +
                                              self.system_path_name());
          },
          py::arg("index"), py::arg("value"), "Sets abstract state `index` (converted to its type).")
      .def("num_numeric_parameter_groups", &Context::num_numeric_parameter_groups, "Number of numeric parameters.")
      .def(
          "get_numeric_parameter",
          [](const Context& self, int index) { return Eigen::VectorXd(self.get_numeric_parameter(index)); },
          py::arg("index"), "A copy of numeric parameter `index`.")
      .def(
          "SetNumericParameter",
          [](Context& self, int index, const Eigen::Ref<const Eigen::VectorXd>& value) {
            Eigen::VectorXd& parameter = self.get_mutable_numeric_parameter(index);
            if (parameter.size() != value.size()) {
              throw py::value_error("numeric parameter " + cairn::FormatShort(index) + " of " + self.system_path_name() +
                                    " has size " + cairn::FormatShort(parameter.size()) + ", got a value of size " +
                                    cairn::FormatShort(value.size()));
            }
            parameter = value;
          },
          py::arg("index"), py::arg("value"), "Sets numeric parameter `index`; ValueError if the size differs.")
      .def("num_abstract_parameters", &Context::num_abstract_parameters, "Number of abstract parameters.")
      .def(
          "get_abstract_parameter",
          [](const Context& self, int index) {
            CheckIndex(index, self.num_abstract_parameters(), "abstract parameter");
            return AbstractValueToPython(self.get_abstract_parameter_value(index), true);
          },
          py::arg("index"), "A copy of abstract parameter `index`.")
      .def(
          "SetAbstractParameter",
          [](Context& self, int index, py::handle value) {
            CheckIndex(index, self.num_abstract_parameters(), "abstract parameter");
            AssignAbstractValueFromPython(value, &self.get_mutable_abstract_parameter_value(index),
                                          "abstract parameter " + cairn::FormatShort(index) + " of " +
                                              self.system_path_name());
          },
          py::arg("index"), py::arg("value"), "Sets abstract parameter `index` (converted to its type).")
      .def("DisableCaching", &Context::DisableCaching,
           "Every Eval recomputes from now on (results are identical); applies to all subcontexts.")
      .def("EnableCaching", &Context::EnableCaching, "Turns caching back on, marking every cached value out of date.")
      .def("is_caching_enabled", &Context::is_caching_enabled, "Whether outputs are cached.")
      .def("is_root", &Context::is_root, "True for a system's own context, false for a diagram's subcontext.")
      .def("num_subcontexts", &Context::num_subcontexts, "Number of subcontexts (a diagram's: one per subsystem).")
      .def("system_path_name", &Context::system_path_name, "Path name of the system that created this context.")
      .def("__repr__", [](const Context& self) {
        return "<Context of " + self.system_path_name() + " at t=" + cairn::FormatShort(self.get_time()) + ">";
      }, "<Context of <system> at t=...>.");

  py::class_<InputPort>(m, "InputPort", py::dynamic_attr(),
                        "An input port of a system. Its value comes from the output it is connected to, the diagram "
                        "input it is exported as, or a value fixed in the context (FixValue). Vector ports carry "
                        "numpy float64 vectors of size(); abstract ports carry their declared type.")
      .def("get_name", &InputPort::get_name, "The port's name.")
      .def("get_index", &InputPort::get_index, "Index among the system's input ports.")
      .def("get_data_type", &InputPort::get_data_type, "Vector or abstract.")
      .def("size", &InputPort::size, "Size of a vector port (0 for abstract ports).")
      .def(
          "get_system", [](py::object self) { return Tied(&self.cast<const InputPort&>().get_system(), self); },
          "The system the port belongs to.")
      .def("ticket", &InputPort::ticket, "The port's dependency ticket (a prerequisite of outputs).")
      .def(
          "Eval",
          [](const InputPort& self, py::object context, bool copy) {
            return EvalInputPort(self, context.cast<const Context&>(), context, copy);
          },
          py::arg("context"), py::arg("copy") = true,
          "The port's value in `context`, pulled from upstream (computing what is out of date, without the GIL). "
          "Vector ports give a new numpy array. Abstract ports give a copy; with copy=False a read-only view or "
          "reference instead, valid while `context` lives and changing when the value is recomputed.")
      .def("HasValue", &InputPort::HasValue, py::arg("context"),
           "True if the port is connected, exported or fixed in `context`.")
      .def(
          "FixValue",
          [](const InputPort& self, Context* context, py::handle value) {
            self.FixAbstractValue(context, *InputValueFromPython(self, value));
          },
          py::arg("context"), py::arg("value"),
          "Fixes the port's value in `context` (a copy of `value`, converted to the port's type: a vector of size() "
          "for vector ports). The port must be neither connected nor exported there.")
      .def("GetFullDescription", &InputPort::GetFullDescription, "\"input port 'u' of system '::diagram::plant'\".")
      .def("GetTypeDescription", &InputPort::GetTypeDescription,
           "\"vector of size 3\" or \"abstract value of type Foo\".")
      .def("__repr__", [](const InputPort& self) { return "<" + self.GetFullDescription() + ">"; },
           "<input port ...>.");

  py::class_<OutputPort>(m, "OutputPort", py::dynamic_attr(),
                         "An output port of a system. Eval() returns the cached value, computing it when one of its "
                         "prerequisites changed.")
      .def("get_name", &OutputPort::get_name, "The port's name.")
      .def("get_index", &OutputPort::get_index, "Index among the system's output ports.")
      .def("get_data_type", &OutputPort::get_data_type, "Vector or abstract.")
      .def("size", &OutputPort::size, "Size of a vector port (0 for abstract ports).")
      .def(
          "get_system", [](py::object self) { return Tied(&self.cast<const OutputPort&>().get_system(), self); },
          "The system the port belongs to.")
      .def(
          "Eval",
          [](const OutputPort& self, py::object context, bool copy) {
            return EvalOutputPort(self, context.cast<const Context&>(), context, copy);
          },
          py::arg("context"), py::arg("copy") = true,
          "The port's value in `context` (computed without the GIL when out of date). Vector ports give a new "
          "numpy array. Abstract ports give a copy; with copy=False a read-only view or reference instead, valid "
          "while `context` lives and changing when the value is recomputed.")
      .def("Allocate", &OutputPort::Allocate, "A new AbstractValue of the port's type (a copy of its model value).")
      .def("GetFullDescription", &OutputPort::GetFullDescription, "\"output port 'y' of system '::diagram::plant'\".")
      .def("GetTypeDescription", &OutputPort::GetTypeDescription,
           "\"vector of size 3\" or \"abstract value of type Foo\".")
      .def("__repr__", [](const OutputPort& self) { return "<" + self.GetFullDescription() + ">"; },
           "<output port ...>.");

  py::class_<System>(m, "System", py::dynamic_attr(),
                     "The abstract block of a block diagram: it describes ports, state, parameters and events; all "
                     "runtime values live in a Context it creates. Subclass LeafSystem to write one in Python.")
      .def("get_name", &System::get_name, "The name, unique among the systems of a diagram.")
      .def("set_name", &System::set_name, py::arg("name"),
           "Renames the system; RuntimeError once it belongs to a built Diagram.")
      .def("GetPathName", &System::GetPathName, "\"::outer::inner::name\", from the outermost diagram.")
      .def("num_input_ports", &System::num_input_ports, "Number of input ports.")
      .def("num_output_ports", &System::num_output_ports, "Number of output ports.")
      .def(
          "get_input_port",
          [](py::object self, int index) { return Tied(&self.cast<const System&>().get_input_port(index), self); },
          py::arg("index"),
           "Input port `index`; IndexError naming the valid range.")
      .def(
          "get_input_port", [](py::object self) { return Tied(&self.cast<const System&>().get_input_port(), self); },
          "The only input port; raises unless there is exactly one.")
      .def(
          "get_output_port",
          [](py::object self, int index) { return Tied(&self.cast<const System&>().get_output_port(index), self); },
          py::arg("index"),
           "Output port `index`; IndexError naming the valid range.")
      .def(
          "get_output_port", [](py::object self) { return Tied(&self.cast<const System&>().get_output_port(), self); },
          "The only output port; raises unless there is exactly one.")
      .def(
          "GetInputPort",
          [](py::object self, const std::string& name) {
            return Tied(&self.cast<const System&>().GetInputPort(name), self);
          },
          py::arg("name"),
           "The input port called `name`; ValueError listing the closest names.")
      .def(
          "GetOutputPort",
          [](py::object self, const std::string& name) {
            return Tied(&self.cast<const System&>().GetOutputPort(name), self);
          },
          py::arg("name"),
           "The output port called `name`; ValueError listing the closest names.")
      .def("HasInputPort", &System::HasInputPort, py::arg("name"), "True if an input port is called `name`.")
      .def("HasOutputPort", &System::HasOutputPort, py::arg("name"), "True if an output port is called `name`.")
      .def(
          "CreateDefaultContext",
          [](py::object self) {
            py::object context = py::cast(self.cast<const System&>().CreateDefaultContext());
            TieToOwner(context, self);
            return context;
          },
           "A new context with every value at its declared default (it keeps this system alive).")
      .def("ValidateContext", &System::ValidateContext, py::arg("context"),
           "Raises RuntimeError unless `context` was created by this system.")
      .def("num_continuous_states", &System::num_continuous_states, "Size of the continuous state.")
      .def(
          "CalcTimeDerivatives",
          [](const System& self, const Context& context) {
            Eigen::VectorXd derivatives;
            py::gil_scoped_release release;
            self.CalcTimeDerivatives(context, &derivatives);
            return derivatives;
          },
          py::arg("context"), "Time derivatives of the continuous state in `context`.")
      .def("HasDirectFeedthrough", &System::HasDirectFeedthrough, py::arg("input"), py::arg("output"),
           "Whether output `output` may depend on input `input` in the same instant.")
      .def("HasAnyDirectFeedthrough", &System::HasAnyDirectFeedthrough, "Whether any output depends on any input.")
      .def("ForcedPublish", &System::ForcedPublish, py::arg("context"), py::call_guard<py::gil_scoped_release>(),
           "Runs every forced publish event (of every leaf, for a diagram).")
      .def("ExecuteForcedEvents", &System::ExecuteForcedEvents, py::arg("context"),
           py::call_guard<py::gil_scoped_release>(),
           "Runs every forced event: unrestricted updates, then discrete updates, then publishes.")
      .def("GetGraphvizString", &System::GetGraphvizString,
           "A Graphviz (dot) description of the system and, for a diagram, its subsystems and connections.")
      .def_static("nothing_ticket", &System::nothing_ticket, "Prerequisite of a value that depends on nothing.")
      .def_static("time_ticket", &System::time_ticket, "Prerequisite: the time.")
      .def_static("xc_ticket", &System::xc_ticket, "Prerequisite: the continuous state.")
      .def_static("xd_ticket", &System::xd_ticket, "Prerequisite: every discrete state group.")
      .def_static("xa_ticket", &System::xa_ticket, "Prerequisite: every abstract state.")
      .def_static("all_state_ticket", &System::all_state_ticket, "Prerequisite: the whole state.")
      .def_static("numeric_parameters_ticket", &System::numeric_parameters_ticket,
                  "Prerequisite: every numeric parameter.")
      .def_static("abstract_parameters_ticket", &System::abstract_parameters_ticket,
                  "Prerequisite: every abstract parameter.")
      .def_static("all_parameters_ticket", &System::all_parameters_ticket, "Prerequisite: every parameter.")
      .def_static("all_input_ports_ticket", &System::all_input_ports_ticket, "Prerequisite: every input port.")
      .def_static("all_sources_ticket", &System::all_sources_ticket,
                  "Prerequisite: time, state, parameters and inputs (the default).")
      .def("input_port_ticket", &System::input_port_ticket, py::arg("index"), "Prerequisite: input port `index`.")
      .def("__repr__", [](py::handle self) {
        const auto& system = self.cast<const System&>();
        return "<" + std::string(py::str(py::type::handle_of(self).attr("__name__"))) + " '" + system.GetPathName() +
               "'>";
      }, "<Class '::path::name'>.");

  py::class_<Diagram, System>(m, "Diagram",
                              "A system made of subsystems connected output-to-input, built by DiagramBuilder. It "
                              "owns its subsystems; Python references to them keep the diagram alive.")
      .def("num_subsystems", &Diagram::num_subsystems, "Number of direct subsystems.")
      .def(
          "GetSystems", [](py::object self) { return WrapSystems(self.cast<const Diagram&>().GetSystems(), self); },
          "The subsystems in the order they were added.")
      .def(
          "GetSubsystemByName",
          [](py::object self, const std::string& name) {
            return Tied(&self.cast<const Diagram&>().GetSubsystemByName(name), self);
          },
          py::arg("name"), "A direct subsystem by name; ValueError listing the closest names.")
      .def(
          "GetSubsystemContext",
          [](const Diagram& self, const System& subsystem, py::object context) {
            return Tied(&self.GetSubsystemContext(subsystem, context.cast<const Context&>()), context);
          },
          py::arg("subsystem"), py::arg("context"),
           "The context of `subsystem` (direct or nested) within this diagram's `context`.")
      .def(
          "GetMutableSubsystemContext",
          [](const Diagram& self, const System& subsystem, py::object context) {
            return Tied(&self.GetMutableSubsystemContext(subsystem, context.cast<Context*>()), context);
          },
          py::arg("subsystem"), py::arg("context"),
          "The context of `subsystem` within `context`, for changing its values.")
      .def(
          "connections",
          [](py::object self) {
            const auto& diagram = self.cast<const Diagram&>();
            const std::vector<const System*> systems = diagram.GetSystems();
            py::list out;
            for (const auto& [input, output] : diagram.connections()) {
              const System* source = systems[static_cast<std::size_t>(output.first)];
              const System* destination = systems[static_cast<std::size_t>(input.first)];
              out.append(py::make_tuple(
                  Tied(&source->get_output_port(output.second), Tied(source, self)),
                  Tied(&destination->get_input_port(input.second), Tied(destination, self))));
            }
            return out;
          },
          "Every connection as (output port, input port), ordered by input.");

  py::class_<DiagramBuilder>(m, "DiagramBuilder", py::dynamic_attr(),
                             "Assembles a Diagram: add systems, connect outputs to inputs, export the diagram's own "
                             "ports, Build(). Mistakes are reported where they are made (mismatched ports, an input "
                             "connected twice, a system added twice) or by Build() (unconnected inputs, duplicate "
                             "names, algebraic loops).")
      .def(py::init<>(), "An empty builder.")
      .def(
          "AddSystem", [](py::object self, py::object system) { return AddSystemToBuilder(self, system, ""); },
          py::arg("system"),
          "Adds `system` (C++ or Python-written) and returns it. The builder, then the diagram, owns it; a system "
          "can be added to one builder only. Unnamed systems get a unique name from their class.")
      .def(
          "AddNamedSystem",
          [](py::object self, const std::string& name, py::object system) {
            return AddSystemToBuilder(self, system, name);
          },
          py::arg("name"), py::arg("system"), "As AddSystem, naming the system.")
      .def("Connect", py::overload_cast<const OutputPort&, const InputPort&>(&DiagramBuilder::Connect),
           py::arg("source"), py::arg("destination"),
           "Connects output `source` to input `destination` (same vector size or abstract type; one source per "
           "input).")
      .def("Connect", py::overload_cast<const System&, const System&>(&DiagramBuilder::Connect), py::arg("source"),
           py::arg("destination"), "Connects the only output of `source` to the only input of `destination`.")
      .def("ExportInput", &DiagramBuilder::ExportInput, py::arg("input"), py::arg("name") = "",
           "Makes `input` an input of the diagram named `name` (default \"<system>_<port>\"); returns its index.")
      .def("ConnectInput", py::overload_cast<int, const InputPort&>(&DiagramBuilder::ConnectInput),
           py::arg("diagram_input"), py::arg("input"), "Feeds one more subsystem input from an exported input.")
      .def("ConnectInput", py::overload_cast<const std::string&, const InputPort&>(&DiagramBuilder::ConnectInput),
           py::arg("diagram_input_name"), py::arg("input"), "Feeds one more subsystem input from an exported input.")
      .def("ExportOutput", &DiagramBuilder::ExportOutput, py::arg("output"), py::arg("name") = "",
           "Makes `output` an output of the diagram named `name` (default \"<system>_<port>\"); returns its index.")
      .def(
          "FixInput",
          [](DiagramBuilder& self, const InputPort& input, py::handle value) {
            self.FixInputValue(input, *InputValueFromPython(input, value));
          },
          py::arg("input"), py::arg("value"),
          "Gives `input` a constant value (a copy, converted to the port's type) in every context of the diagram.")
      .def(
          "GetSystems",
          [](py::object self) { return WrapSystems(self.cast<const DiagramBuilder&>().GetSystems(), self); },
          "The systems added so far, in order.")
      .def("IsConnectedOrExported", &DiagramBuilder::IsConnectedOrExported, py::arg("input"),
           "True if `input` is connected, exported or fixed.")
      .def("Build", &BuildDiagram,
           "Checks the diagram and builds it (it then owns every system); the builder cannot be used afterwards.");
}

}  // namespace cairn::python
