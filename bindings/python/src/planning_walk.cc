// cairn.planning (walk part): the walk diagram of `cairn walk` -- WalkSetup, BuildWalkDiagram, RunWalk and its
// record, ScenarioTerrainBoxes, the StabilizedReferencePlayer and BalanceFeedback systems; and cairn.visualization's
// MotionHtml.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "system_support.h"
#include "cairn/multibody/model.h"
#include "cairn/planning/stabilization/stabilized_reference_player.h"
#include "cairn/planning/walk/balance_feedback.h"
#include "cairn/planning/walk/scenario_terrain_boxes.h"
#include "cairn/planning/walk/walk_diagram.h"
#include "cairn/planning/walk/walk_run.h"
#include "cairn/visualization/motion_html.h"

namespace cairn::python {

using namespace cairn::planning;

void DefinePlanningWalk(py::module_ m) {
  py::class_<StabilizedReferencePlayer, systems::LeafSystem>(
      m, "StabilizedReferencePlayer",
      "System: input `reference` (StabilizedTrajectory); output `reference` ([q; v] at the context's time, "
      "interpolated between samples, the base quaternion by slerp).")
      .def(py::init([](const multibody::Model& model) {
             return std::make_unique<StabilizedReferencePlayer>(std::make_shared<const multibody::Model>(model));
           }),
           py::arg("model"), "Keeps a copy of the model (floating base required).")
      .def("get_reference_input_port", PortGetter(&StabilizedReferencePlayer::get_reference_input_port),
           "Input `reference`.")
      .def("get_reference_output_port", PortGetter(&StabilizedReferencePlayer::get_reference_output_port),
           "Output `reference`.")
      .def("Sample", &StabilizedReferencePlayer::Sample, py::arg("reference"), py::arg("t"),
           "[q; v] of the reference at time t, as the output computes it.");

  py::class_<BalanceFeedbackOptions>(m, "BalanceFeedbackOptions", "Gains and limits of BalanceFeedback.")
      .def(py::init<>(), "0.8 rad/m forward, 1 rad/m sideways, at most 0.2 / 0.15 rad, COM height 0.8 m.")
      .def_readwrite("pitch_gain", &BalanceFeedbackOptions::pitch_gain,
                     "Leg tilt about y per m of forward capture-point error, rad/m, in [0, 1000].")
      .def_readwrite("roll_gain", &BalanceFeedbackOptions::roll_gain,
                     "Leg tilt about x per m of sideways capture-point error, rad/m, in [0, 1000].")
      .def_readwrite("max_pitch", &BalanceFeedbackOptions::max_pitch, "Largest pitch offset, rad, in [0, 0.5].")
      .def_readwrite("max_roll", &BalanceFeedbackOptions::max_roll, "Largest roll offset, rad, in [0, 0.5].")
      .def_readwrite("com_height", &BalanceFeedbackOptions::com_height,
                     "Pendulum height of the capture point, m, in (0.1, 3].")
      .def_readwrite("foothold_gain", &BalanceFeedbackOptions::foothold_gain,
                     "Share of a loaded foot's x-y placement error written into its leg's reference, in [0, 1].")
      .def_readwrite("swing_orientation_gain", &BalanceFeedbackOptions::swing_orientation_gain,
                     "Share of the swing sole's rotation error from the base's error taken out, in [0, 1].")
      .def_readwrite("swing_position_gain", &BalanceFeedbackOptions::swing_position_gain,
                     "Share of the swing sole's translation error from the base's error taken out, in [0, 1].")
      .def_readwrite("left_sole", &BalanceFeedbackOptions::left_sole, "Frame name.")
      .def_readwrite("right_sole", &BalanceFeedbackOptions::right_sole, "Frame name.")
      .def_readwrite("left_ankle_pitch", &BalanceFeedbackOptions::left_ankle_pitch, "Joint name.")
      .def_readwrite("left_ankle_roll", &BalanceFeedbackOptions::left_ankle_roll, "Joint name.")
      .def_readwrite("right_ankle_pitch", &BalanceFeedbackOptions::right_ankle_pitch, "Joint name.")
      .def_readwrite("right_ankle_roll", &BalanceFeedbackOptions::right_ankle_roll, "Joint name.");
  py::class_<BalanceFeedback, systems::LeafSystem>(
      m, "BalanceFeedback",
      "System: inputs `reference` and `state` ([q; v]) and `contacts` (the soles); output `reference` with the "
      "loaded legs tilted about their ankles against the capture-point error.")
      .def(py::init([](const multibody::Model& model, const BalanceFeedbackOptions& options) {
             return std::make_unique<BalanceFeedback>(std::make_shared<const multibody::Model>(model), options);
           }),
           py::arg("model"), py::arg("options") = BalanceFeedbackOptions(),
           "Keeps a copy of the model (floating base and the named ankle joints required).")
      .def("get_reference_input_port", PortGetter(&BalanceFeedback::get_reference_input_port), "Input `reference`.")
      .def("get_state_input_port", PortGetter(&BalanceFeedback::get_state_input_port), "Input `state`.")
      .def("get_contacts_input_port", PortGetter(&BalanceFeedback::get_contacts_input_port), "Input `contacts`.")
      .def("get_reference_output_port", PortGetter(&BalanceFeedback::get_reference_output_port),
           "Output `reference`.")
      .def("options", &BalanceFeedback::options, py::return_value_policy::copy, "The BalanceFeedbackOptions.")
      .def("Correct", &BalanceFeedback::Correct, py::arg("reference"), py::arg("state"), py::arg("left_loaded"),
           py::arg("right_loaded"), "The corrected reference as the output computes it.");

  py::class_<GravityFeedforward, systems::LeafSystem>(
      m, "GravityFeedforward",
      "System: inputs `state` ([q; v]) and `contacts` (the soles); output `torque`: gain times the static gravity "
      "torques of every joint that carries no loaded sole (0 on the stance legs and the base).")
      .def(py::init([](const multibody::Model& model, std::vector<std::string> sole_bodies, double gain) {
             return std::make_unique<GravityFeedforward>(std::make_shared<const multibody::Model>(model),
                                                         std::move(sole_bodies), gain);
           }),
           py::arg("model"), py::arg("sole_bodies"), py::arg("gain") = 1.0,
           "Keeps a copy of the model (floating base; the left and the right sole body or frame).")
      .def("get_state_input_port", PortGetter(&GravityFeedforward::get_state_input_port), "Input `state`.")
      .def("get_contacts_input_port", PortGetter(&GravityFeedforward::get_contacts_input_port), "Input `contacts`.")
      .def("get_torque_output_port", PortGetter(&GravityFeedforward::get_torque_output_port), "Output `torque`.")
      .def("gain", &GravityFeedforward::gain, "The gain.")
      .def("Torques", &GravityFeedforward::Torques, py::arg("q"), py::arg("left_loaded"), py::arg("right_loaded"),
           "The torques as the output computes them.");

  m.def("ScenarioTerrainBoxes", &ScenarioTerrainBoxes, py::arg("scenario"),
        "A footstep scenario's regions and obstacles as the plant's non-overlapping TerrainBoxes (true friction).");

  py::class_<WalkSetup>(m, "WalkSetup", "Everything the walk diagram is built from (make it with WalkSetupFromScenario).")
      .def_readwrite("objective", &WalkSetup::objective, "The cost model's objective.")
      .def_readwrite("geometry", &WalkSetup::geometry, "BipedGeometry of the footstep planner.")
      .def_readwrite("planner", &WalkSetup::planner, "FootstepPlannerOptions (give it an expansion budget).")
      .def_readwrite("start", &WalkSetup::start, "Start stance.")
      .def_readwrite("goal", &WalkSetup::goal, "Goal.")
      .def_readwrite("environment", &WalkSetup::environment, "EnvironmentBoxes of the collision penalty.")
      .def_readwrite("trajectory", &WalkSetup::trajectory, "TrajectoryOptimizerOptions.")
      .def_readwrite("stabilizer", &WalkSetup::stabilizer, "StabilizerOptions (WalkingStabilizerOptions).")
      .def_readwrite("feedback", &WalkSetup::feedback,
                     "Close the loop on the capture point (BalanceFeedback); False plays the reference open loop.")
      .def_readwrite("balance", &WalkSetup::balance, "BalanceFeedbackOptions.")
      .def_readwrite("gravity_feedforward", &WalkSetup::gravity_feedforward,
                     "Share of GravityFeedforward's torques added to the PD drive, in [0, 1] (0: none).")
      .def_readwrite("plant_terrain", &WalkSetup::plant_terrain, "The plant's TerrainBoxes (the true world).")
      .def_readwrite("plant", &WalkSetup::plant, "HumanoidPlantOptions.");
  m.def(
      "WalkSetupFromScenario",
      [](const FootstepScenario& scenario, std::shared_ptr<StepCostModel> cost_model,
         std::shared_ptr<WalkingModel> walking_model, WalkingObjective objective, const multibody::Model& robot,
         const multibody::JointPdController& controller) {
        return WalkSetupFromScenario(scenario, std::move(cost_model), std::move(walking_model), objective,
                                     std::make_shared<const multibody::Model>(robot),
                                     std::make_shared<const multibody::JointPdController>(controller));
      },
      py::arg("scenario"), py::arg("cost_model"), py::arg("walking_model"), py::arg("objective"), py::arg("robot"),
      py::arg("controller"), "The scenario's walk with its terrain, start, goal, obstacles and plant boxes.");
  m.def("StandingAtStart", &StandingAtStart, py::arg("robot"), py::arg("sole_bodies"), py::arg("start"),
        "The robot standing at a stance: neutral joints, base over the feet, lowest sole on the ground.");

  py::class_<WalkDiagram>(m, "WalkDiagram", "The walk diagram and its blocks (from BuildWalkDiagram).")
      .def_property_readonly(
          "diagram", [](const WalkDiagram& w) { return w.diagram.get(); }, py::return_value_policy::reference_internal,
          "The Diagram.")
      .def_property_readonly(
          "footsteps", [](const WalkDiagram& w) { return w.footsteps; }, py::return_value_policy::reference_internal,
          "The FootstepPlanner.")
      .def_property_readonly(
          "trajectory", [](const WalkDiagram& w) { return w.trajectory; },
          py::return_value_policy::reference_internal, "The TrajectoryOptimizer.")
      .def_property_readonly(
          "stabilizer", [](const WalkDiagram& w) { return w.stabilizer; },
          py::return_value_policy::reference_internal, "The Stabilizer.")
      .def_property_readonly(
          "player", [](const WalkDiagram& w) { return w.player; }, py::return_value_policy::reference_internal,
          "The StabilizedReferencePlayer.")
      .def_property_readonly(
          "balance", [](const WalkDiagram& w) { return w.balance; }, py::return_value_policy::reference_internal,
          "The BalanceFeedback (None when the setup plays the reference open loop).")
      .def_property_readonly(
          "feedforward", [](const WalkDiagram& w) { return w.feedforward; },
          py::return_value_policy::reference_internal, "The GravityFeedforward (None with gravity_feedforward 0).")
      .def_property_readonly(
          "plant", [](const WalkDiagram& w) { return w.plant; }, py::return_value_policy::reference_internal,
          "The HumanoidPlant.");
  m.def("BuildWalkDiagram", &BuildWalkDiagram, py::arg("setup"),
        "FootstepPlanner -> TrajectoryOptimizer -> Stabilizer -> StabilizedReferencePlayer -> BalanceFeedback -> "
        "HumanoidPlant.");

  py::class_<WalkSettleTimes>(m, "WalkSettleTimes", "Wall time of each planning stage, s.")
      .def_readonly("footsteps", &WalkSettleTimes::footsteps, "The footstep search.")
      .def_readonly("trajectory", &WalkSettleTimes::trajectory, "The whole-body solve.")
      .def_readonly("stabilizer", &WalkSettleTimes::stabilizer, "The stabilisation.");
  py::class_<WalkStart>(m, "WalkStart", "Whether the planning chain settled on a reference.")
      .def_readonly("ready", &WalkStart::ready, "A reference the plant can follow.")
      .def_readonly("reason", &WalkStart::reason, "The stage that gave none.")
      .def_readonly("seconds", &WalkStart::seconds, "WalkSettleTimes.");
  py::class_<WalkRunOptions>(m, "WalkRunOptions", "How RunWalk samples and ends the walk.")
      .def(py::init<>(), "Samples every 10 ms, 1 s of standing after the reference.")
      .def_readwrite("log_period", &WalkRunOptions::log_period, "s between samples, in (0, 1].")
      .def_readwrite("settle_time", &WalkRunOptions::settle_time, "s after the reference ends, in [0, 60].");
  py::class_<WalkSample>(m, "WalkSample", "One recorded sample of the plant.")
      .def_readonly("time", &WalkSample::time, "s.")
      .def_readonly("q", &WalkSample::q, "Configuration.")
      .def_readonly("com", &WalkSample::com, "Centre of mass, world.")
      .def_readonly("zmp", &WalkSample::zmp, "Measured ZMP (NaN in the air).")
      .def_readonly("left_force", &WalkSample::left_force, "N.")
      .def_readonly("right_force", &WalkSample::right_force, "N.")
      .def_readonly("left_tangential", &WalkSample::left_tangential, "Left sole's tangential force magnitude, N.")
      .def_readonly("right_tangential", &WalkSample::right_tangential, "Right sole's tangential force magnitude, N.")
      .def_readonly("com_energy", &WalkSample::com_energy, "E_COM so far, J.")
      .def_readonly("electrical_energy", &WalkSample::electrical_energy, "E_ele so far, J.");
  py::class_<WalkRecord>(m, "WalkRecord", "Each stage's result, the plant's samples and verdicts.")
      .def_readonly("start", &WalkRecord::start, "WalkStart.")
      .def_readonly("plan", &WalkRecord::plan, "FootstepPlan.")
      .def_readonly("trajectory", &WalkRecord::trajectory, "WholeBodyTrajectory.")
      .def_readonly("reference", &WalkRecord::reference, "StabilizedTrajectory.")
      .def_readonly("samples", &WalkRecord::samples, "WalkSamples.")
      .def_readonly("slips", &WalkRecord::slips, "SlipEvents.")
      .def_readonly("stances", &WalkRecord::stances, "StancePhases with their RCOF.")
      .def_readonly("fell", &WalkRecord::fell, "The plant's verdict.")
      .def_readonly("fall_reason", &WalkRecord::fall_reason, "Why.")
      .def_readonly("duration", &WalkRecord::duration, "Simulated time, s.")
      .def_readonly("plant_seconds", &WalkRecord::plant_seconds, "Wall time of the plant's simulation.");
  m.def("RunWalk", &RunWalk, py::arg("walk"), py::arg("options") = WalkRunOptions(),
        py::call_guard<py::gil_scoped_release>(),
        "Settles the planning chain (InitializeWalk), then simulates the plant to the reference's end plus the "
        "settle time.");
}

void DefineVisualization(py::module_ m) {
  using namespace cairn::visualization;
  py::class_<SceneBox>(m, "SceneBox", "A static box of the scene, coloured by friction.")
      .def(py::init<>(), "A 1 m cube at the origin.")
      .def_readwrite("name", &SceneBox::name, "Name.")
      .def_readwrite("X_WB", &SceneBox::X_WB, "Pose of the box centre.")
      .def_readwrite("size", &SceneBox::size, "Full side lengths, m.")
      .def_readwrite("friction", &SceneBox::friction, "Shown red (0) to green (>= 1).")
      .def_readwrite("occupancy", &SceneBox::occupancy,
                     "In [0, 1]: an occupied cell drawn dark red with this opacity; negative: a terrain box.");
  py::class_<MotionScene>(m, "MotionScene", "A model's configurations over time among boxes.")
      .def(py::init<>(), "Empty.")
      .def_readwrite("title", &MotionScene::title, "Page title.")
      .def_readwrite("boxes", &MotionScene::boxes, "SceneBoxes.")
      .def_readwrite("times", &MotionScene::times, "s, non-decreasing.")
      .def_readwrite("q", &MotionScene::q, "Configurations, one per time.");
  m.def("DefaultThreeJsPath", &DefaultThreeJsPath, "Where three.js (Debian's libjs-three) is read from.");
  m.def("MotionHtml", &MotionHtml, py::arg("model"), py::arg("scene"), py::arg("three_js_path") = DefaultThreeJsPath(),
        "One self-contained HTML page animating the scene (three.js inlined).");
}

}  // namespace cairn::python
