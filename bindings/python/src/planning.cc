// cairn.planning: footstep scenarios and terrain, the walking model and its transition oracle, PlanFootsteps and
// the FootstepPlanner system. Plans and their parts are plain value classes (picklable, with to_dict()).

#include <chrono>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "abstract_values.h"
#include "bindings.h"
#include "system_support.h"
#include "cairn/common/number_text.h"
#include "cairn/planning/footstep/ara_star.h"
#include "cairn/planning/footstep/biped_geometry.h"
#include "cairn/planning/footstep/foot_pose.h"
#include "cairn/planning/footstep/footstep_plan.h"
#include "cairn/planning/footstep/footstep_planner.h"
#include "cairn/planning/footstep/footstep_planner_options.h"
#include "cairn/planning/footstep/footstep_replanner.h"
#include "cairn/planning/footstep/plan_footsteps.h"
#include "cairn/planning/footstep/refine_footstep_plan.h"
#include "cairn/planning/footstep/terrain_map.h"
#include "cairn/planning/locomotion/model_transition_source.h"
#include "cairn/planning/locomotion/oracle_held_out_error.h"
#include "cairn/planning/locomotion/oracle_shard_builder.h"
#include "cairn/planning/locomotion/step_cost_model.h"
#include "cairn/planning/locomotion/transition_oracle.h"
#include "cairn/planning/locomotion/transition_source.h"
#include "cairn/planning/locomotion/walking_model.h"
#include "cairn/planning/locomotion/walking_objective.h"
#include "cairn/planning/scenarios/footstep_scenario.h"

