// ProbeArmPlant: the probe arm in the Bullet plant pushes its tip into terrain boxes of known contact stiffness.
// Known answers: the settled reading is the stiffness times the depth reached (the push drive is a stiff spring in
// series); hard ground gives C = 0, soft soil C = 1 - k d / F_hard, deep water (no box) C = 1. Also BulletPlant's
// validation of a terrain box's contact stiffness and damping.

#include "cairn/planning/scenarios/probe_arm_plant.h"

#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "cairn/multibody/plant/bullet_plant.h"
#include "cairn/multibody/urdf_parser.h"
#include "cairn/perception/terrain/collapsibility_estimator.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

const std::string kArm = std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_probe_arm.urdf";

double Mean(const std::vector<double>& x) { return std::accumulate(x.begin(), x.end(), 0.0) / x.size(); }

ProbeArmPlant::Probe Probe(double stiffness, const Eigen::Vector2d& target = Eigen::Vector2d(0.6, 0.3),
                           ProbeArmPlant::Options options = {}, int seed = 3) {
  const ProbeArmPlant arm = ProbeArmPlant::Load(kArm, options);
  ProbeArmPlant::Ground ground;
  ground.stiffness = stiffness;
  ground.damping = std::isfinite(stiffness) ? 50.0 : 0.0;
  std::mt19937 rng(seed);
  return arm.Run(Eigen::Vector2d(0.0, 0.0), target, ground, &rng);
}

double Collapsibility(const ProbeArmPlant::Probe& p) {
  perception::CollapsibilityEstimator::Options o;
  o.window = static_cast<int>(p.forces.size());
  perception::CollapsibilityEstimator estimator(o);
  for (double f : p.forces) estimator.AddSample(f);
  return estimator.Collapsibility();
}

TEST(ProbeArmPlantTest, SettledForceIsStiffnessTimesDepthReached) {
  for (double k : {750.0, 2000.0, 8000.0}) {
    const ProbeArmPlant::Probe p = Probe(k);
    ASSERT_EQ(p.forces.size(), 20u);
    // The drive (2e5 N/m) yields k / (k + 2e5) of the commanded 2 cm.
    EXPECT_NEAR(p.final_depth, 0.02 * 2e5 / (2e5 + k), 1e-3) << k;
    EXPECT_NEAR(p.true_forces.back(), k * p.final_depth, 0.05 * k * p.final_depth) << k;
    // Bullet's soft contact acts per contact point: k x depth holds only while the tip touches at one.
    EXPECT_EQ(p.max_contact_points, 1) << k;
  }
}

// Hard ground (8000 N/m, 160 N at 2 cm) is at least as stiff as the 100 N reference: C = 0.
TEST(ProbeArmPlantTest, HardGroundIsNotCollapsible) {
  EXPECT_EQ(Collapsibility(Probe(8000.0)), 0.0);
  EXPECT_EQ(Collapsibility(Probe(std::numeric_limits<double>::infinity())), 0.0);
}

// Soft soil under plants (750 N/m, the scenario's): about 15 N at 2 cm, C = 1 - 15 / 100 = 0.85, less what the
// averaged samples miss while the tip settles at the start of the hold.
TEST(ProbeArmPlantTest, SoftSoilIsPartlyCollapsible) {
  const double c = Collapsibility(Probe(750.0));
  EXPECT_GT(c, 0.8);
  EXPECT_LT(c, 0.9);
}

// Deep water: no box within reach, the tip meets nothing; only sensor noise remains.
TEST(ProbeArmPlantTest, DeepWaterGivesNoSupport) {
  const ProbeArmPlant::Probe p = Probe(0.0);
  for (double f : p.true_forces) EXPECT_EQ(f, 0.0);
  EXPECT_GT(Collapsibility(p), 0.95);
  EXPECT_LT(p.final_depth, 0.03);  // the rod stopped at its commanded extension
}

