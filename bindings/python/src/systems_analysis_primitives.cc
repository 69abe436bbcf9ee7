// cairn.systems: Simulator, integrators, and the primitive systems.

#include <memory>
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
#include "cairn/systems/analysis/explicit_euler_integrator.h"
#include "cairn/systems/analysis/integrator_base.h"
#include "cairn/systems/analysis/runge_kutta45_integrator.h"
#include "cairn/systems/analysis/runge_kutta4_integrator.h"
#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/primitives/adder.h"
#include "cairn/systems/primitives/constant_vector_source.h"
#include "cairn/systems/primitives/function_system.h"
#include "cairn/systems/primitives/gain.h"
#include "cairn/systems/primitives/integrator.h"
#include "cairn/systems/primitives/pass_through.h"
#include "cairn/systems/primitives/vector_log.h"
#include "cairn/systems/primitives/vector_log_sink.h"
#include "cairn/systems/primitives/zero_order_hold.h"
#include "numpy_support.h"
#include "ownership.h"
#include "python_object.h"

namespace cairn::python {

using namespace cairn::systems;

namespace {

IntegratorBase& ResetIntegrator(Simulator& simulator, const std::string& kind, double maximum_step_size,
                                double target_accuracy) {
  if (kind == "euler") return simulator.ResetIntegrator<ExplicitEulerIntegrator>(maximum_step_size);
  if (kind == "rk4") return simulator.ResetIntegrator<RungeKutta4Integrator>(maximum_step_size);
  if (kind == "rk45") return simulator.ResetIntegrator<RungeKutta45Integrator>(maximum_step_size, target_accuracy);
  throw std::invalid_argument("Simulator.ResetIntegrator: unknown integrator '" + kind + "'; use euler, rk4 or rk45.");
}

}  // namespace

void DefineSystemsAnalysisAndPrimitives(py::module_ m) {
  // -------------------------------------------------------------------------------------------------------------
  // Simulation

  py::class_<MonitorResult>(m, "MonitorResult", "What a simulator monitor decides after a step.")
      .def_static("Continue", &MonitorResult::Continue, "Keep simulating.")
      .def_static("Stop", &MonitorResult::Stop, py::arg("why"), "End AdvanceTo() with this reason.")
      .def_readonly("stop", &MonitorResult::stop, "True to stop.")
      .def_readonly("reason", &MonitorResult::reason, "Why the simulation stops.");

  py::class_<SimulatorStatus> status(m, "SimulatorStatus", "Why AdvanceTo() returned.");
  py::enum_<SimulatorStatus::Reason>(status, "Reason", "Why AdvanceTo() returned.")
      .value("kReachedBoundaryTime", SimulatorStatus::Reason::kReachedBoundaryTime, "It reached t_final.")
      .value("kReachedTerminationCondition", SimulatorStatus::Reason::kReachedTerminationCondition,
             "The monitor or an event handler (EventStatus.ReachedTermination) stopped it.")
      .value("kEventHandlerFailed", SimulatorStatus::Reason::kEventHandlerFailed,
             "An event handler returned EventStatus.Failed; that step's updates were not applied.");
  status.def_readonly("reason", &SimulatorStatus::reason, "Why AdvanceTo() returned.")
      .def_readonly("time", &SimulatorStatus::time, "The time reached.")
      .def_readonly("message", &SimulatorStatus::message, "Why the monitor or an event handler stopped the run.")
      .def("reached_boundary_time", &SimulatorStatus::reached_boundary_time, "True if it reached t_final.");

  py::class_<IntegratorBase>(m, "IntegratorBase",
                             "Advances the continuous state of a context in time, one step at a time, never past "
                             "the next event.")
      .def("name", &IntegratorBase::name, "Short name (\"explicit_euler\", \"rk4\", \"rk45\").")
      .def("set_maximum_step_size", &IntegratorBase::set_maximum_step_size, py::arg("h"),
           "The largest step; ValueError unless finite and > 0.")
      .def("maximum_step_size", &IntegratorBase::maximum_step_size, "The largest step.")
      .def("supports_error_control", &IntegratorBase::supports_error_control,
           "Whether the integrator controls its local error.")
      .def("set_target_accuracy", &IntegratorBase::set_target_accuracy, py::arg("accuracy"),
           "Local error tolerance per step; raises for integrators without error control.")
      .def("target_accuracy", &IntegratorBase::target_accuracy, "The local error tolerance.")
      .def("num_steps_taken", &IntegratorBase::num_steps_taken, "Steps taken.")
      .def("num_derivative_evaluations", &IntegratorBase::num_derivative_evaluations, "Derivative evaluations.")
      .def("num_step_rejections", &IntegratorBase::num_step_rejections, "Rejected steps (error control).")
      .def("ResetStatistics", &IntegratorBase::ResetStatistics, "Zeroes the counters.");

  py::class_<Simulator>(
      m, "Simulator",
      "Advances a system's context through time: events and continuous integration (RK4 with a 1 ms maximum step by "
      "default). AdvanceTo() runs without the GIL; systems written in Python take it when called back.")
      .def(py::init([](const System& system, const Context* context) {
             return std::make_unique<Simulator>(system, context == nullptr ? nullptr : context->Clone());
           }),
           py::arg("system"), py::arg("context") = nullptr, py::keep_alive<1, 2>(),
           "Simulates `system` from a copy of `context` (a root context of `system`), or from a new default context.")
      .def("Initialize", &Simulator::Initialize, py::call_guard<py::gil_scoped_release>(),
           "Runs initialization events; called by AdvanceTo() if not called before.")
      .def("AdvanceTo", &Simulator::AdvanceTo, py::arg("t_final"), py::call_guard<py::gil_scoped_release>(),
           "Advances to time `t_final` (>= the current time), or until the monitor stops the run; returns a "
           "SimulatorStatus.")
      .def("ResetIntegrator", &ResetIntegrator, py::return_value_policy::reference_internal, py::arg("kind"),
           py::arg("maximum_step_size"), py::arg("target_accuracy") = 1e-6,
           "Replaces the integrator: \"euler\", \"rk4\" or \"rk45\" (error-controlled, `target_accuracy`); returns "
           "it.")
      .def("get_mutable_integrator", &Simulator::get_mutable_integrator, py::return_value_policy::reference_internal,
           "The integrator.")
      .def("set_target_realtime_rate", &Simulator::set_target_realtime_rate, py::arg("rate"),
           "Paces the simulation to `rate` x real time (0 = as fast as possible).")
      .def(
          "set_monitor",
          [](Simulator& self, py::object monitor) {
            if (monitor.is_none()) {
              self.set_monitor(nullptr);
              return;
            }
            SharedPyObject held(std::move(monitor));
            self.set_monitor([held](const Context& context) {
              py::gil_scoped_acquire gil;
              py::object result = held.get()(py::cast(&context, py::return_value_policy::reference));
              if (result.is_none()) return MonitorResult::Continue();
              return result.cast<MonitorResult>();
            });
          },
          py::arg("monitor"),
          "Calls monitor(context) after initialization and after every step; returning MonitorResult.Stop(why) ends "
          "AdvanceTo(), None or MonitorResult.Continue() goes on. None removes the monitor.")
      .def("get_context", &Simulator::get_context, py::return_value_policy::reference_internal,
           "The simulated context.")
      .def("get_mutable_context", &Simulator::get_mutable_context, py::return_value_policy::reference_internal,
           "The simulated context, for changing it (also after Initialize()).")
      .def("get_system", &Simulator::get_system, py::return_value_policy::reference_internal, "The simulated system.")
      .def("num_steps_taken", &Simulator::num_steps_taken, "Steps taken.")
      .def("num_discrete_updates", &Simulator::num_discrete_updates, "Discrete updates applied.")
      .def("num_unrestricted_updates", &Simulator::num_unrestricted_updates, "Unrestricted updates applied.")
      .def("num_publishes", &Simulator::num_publishes, "Publish events run.");

  // -------------------------------------------------------------------------------------------------------------
  // Primitives

  py::class_<Adder, LeafSystem>(m, "Adder",
                                "Sums its inputs u0 ... u<n-1> (vectors of size m) into output `sum` (direct "
                                "feedthrough).")
      .def(py::init<int, int>(), py::arg("num_inputs"), py::arg("size"), "`num_inputs` addends of `size`.");

  py::class_<ConstantVectorSource, LeafSystem>(m, "ConstantVectorSource",
                                               "Outputs a constant vector on `y0`; the value is a numeric parameter, "
                                               "so it can differ per context.")
      .def(py::init<const Eigen::VectorXd&>(), py::arg("value"), "Outputs `value`.")
      .def(
          "get_value",
          [](const ConstantVectorSource& self, const Context& context) {
            return Eigen::VectorXd(self.get_value(context));
          },
          py::arg("context"), "A copy of the value in `context`.")
      .def("SetValue", &ConstantVectorSource::SetValue, py::arg("context"), py::arg("value"),
           "Sets the value in `context`; the size must stay the same.");

  m.def(
      "ConstantValueSource",
      [](py::handle value) -> py::object {
        std::unique_ptr<AbstractValue> held = MakeAbstractValue(value);
        std::unique_ptr<System> source;
        if (held->type_info() == typeid(PythonObject)) {
          source = std::make_unique<ConstantValueSource<PythonObject>>(held->get_value<PythonObject>());
        } else {
          const AbstractValueType* type = FindAbstractValueType(held->type_info());
          source = type->make_constant_source(*held);
        }
        return py::cast(std::move(source));
      },
      py::arg("value"),
      "A system whose abstract output `y0` is the constant `value` (an AbstractValue, an instance of a bound C++ "
      "value class, or any Python object); the value is an abstract parameter, per context.");

  py::class_<FunctionSystem, LeafSystem>(m, "FunctionSystem",
                                         "Wraps a function y = f(t, u) as a system: input `u` (if input_size > 0), "
                                         "output `y` (direct feedthrough).")
      .def(py::init([](int input_size, int output_size, py::object function) {
             SharedPyObject held(std::move(function));
             return std::make_unique<FunctionSystem>(
                 input_size, output_size, [held, output_size](double time, const Eigen::VectorXd& u) {
                   py::gil_scoped_acquire gil;
                   py::object y = held.get()(time, CallbackConstVectorView(u.data(), u.size()));
                   auto result = y.cast<Eigen::VectorXd>();
                   if (result.size() != output_size) {
                     throw std::logic_error("FunctionSystem: the function returned a vector of size " +
                                            cairn::FormatShort(result.size()) + ", expected " +
                                            cairn::FormatShort(output_size));
                   }
                   return result;
                 });
           }),
           py::arg("input_size"), py::arg("output_size"), py::arg("function"),
           "`function(t, u)` returns y (array-like of `output_size`); u is a read-only view valid during the call.");

  py::class_<Gain, LeafSystem>(m, "Gain", "y = k * u elementwise, with a scalar or per-element gain k.")
      .def(py::init<double, int>(), py::arg("k"), py::arg("size"), "The same gain `k` on all `size` elements.")
      .def(py::init<const Eigen::VectorXd&>(), py::arg("k"), "A gain per element.")
      .def("k", [](const Gain& self) { return Eigen::VectorXd(self.k()); }, "The gains.");

  py::class_<Integrator, LeafSystem>(m, "Integrator", "Continuous integrator: x' = u, y = x (no direct feedthrough).")
      .def(py::init<int>(), py::arg("size"), "Initially zero.")
      .def(py::init<const Eigen::VectorXd&>(), py::arg("initial_value"), "Initially `initial_value`.");

  py::class_<PassThrough, LeafSystem>(m, "PassThrough", "Copies input `u` to output `y` (vector or abstract).")
      .def(py::init<int>(), py::arg("size"), "A vector pass-through of `size` elements.")
      .def(py::init([](py::handle model_value) { return std::make_unique<PassThrough>(*ModelValueFromPython(model_value)); }),
           py::arg("model_value"), "An abstract pass-through for values of `model_value`'s type.");

  py::class_<ZeroOrderHold, LeafSystem>(m, "ZeroOrderHold",
                                        "Samples input `u` every `period` (t = 0, period, ...) and holds it on `y`; "
                                        "the output never depends on the current input, so it breaks algebraic "
                                        "loops.")
      .def(py::init<double, int>(), py::arg("period"), py::arg("size"), "A vector hold of `size` elements.")
      .def(py::init([](double period, py::handle model_value) {
             return std::make_unique<ZeroOrderHold>(period, *ModelValueFromPython(model_value));
           }),
           py::arg("period"), py::arg("model_value"),
           "An abstract hold for values of `model_value`'s type, holding `model_value` until the first sample.")
      .def("period", &ZeroOrderHold::period, "The sampling period.");

  py::class_<VectorLog>(m, "VectorLog", "A time series of vectors of fixed size: what VectorLogSink records.")
      .def(py::init<int>(), py::arg("size") = 0, "An empty log of vectors of `size`.")
      .def("size", &VectorLog::size, "Size of each sample.")
      .def("num_samples", &VectorLog::num_samples, "Number of samples.")
      .def(
          "sample_times", [](const VectorLog& self) { return Eigen::VectorXd(self.sample_times()); },
          "A copy of the sample times (ascending as recorded).")
      .def(
          "data", [](const VectorLog& self) { return Eigen::MatrixXd(self.data()); },
          "A copy of the samples: size() x num_samples(), column k at sample_times()[k].")
      .def("AddData", &VectorLog::AddData, py::arg("time"), py::arg("value"),
           "Appends one sample; ValueError if its size differs.")
      .def("Clear", &VectorLog::Clear, "Removes every sample.")
      .def("WriteCsv", &VectorLog::WriteCsv, py::arg("path"), py::arg("column_names") = std::vector<std::string>{},
           "Writes \"time,<names...>\" and one row per sample, atomically.");

  py::class_<VectorLogSink, LeafSystem>(m, "VectorLogSink",
                                        "Records input `data` over time, in the context (each simulation has its own "
                                        "log): every step with publish_period = 0, else at t = 0, period, ...")
      .def(py::init<int, double>(), py::arg("size"), py::arg("publish_period") = 0.0, "Records vectors of `size`.")
      .def("GetLog", &VectorLogSink::GetLog, py::return_value_policy::reference, py::keep_alive<0, 2>(),
           py::arg("context"), "The log in `context` (this sink's own context within a diagram's).");

  m.def(
      "LogVectorOutput",
      [](const OutputPort& port, py::object builder, double publish_period) {
        VectorLogSink* sink = LogVectorOutput(port, &builder.cast<DiagramBuilder&>(), publish_period);
        py::object sink_object = py::cast(sink, py::return_value_policy::reference);
        Adopt(builder, sink_object);
        return sink_object;
      },
      py::arg("port"), py::arg("builder"), py::arg("publish_period") = 0.0,
      "Adds a VectorLogSink recording `port` to `builder` (publish_period as in VectorLogSink) and returns it.");
}

}  // namespace cairn::python
