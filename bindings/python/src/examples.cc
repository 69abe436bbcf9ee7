// cairn.examples: the systems of examples/systems (a pendulum plant and a PD controller), so that Python diagrams
// can mix them with systems written in Python (examples/python/pendulum.py).

#include <memory>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "examples/systems/pd_controller.h"
#include "examples/systems/pendulum_example.h"
#include "examples/systems/pendulum_plant.h"

namespace cairn::python {

using namespace cairn::examples;

void DefineExamples(py::module_ m) {
  py::class_<PendulumParameters>(m, "PendulumParameters",
                                 "Point-mass pendulum on a massless rod with viscous joint damping.")
      .def(py::init<>(), "1 kg, 0.5 m, damping 0.1 N m s, g = 9.81.")
      .def_readwrite("mass", &PendulumParameters::mass, "kg.")
      .def_readwrite("length", &PendulumParameters::length, "m.")
      .def_readwrite("damping", &PendulumParameters::damping, "N m s / rad.")
      .def_readwrite("gravity", &PendulumParameters::gravity, "m / s^2.");

  py::class_<PendulumPlant, systems::LeafSystem>(
      m, "PendulumPlant",
      "m l^2 theta'' = tau - b theta' - m g l sin(theta): input `torque` (size 1), output `state` (theta, theta'), "
      "no direct feedthrough; continuous state (theta, theta').")
      .def(py::init<const PendulumParameters&>(), py::arg("parameters") = PendulumParameters(), "A plant.")
      .def("GetParameters", &PendulumPlant::GetParameters, py::arg("context"), "The parameters in `context`.")
      .def("CalcTotalEnergy", &PendulumPlant::CalcTotalEnergy, py::arg("context"),
           "Kinetic + potential energy (zero hanging at rest).");

  py::class_<PdController, systems::LeafSystem>(m, "PdController",
                                                "tau = kp (theta_d - theta) - kd theta': input `state` (2), output "
                                                "`torque` (1), direct feedthrough.")
      .def(py::init<double, double, double>(), py::arg("kp"), py::arg("kd"), py::arg("theta_desired"), "Gains.");

  py::class_<PendulumExampleOptions>(m, "PendulumExampleOptions", "Settings of the C++ pendulum example.")
      .def(py::init<>(), "kp 5, kd 0.5, 45 degrees, 1 ms control period, 10 s.")
      .def_readwrite("plant", &PendulumExampleOptions::plant, "PendulumParameters.")
      .def_readwrite("kp", &PendulumExampleOptions::kp, "N m / rad.")
      .def_readwrite("kd", &PendulumExampleOptions::kd, "N m s / rad.")
      .def_readwrite("theta_desired", &PendulumExampleOptions::theta_desired, "rad.")
      .def_readwrite("control_period", &PendulumExampleOptions::control_period, "s.")
      .def_readwrite("initial_state", &PendulumExampleOptions::initial_state, "(theta, theta').")
      .def_readwrite("duration", &PendulumExampleOptions::duration, "s.")
      .def_readwrite("integrator", &PendulumExampleOptions::integrator, "\"euler\", \"rk4\" or \"rk45\".")
      .def_readwrite("max_step", &PendulumExampleOptions::max_step, "s.")
      .def_readwrite("log_period", &PendulumExampleOptions::log_period, "s; 0 logs every step.");

  m.def("BuildPendulumDiagram", &BuildPendulumDiagram, py::arg("options") = PendulumExampleOptions(),
        "The C++ example's diagram: plant -> hold -> controller -> plant, plant -> logger.");
}

}  // namespace cairn::python
