// cairn.planning (stabilisation part): interpolation and ZMP stabilisation of thesis 2.5.1c -- options, the
// stabilised reference and its report, StabilizeTrajectory, the full model's ZMP, preview control on the cart-table
// model, the Riccati solver under it, and the Stabilizer system.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "abstract_values.h"
#include "bindings.h"
#include "system_support.h"
#include "cairn/multibody/model.h"
#include "cairn/planning/stabilization/cart_table_preview_controller.h"
#include "cairn/planning/stabilization/discrete_riccati.h"
#include "cairn/planning/stabilization/motion_zmp.h"
#include "cairn/planning/stabilization/stabilize_trajectory.h"
#include "cairn/planning/stabilization/stabilized_trajectory.h"
#include "cairn/planning/stabilization/stabilizer.h"
#include "cairn/planning/stabilization/stabilizer_options.h"

namespace cairn::python {

using namespace cairn::planning;

void DefinePlanningStabilization(py::module_ m) {
  py::class_<StabilizerOptions>(m, "StabilizerOptions", "Parameters of interpolation and ZMP stabilisation.")
      .def(py::init<>(), "FFT compensation, Hermite interpolation at 200 Hz, Kajita's preview defaults.")
      .def_readwrite("method", &StabilizerOptions::method, "'fft', 'preview' or 'none'.")
      .def_readwrite("interpolation", &StabilizerOptions::interpolation, "'hermite' or 'spline'.")
      .def_readwrite("control_period", &StabilizerOptions::control_period, "Sampling period, s.")
      .def_readwrite("contact_timing", &StabilizerOptions::contact_timing, "Re-time knots to contact events.")
      .def_readwrite("cart_table_start", &StabilizerOptions::cart_table_start,
                     "Start from the cart-table COM of the reference ZMP.")
      .def_readwrite("crouch", &StabilizerOptions::crouch, "With contact timing: lower the waist by this (m).")
      .def_readwrite("landing_height", &StabilizerOptions::landing_height,
                     "With contact timing: the swing sole's last this (m) is a straight descent at constant speed.")
      .def_readwrite("landing_time", &StabilizerOptions::landing_time,
                     "Duration of that descent (s), at most half of each swing; both 0 or both > 0.")
      .def_readwrite("max_iterations", &StabilizerOptions::max_iterations, "Compensation passes.")
      .def_readwrite("step_fraction", &StabilizerOptions::step_fraction, "Fraction of each pass's offsets applied.")
      .def_readwrite("tolerance", &StabilizerOptions::tolerance, "RMS ZMP error to stop at, m.")
      .def_readwrite("min_improvement", &StabilizerOptions::min_improvement, "Smallest relative gain per pass.")
      .def_readwrite("preview_time", &StabilizerOptions::preview_time, "Preview horizon, s.")
      .def_readwrite("preview_q", &StabilizerOptions::preview_q, "Weight of the ZMP error.")
      .def_readwrite("preview_r", &StabilizerOptions::preview_r, "Weight of the jerk increment.")
      .def_readwrite("fft_padding", &StabilizerOptions::fft_padding, "Zero padding on each side, s.")
      .def_readwrite("waist_orientation", &StabilizerOptions::waist_orientation, "'interpolated' or 'upright'.")
      .def_readwrite("sole_length", &StabilizerOptions::sole_length, "Sole length, m.")
      .def_readwrite("sole_width", &StabilizerOptions::sole_width, "Sole width, m.");

  py::class_<StabilizationReport>(m, "StabilizationReport", "ZMP errors before and after, and how it went.")
      .def_readonly("success", &StabilizationReport::success, "A reference was produced.")
      .def_readonly("method", &StabilizationReport::method, "The method.")
      .def_readonly("message", &StabilizationReport::message, "One line.")
      .def_readonly("rms_error_before", &StabilizationReport::rms_error_before, "m.")
      .def_readonly("max_error_before", &StabilizationReport::max_error_before, "m.")
      .def_readonly("rms_error_after", &StabilizationReport::rms_error_after, "m.")
      .def_readonly("max_error_after", &StabilizationReport::max_error_after, "m.")
      .def_readonly("min_support_margin_before", &StabilizationReport::min_support_margin_before, "m.")
      .def_readonly("min_support_margin_after", &StabilizationReport::min_support_margin_after, "m.")
      .def_readonly("unsupported_samples_before", &StabilizationReport::unsupported_samples_before, "f_z <= 0.")
      .def_readonly("unsupported_samples_after", &StabilizationReport::unsupported_samples_after, "f_z <= 0.")
      .def_readonly("iterations", &StabilizationReport::iterations, "Passes kept.")
      .def_readonly("joint_limits_held", &StabilizationReport::joint_limits_held, "Within the limits.")
      .def_readonly("max_ik_error", &StabilizationReport::max_ik_error, "Largest sole error of the leg IK, m.")
      .def_readonly("seconds", &StabilizationReport::seconds, "Wall time.");

  py::class_<StabilizedTrajectory>(m, "StabilizedTrajectory", "Dense q, v at the control rate and the ZMPs.")
      .def(py::init<>(), "Empty.")
      .def_readonly("period", &StabilizedTrajectory::period, "s between samples.")
      .def_readonly("q", &StabilizedTrajectory::q, "Configurations.")
      .def_readonly("v", &StabilizedTrajectory::v, "Velocities.")
      .def_readonly("zmp_reference", &StabilizedTrajectory::zmp_reference, "Reference ZMP per sample.")
      .def_readonly("zmp", &StabilizedTrajectory::zmp, "ZMP of the stabilised motion (full model).")
      .def_readonly("zmp_before", &StabilizedTrajectory::zmp_before, "ZMP of the interpolated motion.")
      .def_readonly("com", &StabilizedTrajectory::com, "Horizontal COM.")
      .def_readonly("contacts", &StabilizedTrajectory::contacts, "Bit 0 left, bit 1 right sole loaded.")
      .def_readonly("report", &StabilizedTrajectory::report, "The report.")
      .def("duration", &StabilizedTrajectory::duration, "s.");

  m.def("WalkingStabilizerOptions", &WalkingStabilizerOptions, py::arg("method") = "fft",
        "The defaults with what a walk in the plant needs: contact timing, an upright waist, the cart-table start, "
        "a 6 cm crouch.");

  m.def(
      "StabilizeTrajectory",
      [](const multibody::Model& model, const WholeBodyTrajectory& trajectory, const StabilizerOptions& options) {
        auto shared = std::make_shared<const multibody::Model>(model);
        py::gil_scoped_release release;
        return StabilizeTrajectory(std::move(shared), trajectory, options);
      },
      py::arg("model"), py::arg("trajectory"), py::arg("options") = StabilizerOptions(),
      "Interpolates and stabilises a whole-body trajectory (a copy of the model is kept for the call).");

  m.def(
      "ComputeMotionZmp",
      [](const multibody::Model& model, const std::vector<Eigen::VectorXd>& q, double period,
         const std::vector<double>& ground_height) { return ComputeMotionZmp(model, q, period, ground_height); },
      py::arg("model"), py::arg("q"), py::arg("period"), py::arg("ground_height") = std::vector<double>{0.0},
      "The ZMP of sampled configurations from the full rigid-body model (NaN where no support force).");

  m.def("SolveDiscreteAlgebraicRiccati", &SolveDiscreteAlgebraicRiccati, py::arg("A"), py::arg("B"), py::arg("Q"),
        py::arg("R"), "The stabilising solution of the discrete algebraic Riccati equation (doubling).");

  py::class_<CartTableMotion>(m, "CartTableMotion", "A COM motion of the cart-table model and its ZMP.")
      .def_readonly("position", &CartTableMotion::position, "m.")
      .def_readonly("velocity", &CartTableMotion::velocity, "m/s.")
      .def_readonly("acceleration", &CartTableMotion::acceleration, "m/s^2.")
      .def_readonly("zmp", &CartTableMotion::zmp, "m.");

  py::class_<CartTablePreviewController>(m, "CartTablePreviewController",
                                         "Kajita's ZMP preview control on the cart-table model (one axis).")
      .def(py::init<double, double, double, double, double, double>(), py::arg("dt"), py::arg("com_height"),
           py::arg("gravity") = 9.81, py::arg("preview") = 1.6, py::arg("q") = 1.0, py::arg("r") = 1e-6,
           "Computes the gains.")
      .def("Track", &CartTablePreviewController::Track, py::arg("zmp_reference"), py::arg("start") = 0.0,
           "Runs the controller from rest along the reference ZMP.")
      .def("integral_gain", &CartTablePreviewController::integral_gain, "G_i.")
      .def("preview_gains", &CartTablePreviewController::preview_gains, "G_d(1..N).");

  py::class_<Stabilizer, systems::LeafSystem>(
      m, "Stabilizer",
      "System: input `trajectory` (WholeBodyTrajectory); output `reference` (StabilizedTrajectory), computed at "
      "initialization, on forced events and when the input changes.")
      .def(py::init([](const multibody::Model& model, const StabilizerOptions& options) {
             return std::make_unique<Stabilizer>(std::make_shared<const multibody::Model>(model), options);
           }),
           py::arg("model"), py::arg("options") = StabilizerOptions(), "Keeps a copy of the model.")
      .def("get_trajectory_input_port", PortGetter(&Stabilizer::get_trajectory_input_port), "Input `trajectory`.")
      .def("get_reference_output_port", PortGetter(&Stabilizer::get_reference_output_port), "Output `reference`.");

  RegisterBoundAbstractValueType<StabilizedTrajectory>("StabilizedTrajectory");
}

}  // namespace cairn::python