TEST(ProbeArmPlantTest, SeededNoiseIsReproducible) {
  const ProbeArmPlant::Probe a = Probe(2000.0, {0.5, -0.4}, {}, 7);
  const ProbeArmPlant::Probe b = Probe(2000.0, {0.5, -0.4}, {}, 7);
  const ProbeArmPlant::Probe c = Probe(2000.0, {0.5, -0.4}, {}, 8);
  EXPECT_EQ(a.forces, b.forces);
  EXPECT_NE(a.forces, c.forces);
  EXPECT_EQ(a.true_forces, c.true_forces);
  // Noise of 2 N over 20 samples: the mean stays within a few newtons of the noise-free one.
  EXPECT_NEAR(Mean(a.forces), Mean(a.true_forces), 2.0);
}

TEST(ProbeArmPlantTest, TargetDirectlyBelowAndFarWorkOrAreRefused) {
  const ProbeArmPlant::Probe below = Probe(8000.0, {0.0, 0.0});
  EXPECT_NEAR(below.true_forces.back(), 8000.0 * below.final_depth, 8.0);
  const ProbeArmPlant arm = ProbeArmPlant::Load(kArm, {});
  EXPECT_GT(arm.reach(), 0.8);
  std::mt19937 rng(1);
  CAIRN_EXPECT_THROWS_WITH(arm.Run({0, 0}, {2.0, 0.0}, {0.0, 8000.0, 0.0}, &rng), std::invalid_argument,
                           "beyond the arm's reach");
  CAIRN_EXPECT_THROWS_WITH(arm.Run({0, 0}, {0.5, 0.0}, {0.0, -1.0, 0.0}, &rng), std::invalid_argument,
                           "ground stiffness -1");
}

TEST(ProbeArmPlantTest, BadOptionsAndModelsAreRefused) {
  ProbeArmPlant::Options o;
  o.depth = 0.0;
  CAIRN_EXPECT_THROWS_WITH(ProbeArmPlant::Load(kArm, o), std::invalid_argument, "depth is 0");
  o = {};
  o.samples = 1000;
  CAIRN_EXPECT_THROWS_WITH(ProbeArmPlant::Load(kArm, o), std::invalid_argument, "1000 samples do not fit");
  o = {};
  o.hold_time = 1e4;
  CAIRN_EXPECT_THROWS_WITH(ProbeArmPlant::Load(kArm, o), std::invalid_argument, "more than the limit");
  const multibody::Model humanoid = multibody::ParseUrdfFile(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_antenna.urdf");
  CAIRN_EXPECT_THROWS_WITH(ProbeArmPlant(humanoid, {}), std::invalid_argument, "needs the joints yaw, pitch, push");
}

TEST(ProbeArmPlantTest, PlantRefusesBadContactStiffnessAndDamping) {
  const multibody::Model arm = multibody::ParseUrdfFile(kArm);
  multibody::TerrainBox box;
  box.name = "soil";
  box.contact_stiffness = 0.0;
  CAIRN_EXPECT_THROWS_WITH(multibody::BulletPlant(arm, {box}), std::invalid_argument,
                           "terrain box 'soil' has contact_stiffness 0 N/m");
  box.contact_stiffness = 1000.0;
  box.contact_damping = -1.0;
  CAIRN_EXPECT_THROWS_WITH(multibody::BulletPlant(arm, {box}), std::invalid_argument,
                           "terrain box 'soil' has contact_damping -1 N s/m");
  box.contact_stiffness = std::numeric_limits<double>::infinity();
  box.contact_damping = 10.0;
  CAIRN_EXPECT_THROWS_WITH(multibody::BulletPlant(arm, {box}), std::invalid_argument, "but a rigid contact");
  box.contact_damping = 0.0;
  EXPECT_NO_THROW(multibody::BulletPlant(arm, {box}));
}

}  // namespace
}  // namespace cairn::planning
