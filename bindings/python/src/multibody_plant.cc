// cairn.multibody (plant part): the Bullet physics plant, its PD controller, contact monitor and the HumanoidPlant
// system. Stepping releases the GIL: a humanoid second is thousands of Bullet steps.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "abstract_values.h"
#include "bindings.h"
#include "cairn/multibody/plant/bullet_plant.h"
#include "cairn/multibody/plant/contact_monitor.h"
#include "cairn/multibody/plant/humanoid_plant.h"
#include "cairn/multibody/plant/joint_drive.h"
#include "cairn/multibody/plant/joint_pd_controller.h"
#include "cairn/multibody/plant/joint_trajectory.h"
#include "cairn/multibody/plant/plant_scenario.h"
#include "system_support.h"

namespace cairn::python {

using namespace cairn::multibody;
using VectorRef = Eigen::Ref<const Eigen::VectorXd>;

void DefineMultibodyPlant(py::module_ m) {
  py::class_<TerrainBox>(m, "TerrainBox", "A static terrain box of the plant with its own Coulomb friction.")
      .def(py::init<>(), "A 1 m cube at the origin with friction 1.")
      .def(py::init([](std::string name, const Pose& X_WB, const Eigen::Vector3d& size, double friction) {
             return TerrainBox{std::move(name), X_WB, size, friction};
           }),
           py::arg("name"), py::arg("X_WB"), py::arg("size"), py::arg("friction"),
           "A box of full side lengths `size` at pose X_WB with friction coefficient `friction`.")
      .def_readwrite("name", &TerrainBox::name, "Region name.")
      .def_readwrite("X_WB", &TerrainBox::X_WB, "Pose of the box centre in the world.")
      .def_readwrite("size", &TerrainBox::size, "Full side lengths (m).")
      .def_readwrite("friction", &TerrainBox::friction, "Coulomb friction coefficient in [0, 10].")
      .def_readwrite("contact_stiffness", &TerrainBox::contact_stiffness,
                     "Normal contact stiffness per contact point, N/m (inf: rigid).")
      .def_readwrite("contact_damping", &TerrainBox::contact_damping,
                     "Normal contact damping, N s/m (0 for a rigid box).");

  py::class_<BulletPlantOptions>(m, "BulletPlantOptions", "How a BulletPlant steps.")
      .def(py::init<>(), "1 ms steps, contacts on, 100 solver iterations.")
      .def_readwrite("time_step", &BulletPlantOptions::time_step, "Fixed step (s), in (0, 0.01].")
      .def_readwrite("contacts", &BulletPlantOptions::contacts, "Create collision shapes and contacts.")
      .def_readwrite("solver_iterations", &BulletPlantOptions::solver_iterations, "Contact solver iterations.");

  py::class_<ContactPoint>(m, "ContactPoint", "A contact point of the last plant step and its force on the robot.")
      .def_readonly("body", &ContactPoint::body, "Cairn body index of the robot body in contact.")
      .def_readonly("terrain", &ContactPoint::terrain, "Index of the terrain box.")
      .def_readonly("position", &ContactPoint::position, "Point on the terrain (world).")
      .def_readonly("normal", &ContactPoint::normal, "Unit normal from the terrain into the robot.")
      .def_readonly("normal_force", &ContactPoint::normal_force, "Normal force (N).")
      .def_readonly("tangential_force", &ContactPoint::tangential_force, "Friction force (N, world).")
      .def_readonly("distance", &ContactPoint::distance, "Signed distance (m, negative when penetrating).");

  py::class_<BulletPlant>(m, "BulletPlant",
                          "A Bullet btMultiBody of a Model on terrain boxes; states in Cairn's coordinates.")
      .def(py::init<const Model&, const std::vector<TerrainBox>&, const BulletPlantOptions&>(), py::arg("model"),
           py::arg("terrain"), py::arg("options") = BulletPlantOptions(), "Builds the Bullet world.")
      .def("SetState", &BulletPlant::SetState, py::arg("q"), py::arg("v"), "Sets the state (Cairn coordinates).")
      .def("positions", &BulletPlant::positions, "The configuration q.")
      .def("velocities", &BulletPlant::velocities, "The velocity v.")
      .def(
          "Step",
          [](BulletPlant& self, const Eigen::VectorXd& tau, int steps) {
            if (steps < 1) throw py::value_error("BulletPlant.Step: steps must be >= 1");
            py::gil_scoped_release release;
            for (int i = 0; i < steps; ++i) self.Step(tau);
          },
          py::arg("tau"), py::arg("steps") = 1, "Advances `steps` time steps holding generalized forces `tau`.")
      .def("contacts", &BulletPlant::contacts, "The contact points of the last step (copies).")
      .def("time", &BulletPlant::time, "Simulated time (s).")
      .def("num_links", &BulletPlant::num_links, "Bullet links (moving joints below the base).")
      .def("merged_body", &BulletPlant::merged_body, py::arg("body"),
           "The moving body that `body` is merged into through fixed joints.");

  py::class_<JointDrive>(m, "JointDrive", "A joint's DC drive for the electrical energy (thesis eq. 2.6).")
      .def(py::init<>(), "No drive data.")
      .def_readwrite("resistance", &JointDrive::resistance, "Armature resistance (ohm).")
      .def_readwrite("torque_constant", &JointDrive::torque_constant, "Torque constant (N m / A); 0: no drive.")
      .def_readwrite("gear_ratio", &JointDrive::gear_ratio, "Gear reduction ratio.");
  m.def("LoadJointDrives", &LoadJointDrives, py::arg("model"), py::arg("walking_yaml_path"),
        "The drives per velocity coordinate from the `motors` of a walking-model YAML.");

  py::class_<JointPdController>(m, "JointPdController",
                                "Joint PD position control saturated at the URDF effort limits.")
      .def(py::init<const Model&, const Eigen::VectorXd&, const Eigen::VectorXd&>(), py::arg("model"), py::arg("kp"),
           py::arg("kd"), "Gains per velocity coordinate.")
      .def_static("Load", &JointPdController::Load, py::arg("model"), py::arg("yaml_path"),
                  "Reads per-group gains from a control YAML (data/robots/cairn_humanoid_control.yaml).")
      .def("kp", &JointPdController::kp, "Proportional gains.")
      .def("kd", &JointPdController::kd, "Derivative gains.")
      .def("Torques",
           py::overload_cast<const VectorRef&, const VectorRef&, const VectorRef&, const VectorRef&>(
               &JointPdController::Torques, py::const_),
           py::arg("q"), py::arg("v"), py::arg("q_ref"), py::arg("v_ref"), "The saturated PD torques.");

  py::class_<SoleState>(m, "SoleState", "One sole's contact after a step.")
      .def_readonly("force", &SoleState::force, "Total contact force (N, world).")
      .def_readonly("normal_force", &SoleState::normal_force, "Normal force (N).")
      .def_readonly("tangential_force", &SoleState::tangential_force, "Tangential force magnitude (N).")
      .def_readonly("cop", &SoleState::cop, "Centre of pressure (world).")
      .def_readonly("loaded", &SoleState::loaded, "Normal force above the loaded threshold.")
      .def_readonly("position", &SoleState::position, "Sole frame position (world).")
      .def_readonly("tangential_speed", &SoleState::tangential_speed, "Sole speed along the ground (m/s).");
  py::class_<SlipEvent>(m, "SlipEvent", "A loaded sole slid beyond the slip thresholds.")
      .def_readonly("time", &SlipEvent::time, "Detection time (s).")
      .def_readonly("foot", &SlipEvent::foot, "0 left, 1 right.")
      .def_readonly("position", &SlipEvent::position, "Sole position at detection.")
      .def_readonly("force_ratio", &SlipEvent::force_ratio, "|F_t| / F_n at detection.");
  py::class_<StancePhase>(m, "StancePhase", "One stance of a sole with its RCOF (thesis eq. 2.2).")
      .def_readonly("foot", &StancePhase::foot, "0 left, 1 right.")
      .def_readonly("start", &StancePhase::start, "First loaded time (s).")
      .def_readonly("end", &StancePhase::end, "Last loaded time (s).")
      .def_readonly("rcof", &StancePhase::rcof, "max |F_t / F_n| of this sole while loaded.")
      .def_readonly("rcof_after_touchdown", &StancePhase::rcof_after_touchdown,
                    "The same after the stance's first touchdown_time.")
      .def_readonly("net_rcof", &StancePhase::net_rcof,
                    "max |F_t / F_n| of both soles' low-passed net force over the stance.")
      .def_readonly("finished", &StancePhase::finished, "False while the stance goes on (stance_gap).");

  py::class_<ContactMonitorOptions>(m, "ContactMonitorOptions", "Load, slip and fall thresholds.")
      .def(py::init<>(), "The defaults (20 N, 0.01 m/s, 2 mm, 0.5 m, 0.7 rad, 1 N).")
      .def_readwrite("loaded_force", &ContactMonitorOptions::loaded_force, "Loaded above this normal force (N).")
      .def_readwrite("slip_speed", &ContactMonitorOptions::slip_speed, "Sliding above this speed (m/s).")
      .def_readwrite("slip_distance", &ContactMonitorOptions::slip_distance, "Slip reported after this slide (m).")
      .def_readwrite("stance_gap", &ContactMonitorOptions::stance_gap,
                     "Unloaded spells shorter than this (s) do not end a stance.")
      .def_readwrite("touchdown_time", &ContactMonitorOptions::touchdown_time,
                     "rcof_after_touchdown leaves out a stance's first this (s).")
      .def_readwrite("force_filter_time", &ContactMonitorOptions::force_filter_time,
                     "Low-pass time constant of the net force behind net_rcof (s; 0 unfiltered).")
      .def_readwrite("fall_base_height", &ContactMonitorOptions::fall_base_height, "Base height limit (m).")
      .def_readwrite("fall_tilt", &ContactMonitorOptions::fall_tilt, "Base tilt limit (rad).")
      .def_readwrite("fall_contact_force", &ContactMonitorOptions::fall_contact_force,
                     "Non-foot contact force limit (N).");

  py::class_<HumanoidPlantOptions>(m, "HumanoidPlantOptions", "How a HumanoidPlant is built.")
      .def(py::init<>(), "Soles l_sole / r_sole, base pelvis, no drives, no torque input, stop on a fall.")
      .def_readwrite("bullet", &HumanoidPlantOptions::bullet, "Bullet world options.")
      .def_readwrite("monitor", &HumanoidPlantOptions::monitor, "Monitor thresholds.")
      .def_readwrite("sole_bodies", &HumanoidPlantOptions::sole_bodies, "Left and right sole bodies.")
      .def_readwrite("base_body", &HumanoidPlantOptions::base_body, "Base body deciding falls.")
      .def_readwrite("drives", &HumanoidPlantOptions::drives, "Drives per velocity coordinate (E_ele).")
      .def_readwrite("torque_input", &HumanoidPlantOptions::torque_input, "Declare the `torque` input.")
      .def_readwrite("stop_on_fall", &HumanoidPlantOptions::stop_on_fall, "End the simulation at a fall.");

  py::class_<HumanoidPlant, systems::LeafSystem>(
      m, "HumanoidPlant",
      "System: inputs `reference` ([q; v]) and optionally `torque`; outputs `state` ([q; v]), `contacts` "
      "(list of SoleState), `slips`, `stances`, `zmp` and `energy` ([E_COM, E_ele]); a periodic update per time "
      "step. A fall ends the simulation (SimulatorStatus.Reason.kReachedTerminationCondition).")
      .def(py::init([](const Model& model, std::vector<TerrainBox> terrain, const JointPdController& controller,
                       const Eigen::VectorXd& initial_q, HumanoidPlantOptions options) {
             return std::make_unique<HumanoidPlant>(model, std::move(terrain), controller, initial_q,
                                                    std::move(options));
           }),
           py::arg("model"), py::arg("terrain"), py::arg("controller"), py::arg("initial_q"),
           py::arg("options") = HumanoidPlantOptions(), "Builds the plant; the initial velocity is zero.");

  py::class_<PlantScenario>(m, "PlantScenario", "A plant scenario file: terrain boxes with friction, drop height.")
      .def_static("Load", &PlantScenario::Load, py::arg("path"), "Reads and validates a scenario YAML.")
      .def_readonly("terrain", &PlantScenario::terrain, "The terrain boxes.")
      .def_readonly("drop_height", &PlantScenario::drop_height, "Start height of the soles above z = 0 (m).");

  py::class_<JointTrajectory>(m, "JointTrajectory", "A joint reference from a CSV file (time,<joint>,...).")
      .def_static("LoadCsv", &JointTrajectory::LoadCsv, py::arg("model"), py::arg("path"), "Reads and validates it.")
      .def(
          "Evaluate",
          [](const JointTrajectory& self, double t, const Eigen::VectorXd& q_base) {
            Eigen::VectorXd q, v;
            self.Evaluate(t, q_base, &q, &v);
            return py::make_tuple(q, v);
          },
          py::arg("t"), py::arg("q_base"), "The reference (q, v) at time t.")
      .def("end_time", &JointTrajectory::end_time, "Time of the last row (s).")
      .def("num_rows", &JointTrajectory::num_rows, "Number of rows.");

  RegisterConvertedAbstractValueType<std::vector<SoleState>>("SoleStates");
  RegisterConvertedAbstractValueType<std::vector<SlipEvent>>("SlipEvents");
  RegisterConvertedAbstractValueType<std::vector<StancePhase>>("StancePhases");
}

}  // namespace cairn::python
