// cairn.planning, grid part (seed 001): TraversabilityGrid, GridSearch (Dijkstra/A*), ProbingPlanner, the
// GridPathPlanner system, and the traverse scenario with its simulation (what `cairn traverse` runs).

#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "abstract_values.h"
#include "bindings.h"
#include "system_support.h"
#include "cairn/common/number_text.h"
#include "cairn/planning/grid/grid_path_planner.h"
#include "cairn/planning/grid/grid_search.h"
#include "cairn/planning/grid/probing_planner.h"
#include "cairn/planning/grid/traversability_grid.h"
#include "cairn/planning/scenarios/traverse_scenario.h"
#include "cairn/planning/scenarios/traverse_simulation.h"

namespace cairn::python {

using namespace cairn::planning;

void DefinePlanningGrid(py::module_ m) {
  py::class_<TraversabilityGrid>(m, "TraversabilityGrid", "A traversability raster [i, j] placed in the world.")
      .def(py::init([](const Eigen::MatrixXd& values, double resolution, const Eigen::Vector2d& min_corner) {
             TraversabilityGrid g;
             g.values = values;
             g.resolution = resolution;
             g.min_corner = min_corner;
             g.Validate();
             return g;
           }),
           py::arg("values"), py::arg("resolution") = 0.05, py::arg("min_corner") = Eigen::Vector2d::Zero(),
           "Values in [0, 1] or NaN (unknown); validated.")
      .def_readwrite("values", &TraversabilityGrid::values, "t by cell [i, j].")
      .def_readwrite("resolution", &TraversabilityGrid::resolution, "m.")
      .def_readwrite("min_corner", &TraversabilityGrid::min_corner, "World position of the minimum corner.")
      .def("CellCenter", &TraversabilityGrid::CellCenter, py::arg("cell"), "World centre of a cell.");

  py::class_<GridPath>(m, "GridPath", "What a grid search found.")
      .def_readonly("found", &GridPath::found, "Whether a path exists.")
      .def_readonly("cells", &GridPath::cells, "Cells from start to goal.")
      .def_readonly("cost", &GridPath::cost, "Sum of edge costs.")
      .def_readonly("length", &GridPath::length, "m.")
      .def_readonly("expansions", &GridPath::expansions, "States expanded.")
      .def_readonly("expansion_limit_reached", &GridPath::expansion_limit_reached, "The budget ran out.");

  py::class_<GridSearch> search(m, "GridSearch", "Dijkstra and A* on a TraversabilityGrid, 8-connected.");
  py::enum_<GridSearch::Algorithm>(search, "Algorithm", "Which search.")
      .value("kDijkstra", GridSearch::Algorithm::kDijkstra, "Dijkstra.")
      .value("kAStar", GridSearch::Algorithm::kAStar, "A* with the octile heuristic.");
  py::class_<GridSearch::Options>(search, "Options", "Algorithm, blocking threshold, unknown cells, budget.")
      .def(py::init<>(), "Defaults.")
      .def_readwrite("algorithm", &GridSearch::Options::algorithm, "Algorithm.")
      .def_readwrite("blocked_below", &GridSearch::Options::blocked_below, "Cells below this are blocked.")
      .def_readwrite("unknown_traversability", &GridSearch::Options::unknown_traversability, "t of unknown cells.")
      .def_readwrite("max_expansions", &GridSearch::Options::max_expansions, "Budget (negative: unlimited).");
  search.def(py::init<const GridSearch::Options&>(), py::arg("options") = GridSearch::Options{}, "With options.")
      .def(
          "Plan",
          [](const GridSearch& self, const TraversabilityGrid& grid, const Eigen::Vector2i& start,
             const Eigen::Vector2i& goal) {
            py::gil_scoped_release release;
            return self.Plan(grid, start, goal);
          },
          py::arg("grid"), py::arg("start"), py::arg("goal"), "The optimal path between two cells.")
      .def("PathCost", &GridSearch::PathCost, py::arg("grid"), py::arg("cells"),
           "Cost of a path on a (changed) grid; inf if blocked.");

  py::class_<ProbingPlanner> prober(m, "ProbingPlanner", "Where to probe questionable terrain next (seed 001 5.3).");
  py::class_<ProbingPlanner::Options>(prober, "Options", "Clustering, down-sampling and reach.")
      .def(py::init<>(), "Defaults.")
      .def_readwrite("cluster_distance", &ProbingPlanner::Options::cluster_distance, "m.")
      .def_readwrite("candidate_spacing", &ProbingPlanner::Options::candidate_spacing, "m.")
      .def_readwrite("reach", &ProbingPlanner::Options::reach, "m.")
      .def_readwrite("min_cluster_points", &ProbingPlanner::Options::min_cluster_points, "Smallest cluster.");
  py::class_<ProbingPlanner::Cluster>(prober, "Cluster", "Connected questionable points of one class.")
      .def_readonly("label", &ProbingPlanner::Cluster::label, "Class.")
      .def_readonly("members", &ProbingPlanner::Cluster::members, "Point indices.")
      .def_readonly("candidates", &ProbingPlanner::Cluster::candidates, "Candidate probe points.");
  py::class_<ProbingPlanner::Decision> decision(prober, "Decision", "What to do now.");
  py::enum_<ProbingPlanner::Decision::Action>(decision, "Action", "Probe, approach or nothing.")
      .value("kNone", ProbingPlanner::Decision::Action::kNone, "Nothing to probe.")
      .value("kApproach", ProbingPlanner::Decision::Action::kApproach, "Out of reach.")
      .value("kProbe", ProbingPlanner::Decision::Action::kProbe, "Pause and probe.");
  decision.def_readonly("action", &ProbingPlanner::Decision::action, "Action.")
      .def_readonly("cluster", &ProbingPlanner::Decision::cluster, "Index into the clusters.")
      .def_readonly("target", &ProbingPlanner::Decision::target, "Probe point.")
      .def_readonly("distance", &ProbingPlanner::Decision::distance, "From the robot, m.");
  prober.def(py::init<const ProbingPlanner::Options&>(), py::arg("options") = ProbingPlanner::Options{}, "With options.")
      .def("FindClusters", &ProbingPlanner::FindClusters, py::arg("points"), py::arg("labels"),
           "Clusters 2 x N points by class label (negative: skipped).")
      .def("Decide", &ProbingPlanner::Decide, py::arg("clusters"), py::arg("points"), py::arg("robot"),
           "The nearest candidate and whether it is within reach.")
      .def("RecordProbe", &ProbingPlanner::RecordProbe, py::arg("cluster"), py::arg("points"), py::arg("target"),
           py::arg("collapsibility"), "Records a probe's C for the cluster.")
      .def("TouchingProbe", &ProbingPlanner::TouchingProbe, py::arg("cluster"), py::arg("points"),
           "The recorded probe a cluster grows out of, or -1.");

  py::class_<GridPathPlanner, systems::LeafSystem>(
      m, "GridPathPlanner",
      "System: inputs `traversability` (array [i, j]), `start` (2), `goal` (2); outputs `path` (2 x N) and "
      "`status` ([found, cost, replans]); replanned every period.")
      .def(py::init<double, const Eigen::Vector2d&, const GridSearch::Options&, double>(), py::arg("resolution"),
           py::arg("min_corner"), py::arg("options"), py::arg("period"), "Raster placement, search, period.")
      .def("get_traversability_input_port", PortGetter(&GridPathPlanner::get_traversability_input_port),
           "Input `traversability`.")
      .def("get_start_input_port", PortGetter(&GridPathPlanner::get_start_input_port), "Input `start`.")
      .def("get_goal_input_port", PortGetter(&GridPathPlanner::get_goal_input_port), "Input `goal`.")
      .def("get_path_output_port", PortGetter(&GridPathPlanner::get_path_output_port), "Output `path`.")
      .def("get_status_output_port", PortGetter(&GridPathPlanner::get_status_output_port), "Output `status`.");

  py::class_<TraverseScenario>(m, "TraverseScenario", "A probing scenario read from YAML (docs/traverse.md).")
      .def_static("Load", &TraverseScenario::Load, py::arg("path"), "Reads and validates a scenario file.")
      .def_readonly("start", &TraverseScenario::start, "Start x-y.")
      .def_readonly("goal", &TraverseScenario::goal, "Goal x-y.")
      .def_readonly("resolution", &TraverseScenario::resolution, "Map cell size, m.")
      .def("ClassAt", &TraverseScenario::ClassAt, py::arg("p"), "0 plants, 1 water, -1 none.")
      .def("TrueCollapsibility", &TraverseScenario::TrueCollapsibility, py::arg("p"), "Noiseless probe's C at p.");

  py::class_<TraverseSimulation> simulation(m, "TraverseSimulation", "See, map, probe, plan, walk (cairn traverse).");
  py::class_<TraverseSimulation::Options>(simulation, "Options", "Probing on or off, threads.")
      .def(py::init<>(), "Defaults (probing on).")
      .def_readwrite("probing", &TraverseSimulation::Options::probing, "Probe questionable regions.")
      .def_readwrite("num_threads", &TraverseSimulation::Options::num_threads, "0: one per core.");
  py::class_<TraverseSimulation::ProbeRecord>(simulation, "ProbeRecord", "One probe.")
      .def_readonly("tick", &TraverseSimulation::ProbeRecord::tick, "When.")
      .def_readonly("target", &TraverseSimulation::ProbeRecord::target, "Where.")
      .def_readonly("cluster_class", &TraverseSimulation::ProbeRecord::cluster_class, "plants or water.")
      .def_readonly("region", &TraverseSimulation::ProbeRecord::region, "Scenario region under the target.")
      .def_readonly("average_force", &TraverseSimulation::ProbeRecord::average_force, "N.")
      .def_readonly("collapsibility", &TraverseSimulation::ProbeRecord::collapsibility, "C.")
      .def_readonly("path_crossed_cluster", &TraverseSimulation::ProbeRecord::path_crossed_cluster,
                    "The plan before crossed the cluster.")
      .def_readonly("path_crosses_after", &TraverseSimulation::ProbeRecord::path_crosses_after,
                    "The plan after crosses it.");
  py::class_<TraverseSimulation::Result>(simulation, "Result", "What a run did.")
      .def_readonly("reached_goal", &TraverseSimulation::Result::reached_goal, "Goal reached.")
      .def_readonly("ticks", &TraverseSimulation::Result::ticks, "Ticks run.")
      .def_readonly("trajectory", &TraverseSimulation::Result::trajectory, "Positions.")
      .def_readonly("distance_walked", &TraverseSimulation::Result::distance_walked, "m.")
      .def_readonly("probes", &TraverseSimulation::Result::probes, "ProbeRecords.")
      .def_readonly("replans", &TraverseSimulation::Result::replans, "Plans forced by map changes.")
      .def_readonly("collapsible_steps", &TraverseSimulation::Result::collapsible_steps, "Steps on C >= 0.5.")
      .def_readonly("regions_entered", &TraverseSimulation::Result::regions_entered, "Region names.")
      .def_readonly("failure", &TraverseSimulation::Result::failure, "Why it stopped early.")
      .def_readonly("map", &TraverseSimulation::Result::map, "The final global GridMap.");
  simulation
      .def(py::init<TraverseScenario, const TraverseSimulation::Options&>(), py::arg("scenario"),
           py::arg("options") = TraverseSimulation::Options{}, "A run of the scenario.")
      .def(
          "Run",
          [](const TraverseSimulation& self) {
            py::gil_scoped_release release;
            return self.Run();
          },
          "Runs to the goal, max_ticks or a dead end.");

  RegisterConvertedAbstractValueType<Eigen::Matrix2Xd>("Matrix2Xd");
}

}  // namespace cairn::python
