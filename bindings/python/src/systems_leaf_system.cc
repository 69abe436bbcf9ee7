// cairn.systems.LeafSystem: leaf systems written in Python, which connect to C++ systems in one diagram.
//
// A Python subclass declares its ports, state, parameters and events in __init__, with Python callables computing
// its outputs and handling its events. C++ calls them back (taking the GIL) whenever the framework computes: when an
// output is evaluated, the simulator steps, an event is due. The callables live in the instance's dictionary
// (`_cairn_callbacks`), not in C++ objects, so the cycles they form with the instance stay visible to Python's
// garbage collector; the C++ side keeps only borrowed pointers, valid because the instance outlives its C++ object
// (ownership.h).

#include <deque>
#include <memory>
#include <optional>
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
#include "cairn/systems/framework/discrete_values.h"
#include "cairn/systems/framework/event_status.h"
#include "cairn/systems/framework/leaf_system.h"
#include "cairn/systems/framework/state.h"
#include "numpy_support.h"
#include "system_support.h"

namespace cairn::python {

using namespace cairn::systems;

namespace {

/// The C++ side of a LeafSystem subclass written in Python.
class PyLeafSystem final : public LeafSystem {
 public:
  PyLeafSystem() = default;

  using LeafSystem::DeclareAbstractInputPort;
  using LeafSystem::DeclareAbstractParameter;
  using LeafSystem::DeclareAbstractState;
  using LeafSystem::DeclareContinuousState;
  using LeafSystem::DeclareDiscreteState;
  using LeafSystem::DeclareNumericParameter;
  using LeafSystem::DeclareVectorInputPort;
  using LeafSystem::Prerequisites;
  using LeafSystem::DeclareAbstractOutputPort;
  using LeafSystem::DeclareVectorOutputPort;
  using LeafSystem::DeclarePeriodicPublishEvent;
  using LeafSystem::DeclarePeriodicDiscreteUpdateEvent;
  using LeafSystem::DeclarePeriodicUnrestrictedUpdateEvent;
  using LeafSystem::DeclarePerStepPublishEvent;
  using LeafSystem::DeclarePerStepDiscreteUpdateEvent;
  using LeafSystem::DeclarePerStepUnrestrictedUpdateEvent;
  using LeafSystem::DeclareInitializationPublishEvent;
  using LeafSystem::DeclareInitializationDiscreteUpdateEvent;
  using LeafSystem::DeclareInitializationUnrestrictedUpdateEvent;
  using LeafSystem::DeclareForcedPublishEvent;
  using LeafSystem::DeclareForcedDiscreteUpdateEvent;
  using LeafSystem::DeclareForcedUnrestrictedUpdateEvent;

  /// Stores `callable` in the instance dictionary of `self` (this system's Python object); returns its index.
  int AddCallback(py::handle self, py::handle callable) {
    if (!PyCallable_Check(callable.ptr())) {
      throw py::type_error("LeafSystem: expected a callable, got a " +
                           std::string(py::str(py::type::handle_of(callable).attr("__name__"))));
    }
    if (callbacks_ == nullptr) {
      py::list list;
      SetInstanceAttribute(self, "_cairn_callbacks", list);
      callbacks_ = list.ptr();  // Borrowed: the instance's dictionary holds it.
    }
    py::reinterpret_borrow<py::list>(callbacks_).append(callable);
    return static_cast<int>(PyList_GET_SIZE(callbacks_)) - 1;
  }

  /// Callback `index` (borrowed); the GIL must be held.
  py::handle callback(int index) const { return PyList_GET_ITEM(callbacks_, index); }

