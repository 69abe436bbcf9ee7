// The humanoid in the Bullet plant under joint PD control (gains from data/robots/cairn_humanoid_control.yaml):
// standing still on flat ground, slipping on a 25° slope of μ = 0.1, landing from 0.2 m, and bit-for-bit
// determinism; and a single joint tracking a sine with the error its gains predict.

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/model_builder.h>
#include <cairn/multibody/plant/bullet_plant.h>
#include <cairn/multibody/plant/contact_monitor.h>
#include <cairn/multibody/plant/joint_pd_controller.h>

#include "expect_throws.h"
#include "test_models.h"
#include "test_paths.h"

namespace cairn::multibody {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string ControlYaml() { return std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_control.yaml"; }
std::string WalkingYaml() { return std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_walking.yaml"; }

// The standing configuration: joints at zero, soles on the plane through the origin with rotation R_ground
// (raised by `lift` along its normal).
Eigen::VectorXd StandingQ(const Model& model, const Eigen::Matrix3d& R_ground, double lift) {
  Eigen::VectorXd q = NeutralConfiguration(model);
  Data data(model);
  ForwardKinematics(model, data, q);
  const double sole_z = data.X_world[static_cast<std::size_t>(model.GetBodyIndex("l_sole"))].translation().z();
  const Eigen::Vector3d base = R_ground * Eigen::Vector3d(0.0, 0.0, -sole_z + lift);
  const Eigen::Quaterniond quaternion(R_ground);
  q.head<3>() = base;
  q.segment<4>(3) << quaternion.w(), quaternion.x(), quaternion.y(), quaternion.z();
  return q;
}

struct StandRun {
  std::vector<Eigen::VectorXd> q;  // every 100 steps, and the last
  std::vector<SlipEvent> slips;
  std::vector<StancePhase> stances;
  bool fallen = false;
  std::string fall_reason;
  double max_abs_tau = 0.0;
  double electrical_energy = 0.0;
  double com_energy = 0.0;
  Eigen::Vector3d zmp;
  double sole_travel = 0.0;  // largest horizontal displacement of a sole frame from where it was after step 1
  double normal_force_sum = 0.0;
};

// Holds the standing posture for `steps` steps on a ground slab tilted by `theta` about y with friction `mu`.
StandRun Stand(double theta, double mu, double lift, int steps) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), true);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()).toRotationMatrix();
  TerrainBox ground;
  ground.name = "ground";
  ground.X_WB = Pose(R, R * Eigen::Vector3d(0.0, 0.0, -0.5));
  ground.size = Eigen::Vector3d(20.0, 20.0, 1.0);
  ground.friction = mu;
  BulletPlant plant(model, {ground});
  const JointPdController pd = JointPdController::Load(model, ControlYaml());
  ContactMonitor monitor(plant, {"l_sole", "r_sole"}, "pelvis", LoadJointDrives(model, WalkingYaml()));
  const Eigen::VectorXd q_ref = StandingQ(model, R, lift);
  const Eigen::VectorXd v_ref = Eigen::VectorXd::Zero(model.nv());
  plant.SetState(q_ref, v_ref);
  StandRun run;
  std::vector<Eigen::Vector3d> first_soles;
  for (int step = 1; step <= steps; ++step) {
    const Eigen::VectorXd tau = pd.Torques(plant.positions(), plant.velocities(), q_ref, v_ref);
    run.max_abs_tau = std::max(run.max_abs_tau, tau.cwiseAbs().maxCoeff());
    plant.Step(tau);
    monitor.Update(plant, tau);
    if (step % 100 == 0 || step == steps) run.q.push_back(plant.positions());
    if (step == 1) {
      for (const SoleState& sole : monitor.soles()) first_soles.push_back(sole.position);
    }
    for (std::size_t f = 0; f < 2; ++f) {
      run.sole_travel = std::max(run.sole_travel, (monitor.soles()[f].position - first_soles[f]).head<2>().norm());
    }
  }
  run.slips = monitor.slips();
  run.stances = monitor.stances();
  run.fallen = monitor.fallen();
  run.fall_reason = monitor.fall_reason();
  run.electrical_energy = monitor.electrical_energy();
  run.com_energy = monitor.com_energy();
  run.zmp = monitor.zmp();
  run.normal_force_sum = monitor.soles()[0].normal_force + monitor.soles()[1].normal_force;
  return run;
}

