// The Bullet plant (issue 14): simulated seconds per wall second for the humanoid (30 joints, 1 ms steps, one
// core), standing and marching in place, through the plant's C++ API and as a HumanoidPlant in a diagram.
// Anchors: a 30-DoF humanoid in Gazebo/DART runs at about 4% of real time (gym-ignition's iCub report); MuJoCo
// reaches ~123 k dynamics evaluations per second on a 29-DoF humanoid. Aim: at least 5x real time.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "cairn/multibody/configuration.h"
#include "cairn/multibody/data.h"
#include "cairn/multibody/kinematics.h"
#include "cairn/multibody/plant/bullet_plant.h"
#include "cairn/multibody/plant/contact_monitor.h"
#include "cairn/multibody/plant/humanoid_plant.h"
#include "cairn/multibody/plant/joint_drive.h"
#include "cairn/multibody/plant/joint_pd_controller.h"
#include "cairn/multibody/urdf_parser.h"
#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/primitives/constant_vector_source.h"

namespace {

using namespace cairn::multibody;

const std::string kRobots = std::string(CAIRN_SOURCE_DIR) + "/data/robots/";

Model Humanoid() {
  UrdfOptions options;
  options.floating_base = true;
  return ParseUrdfFile(kRobots + "cairn_humanoid.urdf", options);
}

Eigen::VectorXd StandingQ(const Model& model) {
  Eigen::VectorXd q = NeutralConfiguration(model);
  Data data(model);
  ForwardKinematics(model, data, q);
  q[2] = -data.X_world[static_cast<std::size_t>(model.GetBodyIndex("l_sole"))].translation().z();
  return q;
}

std::vector<TerrainBox> Ground() {
  TerrainBox ground;
  ground.name = "ground";
  ground.X_WB = Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, -0.5));
  ground.size = Eigen::Vector3d(40.0, 40.0, 1.0);
  ground.friction = 0.8;
  return {ground};
}

// Marching in place: each leg in turn bends hip, knee and ankle (foot kept parallel to the ground, 0.15 rad at
// the hip) with a 1 s period while the other leg stands, so the load moves from sole to sole and the swing foot
// lifts by 1 to 6 cm. There is no balance control: the robot rocks and drifts sideways (0.3 m in 10 s) but does
// not fall within the 10 s measured (the `fallen` counter says so).
void MarchingReference(const Model& model, const Eigen::VectorXd& q0, double t, Eigen::VectorXd* q_ref,
                       Eigen::VectorXd* v_ref) {
  *q_ref = q0;
  v_ref->setZero();
  const double w = 2.0 * 3.14159265358979323846;
  for (int side = 0; side < 2; ++side) {
    const std::string p = side == 0 ? "l_" : "r_";
    const double phase = w * t + side * 3.14159265358979323846;
    const double bend = 0.15 * std::max(0.0, std::sin(phase));
    const double rate = std::sin(phase) > 0.0 ? 0.15 * w * std::cos(phase) : 0.0;
    const Joint& hip = model.joint(model.GetJointIndex(p + "hip_pitch"));
    const Joint& knee = model.joint(model.GetJointIndex(p + "knee"));
    const Joint& ankle = model.joint(model.GetJointIndex(p + "ankle_pitch"));
    (*q_ref)[hip.idx_q] = -bend;
    (*q_ref)[knee.idx_q] = 2.0 * bend;
    (*q_ref)[ankle.idx_q] = -bend;
    (*v_ref)[hip.idx_v] = -rate;
    (*v_ref)[knee.idx_v] = 2.0 * rate;
    (*v_ref)[ankle.idx_v] = -rate;
  }
}

// One iteration = 1 s of simulated time (1000 steps of the plant, the PD law and the contact monitor).
void RunPlant(benchmark::State& state, bool marching) {
  const Model model = Humanoid();
  const JointPdController pd = JointPdController::Load(model, kRobots + "cairn_humanoid_control.yaml");
  BulletPlant plant(model, Ground());
  ContactMonitor monitor(plant, {"l_sole", "r_sole"}, "pelvis", LoadJointDrives(model, kRobots + "cairn_humanoid_walking.yaml"));
  const Eigen::VectorXd q0 = StandingQ(model);
  plant.SetState(q0, Eigen::VectorXd::Zero(model.nv()));
  Eigen::VectorXd q_ref = q0, v_ref = Eigen::VectorXd::Zero(model.nv());
  for (auto _ : state) {
    for (int step = 0; step < 1000; ++step) {
      if (marching) MarchingReference(model, q0, plant.time(), &q_ref, &v_ref);
      const Eigen::VectorXd tau = pd.Torques(plant.positions(), plant.velocities(), q_ref, v_ref);
      plant.Step(tau);
      monitor.Update(plant, tau);
    }
    benchmark::DoNotOptimize(plant.positions());
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                          benchmark::Counter::kIsRate);
  state.counters["fallen"] = monitor.fallen() ? 1.0 : 0.0;
  state.counters["slips"] = static_cast<double>(monitor.slips().size());
}

void BM_PlantStanding(benchmark::State& state) { RunPlant(state, false); }
void BM_PlantMarching(benchmark::State& state) { RunPlant(state, true); }

// The same standing robot as a HumanoidPlant in a diagram, advanced by the Simulator (framework overhead).
void BM_HumanoidPlantDiagramStanding(benchmark::State& state) {
  const Model model = Humanoid();
  const JointPdController pd = JointPdController::Load(model, kRobots + "cairn_humanoid_control.yaml");
  const Eigen::VectorXd q0 = StandingQ(model);
  cairn::systems::DiagramBuilder builder;
  auto* plant = builder.AddNamedSystem<HumanoidPlant>("plant", model, Ground(), pd, q0);
  Eigen::VectorXd reference = Eigen::VectorXd::Zero(model.nq() + model.nv());
  reference.head(model.nq()) = q0;
  auto* source = builder.AddNamedSystem<cairn::systems::ConstantVectorSource>("reference", reference);
  builder.Connect(source->get_output_port(0), plant->GetInputPort("reference"));
  auto diagram = builder.Build();
  cairn::systems::Simulator simulator(*diagram);
  double t = 0.0;
  for (auto _ : state) {
    t += 1.0;
    benchmark::DoNotOptimize(simulator.AdvanceTo(t));
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                          benchmark::Counter::kIsRate);
}

// 10 iterations = 10 simulated seconds each: the marching motion is checked not to fall within them.
BENCHMARK(BM_PlantStanding)->Unit(benchmark::kMillisecond)->Iterations(10);
BENCHMARK(BM_PlantMarching)->Unit(benchmark::kMillisecond)->Iterations(10);
BENCHMARK(BM_HumanoidPlantDiagramStanding)->Unit(benchmark::kMillisecond)->Iterations(10);

}  // namespace

BENCHMARK_MAIN();
