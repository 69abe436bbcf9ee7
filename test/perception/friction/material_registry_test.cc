#include "cairn/perception/friction/material_registry.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cairn/perception/friction/friction_quantile.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

namespace fs = std::filesystem;

fs::path TempFile(const std::string& name) { return fs::temp_directory_path() / ("cairn_friction_" + name); }

void Write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(MaterialRegistryTest, ThesisTableHasFourteenLabels) {
  const auto registry = MaterialRegistry::ThesisTable33();
  ASSERT_EQ(registry.size(), 14);
  EXPECT_EQ(registry.material(registry.IndexOf("carpet")).friction.b(), 0.02);
  EXPECT_FALSE(registry.material(registry.IndexOf("snow")).friction.walkable());
  CAIRN_EXPECT_THROWS_WITH(registry.IndexOf("ceramics"), std::invalid_argument, "Unknown material 'ceramics'",
                           "did you mean 'ceramic'");
}

TEST(MaterialRegistryTest, YamlRoundTripKeepsEveryParameter) {
  std::vector<MaterialRegistry::Material> materials = {
      {"tile", FrictionDistribution::Normal(0.9, 0.05), 3},
      {"rubber", FrictionDistribution::TruncatedNormal(1.1, 0.2), 0},
      {"ice", FrictionDistribution::GeneralizedExtremeValue(0.1, 0.03, -0.1), 0},
      {"water", FrictionDistribution::NotWalkable(), 0},
  };
  const MaterialRegistry original(materials);
  const fs::path path = TempFile("roundtrip.yaml");
  original.SaveYaml(path.string());
  const MaterialRegistry loaded = MaterialRegistry::LoadYaml(path.string());
  ASSERT_EQ(loaded.size(), 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(loaded.material(i).label, original.material(i).label);
    EXPECT_EQ(loaded.material(i).friction.kind(), original.material(i).friction.kind());
    EXPECT_EQ(loaded.material(i).friction.a(), original.material(i).friction.a());
    EXPECT_EQ(loaded.material(i).friction.b(), original.material(i).friction.b());
    EXPECT_EQ(loaded.material(i).friction.c(), original.material(i).friction.c());
    EXPECT_EQ(loaded.material(i).num_contacts, original.material(i).num_contacts);
  }
  fs::remove(path);
}