TEST(HumanoidPlantTest, StandsTenSecondsWithoutDriftSlipOrFall) {
  const StandRun run = Stand(0.0, 1.0, 0.0, 10000);
  // Drift: base displacement between t = 1 s (after the PD offsets have settled) and t = 10 s; stated limit 1 mm.
  // Measured 0.94 mm. It is not sliding (the soles move less than 10 micrometres horizontally, checked below) but
  // the robot swaying on its ankles: the inverted-pendulum mode of the ankle PD (kp 2 x 1000 against m g h ~ 500
  // N m/rad, about 41 kg m^2 about the ankles: period ~1 s) has a damping ratio of only ~0.04 with kd = 2 x 10,
  // and the sag into the PD offsets at the start excites it; its amplitude decays from ~1.3 mm to ~0.3 mm over
  // the 10 s, so the largest excursion from the t = 1 s position is 2.4 mm (sampled every 0.1 s; bounded at 3 mm).
  const Eigen::Vector3d settled = run.q[9].head<3>();
  const double drift = (run.q.back().head<3>() - settled).norm();
  RecordProperty("drift_m", std::to_string(drift));
  double excursion = 0.0;
  for (std::size_t i = 9; i < run.q.size(); ++i) excursion = std::max(excursion, (run.q[i].head<3>() - settled).norm());
  EXPECT_LT(excursion, 3e-3);
  RecordProperty("excursion_m", std::to_string(excursion));
  EXPECT_LT(drift, 1e-3);
  EXPECT_TRUE(run.slips.empty());
  EXPECT_LT(run.sole_travel, 1e-5);
  RecordProperty("sole_travel_m", std::to_string(run.sole_travel));
  EXPECT_FALSE(run.fallen) << run.fall_reason;
  // The soles carry the weight (64 kg), and the ZMP lies between the feet.
  EXPECT_NEAR(run.normal_force_sum, 64.0 * 9.81, 0.02 * 64.0 * 9.81);
  EXPECT_LT(std::abs(run.zmp.y()), 0.08);
  // One stance per foot, never lifted; standing still needs almost no friction (RCOF, eq. 2.2).
  ASSERT_EQ(run.stances.size(), 2u);
  for (const StancePhase& stance : run.stances) {
    EXPECT_FALSE(stance.finished);
    EXPECT_LT(stance.rcof, 0.05);
    EXPECT_LT(stance.net_rcof, 0.05);
  }
  // Holding the posture costs electrical energy in the leg drives (R I^2) even without motion.
  EXPECT_GT(run.electrical_energy, 0.0);
}

TEST(HumanoidPlantTest, MonitorRejectsUnknownBodiesAndBadThresholds) {
  const Model model = test::LoadRobot(test::HumanoidUrdf(), true);
  BulletPlant plant(model, {});
  CAIRN_EXPECT_THROWS_WITH(ContactMonitor(plant, {"l_sole", "r_soul"}, "pelvis"), std::invalid_argument, "r_soul");
  CAIRN_EXPECT_THROWS_WITH(ContactMonitor(plant, {"l_sole"}, "pelvis"), std::invalid_argument, "1 sole bodies");
  ContactMonitorOptions options;
  options.slip_speed = -1.0;
  CAIRN_EXPECT_THROWS_WITH(ContactMonitor(plant, {"l_sole", "r_sole"}, "pelvis", {}, options), std::invalid_argument,
                           "slip_speed is -1");
  options = ContactMonitorOptions();
  options.stance_gap = -0.01;
  CAIRN_EXPECT_THROWS_WITH(ContactMonitor(plant, {"l_sole", "r_sole"}, "pelvis", {}, options), std::invalid_argument,
                           "stance_gap is -0.01", "finite and >= 0");
  options = ContactMonitorOptions();
  options.force_filter_time = std::numeric_limits<double>::quiet_NaN();
  CAIRN_EXPECT_THROWS_WITH(ContactMonitor(plant, {"l_sole", "r_sole"}, "pelvis", {}, options), std::invalid_argument,
                           "force_filter_time is nan");
  options = ContactMonitorOptions();
  options.touchdown_time = 2.0;
  CAIRN_EXPECT_THROWS_WITH(ContactMonitor(plant, {"l_sole", "r_sole"}, "pelvis", {}, options), std::invalid_argument,
                           "touchdown_time 2 s must be at most 1 s");
}

TEST(HumanoidPlantTest, SlipsOnA25DegreeSlopeWithMu01) {
  const StandRun run = Stand(25.0 * kPi / 180.0, 0.1, 0.0, 2000);
  ASSERT_FALSE(run.slips.empty());
  RecordProperty("first_slip_s", std::to_string(run.slips.front().time));
  // A sliding sole carries the Coulomb limit: |F_t| / F_n at the detection is mu within 10 %.
  EXPECT_NEAR(run.slips.front().force_ratio, 0.1, 0.01);
  // The stances' RCOF is the friction the slope demanded and got: mu.
  ASSERT_FALSE(run.stances.empty());
  EXPECT_NEAR(run.stances.front().rcof, 0.1, 0.01);
  // The whole robot slides, so the net force of both soles is at the limit too.
  EXPECT_NEAR(run.stances.front().net_rcof, 0.1, 0.015);
}

TEST(HumanoidPlantTest, LandsFromTwentyCentimetresWithoutFalling) {
  const StandRun run = Stand(0.0, 1.0, 0.2, 3000);
  EXPECT_FALSE(run.fallen) << run.fall_reason;
  // It landed: the base is back at standing height within 2 cm.
  const StandRun standing = Stand(0.0, 1.0, 0.0, 3000);
  EXPECT_NEAR(run.q.back()[2], standing.q.back()[2], 0.02);
}

TEST(HumanoidPlantTest, TwoRunsGiveIdenticalBytes) {
  const StandRun a = Stand(0.0, 1.0, 0.05, 1000);
  const StandRun b = Stand(0.0, 1.0, 0.05, 1000);
  ASSERT_EQ(a.q.size(), b.q.size());
  for (std::size_t i = 0; i < a.q.size(); ++i) {
    ASSERT_EQ(0, std::memcmp(a.q[i].data(), b.q[i].data(), sizeof(double) * static_cast<std::size_t>(a.q[i].size())))
        << "sample " << i;
  }
}

}  // namespace
}  // namespace cairn::multibody