namespace cairn::python {

using namespace cairn::planning;

namespace {

py::dict PoseDict(const FootPose& p) {
  py::dict d;
  d["x"] = p.x;
  d["y"] = p.y;
  d["z"] = p.z;
  d["theta"] = p.theta;
  return d;
}

py::dict PlanDict(const FootstepPlan& plan) {
  py::dict d;
  d["found"] = plan.found;
  d["reason"] = plan.reason;
  d["start"] = py::dict(py::arg("left") = PoseDict(plan.start.left), py::arg("right") = PoseDict(plan.start.right));
  d["first_side"] = FootSideName(plan.first_side);
  py::list steps;
  for (const PlannedStep& s : plan.steps) {
    py::dict step = PoseDict(s.pose);
    step["side"] = FootSideName(s.side);
    step["t_ds"] = s.transition.parameters.t_ds;
    step["t_sw"] = s.transition.parameters.t_sw;
    step["com_height"] = s.transition.parameters.com_height;
    step["cost"] = s.transition.cost;
    step["com_work"] = s.transition.com_work;
    step["heat"] = s.transition.heat;
    step["energy"] = s.transition.com_work + s.transition.heat;
    step["rcof"] = s.transition.rcof;
    step["duration"] = s.transition.duration;
    step["mu_allowed"] = s.mu_allowed;
    steps.append(step);
  }
  d["steps"] = steps;
  d["cost"] = plan.cost;
  d["energy"] = plan.energy;
  d["duration"] = plan.duration;
  d["distance"] = plan.distance;
  d["max_rcof"] = plan.max_rcof;
  d["min_friction_margin"] = plan.min_friction_margin;
  d["cost_model"] = plan.cost_model;
  const FootstepPlanStatistics& st = plan.statistics;
  d["statistics"] = py::dict(py::arg("expansions") = st.expansions, py::arg("generated") = st.generated,
                             py::arg("plan_seconds") = st.plan_seconds,
                             py::arg("first_plan_seconds") = st.first_plan_seconds, py::arg("epsilon") = st.epsilon,
                             py::arg("improvements") = st.improvements,
                             py::arg("rejected_support") = st.rejected_support,
                             py::arg("rejected_collision") = st.rejected_collision,
                             py::arg("rejected_friction") = st.rejected_friction);
  return d;
}

void CheckState(const py::tuple& t, std::size_t size, const char* what) {
  if (t.size() != size) throw std::runtime_error(std::string(what) + ": bad pickle state");
}

template <typename Array>
py::array_t<double> CellArray(const TerrainMap& terrain, Array value) {
  py::array_t<double> out({static_cast<py::ssize_t>(terrain.rows()), static_cast<py::ssize_t>(terrain.cols())});
  auto view = out.mutable_unchecked<2>();
  for (int r = 0; r < terrain.rows(); ++r) {
    for (int c = 0; c < terrain.cols(); ++c) view(r, c) = value(c, r);
  }
  return out;
}

void CheckTerrainCell(const TerrainMap& terrain, int col, int row) {
  if (col < 0 || col >= terrain.cols() || row < 0 || row >= terrain.rows()) {
    throw py::index_error("cell (" + cairn::FormatShort(col) + ", " + cairn::FormatShort(row) + ") is outside the " +
                          cairn::FormatShort(terrain.cols()) + " x " + cairn::FormatShort(terrain.rows()) + " terrain");
  }
}

}  // namespace

void DefinePlanning(py::module_ m) {
  py::enum_<FootSide>(m, "FootSide", "Which foot.")
      .value("kLeft", FootSide::kLeft, "Left.")
      .value("kRight", FootSide::kRight, "Right.");
  m.def("FootSideName", &FootSideName, py::arg("side"), "\"left\" or \"right\".");
  m.def("OtherSide", &OtherSide, py::arg("side"), "The other foot.");

  py::class_<FootPose>(m, "FootPose", "A foothold: sole centre (x, y, z) and yaw theta in the world (picklable).")
      .def(py::init([](double x, double y, double z, double theta) { return FootPose{x, y, z, theta}; }),
           py::arg("x") = 0.0, py::arg("y") = 0.0, py::arg("z") = 0.0, py::arg("theta") = 0.0, "From values.")
      .def_readwrite("x", &FootPose::x, "m.")
      .def_readwrite("y", &FootPose::y, "m.")
      .def_readwrite("z", &FootPose::z, "m.")
      .def_readwrite("theta", &FootPose::theta, "Yaw, rad, counter-clockwise from x.")
      .def("to_dict", &PoseDict, "{x, y, z, theta}.")
      .def(py::pickle([](const FootPose& p) { return py::make_tuple(p.x, p.y, p.z, p.theta); },
                      [](const py::tuple& t) {
                        CheckState(t, 4, "FootPose");
                        return FootPose{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(),
                                        t[3].cast<double>()};
                      }),
           "Pickles the four values.")
      .def("__repr__", [](const FootPose& p) {
        return "FootPose(x=" + cairn::FormatShort(p.x) + ", y=" + cairn::FormatShort(p.y) + ", z=" + cairn::FormatShort(p.z) +
               ", theta=" + cairn::FormatShort(p.theta) + ")";
      }, "FootPose(x=..., y=..., z=..., theta=...).");

  py::class_<Stance>(m, "Stance", "Two feet on the ground (picklable).")
      .def(py::init([](const FootPose& left, const FootPose& right) { return Stance{left, right}; }),
           py::arg("left") = FootPose{}, py::arg("right") = FootPose{}, "From the two feet.")
      .def_readwrite("left", &Stance::left, "Left foot.")
      .def_readwrite("right", &Stance::right, "Right foot.")
      .def(py::pickle([](const Stance& s) { return py::make_tuple(s.left, s.right); },
                      [](const py::tuple& t) {
                        CheckState(t, 2, "Stance");
                        return Stance{t[0].cast<FootPose>(), t[1].cast<FootPose>()};
                      }),
           "Pickles both feet.");

  py::class_<StanceGoal>(m, "StanceGoal", "Where a plan must end, with tolerances (picklable).")
      .def(py::init([](const Stance& stance, double position_tolerance, double yaw_tolerance) {
             return StanceGoal{stance, position_tolerance, yaw_tolerance};
           }),
           py::arg("stance") = Stance{}, py::arg("position_tolerance") = 0.1, py::arg("yaw_tolerance") = 0.27,
           "From a stance and tolerances (m, rad).")
      .def_readwrite("stance", &StanceGoal::stance, "The goal stance.")
      .def_readwrite("position_tolerance", &StanceGoal::position_tolerance, "m.")
      .def_readwrite("yaw_tolerance", &StanceGoal::yaw_tolerance, "rad.")
      .def(py::pickle(
               [](const StanceGoal& g) { return py::make_tuple(g.stance, g.position_tolerance, g.yaw_tolerance); },
               [](const py::tuple& t) {
                 CheckState(t, 3, "StanceGoal");
                 return StanceGoal{t[0].cast<Stance>(), t[1].cast<double>(), t[2].cast<double>()};
               }),
           "Pickles stance and tolerances.");

  py::class_<StepDisplacement>(m, "StepDisplacement", "The next foot relative to the stance foot (mirrored).")
      .def(py::init([](double dx, double dy, double dz, double dtheta) { return StepDisplacement{dx, dy, dz, dtheta}; }),
           py::arg("dx") = 0.0, py::arg("dy") = 0.0, py::arg("dz") = 0.0, py::arg("dtheta") = 0.0, "From values.")
      .def_readwrite("dx", &StepDisplacement::dx, "Forward, m.")
      .def_readwrite("dy", &StepDisplacement::dy, "Outward, m.")
      .def_readwrite("dz", &StepDisplacement::dz, "Up, m.")
      .def_readwrite("dtheta", &StepDisplacement::dtheta, "Outward yaw, rad.")
      .def(py::pickle([](const StepDisplacement& d) { return py::make_tuple(d.dx, d.dy, d.dz, d.dtheta); },
                      [](const py::tuple& t) {
                        CheckState(t, 4, "StepDisplacement");
                        return StepDisplacement{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(),
                                                t[3].cast<double>()};
                      }),
           "Pickles the four values.");

  py::class_<StepParameters>(m, "StepParameters", "Double-support time, swing time, COM height of a step.")
      .def(py::init([](double t_ds, double t_sw, double com_height) { return StepParameters{t_ds, t_sw, com_height}; }),
           py::arg("t_ds") = 0.0, py::arg("t_sw") = 0.0, py::arg("com_height") = 0.0, "From values.")
      .def_readwrite("t_ds", &StepParameters::t_ds, "s.")
      .def_readwrite("t_sw", &StepParameters::t_sw, "s.")
      .def_readwrite("com_height", &StepParameters::com_height, "m.")
      .def(py::pickle([](const StepParameters& p) { return py::make_tuple(p.t_ds, p.t_sw, p.com_height); },
                      [](const py::tuple& t) {
                        CheckState(t, 3, "StepParameters");
                        return StepParameters{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>()};
                      }),
           "Pickles the three values.");

  py::class_<StepReach>(m, "StepReach", "Reachability box of a step.")
      .def_readonly("dx_min", &StepReach::dx_min, "m.")
      .def_readonly("dx_max", &StepReach::dx_max, "m.")
      .def_readonly("dy_min", &StepReach::dy_min, "m.")
      .def_readonly("dy_max", &StepReach::dy_max, "m.")
      .def_readonly("dz_min", &StepReach::dz_min, "m.")
      .def_readonly("dz_max", &StepReach::dz_max, "m.")
      .def_readonly("dtheta_min", &StepReach::dtheta_min, "rad.")
      .def_readonly("dtheta_max", &StepReach::dtheta_max, "rad.")
      .def("Contains", &StepReach::Contains, py::arg("d"), "True if the displacement is inside.");

  py::class_<TransitionCost>(m, "TransitionCost", "The minimum-cost transition and what it predicts (picklable).")
      .def(py::init<>(), "Infeasible.")
      .def_readwrite("feasible", &TransitionCost::feasible, "Feasible under the friction limit.")
      .def_readwrite("cost", &TransitionCost::cost, "Objective value.")
      .def_readwrite("parameters", &TransitionCost::parameters, "Optimal step parameters.")
      .def_readwrite("com_work", &TransitionCost::com_work, "E_COM, J.")
      .def_readwrite("heat", &TransitionCost::heat, "Motor heat, J.")
      .def_readwrite("rcof", &TransitionCost::rcof, "Required coefficient of friction.")
      .def_readwrite("duration", &TransitionCost::duration, "s.")
      .def(py::pickle(
               [](const TransitionCost& c) {
                 return py::make_tuple(c.feasible, c.cost, c.parameters, c.com_work, c.heat, c.rcof, c.duration);
               },
               [](const py::tuple& t) {
                 CheckState(t, 7, "TransitionCost");
                 TransitionCost c;
                 c.feasible = t[0].cast<bool>();
                 c.cost = t[1].cast<double>();
                 c.parameters = t[2].cast<StepParameters>();
                 c.com_work = t[3].cast<double>();
                 c.heat = t[4].cast<double>();
                 c.rcof = t[5].cast<double>();
                 c.duration = t[6].cast<double>();
                 return c;
               }),
           "Pickles every field.");

  py::class_<PlannedStep>(m, "PlannedStep", "One step of a plan: the swing foot lands on `pose` (picklable).")
      .def(py::init<>(), "A left step at the origin.")
      .def_readwrite("side", &PlannedStep::side, "The foot that moves.")
      .def_readwrite("pose", &PlannedStep::pose, "Where it lands.")
      .def_readwrite("displacement", &PlannedStep::displacement, "Landing pose relative to the stance foot.")
      .def_readwrite("mu_allowed", &PlannedStep::mu_allowed, "Friction the step may use.")
      .def_readwrite("transition", &PlannedStep::transition, "Parameters and predictions.")
      .def(py::pickle(
               [](const PlannedStep& s) {
                 return py::make_tuple(s.side, s.pose, s.displacement, s.mu_allowed, s.transition);
               },
               [](const py::tuple& t) {
                 CheckState(t, 5, "PlannedStep");
                 PlannedStep s;
                 s.side = t[0].cast<FootSide>();
                 s.pose = t[1].cast<FootPose>();
                 s.displacement = t[2].cast<StepDisplacement>();
                 s.mu_allowed = t[3].cast<double>();
                 s.transition = t[4].cast<TransitionCost>();
                 return s;
               }),
           "Pickles every field.");

  py::class_<FootstepPlanStatistics>(m, "FootstepPlanStatistics", "Search statistics of a plan.")
      .def(py::init<>(), "Zeros.")
      .def_readwrite("expansions", &FootstepPlanStatistics::expansions, "Expansions.")
      .def_readwrite("generated", &FootstepPlanStatistics::generated, "Distinct stances seen.")
      .def_readwrite("plan_seconds", &FootstepPlanStatistics::plan_seconds, "Wall time of the call.")
      .def_readwrite("first_plan_seconds", &FootstepPlanStatistics::first_plan_seconds, "Time to the first plan.")
      .def_readwrite("epsilon", &FootstepPlanStatistics::epsilon, "Proven suboptimality bound.")
      .def_readwrite("improvements", &FootstepPlanStatistics::improvements, "Plans published.")
      .def_readwrite("rejected_support", &FootstepPlanStatistics::rejected_support, "Unsupported footholds.")
      .def_readwrite("rejected_collision", &FootstepPlanStatistics::rejected_collision, "Colliding stances.")
      .def_readwrite("rejected_friction", &FootstepPlanStatistics::rejected_friction, "Steps refused by friction.")
      .def(py::pickle(
               [](const FootstepPlanStatistics& s) {
                 return py::make_tuple(s.expansions, s.generated, s.plan_seconds, s.first_plan_seconds, s.epsilon,
                                       s.improvements, s.rejected_support, s.rejected_collision, s.rejected_friction);
               },
               [](const py::tuple& t) {
                 CheckState(t, 9, "FootstepPlanStatistics");
                 FootstepPlanStatistics s;
                 s.expansions = t[0].cast<std::int64_t>();
                 s.generated = t[1].cast<std::int64_t>();
                 s.plan_seconds = t[2].cast<double>();
                 s.first_plan_seconds = t[3].cast<double>();
                 s.epsilon = t[4].cast<double>();
                 s.improvements = t[5].cast<int>();
                 s.rejected_support = t[6].cast<std::int64_t>();
                 s.rejected_collision = t[7].cast<std::int64_t>();
                 s.rejected_friction = t[8].cast<std::int64_t>();
                 return s;
               }),
           "Pickles every field.");

  py::class_<FootstepPlan>(m, "FootstepPlan",
                           "The result of footstep planning: steps from the start stance to the goal, or the reason "
                           "there is none (picklable; to_dict() gives plain Python values).")
      .def(py::init<>(), "No plan.")
      .def_readwrite("found", &FootstepPlan::found, "Whether a plan was found.")
      .def_readwrite("reason", &FootstepPlan::reason, "Why not (empty when found).")
      .def_readwrite("start", &FootstepPlan::start, "The start stance as planned.")
      .def_readwrite("first_side", &FootstepPlan::first_side, "Which foot moves first.")
      .def_readwrite("steps", &FootstepPlan::steps, "The steps (a list of copies; assign a list to change them).")
      .def_readwrite("cost", &FootstepPlan::cost, "Sum of the steps' objective values.")
      .def_readwrite("energy", &FootstepPlan::energy, "Sum of E_COM + heat, J.")
      .def_readwrite("duration", &FootstepPlan::duration, "s.")
      .def_readwrite("distance", &FootstepPlan::distance, "Path length of the stance midpoint, m.")
      .def_readwrite("max_rcof", &FootstepPlan::max_rcof, "Largest RCOF.")
      .def_readwrite("min_friction_margin", &FootstepPlan::min_friction_margin, "Smallest mu_allowed - rcof.")
      .def_readwrite("cost_model", &FootstepPlan::cost_model, "Description of the cost model.")
      .def_readwrite("statistics", &FootstepPlan::statistics, "Search statistics.")
      .def("UpdateTotals", &FootstepPlan::UpdateTotals, "Recomputes the totals from start and steps.")
      .def("StanceAfter", &FootstepPlan::StanceAfter, py::arg("k"), "The stance after step k (-1: start).")
      .def("to_dict", &PlanDict, "The plan as plain Python values (JSON-friendly).")
      .def(py::pickle(
               [](const FootstepPlan& p) {
                 return py::make_tuple(p.found, p.reason, p.start, p.first_side, p.steps, p.cost, p.energy, p.duration,
                                       p.distance, p.max_rcof, p.min_friction_margin, p.cost_model, p.statistics);
               },
               [](const py::tuple& t) {
                 CheckState(t, 13, "FootstepPlan");
                 FootstepPlan p;
                 p.found = t[0].cast<bool>();
                 p.reason = t[1].cast<std::string>();
                 p.start = t[2].cast<Stance>();
                 p.first_side = t[3].cast<FootSide>();
                 p.steps = t[4].cast<std::vector<PlannedStep>>();
                 p.cost = t[5].cast<double>();
                 p.energy = t[6].cast<double>();
                 p.duration = t[7].cast<double>();
                 p.distance = t[8].cast<double>();
                 p.max_rcof = t[9].cast<double>();
                 p.min_friction_margin = t[10].cast<double>();
                 p.cost_model = t[11].cast<std::string>();
                 p.statistics = t[12].cast<FootstepPlanStatistics>();
                 return p;
               }),
           "Pickles every field.");

  py::class_<AraStarOptions>(m, "AraStarOptions", "ARA* settings.")
      .def(py::init<>(), "epsilon 3 -> 1 in steps of 0.5, no limits.")
      .def_readwrite("initial_epsilon", &AraStarOptions::initial_epsilon, "First inflation.")
      .def_readwrite("epsilon_step", &AraStarOptions::epsilon_step, "Decrease per solution.")
      .def_readwrite("final_epsilon", &AraStarOptions::final_epsilon, "Stop at this bound.")
      .def_readwrite("time_limit", &AraStarOptions::time_limit, "Wall-clock budget, s.")
      .def_readwrite("max_expansions", &AraStarOptions::max_expansions,
                     "Expansion budget (negative: unlimited); reproducible, unlike the time limit.");
  py::class_<FootstepPlannerOptions>(m, "FootstepPlannerOptions", "Settings of the footstep search.")
      .def(py::init<>(), "5 cm lattice, 24 directions.")
      .def_readwrite("lattice_resolution", &FootstepPlannerOptions::lattice_resolution, "m.")
      .def_readwrite("orientations", &FootstepPlannerOptions::orientations, "Footstep directions (<= 32).")
      .def_readwrite("max_slope", &FootstepPlannerOptions::max_slope, "rad.")
      .def_readwrite("support_tolerance", &FootstepPlannerOptions::support_tolerance, "m.")
      .def_readwrite("level_step_tolerance", &FootstepPlannerOptions::level_step_tolerance,
                     "Largest foothold height difference priced as a level step, m (perceived heights' noise).")
      .def_readwrite("min_body_free_probability", &FootstepPlannerOptions::min_body_free_probability,
                     "eta_geom: least probability that a stance's body box is free of occupied voxels.")
      .def_readwrite("search", &FootstepPlannerOptions::search, "AraStarOptions.");
  py::class_<BipedGeometry>(m, "BipedGeometry", "Sole rectangles and the body box the planner checks.")
      .def(py::init<>(), "Defaults (24 x 14 cm soles).")
      .def_static(
          "FromWalkingModel",
          [](const WalkingModel& model) {
            BipedGeometry g;
            g.foot_length = model.foot_length();
            g.foot_width = model.foot_width();
            g.body_half_extents = model.body_half_extents();
            g.body_bottom = model.body_box_bottom();
            return g;
          },
          py::arg("model"), "The robot's soles and body box, as `cairn plan` uses them.")
      .def_readwrite("foot_length", &BipedGeometry::foot_length, "m.")
      .def_readwrite("foot_width", &BipedGeometry::foot_width, "m.")
      .def_readwrite("body_half_extents", &BipedGeometry::body_half_extents, "m.")
      .def_readwrite("body_bottom", &BipedGeometry::body_bottom, "m.");

  py::class_<TerrainMap> terrain(m, "TerrainMap",
                                 "Friction-annotated 2.5-D terrain: per cell height, normal and usable friction "
                                 "(Q_{1-eta}), plus box obstacles.");
  py::class_<TerrainMap::Obstacle>(terrain, "Obstacle", "A yawed box obstacle.")
      .def(py::init([](std::string name, const Eigen::Vector3d& center, const Eigen::Vector3d& half_extents,
                       double yaw) { return TerrainMap::Obstacle{std::move(name), center, half_extents, yaw}; }),
           py::arg("name"), py::arg("center"), py::arg("half_extents"), py::arg("yaw") = 0.0, "From values.")
      .def_readwrite("name", &TerrainMap::Obstacle::name, "Name.")
      .def_readwrite("center", &TerrainMap::Obstacle::center, "Centre.")
      .def_readwrite("half_extents", &TerrainMap::Obstacle::half_extents, "Half extents.")
      .def_readwrite("yaw", &TerrainMap::Obstacle::yaw, "Yaw.");
  terrain
      .def(py::init<const Eigen::Vector2d&, int, int, double>(), py::arg("origin"), py::arg("cols"), py::arg("rows"),
           py::arg("resolution"), "Cells without ground; ValueError for bad sizes.")
      .def("SetCell", &TerrainMap::SetCell, py::arg("col"), py::arg("row"), py::arg("height"), py::arg("normal"),
           py::arg("friction"), "Puts ground in a cell.")
      .def("ClearCell", &TerrainMap::ClearCell, py::arg("col"), py::arg("row"), "Removes a cell's ground.")
      .def("AddObstacle", &TerrainMap::AddObstacle, py::arg("obstacle"), "Adds a box obstacle.")
      .def("origin", [](const TerrainMap& t) { return Eigen::Vector2d(t.origin()); }, "Minimum corner.")
      .def("cols", &TerrainMap::cols, "Columns (x).")
      .def("rows", &TerrainMap::rows, "Rows (y).")
      .def("resolution", &TerrainMap::resolution, "Cell side, m.")
      .def("max_corner", &TerrainMap::max_corner, "Maximum corner.")
      .def("obstacles", &TerrainMap::obstacles, "The obstacles.")
      .def(
          "CellAt",
          [](const TerrainMap& t, double x, double y) -> std::optional<std::pair<int, int>> {
            int col = 0, row = 0;
            if (!t.CellAt(x, y, &col, &row)) return std::nullopt;
            return std::make_pair(col, row);
          },
          py::arg("x"), py::arg("y"), "(col, row) of the cell containing (x, y), or None.")
      .def(
          "CellCenter",
          [](const TerrainMap& t, int col, int row) {
            CheckTerrainCell(t, col, row);
            return t.CellCenter(col, row);
          },
          py::arg("col"), py::arg("row"), "Centre of a cell.")
      .def(
          "height",
          [](const TerrainMap& t, int col, int row) {
            CheckTerrainCell(t, col, row);
            return t.height(col, row);
          },
          py::arg("col"), py::arg("row"), "Ground height (NaN: none).")
      .def(
          "friction",
          [](const TerrainMap& t, int col, int row) {
            CheckTerrainCell(t, col, row);
            return t.friction(col, row);
          },
          py::arg("col"), py::arg("row"), "Usable friction.")
      .def(
          "walkable",
          [](const TerrainMap& t, int col, int row) {
            CheckTerrainCell(t, col, row);
            return t.walkable(col, row);
          },
          py::arg("col"), py::arg("row"), "Ground present and friction above zero.")
      .def(
          "heights", [](const TerrainMap& t) { return CellArray(t, [&t](int c, int r) { return t.height(c, r); }); },
          "Every cell's height as a (rows, cols) array (a copy; NaN without ground).")
      .def(
          "frictions",
          [](const TerrainMap& t) { return CellArray(t, [&t](int c, int r) { return t.friction(c, r); }); },
          "Every cell's friction as a (rows, cols) array (a copy).")
      .def("BoxHitsObstacle", &TerrainMap::BoxHitsObstacle, py::arg("center"), py::arg("half_extents"), py::arg("yaw"),
           "Whether a yawed box overlaps an obstacle.")
      .def(
          "SetOccupiedVoxels",
          [](TerrainMap& t, const Eigen::MatrixX3d& centers, const Eigen::VectorXd& probabilities, double size) {
            if (centers.rows() != probabilities.size()) {
              throw std::invalid_argument("SetOccupiedVoxels: " + cairn::FormatShort(centers.rows()) + " centres but " +
                                          cairn::FormatShort(probabilities.size()) + " probabilities; give one per voxel");
            }
            std::vector<TerrainMap::OccupiedVoxel> voxels(static_cast<std::size_t>(centers.rows()));
            for (Eigen::Index i = 0; i < centers.rows(); ++i) {
              voxels[static_cast<std::size_t>(i)] = {centers.row(i).transpose(), probabilities(i)};
            }
            t.SetOccupiedVoxels(std::move(voxels), size);
          },
          py::arg("centers"), py::arg("probabilities"), py::arg("size"),
          "Occupied voxels: (n, 3) centres, n probabilities in (0, 1), cube side in m.")
      .def(
          "occupied_voxels",
          [](const TerrainMap& t) {
            Eigen::MatrixX3d centers(static_cast<Eigen::Index>(t.occupied_voxels().size()), 3);
            Eigen::VectorXd probabilities(static_cast<Eigen::Index>(t.occupied_voxels().size()));
            for (std::size_t i = 0; i < t.occupied_voxels().size(); ++i) {
              centers.row(static_cast<Eigen::Index>(i)) = t.occupied_voxels()[i].center.transpose();
              probabilities(static_cast<Eigen::Index>(i)) = t.occupied_voxels()[i].probability;
            }
            return py::make_tuple(centers, probabilities);
          },
          "(centres (n, 3), probabilities (n,)), copies.")
      .def("voxel_size", &TerrainMap::voxel_size, "Side of the voxels, m (0 without).")
      .def("BoxFreeProbability", &TerrainMap::BoxFreeProbability, py::arg("center"), py::arg("half_extents"),
           py::arg("yaw"), py::arg("stop_below") = 0.0, "Probability that a yawed box overlaps no occupied voxel.");

  py::enum_<WalkingObjective>(m, "WalkingObjective", "What a step's cost measures.")
      .value("kComWork", WalkingObjective::kComWork, "\"ecom\": COM work.")
      .value("kComWorkPlusHeat", WalkingObjective::kComWorkPlusHeat, "\"ecom_heat\": COM work plus motor heat.")
      .value("kTravelTime", WalkingObjective::kTravelTime, "\"time\": step duration.")
      .value("kSquaredTorque", WalkingObjective::kSquaredTorque, "\"torque\": squared static leg torques.");
  m.def("ParseWalkingObjective", &ParseWalkingObjective, py::arg("name"), "From \"ecom\", \"ecom_heat\", ...");
  m.def("WalkingObjectiveNames", &WalkingObjectiveNames, "Every objective name.");
  m.def("to_string", py::overload_cast<WalkingObjective>(&to_string), py::arg("objective"), "The objective's name.");

  py::class_<WalkingModel, std::shared_ptr<WalkingModel>>(m, "WalkingModel",
                                                          "A robot as the footstep planner sees it, from a walking "
                                                          "YAML next to its URDF.")
      .def_static("Load", [](const std::string& path) { return std::make_shared<WalkingModel>(WalkingModel::Load(path)); },
                  py::arg("yaml_path"), "Reads the YAML and its URDF; RuntimeError naming the file and key.")
      .def("name", &WalkingModel::name, "Robot name.")
      .def("mass", &WalkingModel::mass, "Total mass, kg.")
      .def("gravity", &WalkingModel::gravity, "Gravity magnitude.")
      .def("reach", &WalkingModel::reach, "Reachable step displacements.")
      .def("parameter_lower", &WalkingModel::parameter_lower, "Lower step-parameter bounds.")
      .def("parameter_upper", &WalkingModel::parameter_upper, "Upper step-parameter bounds.")
      .def("foot_length", &WalkingModel::foot_length, "Sole length, m.")
      .def("foot_width", &WalkingModel::foot_width, "Sole width, m.")
      .def("body_half_extents", &WalkingModel::body_half_extents, "Body box half extents.")
      .def("body_box_bottom", &WalkingModel::body_box_bottom, "Body box bottom above the soles.")
      .def("swing_height", &WalkingModel::swing_height, "Swing apex height.")
      .def("multibody", &WalkingModel::multibody, py::return_value_policy::reference_internal, "The multibody Model.")
      .def("yaml_path", &WalkingModel::yaml_path, "The YAML file.")
      .def("urdf_path", &WalkingModel::urdf_path, "The URDF file.")
      .def(py::pickle([](const WalkingModel& w) { return py::make_tuple(w.yaml_path()); },
                      [](const py::tuple& t) { return std::make_shared<WalkingModel>(WalkingModel::Load(t[0].cast<std::string>())); }),
           "Pickles the YAML path (re-read on unpickling).");

  py::class_<StepCostModel, std::shared_ptr<StepCostModel>>(m, "StepCostModel",
                                                            "The cost of a step under a friction limit, bounds for the "
                                                            "heuristic and the reach.")
      .def("Evaluate", &StepCostModel::Evaluate, py::arg("d"), py::arg("mu_allowed"),
           "Minimum-cost step with displacement d and RCOF <= mu_allowed.")
      .def("MinCostOverHeights", &StepCostModel::MinCostOverHeights, py::arg("d"), py::arg("dz_lo"), py::arg("dz_hi"),
           py::arg("mu_allowed"),
           "Lower bound on the cost of step d with its height anywhere in [dz_lo, dz_hi] (inf: none is feasible).")
      .def("min_cost_per_metre", &StepCostModel::min_cost_per_metre, "Lower bound of cost per metre.")
      .def("min_cost_per_step", &StepCostModel::min_cost_per_step, "Fixed cost every step pays.")
      .def("reach", &StepCostModel::reach, "Evaluable displacements.")
      .def("description", &StepCostModel::description, "Short description.");

  py::class_<OracleGrid>(m, "OracleGrid", "The displacements and friction limits an oracle covers.")
      .def(py::init<>(), "Empty axes.")
      .def_static("Default", &OracleGrid::Default, py::arg("model"), "The default grid for `model`.")
      .def_readwrite("dx", &OracleGrid::dx, "dx axis.")
      .def_readwrite("dy", &OracleGrid::dy, "dy axis.")
      .def_readwrite("dz", &OracleGrid::dz, "dz axis.")
      .def_readwrite("dtheta", &OracleGrid::dtheta, "dtheta axis.")
      .def_readwrite("mu", &OracleGrid::mu, "Friction axis.")
      .def("num_entries", &OracleGrid::num_entries, "Entries.")
      .def("Validate", &OracleGrid::Validate, py::arg("reach"), "ValueError naming a bad axis value.")
      .def("Fingerprint", &OracleGrid::Fingerprint,
           "16 hex digits naming the grid's values (the CLI's oracle cache names other grids' tables by it).")
      .def_static("Load", &OracleGrid::Load, py::arg("path"),
                  "A grid from YAML (dx, dy, dz, dtheta, mu: lists or {from, to, step}).");
  py::class_<TransitionSource, std::shared_ptr<TransitionSource>>(
      m, "TransitionSource", "Where an oracle's entries come from: the minimum-cost transitions of one displacement.")
      .def("name", &TransitionSource::name, "The name written into oracle headers.")
      .def("settings", &TransitionSource::settings, "The settings the entries depend on, one line.")
      .def("Describe", &TransitionSource::Describe, "The header's source line: name and settings.")
      .def("concurrent", &TransitionSource::concurrent, "Whether cells may be computed on several threads.")
      .def("CellEntries", &TransitionSource::CellEntries, py::arg("model"), py::arg("objective"), py::arg("d"),
           py::arg("mu"), py::call_guard<py::gil_scoped_release>(),
           "The TransitionCost of displacement d at each friction limit of mu (increasing), without the GIL.");
  py::class_<ModelTransitionSource, TransitionSource, std::shared_ptr<ModelTransitionSource>>(
      m, "ModelTransitionSource", "The analytic source \"model\" (OptimizeTransition), the oracle's default.")
      .def(py::init<>(), "Default optimiser settings.");
  py::class_<OracleBuildOptions>(m, "OracleBuildOptions", "How an oracle table is built.")
      .def(py::init<>(), "One thread per core.")
      .def_readwrite("num_threads", &OracleBuildOptions::num_threads, "Worker threads (0: one per core).")
      .def_property(
          "source", [](const OracleBuildOptions& o) { return std::const_pointer_cast<TransitionSource>(o.source); },
          [](OracleBuildOptions& o, std::shared_ptr<TransitionSource> source) { o.source = std::move(source); },
          "The TransitionSource (None: the analytic model).");

  py::class_<TransitionOracle, StepCostModel, std::shared_ptr<TransitionOracle>>(
      m, "TransitionOracle", "Precomputed minimum-cost transitions over an OracleGrid (microsecond lookups).")
      .def_static(
          "Build",
          [](const WalkingModel& model, WalkingObjective objective, const OracleGrid& grid,
             const OracleBuildOptions& options) {
            py::gil_scoped_release release;
            return std::make_shared<TransitionOracle>(TransitionOracle::Build(model, objective, grid, options));
          },
          py::arg("model"), py::arg("objective"), py::arg("grid"), py::arg("options") = OracleBuildOptions(),
          "Builds the table (without the GIL).")
      .def_static(
          "Load",
          [](const std::string& path, const WalkingModel& model, WalkingObjective objective, const OracleGrid& grid,
             const std::shared_ptr<TransitionSource>& source) {
            return std::make_shared<TransitionOracle>(TransitionOracle::Load(path, model, objective, grid, source.get()));
          },
          py::arg("path"), py::arg("model"), py::arg("objective"), py::arg("grid"), py::arg("source") = nullptr,
          "Reads a table written by Save and checks it against model, objective, grid and source (None: model).")
      .def_static(
          "LoadOrBuild",
          [](const std::string& path, const WalkingModel& model, WalkingObjective objective, const OracleGrid& grid,
             const OracleBuildOptions& options) {
            std::ostringstream log;
            std::shared_ptr<TransitionOracle> oracle;
            {
              py::gil_scoped_release release;
              oracle = std::make_shared<TransitionOracle>(
                  TransitionOracle::LoadOrBuild(path, model, objective, grid, options, &log));
            }
            return py::make_tuple(oracle, log.str());
          },
          py::arg("path"), py::arg("model"), py::arg("objective"), py::arg("grid"),
          py::arg("options") = OracleBuildOptions(),
          "Load, or Build and Save when the file is missing, stale or corrupt; returns (oracle, log line).")
      .def("Save", &TransitionOracle::Save, py::arg("path"), "Writes the table atomically.")
      .def("grid", &TransitionOracle::grid, "The grid.")
      .def("objective", &TransitionOracle::objective, "The objective.")
      .def("robot_name", &TransitionOracle::robot_name, "The robot.")
      .def("source", &TransitionOracle::source, "The source line the entries came from (\"model\" by default).")
      .def("num_entries", &TransitionOracle::num_entries, "Entries.")
      .def("num_feasible", &TransitionOracle::num_feasible, "Feasible entries.")
      .def("build_seconds", &TransitionOracle::build_seconds, "Build wall time (0 if loaded).")
      .def("Serialize", [](const TransitionOracle& o) { return py::bytes(o.Serialize()); },
           "The bytes Save writes.");

  py::class_<HeldOutSample>(m, "HeldOutSample", "One held-out step: the table's answer and its source's.")
      .def_readonly("d", &HeldOutSample::d, "The StepDisplacement.")
      .def_readonly("mu", &HeldOutSample::mu, "The friction limit (one of the grid's).")
      .def_readonly("predicted", &HeldOutSample::predicted, "The table's TransitionCost.")
      .def_readonly("measured", &HeldOutSample::measured, "The source's TransitionCost.");
  py::class_<OracleHeldOutError>(m, "OracleHeldOutError", "How well a table predicts its source between grid values.")
      .def_readonly("samples", &OracleHeldOutError::samples, "The HeldOutSample list.")
      .def_readonly("both_feasible", &OracleHeldOutError::both_feasible, "Samples feasible for both.")
      .def_readonly("only_predicted", &OracleHeldOutError::only_predicted, "Feasible for the table only.")
      .def_readonly("only_measured", &OracleHeldOutError::only_measured, "Feasible for the source only.")
      .def_readonly("neither", &OracleHeldOutError::neither, "Feasible for neither.")
      .def_readonly("smse", &OracleHeldOutError::smse, "Standardised mean squared error of the cost.")
      .def_readonly("mean_absolute_error", &OracleHeldOutError::mean_absolute_error, "Objective's unit.")
      .def_readonly("mean_relative_error", &OracleHeldOutError::mean_relative_error, "|pred - meas| / meas.")
      .def_readonly("correlation", &OracleHeldOutError::correlation, "Pearson's, predicted against measured.");
  py::class_<OracleHeldOutOptions>(m, "OracleHeldOutOptions", "Options of MeasureOracleHeldOutError.")
      .def(py::init<>(), "20 samples, seed 1.")
      .def_readwrite("num_samples", &OracleHeldOutOptions::num_samples, "Held-out steps, [1, 100000].")
      .def_readwrite("seed", &OracleHeldOutOptions::seed, "Seeds the steps.");
  m.def("MeasureOracleHeldOutError", &MeasureOracleHeldOutError, py::arg("oracle"), py::arg("source"),
        py::arg("model"), py::arg("options") = OracleHeldOutOptions(), py::call_guard<py::gil_scoped_release>(),
        "Held-out steps over the oracle's grid, the table against its source (without the GIL).");

  py::class_<OracleShardBuilder::ShardReport>(m, "OracleShardReport", "What OracleShardBuilder.BuildShard did.")
      .def_readonly("computed", &OracleShardBuilder::ShardReport::computed, "Chunks computed.")
      .def_readonly("resumed", &OracleShardBuilder::ShardReport::resumed, "Chunks already on disk, skipped.")
      .def_readonly("replaced", &OracleShardBuilder::ShardReport::replaced, "Of computed: stale or corrupt files.");
  py::class_<OracleShardBuilder>(m, "OracleShardBuilder",
                                 "A transition oracle built in checkpointed chunks shared by ranks; merges to the "
                                 "bytes of one build.")
      .def(py::init([](const WalkingModel& model, WalkingObjective objective, OracleGrid grid, std::string folder,
                       int cells_per_chunk, std::shared_ptr<TransitionSource> source) {
             return std::make_unique<OracleShardBuilder>(model, objective, std::move(grid), std::move(folder),
                                                         cells_per_chunk, std::move(source));
           }),
           py::arg("model"), py::arg("objective"), py::arg("grid"), py::arg("checkpoint_folder"),
           py::arg("cells_per_chunk") = 16, py::arg("source") = nullptr, py::keep_alive<1, 2>(),
           "Keeps the model alive; source None: the analytic model.")
      .def("num_chunks", &OracleShardBuilder::num_chunks, "Chunks of the build.")
      .def("ChunksOfRank", &OracleShardBuilder::ChunksOfRank, py::arg("rank"), py::arg("num_ranks"),
           "The chunks a rank computes.")
      .def("BuildShard",
           [](const OracleShardBuilder& b, int rank, int num_ranks, const OracleBuildOptions& options) {
             return b.BuildShard(rank, num_ranks, options);
           },
           py::arg("rank"), py::arg("num_ranks"), py::arg("options") = OracleBuildOptions(),
           py::call_guard<py::gil_scoped_release>(), "Computes the rank's missing chunks (without the GIL).")
      .def("MissingChunks", &OracleShardBuilder::MissingChunks, "Chunks without a valid checkpoint.")
      .def("Merge", [](const OracleShardBuilder& b) { return std::make_shared<TransitionOracle>(b.Merge()); },
           "The table from every chunk; RuntimeError naming the chunks not ready.")
      .def("RemoveCheckpoints", &OracleShardBuilder::RemoveCheckpoints, "Removes this build's chunk files.");

  m.def("PlanFootsteps", &PlanFootsteps, py::arg("terrain"), py::arg("start"), py::arg("goal"), py::arg("cost_model"),
        py::arg("geometry"), py::arg("options"), py::call_guard<py::gil_scoped_release>(),
        "ARA* footstep planning with step timing (without the GIL); returns a FootstepPlan (found or with a reason).");
  py::class_<FootstepReplanner>(m, "FootstepReplanner",
                                "PlanFootsteps to one goal over one terrain from starts that change as the robot "
                                "walks, reusing the heuristic's precomputation after the first Plan().")
      .def(py::init([](const TerrainMap& terrain, const StanceGoal& goal, std::shared_ptr<StepCostModel> cost_model,
                       const BipedGeometry& geometry, const FootstepPlannerOptions& options) {
             return std::make_unique<FootstepReplanner>(terrain, goal, std::move(cost_model), geometry, options);
           }),
           py::arg("terrain"), py::arg("goal"), py::arg("cost_model"), py::arg("geometry"), py::arg("options"),
           "Keeps a copy of the terrain.")
      .def("Plan", &FootstepReplanner::Plan, py::arg("start"), py::call_guard<py::gil_scoped_release>(),
           "The plan PlanFootsteps would return from `start` (without the GIL).")
      .def("UpdateTerrain", &FootstepReplanner::UpdateTerrain, py::arg("terrain"),
           "Replaces the terrain (same grid); True when the precomputation is kept (the change only raised costs).")
      .def("prepared", &FootstepReplanner::prepared, "Whether the heuristic's precomputation is done.");
  m.def(
      "RefineFootstepPlan",
      [](const WalkingModel& model, WalkingObjective objective, FootstepPlan& plan) {
        py::gil_scoped_release release;
        return RefineFootstepPlan(model, objective, &plan);
      },
      py::arg("model"), py::arg("objective"), py::arg("plan"),
      "Refines each step's parameters by SLSQP (plan changed in place); returns the number refined.");

  py::class_<FootstepPlanner, systems::LeafSystem>(
      m, "FootstepPlanner",
      "System: inputs `terrain` (TerrainMap), `start` (Stance), `goal` (StanceGoal); output `plan` (FootstepPlan), "
      "searched at initialization, on forced events and every `period` s when positive, and kept as state.")
      .def(py::init([](std::shared_ptr<StepCostModel> cost_model, const BipedGeometry& geometry,
                       const FootstepPlannerOptions& options, std::shared_ptr<WalkingModel> refine_model,
                       WalkingObjective objective, double period) {
             return std::make_unique<FootstepPlanner>(std::move(cost_model), geometry, options, std::move(refine_model),
                                                      objective, period);
           }),
           py::arg("cost_model"), py::arg("geometry"), py::arg("options"), py::arg("refine_model") = nullptr,
           py::arg("objective") = WalkingObjective::kComWorkPlusHeat, py::arg("period") = 0.0,
           "With `refine_model`, plans are refined for `objective` (the cost model's).")
      .def("get_terrain_input_port", PortGetter(&FootstepPlanner::get_terrain_input_port), "Input `terrain`.")
      .def("get_start_input_port", PortGetter(&FootstepPlanner::get_start_input_port), "Input `start`.")
      .def("get_goal_input_port", PortGetter(&FootstepPlanner::get_goal_input_port), "Input `goal`.")
      .def("get_plan_output_port", PortGetter(&FootstepPlanner::get_plan_output_port), "Output `plan`.");

  py::class_<FootstepScenario> scenario(m, "FootstepScenario",
                                        "A footstep planning problem read from YAML (docs/scenarios.md).");
  py::class_<FootstepScenario::Region>(scenario, "Region", "A patch of ground with a plane and friction.")
      .def_readonly("name", &FootstepScenario::Region::name, "Name.")
      .def_readonly("polygon", &FootstepScenario::Region::polygon, "Vertices (list of 2-vectors).")
      .def_readonly("height", &FootstepScenario::Region::height, "Height at slope_origin.")
      .def_readonly("slope", &FootstepScenario::Region::slope, "rad.")
      .def_readonly("uphill", &FootstepScenario::Region::uphill, "Direction of steepest ascent.")
      .def_readonly("friction", &FootstepScenario::Region::friction, "Friction distribution.")
      .def_readonly("friction_source", &FootstepScenario::Region::friction_source, "For reports.")
      .def_readonly("material", &FootstepScenario::Region::material,
                    "Registry label of a `material:` region, else empty.")
      .def("HeightAt", &FootstepScenario::Region::HeightAt, py::arg("p"), "Plane height at p.")
      .def("Contains", &FootstepScenario::Region::Contains, py::arg("p"), "True if p is inside.");
  scenario.def_static("Load", &FootstepScenario::Load, py::arg("path"), "Reads and validates a scenario file.")
      .def("path", &FootstepScenario::path, "The file.")
      .def("name", &FootstepScenario::name, "Name.")
      .def("robot", &FootstepScenario::robot, "Walking-model YAML (empty: the default robot).")
      .def("objective", &FootstepScenario::objective, "Objective name.")
      .def("oracle", &FootstepScenario::oracle, "The oracle's source: \"model\", \"plant\" or \"pipeline\".")
      .def("set_objective", &FootstepScenario::set_objective, py::arg("objective"), "Sets the objective name.")
      .def("eta", &FootstepScenario::eta, "Chance-constraint confidence.")
      .def("regions", &FootstepScenario::regions, "Terrain regions.")
      .def("registry", &FootstepScenario::registry, "The material registry of `material:` regions.")
      .def("min_corner", &FootstepScenario::min_corner, "Mapped area, minimum [x, y].")
      .def("max_corner", &FootstepScenario::max_corner, "Mapped area, maximum [x, y].")
      .def("resolution", &FootstepScenario::resolution, "Raster resolution of the terrain, m.")
      .def("obstacles", &FootstepScenario::obstacles, "Obstacles.")
      .def("start", &FootstepScenario::start, "Start stance.")
      .def("goal", &FootstepScenario::goal, "Goal.")
      .def("planner", &FootstepScenario::planner, "Planner settings (a copy).")
      .def(
          "set_planner",
          [](FootstepScenario& self, const FootstepPlannerOptions& options) { self.mutable_planner() = options; },
          py::arg("options"), "Replaces the planner settings.")
      .def(
          "BuildTerrain",
          [](const FootstepScenario& self, std::optional<double> time_limit) {
            auto deadline = std::chrono::steady_clock::time_point::max();
            if (time_limit) {
              // Bounded so that now + limit cannot overflow the clock (a day is far more than any rasterisation).
              if (!(*time_limit > 0.0) || !(*time_limit <= 86400.0)) {
                throw std::invalid_argument("BuildTerrain: time_limit " + cairn::FormatShort(*time_limit) +
                                            " s must be in (0, 86400]; pass None for no limit");
              }
              deadline = std::chrono::steady_clock::now() +
                         std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(*time_limit));
            }
            py::gil_scoped_release release;
            return self.BuildTerrain(deadline);
          },
          py::arg("time_limit") = py::none(),
          "Rasterises regions and obstacles into a TerrainMap; with `time_limit` (seconds) RuntimeError "
          "(TimeLimitReached) naming how far it got if it is still running then.");

  RegisterBoundAbstractValueType<TerrainMap>("TerrainMap");
  RegisterBoundAbstractValueType<Stance>("Stance");
  RegisterBoundAbstractValueType<StanceGoal>("StanceGoal");
  RegisterBoundAbstractValueType<FootstepPlan>("FootstepPlan");
}

}  // namespace cairn::python