TEST(MaterialRegistryTest, MalformedFilesNameTheKeyAndTheLine) {
  const fs::path path = TempFile("bad.yaml");
  Write(path, "materials:\n  - label: tile\n    distribution: normal\n    mean: 0.9\n    stddev: -0.1\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "line 2",
                           "material 'tile'", "standard deviation must be >= 0; got -0.1");
  Write(path, "materials:\n  - label: tile\n    distribution: lognormal\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "line 3",
                           "unknown distribution 'lognormal'");
  Write(path, "materials:\n  - label: tile\n    mean: high\n    stddev: 0.1\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "line 3",
                           "'mean' must be a number, got 'high'");
  Write(path, "materials: [\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "Malformed YAML");
  Write(path, "- {label: a}\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument,
                           "must hold a YAML mapping");
  Write(path, "material:\n  - {label: a}\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "line 1",
                           "unknown key 'material'", "Did you mean 'materials'?");
  Write(path, "materials:\n  - {label: a, distribution: normal, mean: 0.5, stddev: 0.1, mean: 0.6}\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "line 2",
                           "the key 'mean' appears twice");
  Write(path, "materials:\n  - {label: a, distribution: not_walkable}\n  - {label: a, distribution: not_walkable}\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "'a' appears twice");
  fs::remove(path);
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml("/nonexistent/registry.yaml"), std::invalid_argument,
                           "Cannot read '/nonexistent/registry.yaml'");
}

// Finite but physically meaningless friction used to pass: a mean of 1e6 lets every step through.
TEST(MaterialRegistryTest, RefusesFrictionOutsidePhysicalRanges) {
  const fs::path path = TempFile("unphysical.yaml");
  Write(path, "materials:\n  - {label: tile, distribution: normal, mean: 0.9, stddev: 0.1}\n"
              "  - {label: glue, distribution: normal, mean: 1e6, stddev: 0.1}\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "line 3",
                           "material 'glue'", "the mean 1e+06 is outside (0, 10]");
  Write(path, "materials:\n  - {label: tile, distribution: truncated_normal, mean: 0.9, stddev: 50}\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument,
                           "the standard deviation 50 is outside [0, 10]");
  Write(path, "materials:\n  - {label: ice, distribution: gev, location: 0.1, scale: 0.03, shape: -40}\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument,
                           "the shape -40 is outside [-5, 5]");
  Write(path, "materials:\n  - {label: ice, distribution: normal, mean: .nan, stddev: 0.1}\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "line 2",
                           "'mean' must be a finite number, got '.nan'");
  Write(path, "materials:\n  - {label: tile, mean: 0.9, stddev: 0.1, contacts: -3}\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "'contacts'",
                           "integer in [0, 1000000000], got '-3'");
  Write(path, "materials:\n  - {label: tile, mean: 0.9, stddev: 0.1, contacts: 1e12}\n");
  CAIRN_EXPECT_THROWS_WITH(MaterialRegistry::LoadYaml(path.string()), std::invalid_argument, "'contacts'",
                           "got '1e12'");
  fs::remove(path);
  EXPECT_NO_THROW(CheckPhysicalFriction(FrictionDistribution::NotWalkable()));
  CAIRN_EXPECT_THROWS_WITH(CheckPhysicalFriction(FrictionDistribution::Normal(0.0, 0.1)), std::invalid_argument,
                           "the mean 0 is outside (0, 10]", "not_walkable");
}

TEST(MaterialRegistryTest, MeasuredContactIsANormalNormalUpdate) {
  MaterialRegistry registry({{"tile", FrictionDistribution::Normal(0.9, 0.1), 0}});
  const Eigen::VectorXd certain = Eigen::VectorXd::Ones(1);
  const Eigen::VectorXd posterior = registry.UpdateFromContact(certain, ContactObservation::Measured(0.5, 0.1));
  EXPECT_EQ(posterior[0], 1.0);
  // Equal prior and measurement variances: the mean moves halfway, the variance halves.
  EXPECT_NEAR(registry.material(0).friction.a(), 0.7, 1e-12);
  EXPECT_NEAR(registry.material(0).friction.b(), 0.1 / std::sqrt(2.0), 1e-12);
  EXPECT_EQ(registry.material(0).num_contacts, 1);
}

TEST(MaterialRegistryTest, LookAlikeSurfaceQuantileMovesAfterSlips) {
  // A wet floor looks like ceramic to the segmenter. Each time the robot walks there using μ = 0.5 it slips; the
  // ceramic label's belief — and the friction bound the planner gets — drop accordingly.
  MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  Eigen::VectorXd looks_ceramic = Eigen::VectorXd::Zero(registry.size());
  looks_ceramic[registry.IndexOf("ceramic")] = 0.9;
  looks_ceramic[registry.IndexOf("wood")] = 0.1;
  const double before = FrictionQuantile(registry, looks_ceramic, 0.95, QuantileMethod::kExact);
  for (int i = 0; i < 5; ++i) registry.UpdateFromContact(looks_ceramic, ContactObservation::Slipped(0.5));
  const double after = FrictionQuantile(registry, looks_ceramic, 0.95, QuantileMethod::kExact);
  EXPECT_GT(before, 0.8);
  EXPECT_LT(after, 0.5);
  // Bayes puts the blame where the slip is least surprising: wood (0.88 ± 0.12) explains a slip at 0.5 far
  // better than ceramic (0.97 ± 0.05), so wood's belief drops and ceramic's barely moves.
  EXPECT_LT(registry.material(registry.IndexOf("wood")).friction.a(), 0.5);
  EXPECT_NEAR(registry.material(registry.IndexOf("ceramic")).friction.a(), 0.97, 1e-3);
  // When the segmenter is sure it is ceramic, ceramic's belief itself must move below the slip.
  MaterialRegistry sure = MaterialRegistry::ThesisTable33();
  Eigen::VectorXd ceramic = Eigen::VectorXd::Zero(sure.size());
  ceramic[sure.IndexOf("ceramic")] = 1.0;
  sure.UpdateFromContact(ceramic, ContactObservation::Slipped(0.5));
  EXPECT_LT(sure.material(sure.IndexOf("ceramic")).friction.a(), 0.5);
  EXPECT_LT(FrictionQuantile(sure, ceramic, 0.95, QuantileMethod::kExact), 0.5);
  // Held observations at a low coefficient barely move a high-friction belief.
  MaterialRegistry other = MaterialRegistry::ThesisTable33();
  other.UpdateFromContact(looks_ceramic, ContactObservation::Held(0.3));
  EXPECT_NEAR(other.material(other.IndexOf("ceramic")).friction.a(), 0.97, 1e-6);

  // The learned belief survives a save and load.
  const fs::path path = TempFile("learned.yaml");
  registry.SaveYaml(path.string());
  const MaterialRegistry loaded = MaterialRegistry::LoadYaml(path.string());
  EXPECT_EQ(FrictionQuantile(loaded, looks_ceramic, 0.95, QuantileMethod::kExact), after);
  EXPECT_EQ(loaded.material(loaded.IndexOf("ceramic")).num_contacts, 5);
  fs::remove(path);
}

TEST(MaterialRegistryTest, ContactUpdatesRejectWhatTheyCannotExplain) {
  MaterialRegistry registry = MaterialRegistry::ThesisTable33();
  Eigen::VectorXd water = Eigen::VectorXd::Zero(registry.size());
  water[registry.IndexOf("water")] = 1.0;
  CAIRN_EXPECT_THROWS_WITH(registry.UpdateFromContact(water, ContactObservation::Held(0.4)), std::invalid_argument,
                           "no material with nonzero probability can explain the observation");
  CAIRN_EXPECT_THROWS_WITH(registry.UpdateFromContact(water, ContactObservation::Measured(0.4, 0.0)),
                           std::invalid_argument, "noise stddev in (0, 10]", "got 0");
  CAIRN_EXPECT_THROWS_WITH(registry.UpdateFromContact(water, ContactObservation::Slipped(1e6)),
                           std::invalid_argument, "value in [0, 10]", "got 1e+06");
  MaterialRegistry gev({{"ice", FrictionDistribution::GeneralizedExtremeValue(0.1, 0.03, 0.0), 0}});
  CAIRN_EXPECT_THROWS_WITH(gev.UpdateFromContact(Eigen::VectorXd::Ones(1), ContactObservation::Slipped(0.2)),
                           std::invalid_argument, "material 'ice' has a gev distribution");
}

}  // namespace
}  // namespace cairn::perception