 private:
  void DoCalcTimeDerivatives(const Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const override {
    py::gil_scoped_acquire gil;
    py::function override = py::get_override(static_cast<const LeafSystem*>(this), "DoCalcTimeDerivatives");
    if (!override) {
      LeafSystem::DoCalcTimeDerivatives(context, derivatives);
      return;
    }
    py::object result = override(py::cast(&context, py::return_value_policy::reference),
                                 CallbackVectorView(derivatives.data(), derivatives.size()));
    if (!result.is_none()) {
      const auto value = result.cast<Eigen::VectorXd>();
      if (value.size() != derivatives.size()) {
        throw std::logic_error("DoCalcTimeDerivatives of system '" + GetPathName() + "' returned " +
                               cairn::FormatShort(value.size()) + " derivatives for " +
                               cairn::FormatShort(derivatives.size()) + " continuous states");
      }
      derivatives = value;
    }
  }

  PyObject* callbacks_{nullptr};
};

PyLeafSystem& PythonLeaf(py::handle self, const char* method) {
  auto* leaf = dynamic_cast<PyLeafSystem*>(self.cast<LeafSystem*>());
  if (leaf == nullptr) {
    throw py::type_error(std::string("LeafSystem.") + method +
                         " declares structure of a LeafSystem subclass written in Python (call it in __init__); a "
                         "C++ system's structure is fixed by its constructor");
  }
  // A builder or diagram has recorded the ports and state it found; changing them now would break it.
  if (!GetInstanceAttribute(self, "_cairn_owner").is_none()) {
    throw std::logic_error(std::string("LeafSystem.") + method + " on system '" + leaf->get_name() +
                           "', which already belongs to a DiagramBuilder or Diagram: declare ports, state and events "
                           "in __init__, before adding the system.");
  }
  return *leaf;
}

PyLeafSystem::Prerequisites ToPrerequisites(const std::optional<std::vector<DependencyTicket>>& tickets) {
  if (!tickets) return {System::all_sources_ticket()};
  return PyLeafSystem::Prerequisites(tickets->begin(), tickets->end());
}

py::object ContextObject(const Context& context) { return py::cast(&context, py::return_value_policy::reference); }

// Event handlers, as std::function objects over the callback at `index`.
// A Python handler returns None (succeeded) or an EventStatus.
EventStatus HandlerStatus(const py::object& result, const PyLeafSystem* system) {
  if (result.is_none()) return EventStatus::Succeeded();
  if (py::isinstance<EventStatus>(result)) return result.cast<EventStatus>();
  throw py::type_error("An event handler of system '" + system->GetPathName() + "' returned a " +
                       std::string(py::str(py::type::of(result).attr("__name__"))) +
                       "; return None or a cairn.systems.EventStatus");
}

std::function<EventStatus(const Context&)> PublishHandler(const PyLeafSystem* system, int index) {
  return [system, index](const Context& context) {
    py::gil_scoped_acquire gil;
    return HandlerStatus(system->callback(index)(ContextObject(context)), system);
  };
}
std::function<EventStatus(const Context&, DiscreteValues*)> DiscreteHandler(const PyLeafSystem* system, int index) {
  return [system, index](const Context& context, DiscreteValues* next) {
    py::gil_scoped_acquire gil;
    return HandlerStatus(
        system->callback(index)(ContextObject(context), py::cast(next, py::return_value_policy::reference)), system);
  };
}
std::function<EventStatus(const Context&, State*)> UnrestrictedHandler(const PyLeafSystem* system, int index) {
  return [system, index](const Context& context, State* next) {
    py::gil_scoped_acquire gil;
    return HandlerStatus(
        system->callback(index)(ContextObject(context), py::cast(next, py::return_value_policy::reference)), system);
  };
}

// Docstrings built at run time must outlive the module's functions.
const char* KeepDoc(std::string doc) {
  static auto* docs = new std::deque<std::string>();
  docs->push_back(std::move(doc));
  return docs->back().c_str();
}

const char* kHandlerDoc =
    " `handler` is called with (context) for publish events, (context, discrete_state: DiscreteValues) for discrete "
    "updates and (context, state: State) for unrestricted updates, where the second argument starts as a copy of "
    "the current values and receives the next ones. It returns None, or an EventStatus: "
    "EventStatus.ReachedTermination(message) ends Simulator.AdvanceTo() normally, EventStatus.Failed(message) ends "
    "it with SimulatorStatus.Reason.kEventHandlerFailed.";

}  // namespace

bool IsPythonSystem(const System& system) { return dynamic_cast<const PyLeafSystem*>(&system) != nullptr; }

void DefineSystemsLeafSystem(py::module_ m) {
  py::class_<EventStatus> status(m, "EventStatus",
                                 "What an event handler reports: did nothing, succeeded, reached termination (the "
                                 "Simulator stops) or failed (the Simulator stops; that step's updates are dropped).");
  py::enum_<EventStatus::Severity>(status, "Severity", "In increasing severity.")
      .value("kDidNothing", EventStatus::Severity::kDidNothing, "Nothing to do.")
      .value("kSucceeded", EventStatus::Severity::kSucceeded, "Done.")
      .value("kReachedTermination", EventStatus::Severity::kReachedTermination, "The simulation should end.")
      .value("kFailed", EventStatus::Severity::kFailed, "The simulation cannot go on.");
  status.def_static("DidNothing", &EventStatus::DidNothing, "The handler had nothing to do.")
      .def_static("Succeeded", &EventStatus::Succeeded, "The handler did its work.")
      .def_static("ReachedTermination", &EventStatus::ReachedTermination, py::arg("message"),
                  "End the simulation normally, for `message`.")
      .def_static("Failed", &EventStatus::Failed, py::arg("message"), "The handler failed, for `message`.")
      .def("severity", &EventStatus::severity, "How severe.")
      .def("message", &EventStatus::message, "The handler's message.")
      .def("stops", &EventStatus::stops, "True if the Simulator stops.")
      .def("failed", &EventStatus::failed, "True for a failure.");
  py::class_<LeafSystem, PyLeafSystem, System> leaf(
      m, "LeafSystem",
      "Base class of leaf systems. Subclass it in Python to write a system: call super().__init__(), then declare "
      "ports, state, parameters and events in __init__ with the Declare* methods, passing the methods that compute "
      "outputs and handle events; override DoCalcTimeDerivatives(context, derivatives) for continuous state. A "
      "Python system connects to C++ systems in one diagram; C++ calls it back with the GIL.\n\n"
      "Output callbacks receive (context, output): for a vector port `output` is a writable numpy view to fill in "
      "place (or return the vector); for an abstract port it is an AbstractValue to set_value() (or return the "
      "value). Views and AbstractValue arguments are valid during the call only.");
  leaf.def(py::init_alias<>(), "Declares nothing; subclasses declare their structure in __init__.")
      .def("discrete_state_ticket", &LeafSystem::discrete_state_ticket, py::arg("group"),
           "Prerequisite: discrete state group `group`.")
      .def("abstract_state_ticket", &LeafSystem::abstract_state_ticket, py::arg("index"),
           "Prerequisite: abstract state `index`.")
      .def("numeric_parameter_ticket", &LeafSystem::numeric_parameter_ticket, py::arg("index"),
           "Prerequisite: numeric parameter `index`.")
      .def("abstract_parameter_ticket", &LeafSystem::abstract_parameter_ticket, py::arg("index"),
           "Prerequisite: abstract parameter `index`.")
      .def("output_port_ticket", &LeafSystem::output_port_ticket, py::arg("port"),
           "Prerequisite: the cached value of output port `port`.")
      .def(
          "DeclareVectorInputPort",
          [](py::handle self, std::string name, int size) {
            return Tied(&PythonLeaf(self, "DeclareVectorInputPort").DeclareVectorInputPort(std::move(name), size),
                        self);
          },
          py::arg("name"), py::arg("size"),
          "Declares an input carrying vectors of `size`; an empty name becomes \"u<i>\". Returns the port.")
      .def(
          "DeclareAbstractInputPort",
          [](py::handle self, std::string name, py::handle model_value) {
            return Tied(&PythonLeaf(self, "DeclareAbstractInputPort")
                             .DeclareAbstractInputPort(std::move(name), *ModelValueFromPython(model_value)),
                        self);
          },
          py::arg("name"), py::arg("model_value"),
          "Declares an input carrying values of `model_value`'s type: an AbstractValue (e.g. "
          "AbstractValue.Make(array, type=\"Image\") to connect to C++ image outputs), an instance of a bound C++ "
          "value class (OccupancyGrid, FootstepPlan, ...) or any Python object. Returns the port.")
      .def(
          "DeclareVectorOutputPort",
          [](py::handle self, std::string name, int size, py::handle calc,
             const std::optional<std::vector<DependencyTicket>>& prerequisites) {
            PyLeafSystem& system = PythonLeaf(self, "DeclareVectorOutputPort");
            const int index = system.AddCallback(self, calc);
            const PyLeafSystem* raw = &system;
            const std::string port_name = name;
            auto compute = [raw, index, size, port_name](const Context& context, Eigen::VectorXd* y) {
              py::gil_scoped_acquire gil;
              py::object result = raw->callback(index)(ContextObject(context), CallbackVectorView(y->data(), size));
              if (result.is_none()) return;
              const auto value = result.cast<Eigen::VectorXd>();
              if (value.size() != size) {
                throw std::logic_error("The calc function of output port '" + port_name + "' of system '" +
                                       raw->GetPathName() + "' returned a vector of size " +
                                       cairn::FormatShort(value.size()) + " (declared size " + cairn::FormatShort(size) +
                                       ")");
              }
              *y = value;
            };
            return Tied(&system.DeclareVectorOutputPort(std::move(name), size, compute, ToPrerequisites(prerequisites)),
                        self);
          },
          py::arg("name"), py::arg("size"), py::arg("calc"),
          py::arg("prerequisites_of_calc") = py::none(),
          "Declares a vector output of `size` computed by calc(context, output): fill the writable view `output` in "
          "place, or return the vector. `prerequisites_of_calc` lists DependencyTickets (default: all sources); "
          "narrower ones let feedback loops through this system build. Returns the port.")
      .def(
          "DeclareAbstractOutputPort",
          [](py::handle self, std::string name, py::handle model_value, py::handle calc,
             const std::optional<std::vector<DependencyTicket>>& prerequisites) {
            PyLeafSystem& system = PythonLeaf(self, "DeclareAbstractOutputPort");
            const int index = system.AddCallback(self, calc);
            const PyLeafSystem* raw = &system;
            const std::string port_name = name;
            auto compute = [raw, index, port_name](const Context& context, AbstractValue* value) {
              py::gil_scoped_acquire gil;
              py::object result = raw->callback(index)(ContextObject(context),
                                                       py::cast(value, py::return_value_policy::reference));
              if (result.is_none()) return;
              AssignAbstractValueFromPython(result, value,
                                            "output port '" + port_name + "' of system '" + raw->GetPathName() + "'");
            };
            return Tied(&system.DeclareAbstractOutputPort(std::move(name), *ModelValueFromPython(model_value), compute,
                                                          ToPrerequisites(prerequisites)),
                        self);
          },
          py::arg("name"), py::arg("model_value"), py::arg("calc"),
          py::arg("prerequisites_of_calc") = py::none(),
          "Declares an output of `model_value`'s type (as DeclareAbstractInputPort) computed by "
          "calc(context, output): output.set_value(v), or return v. Returns the port.")
      .def(
          "DeclareContinuousState",
          [](py::handle self, const Eigen::VectorXd& initial_value) {
            PythonLeaf(self, "DeclareContinuousState").DeclareContinuousState(initial_value);
          },
          py::arg("initial_value"),
          "Declares the continuous state (once) with its initial value; override DoCalcTimeDerivatives.")
      .def(
          "DeclareDiscreteState",
          [](py::handle self, const Eigen::VectorXd& initial_value) {
            return PythonLeaf(self, "DeclareDiscreteState").DeclareDiscreteState(initial_value);
          },
          py::arg("initial_value"), "Declares a discrete state group; returns its index.")
      .def(
          "DeclareAbstractState",
          [](py::handle self, py::handle initial_value) {
            return PythonLeaf(self, "DeclareAbstractState").DeclareAbstractState(*ModelValueFromPython(initial_value));
          },
          py::arg("initial_value"),
          "Declares an abstract state holding `initial_value`'s type (as DeclareAbstractInputPort); returns its "
          "index.")
      .def(
          "DeclareNumericParameter",
          [](py::handle self, const Eigen::VectorXd& default_value) {
            return PythonLeaf(self, "DeclareNumericParameter").DeclareNumericParameter(default_value);
          },
          py::arg("default_value"), "Declares a numeric parameter (a vector per context); returns its index.")
      .def(
          "DeclareAbstractParameter",
          [](py::handle self, py::handle default_value) {
            return PythonLeaf(self, "DeclareAbstractParameter")
                .DeclareAbstractParameter(*ModelValueFromPython(default_value));
          },
          py::arg("default_value"), "Declares an abstract parameter; returns its index.");

  // Events: periodic ones take (period, offset, handler), the others (handler).
  struct EventKindNames {
    const char* suffix;
    int kind;  // 0 publish, 1 discrete update, 2 unrestricted update
  };
  const EventKindNames kinds[] = {{"PublishEvent", 0}, {"DiscreteUpdateEvent", 1}, {"UnrestrictedUpdateEvent", 2}};
  for (const EventKindNames& kind : kinds) {
    const int k = kind.kind;
    leaf.def(
        KeepDoc("DeclarePeriodic" + std::string(kind.suffix)),
        [k](py::handle self, double period, double offset, py::handle handler) {
          PyLeafSystem& system = PythonLeaf(self, "DeclarePeriodic...Event");
          const int index = system.AddCallback(self, handler);
          if (k == 0) system.DeclarePeriodicPublishEvent(period, offset, PublishHandler(&system, index));
          if (k == 1) system.DeclarePeriodicDiscreteUpdateEvent(period, offset, DiscreteHandler(&system, index));
          if (k == 2) system.DeclarePeriodicUnrestrictedUpdateEvent(period, offset, UnrestrictedHandler(&system, index));
        },
        py::arg("period"), py::arg("offset"), py::arg("handler"),
        KeepDoc(std::string("Declares an event at offset + k * period, k = 0, 1, ...") + kHandlerDoc));
    for (const char* trigger : {"PerStep", "Initialization", "Forced"}) {
      const std::string t = trigger;
      leaf.def(
          KeepDoc("Declare" + t + kind.suffix),
          [k, t](py::handle self, py::handle handler) {
            PyLeafSystem& system = PythonLeaf(self, "Declare...Event");
            const int index = system.AddCallback(self, handler);
            if (t == "PerStep") {
              if (k == 0) system.DeclarePerStepPublishEvent(PublishHandler(&system, index));
              if (k == 1) system.DeclarePerStepDiscreteUpdateEvent(DiscreteHandler(&system, index));
              if (k == 2) system.DeclarePerStepUnrestrictedUpdateEvent(UnrestrictedHandler(&system, index));
            } else if (t == "Initialization") {
              if (k == 0) system.DeclareInitializationPublishEvent(PublishHandler(&system, index));
              if (k == 1) system.DeclareInitializationDiscreteUpdateEvent(DiscreteHandler(&system, index));
              if (k == 2) system.DeclareInitializationUnrestrictedUpdateEvent(UnrestrictedHandler(&system, index));
            } else {
              if (k == 0) system.DeclareForcedPublishEvent(PublishHandler(&system, index));
              if (k == 1) system.DeclareForcedDiscreteUpdateEvent(DiscreteHandler(&system, index));
              if (k == 2) system.DeclareForcedUnrestrictedUpdateEvent(UnrestrictedHandler(&system, index));
            }
          },
          py::arg("handler"),
          KeepDoc(std::string(t == "PerStep"          ? "Declares an event at every simulator step."
                              : t == "Initialization" ? "Declares an event run once by Simulator.Initialize()."
                                                      : "Declares an event run only by ForcedPublish or "
                                                        "ExecuteForcedEvents.") +
                  kHandlerDoc));
    }
  }
}

}  // namespace cairn::python
