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
#include "cairn/planning/walk/periodic_gait.h"
#include "cairn/planning/walk/plant_gait_sampler.h"
#include "cairn/planning/walk/plant_transition_source.h"
#include "cairn/planning/walk/scenario_terrain_boxes.h"
#include "cairn/planning/walk/walk_diagram.h"
#include "cairn/planning/walk/walk_run.h"
#include "cairn/planning/walk/walk_step_comparison.h"
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
      .def_readwrite("plant", &WalkSetup::plant, "HumanoidPlantOptions.")
      .def_property(
          "refine_model",
          [](const WalkSetup& w) { return std::const_pointer_cast<WalkingModel>(w.refine_model); },
          [](WalkSetup& w, std::shared_ptr<WalkingModel> model) { w.refine_model = std::move(model); },
          "The WalkingModel the plan's step parameters are refined with (SLSQP), or None to keep the table's.")
      .def_property(
          "plan", [](const WalkSetup& w) -> py::object { return w.plan ? py::cast(*w.plan) : py::none(); },
          [](WalkSetup& w, py::object plan) {
            w.plan = plan.is_none() ? nullptr : std::make_shared<const FootstepPlan>(plan.cast<FootstepPlan>());
          },
          "A fixed FootstepPlan to walk instead of planning one (a copy), or None: the FootstepPlanner plans.");
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
      py::arg("controller"),
      "The scenario's walk with its terrain, start, goal, obstacles, plant boxes and the model's motors.");
  m.def("StandingAtStart", &StandingAtStart, py::arg("robot"), py::arg("sole_bodies"), py::arg("start"),
        "The robot standing at a stance: neutral joints, base over the feet, lowest sole on the ground.");

  py::class_<WalkDiagram>(m, "WalkDiagram", "The walk diagram and its blocks (from BuildWalkDiagram).")
      .def_property_readonly(
          "diagram", [](const WalkDiagram& w) { return w.diagram.get(); }, py::return_value_policy::reference_internal,
          "The Diagram.")
      .def_property_readonly(
          "footsteps", [](const WalkDiagram& w) { return w.footsteps; }, py::return_value_policy::reference_internal,
          "The FootstepPlanner (None when the setup walks a fixed plan).")
      .def_property_readonly(
          "plan", [](const WalkDiagram& w) { return w.plan; }, py::return_value_policy::reference_internal,
          "The OutputPort of the plan the trajectory optimizer follows (the planner's, or the fixed plan's source).")
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
      .def_readonly("electrical_energy", &WalkSample::electrical_energy, "E_ele so far, J.")
      .def_readonly("heat", &WalkSample::heat, "E_ele's Joule heat so far, J.");
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

  py::class_<WalkStepComparison>(m, "WalkStepComparison",
                                 "One planned step's predictions against the plant over its planned window.")
      .def_readonly("index", &WalkStepComparison::index, "1 for the first step.")
      .def_readonly("foot", &WalkStepComparison::foot, "The foot that swings.")
      .def_readonly("start", &WalkStepComparison::start, "Window start, s.")
      .def_readonly("end", &WalkStepComparison::end, "Window end, s.")
      .def_readonly("predicted_rcof", &WalkStepComparison::predicted_rcof, "The plan's RCOF.")
      .def_readonly("measured_rcof", &WalkStepComparison::measured_rcof, "The support sole's RCOF.")
      .def_readonly("measured_rcof_after_touchdown", &WalkStepComparison::measured_rcof_after_touchdown,
                    "The same without the landing impact.")
      .def_readonly("measured_net_rcof", &WalkStepComparison::measured_net_rcof, "Of both soles' net force.")
      .def_readonly("mu_allowed", &WalkStepComparison::mu_allowed, "Friction the step may use.")
      .def_readonly("predicted_com_work", &WalkStepComparison::predicted_com_work, "J.")
      .def_readonly("predicted_heat", &WalkStepComparison::predicted_heat, "J.")
      .def_readonly("measured_com_energy", &WalkStepComparison::measured_com_energy, "E_COM over the window, J.")
      .def_readonly("measured_electrical_energy", &WalkStepComparison::measured_electrical_energy,
                    "E_ele over the window, J.")
      .def_readonly("measured_heat", &WalkStepComparison::measured_heat, "E_ele's Joule heat over the window, J.")
      .def_readonly("completed", &WalkStepComparison::completed, "The walk lasted to the window's end.");
  m.def("CompareWalkSteps", &CompareWalkSteps, py::arg("record"),
        "Each step of record.plan against the plant (NaN where the walk did not complete the step).");
  m.def("SoleDistance", &SoleDistance, py::arg("robot"), py::arg("soles"), py::arg("record"), py::arg("stance"),
        "The larger horizontal distance of the two soles from a stance's footholds at the walk's end, m.");

  py::class_<PeriodicGait>(m, "PeriodicGait", "A symmetric periodic gait: num_steps steps of one displacement and p.")
      .def(py::init([](const StepDisplacement& d, const StepParameters& p, int num_steps) {
             return PeriodicGait{d, p, num_steps};
           }),
           py::arg("displacement") = StepDisplacement(), py::arg("parameters") = StepParameters(),
           py::arg("num_steps") = 6, "A gait.")
      .def_readwrite("displacement", &PeriodicGait::displacement, "StepDisplacement of every step.")
      .def_readwrite("parameters", &PeriodicGait::parameters, "StepParameters of every step.")
      .def_readwrite("num_steps", &PeriodicGait::num_steps, "Steps, in [1, 100].");
  m.def("PeriodicGaitPlan", &PeriodicGaitPlan, py::arg("gait"), py::arg("model"), py::arg("objective"),
        py::arg("mu_allowed"),
        "The gait as a FootstepPlan from a start stance that already has its displacement, the right foot first; "
        "each step carries the analytic model's prediction.");
  m.def("PeriodicGaitTerrain", &PeriodicGaitTerrain, py::arg("plan"), py::arg("foot_length"), py::arg("foot_width"),
        py::arg("friction"), py::arg("margin") = 0.01,
        "The plant's ground of a plan: a level floor, or one tread per foothold when their heights differ.");
  py::class_<PlantGaitOptions>(m, "PlantGaitOptions", "How PlantGaitSampler walks and measures a gait.")
      .def(py::init<>(), "Six steps, two transient at each end, friction 1, 5 cm tracking tolerance.")
      .def_readwrite("num_steps", &PlantGaitOptions::num_steps, "Steps of each gait.")
      .def_readwrite("transient_steps", &PlantGaitOptions::transient_steps,
                     "Steps at each end left out of the measurement.")
      .def_readwrite("ground_friction", &PlantGaitOptions::ground_friction, "Ground friction and mu_allowed.")
      .def_readwrite("tracking_tolerance", &PlantGaitOptions::tracking_tolerance,
                     "Largest final sole distance from the plan's last stance, m.")
      .def_readwrite("settle_time", &PlantGaitOptions::settle_time, "Standing after the reference, s.")
      .def_readwrite("min_support_margin", &PlantGaitOptions::min_support_margin,
                     "MeasurePlanned: least ZMP margin inside the support polygon for a feasible gait, m.")
      .def_readwrite("trajectory", &PlantGaitOptions::trajectory, "TrajectoryOptimizerOptions.")
      .def_readwrite("stabilizer", &PlantGaitOptions::stabilizer, "StabilizerOptions.")
      .def_readwrite("feedback", &PlantGaitOptions::feedback, "Close the loop with BalanceFeedback.")
      .def_readwrite("balance", &PlantGaitOptions::balance, "BalanceFeedbackOptions.")
      .def_readwrite("plant", &PlantGaitOptions::plant, "HumanoidPlantOptions (empty drives: the walking model's).");
  py::class_<GaitMeasurement>(m, "GaitMeasurement",
                              "What one periodic gait did in the plant, or what the planning chain made of it.")
      .def(py::init<>(), "Not simulated; to build measurements by hand.")
      .def_readwrite("gait", &GaitMeasurement::gait, "The PeriodicGait.")
      .def_readwrite("predicted", &GaitMeasurement::predicted, "The analytic model's TransitionCost.")
      .def_readwrite("simulated", &GaitMeasurement::simulated, "The plant walked.")
      .def_readwrite("feasible", &GaitMeasurement::feasible, "No fall, soles within the tracking tolerance.")
      .def_readwrite("reason", &GaitMeasurement::reason, "Why not feasible.")
      .def_readwrite("measured_steps", &GaitMeasurement::measured_steps, "Steps measured.")
      .def_readwrite("com_work", &GaitMeasurement::com_work, "Mean E_COM per measured step, J.")
      .def_readwrite("electrical_energy", &GaitMeasurement::electrical_energy, "Mean E_ele per measured step, J.")
      .def_readwrite("heat", &GaitMeasurement::heat, "Mean Joule heat per measured step, J.")
      .def_readwrite("rcof", &GaitMeasurement::rcof, "Largest net-force RCOF of the measured steps.")
      .def_readwrite("sole_rcof", &GaitMeasurement::sole_rcof, "Largest support-sole RCOF after touchdown.")
      .def_readwrite("com_height", &GaitMeasurement::com_height, "Mean COM height above the stance, m.")
      .def_readwrite("torque_cost", &GaitMeasurement::torque_cost,
                     "Mean whole-body torque cost per measured step (torques over effort limits, squared).")
      .def_readwrite("support_margin", &GaitMeasurement::support_margin,
                     "Least ZMP margin of the stabilised reference inside its support polygon, m.")
      .def_readwrite("slips", &GaitMeasurement::slips, "Slips over the whole walk.")
      .def_readwrite("final_error", &GaitMeasurement::final_error, "Soles' distance from the plan's end, m.")
      .def_readwrite("duration", &GaitMeasurement::duration, "Simulated time, s.")
      .def_readwrite("seconds", &GaitMeasurement::seconds, "WalkSettleTimes (wall time).")
      .def_readwrite("plant_seconds", &GaitMeasurement::plant_seconds, "Wall time of the plant.");
  py::class_<PlantGaitSampler, std::shared_ptr<PlantGaitSampler>>(m, "PlantGaitSampler",
                               "Walks periodic gaits in the physics plant and measures E_COM, RCOF, E_ele, Psi.")
      .def(py::init([](std::shared_ptr<WalkingModel> walking_model, const multibody::Model& robot,
                       const multibody::JointPdController& controller, WalkingObjective objective,
                       PlantGaitOptions options) {
             return std::make_shared<PlantGaitSampler>(
                 std::move(walking_model), std::make_shared<const multibody::Model>(robot),
                 std::make_shared<const multibody::JointPdController>(controller), objective, std::move(options));
           }),
           py::arg("walking_model"), py::arg("robot"), py::arg("controller"), py::arg("objective"),
           py::arg("options") = PlantGaitOptions(), "Keeps copies of the robot and the controller.")
      .def("Setup", &PlantGaitSampler::Setup, py::arg("gait"), "The WalkSetup of a gait (its fixed plan and ground).")
      .def("Measure", &PlantGaitSampler::Measure, py::arg("gait"), py::call_guard<py::gil_scoped_release>(),
           "Walks the gait and measures it.")
      .def("MeasurePlanned", &PlantGaitSampler::MeasurePlanned, py::arg("gait"),
           py::call_guard<py::gil_scoped_release>(),
           "Optimises and stabilises the gait without walking it and measures the reference (the pipeline source).")
      .def("options", &PlantGaitSampler::options, py::return_value_policy::copy, "The PlantGaitOptions.");
  py::class_<PlantTransitionSource, TransitionSource, std::shared_ptr<PlantTransitionSource>> source(
      m, "PlantTransitionSource",
      "The \"plant\" and \"pipeline\" oracle sources: per cell, the cheapest feasible periodic gait of a timing "
      "grid, walked in the plant or only planned.");
  py::enum_<PlantTransitionSource::Mode>(source, "Mode", "Walked in the plant, or the planning chain alone.")
      .value("kPlant", PlantTransitionSource::Mode::kPlant)
      .value("kPipeline", PlantTransitionSource::Mode::kPipeline);
  source
      .def(py::init<std::shared_ptr<const PlantGaitSampler>, std::vector<double>, std::vector<double>,
                    PlantTransitionSource::Mode>(),
           py::arg("sampler"), py::arg("t_ds"), py::arg("t_sw"), py::arg("mode") = PlantTransitionSource::Mode::kPlant,
           "ValueError naming a timing out of bounds.")
      .def("mode", &PlantTransitionSource::mode, "Mode.kPlant or Mode.kPipeline.")
      .def_static("DefaultGrid", &PlantTransitionSource::DefaultGrid, py::arg("model"),
                  "The reduced level grid the CLI builds by default.")
      .def_static("DefaultDoubleSupportTimes", &PlantTransitionSource::DefaultDoubleSupportTimes, py::arg("model"),
                  "The default t_ds axis, s.")
      .def_static("DefaultSwingTimes", &PlantTransitionSource::DefaultSwingTimes, py::arg("model"),
                  "The default t_sw axis, s.")
      .def("t_ds", &PlantTransitionSource::t_ds, "The t_ds axis, s.")
      .def("t_sw", &PlantTransitionSource::t_sw, "The t_sw axis, s.")
      .def("MeasureCell", &PlantTransitionSource::MeasureCell, py::arg("d"), py::call_guard<py::gil_scoped_release>(),
           "The GaitMeasurement of every timing pair for displacement d (t_ds outer).")
      .def_static("EntriesFrom", &PlantTransitionSource::EntriesFrom, py::arg("measurements"), py::arg("objective"),
                  py::arg("mu"), py::arg("mode") = PlantTransitionSource::Mode::kPlant,
                  "The cheapest feasible measured gait within each friction limit.");
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
