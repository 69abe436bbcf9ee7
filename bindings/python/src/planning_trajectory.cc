// cairn.planning (whole-body part): the trajectory optimiser of thesis 2.5.1b -- options, environment boxes, the
// WholeBodyTrajectory result, OptimizeWholeBodyTrajectory and the TrajectoryOptimizer system.

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
#include "cairn/planning/trajectory/collision_penalty.h"
#include "cairn/planning/trajectory/environment_from_terrain.h"
#include "cairn/planning/trajectory/optimize_whole_body_trajectory.h"
#include "cairn/planning/trajectory/trajectory_optimizer.h"
#include "cairn/planning/trajectory/trajectory_optimizer_options.h"
#include "cairn/planning/trajectory/waypoint_spec.h"
#include "cairn/planning/trajectory/whole_body_trajectory.h"

namespace cairn::python {

using namespace cairn::planning;

void DefinePlanningTrajectory(py::module_ m) {
  py::class_<EnvironmentBox>(m, "EnvironmentBox", "A fixed obstacle box of the whole-body problem.")
      .def(py::init([](std::string name, const Eigen::Vector3d& size, const Eigen::Vector3d& center) {
             EnvironmentBox box;
             box.name = std::move(name);
             box.size = size;
             box.X_WB = multibody::Pose(Eigen::Matrix3d::Identity(), center);
             return box;
           }),
           py::arg("name"), py::arg("size"), py::arg("center"), "An axis-aligned box (full side lengths, m).")
      .def_readwrite("name", &EnvironmentBox::name, "Unique name.")
      .def_readwrite("size", &EnvironmentBox::size, "Full side lengths, m.")
      .def_readwrite("probability", &EnvironmentBox::probability,
                     "Probability that the box is there, in (0, 1]; weighs its collision penalty.")
      .def_property_readonly(
          "center", [](const EnvironmentBox& box) { return Eigen::Vector3d(box.X_WB.translation()); },
          "Centre, m.");
  m.def("EnvironmentFromTerrain", &EnvironmentFromTerrain, py::arg("terrain"),
        "The terrain's obstacles (probability 1) and occupied voxels (their probability) as EnvironmentBoxes.");

  py::class_<TrajectoryOptimizerOptions>(m, "TrajectoryOptimizerOptions", "Parameters of problem (2.9).")
      .def(py::init<>(), "The thesis' values (alpha = 50, d_safe = 2.5 cm), Ipopt.")
      .def_readwrite("collision_weight", &TrajectoryOptimizerOptions::collision_weight, "Alpha of eq. 2.9a.")
      .def_readwrite("d_safe", &TrajectoryOptimizerOptions::d_safe, "Penalty distance, m.")
      .def_readwrite("self_margin", &TrajectoryOptimizerOptions::self_margin, "Link-link margin, m.")
      .def_readwrite("samples_between", &TrajectoryOptimizerOptions::samples_between, "Collision samples.")
      .def_readwrite("torque_weight", &TrajectoryOptimizerOptions::torque_weight, "Torque cost weight.")
      .def_readwrite("smoothness_weight", &TrajectoryOptimizerOptions::smoothness_weight, "Smoothness weight.")
      .def_readwrite("base_rotation_smoothness_weight", &TrajectoryOptimizerOptions::base_rotation_smoothness_weight,
                     "Weight of the waist-orientation change between waypoints (0: off).")
      .def_readwrite("posture_weight", &TrajectoryOptimizerOptions::posture_weight, "Posture weight.")
      .def_readwrite("com_margin", &TrajectoryOptimizerOptions::com_margin, "COM margin, m.")
      .def_readwrite("ground_height", &TrajectoryOptimizerOptions::ground_height, "Ground plane, m (NaN: none).")
      .def_readwrite("ground_follows_terrain", &TrajectoryOptimizerOptions::ground_follows_terrain,
                     "With a terrain: the ground term follows its cells' planes instead of the level plane.")
      .def_readwrite("solver", &TrajectoryOptimizerOptions::solver, "Solver name (MakeSolver).")
      .def_readwrite("hessian", &TrajectoryOptimizerOptions::hessian,
                     "Ipopt's Hessian: 'exact', 'gauss-newton' or 'limited-memory'.")
      .def_readwrite("max_iterations", &TrajectoryOptimizerOptions::max_iterations, "Iteration budget.")
      .def_readwrite("tolerance", &TrajectoryOptimizerOptions::tolerance, "Solver tolerance.")
      .def_readwrite("window_stances", &TrajectoryOptimizerOptions::window_stances, "0: whole plan.")
      .def_readwrite("nominal_pelvis_height", &TrajectoryOptimizerOptions::nominal_pelvis_height,
                     "Pelvis height of the warm-start posture above the stance's mean foot height, m.");

  py::class_<WholeBodyWaypoint>(m, "WholeBodyWaypoint", "One waypoint q_t.")
      .def_readonly("time", &WholeBodyWaypoint::time, "s.")
      .def_readonly("stance", &WholeBodyWaypoint::stance, "Plan stance.")
      .def_readonly("single_support", &WholeBodyWaypoint::single_support, "Mid-swing.")
      .def_readonly("label", &WholeBodyWaypoint::label, "E.g. 'stance 3 start'.")
      .def_readonly("q", &WholeBodyWaypoint::q, "Configuration.")
      .def_readonly("contacts", &WholeBodyWaypoint::contacts, "Contact frames.")
      .def_readonly("com", &WholeBodyWaypoint::com, "Centre of mass.")
      .def_readonly("min_clearance", &WholeBodyWaypoint::min_clearance, "Smallest distance to the environment, m.")
      .def_readonly("torque_cost", &WholeBodyWaypoint::torque_cost,
                    "The cost's torque term at this waypoint: torques over effort limits, squared (the summands "
                    "of report.torque_cost).");

  py::class_<TrajectorySolveReport>(m, "TrajectorySolveReport", "How the solve went.")
      .def_readonly("success", &TrajectorySolveReport::success, "Converged and feasible.")
      .def_readonly("status", &TrajectorySolveReport::status, "Solver status.")
      .def_readonly("solver", &TrajectorySolveReport::solver, "Solver name.")
      .def_readonly("message", &TrajectorySolveReport::message, "One line, with the worst rows.")
      .def_readonly("violations", &TrajectorySolveReport::violations, "Most violated rows, by name.")
      .def_readonly("iterations", &TrajectorySolveReport::iterations, "Solver iterations.")
      .def_readonly("windows", &TrajectorySolveReport::windows, "Problems solved.")
      .def_readonly("seconds", &TrajectorySolveReport::seconds, "Wall time of the solves.")
      .def_readonly("objective", &TrajectorySolveReport::objective, "Objective at the solution.")
      .def_readonly("torque_cost", &TrajectorySolveReport::torque_cost, "Torque term alone at the solution.")
      .def_readonly("num_variables", &TrajectorySolveReport::num_variables, "Variables.")
      .def_readonly("num_constraints", &TrajectorySolveReport::num_constraints, "Constraint rows.");

  py::class_<WholeBodyTrajectory>(m, "WholeBodyTrajectory", "The whole-body optimiser's output.")
      .def(py::init<>(), "Empty.")
      .def_readonly("found", &WholeBodyTrajectory::found, "True if the solve succeeded.")
      .def_readonly("coordinate_names", &WholeBodyTrajectory::coordinate_names, "Names of q's entries.")
      .def_readonly("waypoints", &WholeBodyTrajectory::waypoints, "Waypoints.")
      .def_readonly("report", &WholeBodyTrajectory::report, "Solver report.");

  m.def(
      "OptimizeWholeBodyTrajectory",
      [](const multibody::Model& model, const FootstepPlan& plan, const std::vector<EnvironmentBox>& environment,
         const TrajectoryOptimizerOptions& options, const TerrainMap* terrain) {
        auto shared = std::make_shared<const multibody::Model>(model);
        py::gil_scoped_release release;
        return OptimizeWholeBodyTrajectory(std::move(shared), plan, environment, options, terrain);
      },
      py::arg("model"), py::arg("plan"), py::arg("environment") = std::vector<EnvironmentBox>(),
      py::arg("options") = TrajectoryOptimizerOptions(), py::arg("terrain") = nullptr,
      "Solves problem (2.9) for a footstep plan (a copy of the model is kept for the call); a `terrain` tilts the "
      "sole targets to its normals.");
  m.def("SoleTargetPose", &SoleTargetPose, py::arg("foot"), py::arg("terrain") = nullptr, py::arg("sole_length") = 0.24,
        py::arg("sole_width") = 0.14,
        "The sole pose the whole-body problem targets for a FootPose: its yaw, tilted onto the plane fitted to the "
        "terrain's heights under the sole (level without a terrain).");

  py::class_<TrajectoryOptimizer, systems::LeafSystem>(
      m, "TrajectoryOptimizer",
      "System: inputs `plan` (FootstepPlan), `environment` (list of EnvironmentBox), optional `terrain` "
      "(TerrainMap: tilts the soles to its normals); output `trajectory` (WholeBodyTrajectory), solved at "
      "initialization, on forced events and every `period` s when positive.")
      .def(py::init([](const multibody::Model& model, const TrajectoryOptimizerOptions& options, double period) {
             return std::make_unique<TrajectoryOptimizer>(std::make_shared<const multibody::Model>(model), options,
                                                          period);
           }),
           py::arg("model"), py::arg("options") = TrajectoryOptimizerOptions(), py::arg("period") = 0.0,
           "Keeps a copy of the model.")
      .def("get_plan_input_port", PortGetter(&TrajectoryOptimizer::get_plan_input_port), "Input `plan`.")
      .def("get_environment_input_port", PortGetter(&TrajectoryOptimizer::get_environment_input_port),
           "Input `environment`.")
      .def("get_terrain_input_port", PortGetter(&TrajectoryOptimizer::get_terrain_input_port),
           "Input `terrain` (optional).")
      .def("get_trajectory_output_port", PortGetter(&TrajectoryOptimizer::get_trajectory_output_port),
           "Output `trajectory`.");

  RegisterBoundAbstractValueType<WholeBodyTrajectory>("WholeBodyTrajectory");
  RegisterConvertedAbstractValueType<std::vector<EnvironmentBox>>("EnvironmentBoxes");
}

}  // namespace cairn::python
