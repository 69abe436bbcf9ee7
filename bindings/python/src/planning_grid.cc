// cairn.planning, grid part (seed 001): TraversabilityGrid, GridSearch (Dijkstra/A*), ProbingPlanner, the
// GridPathPlanner system, and the traverse scenario with its simulation (what `cairn traverse` runs).

#include <optional>
#include <random>
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
#include "cairn/planning/scenarios/path_follower.h"
#include "cairn/planning/scenarios/probe_arm.h"
#include "cairn/planning/scenarios/probe_arm_plant.h"
#include "cairn/planning/scenarios/probe_supervisor.h"
#include "cairn/planning/scenarios/probing_diagram.h"
#include "cairn/planning/scenarios/scenario_sensor.h"
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

  py::class_<TraverseScenario> scenario(m, "TraverseScenario", "A probing scenario read from YAML (docs/traverse.md).");
  py::enum_<TraverseScenario::ProbeModel>(scenario, "ProbeModel", "How a probe's force is simulated.")
      .value("kPlant", TraverseScenario::ProbeModel::kPlant, "The arm in the physics plant (ProbeArmPlant).")
      .value("kSpring", TraverseScenario::ProbeModel::kSpring, "stiffness x depth (fast).");
  scenario
      .def_static("Load", &TraverseScenario::Load, py::arg("path"), "Reads and validates a scenario file.")
      .def_readonly("start", &TraverseScenario::start, "Start x-y.")
      .def_readonly("goal", &TraverseScenario::goal, "Goal x-y.")
      .def_readonly("resolution", &TraverseScenario::resolution, "Map cell size, m.")
      .def("ClassAt", &TraverseScenario::ClassAt, py::arg("p"), "0 plants, 1 water, -1 none.")
      .def("TrueCollapsibility", &TraverseScenario::TrueCollapsibility, py::arg("p"), "Noiseless probe's C at p.")
      .def("StiffnessAt", &TraverseScenario::StiffnessAt, py::arg("p"), "Ground stiffness at p, N/m.")
      .def("HeightAt", &TraverseScenario::HeightAt, py::arg("p"), "Ground height at p, m.")
      .def_readwrite("probe_model", &TraverseScenario::probe_model, "ProbeModel.")
      .def_readwrite("probe_damping", &TraverseScenario::probe_damping, "Contact damping of supported ground, N s/m.")
      .def_readwrite("probe_depth", &TraverseScenario::probe_depth, "m.")
      .def_readwrite("probe_samples", &TraverseScenario::probe_samples, "Force samples per probe.")
      .def_readwrite("reach", &TraverseScenario::reach, "The arm's reach used by the probing planner, m.");

  py::class_<ProbeArmPlant> arm_plant(m, "ProbeArmPlant",
                                      "One probe simulated in the Bullet plant: the yaw-pitch-push arm "
                                      "(data/robots/cairn_probe_arm.urdf) pushes its tip into a terrain box.");
  py::class_<ProbeArmPlant::Options>(arm_plant, "Options", "Mount, depth, timing, sensor, gains.")
      .def(py::init<>(), "Defaults: 0.5 m mount, 2 cm depth, 20 samples, 2 N noise, 0.5 ms step.")
      .def_readwrite("mount_height", &ProbeArmPlant::Options::mount_height, "m.")
      .def_readwrite("clearance", &ProbeArmPlant::Options::clearance, "m.")
      .def_readwrite("depth", &ProbeArmPlant::Options::depth, "m.")
      .def_readwrite("push_time", &ProbeArmPlant::Options::push_time, "s.")
      .def_readwrite("hold_time", &ProbeArmPlant::Options::hold_time, "s.")
      .def_readwrite("samples", &ProbeArmPlant::Options::samples, "Readings during the hold.")
      .def_readwrite("noise", &ProbeArmPlant::Options::noise, "Sensor noise, N.")
      .def_readwrite("time_step", &ProbeArmPlant::Options::time_step, "s.")
      .def_readwrite("kp_rotary", &ProbeArmPlant::Options::kp_rotary, "Yaw and pitch stiffness, N m/rad.")
      .def_readwrite("kd_rotary", &ProbeArmPlant::Options::kd_rotary, "Yaw and pitch damping, N m s/rad.")
      .def_readwrite("kp_push", &ProbeArmPlant::Options::kp_push, "N/m.")
      .def_readwrite("kd_push", &ProbeArmPlant::Options::kd_push, "N s/m.")
      .def_readwrite("patch_size", &ProbeArmPlant::Options::patch_size, "m.");
  py::class_<ProbeArmPlant::Ground>(arm_plant, "Ground", "The ground under the target.")
      .def(py::init([](double height, double stiffness, double damping) {
             return ProbeArmPlant::Ground{height, stiffness, damping};
           }),
           py::arg("height") = 0.0, py::arg("stiffness") = 0.0, py::arg("damping") = 0.0,
           "Stiffness 0: no support (deep water); inf: rigid.")
      .def_readwrite("height", &ProbeArmPlant::Ground::height, "m.")
      .def_readwrite("stiffness", &ProbeArmPlant::Ground::stiffness, "N/m.")
      .def_readwrite("damping", &ProbeArmPlant::Ground::damping, "N s/m.");
  py::class_<ProbeArmPlant::Probe>(arm_plant, "Probe", "What one probe measured.")
      .def_readonly("forces", &ProbeArmPlant::Probe::forces, "Noisy readings, N.")
      .def_readonly("true_forces", &ProbeArmPlant::Probe::true_forces, "Noise-free readings, N.")
      .def_readonly("final_depth", &ProbeArmPlant::Probe::final_depth, "m below the surface.")
      .def_readonly("simulated_time", &ProbeArmPlant::Probe::simulated_time, "s.")
      .def_readonly("steps", &ProbeArmPlant::Probe::steps, "Plant steps.")
      .def_readonly("max_contact_points", &ProbeArmPlant::Probe::max_contact_points,
                    "Most tip contact points at a reading (the soft contact acts per point).");
  arm_plant
      .def_static("Load", &ProbeArmPlant::Load, py::arg("urdf_path"), py::arg("options") = ProbeArmPlant::Options{},
                  "Reads the arm's URDF.")
      .def("reach", &ProbeArmPlant::reach, "Farthest horizontal reach at full depth, m.")
      .def(
          "Run",
          [](const ProbeArmPlant& self, const Eigen::Vector2d& base, const Eigen::Vector2d& target,
             const ProbeArmPlant::Ground& ground, int seed) {
            std::mt19937 rng(static_cast<std::mt19937::result_type>(seed));
            py::gil_scoped_release release;
            return self.Run(base, target, ground, &rng);
          },
          py::arg("base"), py::arg("target"), py::arg("ground"), py::arg("seed") = 1,
          "Simulates one probe from a robot at `base` (x-y) of `target` (x-y), noise seeded by `seed`.");

  py::class_<ScenarioSensor, systems::LeafSystem>(
      m, "ScenarioSensor",
      "System: input `robot` (2); outputs `points_W` (3 x N), `sensor_W` (3), `probabilities` (2 x N) of the "
      "scenario's ground within sensor range.")
      .def(py::init<TraverseScenario>(), py::arg("scenario"), "The scenario's ground truth.")
      .def("get_robot_input_port", PortGetter(&ScenarioSensor::get_robot_input_port), "Input `robot`.");
  py::class_<ProbeArm, systems::LeafSystem>(
      m, "ProbeArm",
      "System: inputs `command` ([x, y, active]) and `robot` (2); outputs `force` (1) and `probing` (1): a probe "
      "simulated when the command switches on, its readings played out one per period.")
      .def(py::init([](TraverseScenario scenario, const std::string& urdf, double period) {
             std::optional<ProbeArmPlant> plant;
             if (scenario.probe_model == TraverseScenario::ProbeModel::kPlant) {
               plant = TraverseSimulation::MakeProbeArm(scenario, urdf);
             }
             return std::make_unique<ProbeArm>(std::move(scenario), std::move(plant), period);
           }),
           py::arg("scenario"), py::arg("probe_arm_urdf") = std::string(), py::arg("period") = 0.005,
           "The scenario's probe model decides plant (needs the URDF) or spring.")
      .def("get_command_input_port", PortGetter(&ProbeArm::get_command_input_port), "Input `command`.")
      .def("get_robot_input_port", PortGetter(&ProbeArm::get_robot_input_port), "Input `robot`.")
      .def("get_force_output_port", PortGetter(&ProbeArm::get_force_output_port), "Output `force`.")
      .def("get_probing_output_port", PortGetter(&ProbeArm::get_probing_output_port), "Output `probing`.")
      .def(
          "simulated_time",
          [](const ProbeArm& self, const systems::Context& context) { return self.memory(context).simulated_time; },
          py::arg("context"), "Plant time simulated by all probes so far, s.");
  py::class_<ProbeSupervisor, systems::LeafSystem>(
      m, "ProbeSupervisor",
      "System (seed 001 5.3): inputs `map` (GridMap), `robot` (2), `collapsibility` ([C, samples]); outputs "
      "`probes` (ProbedRegions), `probe_command` ([x, y, active]), `pause` (1).")
      .def(py::init<const ProbingPlanner::Options&, double, int, double>(), py::arg("options"),
           py::arg("semantic_threshold") = 0.5, py::arg("probe_periods") = 2, py::arg("period") = 0.1,
           "Planner options, class threshold, periods to wait for C, update period.")
      .def("get_map_input_port", PortGetter(&ProbeSupervisor::get_map_input_port), "Input `map`.")
      .def("get_robot_input_port", PortGetter(&ProbeSupervisor::get_robot_input_port), "Input `robot`.")
      .def("get_collapsibility_input_port", PortGetter(&ProbeSupervisor::get_collapsibility_input_port),
           "Input `collapsibility`.")
      .def("get_probes_output_port", PortGetter(&ProbeSupervisor::get_probes_output_port), "Output `probes`.")
      .def("get_probe_command_output_port", PortGetter(&ProbeSupervisor::get_probe_command_output_port),
           "Output `probe_command`.")
      .def("get_pause_output_port", PortGetter(&ProbeSupervisor::get_pause_output_port), "Output `pause`.")
      .def(
          "probes_made",
          [](const ProbeSupervisor& self, const systems::Context& context) { return self.memory(context).probes_made; },
          py::arg("context"), "Probes made so far (not counting inherited ones).");
  py::class_<PathFollower, systems::LeafSystem>(
      m, "PathFollower",
      "System: inputs `path` (2 x N), `pause` (1); output `position` (2): walks `step` m per period unless paused.")
      .def(py::init<const Eigen::Vector2d&, double, double>(), py::arg("start"), py::arg("step"), py::arg("period"),
           "Start x-y, step m, period s.")
      .def("get_path_input_port", PortGetter(&PathFollower::get_path_input_port), "Input `path`.")
      .def("get_pause_input_port", PortGetter(&PathFollower::get_pause_input_port), "Input `pause`.")
      .def("get_position_output_port", PortGetter(&PathFollower::get_position_output_port), "Output `position`.");

  py::class_<ProbingRun>(m, "ProbingRun", "What a run of the probing diagram did.")
      .def_readonly("final_position", &ProbingRun::final_position, "x-y.")
      .def_readonly("reached_goal", &ProbingRun::reached_goal, "Within a cell of the goal.")
      .def_readonly("time", &ProbingRun::time, "s.")
      .def_readonly("probes_made", &ProbingRun::probes_made, "Probes.")
      .def_readonly("collapsibilities", &ProbingRun::collapsibilities, "C of each probe.")
      .def_readonly("trajectory", &ProbingRun::trajectory, "Walker positions per period.")
      .def_readonly("failure", &ProbingRun::failure, "Why it stopped early.")
      .def_readonly("probes", &ProbingRun::probes, "TraverseSimulation.ProbeRecords.")
      .def_readonly("replans", &ProbingRun::replans, "The planner's replans.")
      .def_readonly("collapsible_steps", &ProbingRun::collapsible_steps, "Periods ended on C >= 0.5.")
      .def_readonly("regions_entered", &ProbingRun::regions_entered, "Region names.")
      .def_readonly("map", &ProbingRun::map, "The analyzer's final GridMap.")
      .def_readonly("probe_simulated_time", &ProbingRun::probe_simulated_time, "Plant time of all probes, s.");
  m.def("BuildProbingDiagram", &BuildProbingDiagram, py::arg("scenario"), py::arg("probe_arm_urdf") = std::string(),
        py::arg("probing") = true,
        "The probing diagram: sensor, mapper, analyzer, planner, supervisor, arm, probe_controller, walker.");
  m.def(
      "RunProbingDiagram",
      [](const TraverseScenario& scenario, const std::string& urdf, double max_time, bool probing) {
        py::gil_scoped_release release;
        return RunProbingDiagram(scenario, urdf, max_time, probing);
      },
      py::arg("scenario"), py::arg("probe_arm_urdf") = std::string(), py::arg("max_time") = 300.0,
      py::arg("probing") = true,
      "Builds and simulates the diagram until the goal or max_time.");

  py::class_<TraverseSimulation> simulation(m, "TraverseSimulation", "See, map, probe, plan, walk (cairn traverse).");
  py::class_<TraverseSimulation::Options>(simulation, "Options", "Probing on or off, threads.")
      .def(py::init<>(), "Defaults (probing on).")
      .def_readwrite("probing", &TraverseSimulation::Options::probing, "Probe questionable regions.")
      .def_readwrite("num_threads", &TraverseSimulation::Options::num_threads, "0: one per core.")
      .def_readwrite("probe_arm_urdf", &TraverseSimulation::Options::probe_arm_urdf,
                     "data/robots/cairn_probe_arm.urdf, for the plant probe model.");
  py::class_<TraverseSimulation::ProbeRecord>(simulation, "ProbeRecord", "One probe.")
      .def_readonly("tick", &TraverseSimulation::ProbeRecord::tick, "When.")
      .def_readonly("target", &TraverseSimulation::ProbeRecord::target, "Where.")
      .def_readonly("cluster_class", &TraverseSimulation::ProbeRecord::cluster_class, "plants or water.")
      .def_readonly("region", &TraverseSimulation::ProbeRecord::region, "Scenario region under the target.")
      .def_readonly("average_force", &TraverseSimulation::ProbeRecord::average_force, "N.")
      .def_readonly("collapsibility", &TraverseSimulation::ProbeRecord::collapsibility, "C.")
      .def_readonly("simulated_time", &TraverseSimulation::ProbeRecord::simulated_time, "Plant time, s.")
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
